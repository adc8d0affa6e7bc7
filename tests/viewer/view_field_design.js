// Designing the field in fgsg view in a real browser (#49, item 3): in the Design mode a
// click on the surface adds a wedge to the grammar's first field, dragging its handle
// moves it, the strength box and the Delete key change and remove it. After each edit the
// grammar file holds exactly the expected text (only that element's words changed), the
// overlay's singularities are where the elements are and the same as `fgsg field
// --singularities` finds in the written file. Then four undos (Ctrl+Z and the Undo button)
// give back the text before each edit byte for byte (the drag's moves being one step) and
// the overlay's singularities before it, and four redos (Ctrl+Shift+Z, Ctrl+Y, the Redo
// button) the text and singularities after each.
// usage: node view_field_design.js FGSG_BINARY SOURCE_DIR
'use strict';
const { spawn, execFileSync } = require('child_process');
const crypto = require('crypto');
const fs = require('fs');
const os = require('os');
const path = require('path');

const [fgsg, source] = process.argv.slice(2);
const { ok, chromiumOf, viewUrl, launchChromium } = require('./view_test_support');
const chromium = chromiumOf(source);

// A trisector on a 10 x 10 plane, the wedge's text added after it; a comment and the
// layout around the block must come through every edit byte for byte.
const grammarText = (added) =>
  '// designed in fgsg view\nsurface plane(10, 10, 48);\nfield F = design tensor { trisector at (2, 0, 0) decay 1;' +
  added + ' };  // the field\nAxiom ~> I("cube");\n';
// What the server writes: a millionth of the surface's size (the plane's diagonal is
// 14.1: four decimals), plain decimals, no "-0".
const decimal = (v) => {
  const r = Math.round(v * 1e4) / 1e4;
  return String(r === 0 ? 0 : r);
};
const at = (p) => `(${p.map(decimal).join(', ')})`;
const rounded = (p) => p.map((v) => Number(decimal(v)));

async function main() {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'fgsg-view-design-'));
  const grammar = path.join(dir, 'g.fgsg');
  fs.writeFileSync(grammar, grammarText(''));
  const server = spawn(fgsg, ['view', grammar, '--port', '0'], { stdio: ['ignore', 'pipe', 'inherit'] });
  let browser;
  try {
    const url = await viewUrl(server);
    browser = await launchChromium(chromium);
    const page = await browser.newPage({ viewport: { width: 1000, height: 700 } });
    page.on('pageerror', (e) => console.error('page error: ' + e.message));
    const sent = [];  // the fieldElement messages the page sent
    const steps = [];  // its undo and redo messages
    page.on('websocket', (ws) => {
      ws.on('framesent', (f) => {
        if (typeof f.payload === 'string' && f.payload.includes('"fieldElement"')) sent.push(JSON.parse(f.payload));
        if (typeof f.payload === 'string' && /"type":"(undo|redo)"/.test(f.payload)) steps.push(JSON.parse(f.payload));
      });
      ws.on('framereceived', (f) => {
        if (typeof f.payload === 'string' && /"type":"(rejected|error)"/.test(f.payload))
          console.log('server: ' + f.payload.slice(0, 500));
      });
    });
    await page.goto(url);
    const get = (f, arg) => page.evaluate(f, arg);
    const wait = (f, arg) => page.waitForFunction(f, arg, { timeout: 120000 });
    await wait(() => window.fgsgViewer.models >= 1 && window.fgsgViewer.surfaces >= 1);
    const box = await page.locator('#canvas').boundingBox();
    const screen = async (p) => {
      const [x, y] = await get((q) => window.fgsgViewer.hooks.toScreen(q), p);
      return [box.x + x, box.y + y];
    };

    await page.click('[data-mode=design]');
    await wait(() => window.fgsgViewer.field.lines > 0 && window.fgsgViewer.design.elements.length === 1);
    ok((await get(() => window.fgsgViewer.field.shown)), 'the Design mode shows the overlay');
    const first = (await get(() => window.fgsgViewer.design.elements))[0];
    ok(first.kind === 'trisector' && first.position.join() === '2,0,0' && first.decay === 1,
       'the overlay lists the grammar\'s trisector at (2, 0, 0)');

    // The field's singularities in the overlay and in what fgsg field finds in the file.
    const singular = async (where) => {
      const shown = await get(() => window.fgsgViewer.field.singularities);
      const listing = path.join(dir, 's.json');
      execFileSync(fgsg, ['field', grammar, '--singularities', listing], { encoding: 'utf8' });
      const listed = JSON.parse(fs.readFileSync(listing, 'utf8')).singularities;
      ok(shown.length === where.length && where.every(([kind, p]) => shown.some((s) => s.kind === kind &&
         Math.hypot(s.position[0] - p[0], s.position[1] - p[1]) < 0.1 && Math.abs(s.position[2]) < 1e-6)),
         `the singularities are where the elements are (${shown.map((s) => s.kind + ' ' + s.position).join('; ')})`);
      ok(listed.length === shown.length && listed.every((g, k) => g.kind === shown[k].kind &&
         g.position.every((v, i) => Math.abs(v - shown[k].position[i]) < 1e-4)),
         'the same as fgsg field --singularities lists for the written file');
    };
    const text = () => fs.readFileSync(grammar, 'utf8');
    // The file's bytes and the overlay after each edit, for undo and redo to give back.
    const digest = () => crypto.createHash('sha256').update(fs.readFileSync(grammar)).digest('hex');
    const states = [];
    const record = async () => states.push({
      text: text(), digest: digest(), elements: JSON.stringify(await get(() => window.fgsgViewer.design.elements)),
      singularities: await get(() => window.fgsgViewer.field.singularities),
    });
    await record();

    // 1. A click on the surface adds a wedge there.
    await page.selectOption('#design-kind', 'wedge');
    const [cx, cy] = await screen([-2, 0, 0]);
    await page.mouse.click(cx, cy);
    await wait(() => window.fgsgViewer.design.elements.length === 2);
    ok(sent.length === 1 && sent[0].op === 'add' && sent[0].kind === 'wedge' && !('strength' in sent[0]),
       'one add message for a wedge');
    const added = sent[0].position;
    ok(Math.hypot(added[0] + 2, added[1]) < 0.05 && Math.abs(added[2]) < 1e-6, `added where clicked: ${added}`);
    ok(text() === grammarText(` wedge at ${at(added)};`), 'the grammar gains `wedge at ' + at(added) + ';` and nothing else');
    let wedge = (await get(() => window.fgsgViewer.design.elements))[1];
    ok(wedge.kind === 'wedge' && wedge.position.join() === rounded(added).join(), 'the overlay lists the wedge there');
    await singular([['trisector', [2, 0]], ['wedge', added]]);
    await record();

    // 2. Dragging its handle moves it: moves go out while the drag lasts, the last where it ended.
    const [fx, fy] = await screen(wedge.position);
    const [tx, ty] = await screen([-3, 2, 0]);
    await page.mouse.move(fx, fy);
    await page.mouse.down();
    for (let k = 1; k <= 8; ++k) {
      await page.mouse.move(fx + ((tx - fx) * k) / 8, fy + ((ty - fy) * k) / 8);
      await page.waitForTimeout(60);
    }
    await page.mouse.up();
    // The frames the page sent reach this process through Playwright's events, which may
    // come after mouse.up() returns on a loaded machine: wait (30 s at most) for the move
    // that ends the drag before judging them.
    const dragEnded = () => {
      const m = sent.filter((x) => x.op === 'move').pop();
      return m && Math.hypot(m.position[0] + 3, m.position[1] - 2) < 0.05;
    };
    for (let t = 0; t < 300 && !dragEnded(); ++t) await page.waitForTimeout(100);
    const moves = sent.filter((m) => m.op === 'move');
    const last = moves[moves.length - 1].position;
    ok(moves.length >= 1 && moves.every((m) => m.index === 1) && Math.hypot(last[0] + 3, last[1] - 2) < 0.05,
       `${moves.length} move messages, the last to ${last}`);
    ok(Number.isInteger(moves[0].drag) && moves[0].drag > 0 && moves.every((m) => m.drag === moves[0].drag),
       `the moves carry the drag's number (${moves[0].drag}): one undo step`);
    await wait((p) => {
      const e = window.fgsgViewer.design.elements[1];
      return e && e.position.every((v, k) => Math.abs(v - p[k]) < 1e-9);
    }, rounded(last));
    ok(text() === grammarText(` wedge at ${at(last)};`), 'the wedge\'s `at` now says ' + at(last));
    await singular([['trisector', [2, 0]], ['wedge', last]]);
    await record();

    // 3. The strength box.
    ok((await get(() => window.fgsgViewer.design.selected)) === 1, 'the dragged wedge is selected');
    await page.fill('#design-strength', '2.5');
    await page.dispatchEvent('#design-strength', 'change');
    await wait(() => window.fgsgViewer.design.elements[1].strength === 2.5);
    ok(text() === grammarText(` wedge at ${at(last)} strength 2.5;`), 'strength 2.5 written after the wedge\'s words');
    await singular([['trisector', [2, 0]], ['wedge', last]]);
    await record();

    // 4. Delete: the file as it was.
    await page.evaluate(() => document.activeElement.blur());  // Delete in the strength box edits the box
    await page.keyboard.press('Delete');
    await wait(() => window.fgsgViewer.design.elements.length === 1);
    ok(text() === grammarText(''), 'Delete gives back the file as it was, byte for byte');
    await singular([['trisector', [2, 0]]]);
    await record();

    // 5. Undo x4, redo x4: each gives back the state before (after) its edit — the file's
    // bytes (its digest), the overlay's elements and its singularities to 1e-4.
    const edits = ['add', 'drag', 'strength', 'delete'];
    const sameSingularities = (shown, want) => shown.length === want.length && shown.every((s, k) =>
      s.kind === want[k].kind && s.position.every((v, i) => Math.abs(v - want[k].position[i]) < 1e-4));
    const stepTo = async (how, state, what) => {
      const overlays = await get(() => window.fgsgViewer.design.overlays);
      await how();
      await wait(([n, elements]) => window.fgsgViewer.design.overlays > n &&
        JSON.stringify(window.fgsgViewer.design.elements) === elements, [overlays, state.elements]);
      ok(digest() === state.digest && text() === state.text, `${what}: the grammar's bytes as they were (sha256 ${
        state.digest.slice(0, 12)})`);
      const shown = await get(() => window.fgsgViewer.field.singularities);
      ok(sameSingularities(shown, state.singularities), `${what}: the overlay's singularities as they were (${
        shown.map((s) => s.kind + ' ' + s.position.map((v) => v.toFixed(4))).join('; ')})`);
    };
    const key = (combo) => () => page.keyboard.press(combo);
    const button = (id) => () => page.click(id);
    const undoWith = [key('Control+z'), button('#design-undo'), key('Control+z'), button('#design-undo')];
    for (let k = 4; k >= 1; --k) await stepTo(undoWith[4 - k], states[k - 1], `undo of the ${edits[k - 1]}`);
    const redoWith = [key('Control+Shift+z'), key('Control+y'), button('#design-redo'), key('Control+Shift+z')];
    for (let k = 1; k <= 4; ++k) await stepTo(redoWith[k - 1], states[k], `redo of the ${edits[k - 1]}`);
    ok(steps.length === 8 && steps.every((m, k) => m.type === (k < 4 ? 'undo' : 'redo') && m.history === 'field'),
       'the keys and buttons sent {"type":"undo"|"redo","history":"field"}');
    const refusedBefore = (await get(() => window.fgsgViewer.rejected)) || 0;
    await page.keyboard.press('Control+y');
    await wait((n) => window.fgsgViewer.rejected === n + 1, refusedBefore);
    ok((await get(() => window.fgsgViewer.lastRejected)) === 'redo: no field edit to redo' && digest() === states[4].digest,
       'a redo past the last edit is refused and writes nothing');

    // The last element cannot go (a design needs one): refused, the file unchanged.
    await page.evaluate(() => { window.fgsgViewer.rejected = 0; });
    await page.click('#design-delete');  // nothing selected: nothing sent
    await page.evaluate(() => window.fgsgViewer.hooks.send({ type: 'fieldElement', op: 'delete', index: 0 }));
    await wait(() => window.fgsgViewer.rejected === 1);
    ok(text() === grammarText(''), 'deleting the last element is refused and writes nothing');
    console.log('PASS');
  } finally {
    if (browser) await browser.close();
    server.kill('SIGTERM');
  }
}

main().catch((e) => {
  if (!process.exitCode) console.error('FAIL: ' + (e && e.stack ? e.stack : e));
  process.exitCode = 1;
});
