// fgsg view's incremental regrowth (#49, item 5): a model of seeds derived apart reaches
// the page as pieces, a seed's plant each and the rest after them. Dragging one seed
// derives and sends that seed's piece alone (its .glb and instance numbers, nothing else);
// a paint dab sends exactly the pieces whose plants it changed, and undoing it brings
// back the pieces as they were, byte for byte. After the edits, every piece the page
// shows is byte for byte what a fresh fgsg view derives from the files the edits wrote
// (a full regrowth), with the same triangle count.
// usage: node view_regrow.js FGSG_BINARY SOURCE_DIR
'use strict';
const { spawn } = require('child_process');
const fs = require('fs');
const os = require('os');
const path = require('path');
const zlib = require('zlib');

const [fgsg, source] = process.argv.slice(2);
const { fail, ok, chromiumOf, viewUrl, launchChromium } = require('./view_test_support');
const chromium = chromiumOf(source);

// A white 8-bit grey PNG (filter 0 rows).
function whitePng(side) {
  const crc = (buf) => {
    let c = 0xffffffff;
    for (const b of buf) { c ^= b; for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1; }
    return (c ^ 0xffffffff) >>> 0;
  };
  const chunk = (type, data) => {
    const out = Buffer.alloc(12 + data.length);
    out.writeUInt32BE(data.length, 0);
    out.write(type, 4, 'latin1');
    data.copy(out, 8);
    out.writeUInt32BE(crc(out.subarray(4, 8 + data.length)), 8 + data.length);
    return out;
  };
  const ihdr = Buffer.alloc(13);
  ihdr.writeUInt32BE(side, 0); ihdr.writeUInt32BE(side, 4); ihdr[8] = 8;
  const raw = Buffer.alloc((side + 1) * side, 255);
  for (let y = 0; y < side; ++y) raw[y * (side + 1)] = 0;
  return Buffer.concat([Buffer.from('89504e470d0a1a0a', 'hex'), chunk('IHDR', ihdr), chunk('IDAT', zlib.deflateSync(raw)),
                        chunk('IEND', Buffer.alloc(0))]);
}

// A server on `grammar`, a page on it, the frames it receives kept in order.
async function open(browser, grammar, env) {
  const server = spawn(fgsg, ['view', grammar, '--port', '0'], { stdio: ['ignore', 'pipe', 'inherit'], env });
  const url = await viewUrl(server);
  const page = await browser.newPage({ viewport: { width: 800, height: 600 } });
  page.on('pageerror', (e) => console.error('page error: ' + e.message));
  const frames = [];
  page.on('websocket', (ws) => ws.on('framereceived', (f) => {
    frames.push(f.payload);
    if (typeof f.payload === 'string' && /"type":"(rejected|error)"/.test(f.payload))
      console.log('server: ' + f.payload.slice(0, 500));
  }));
  await page.goto(url);
  await page.waitForFunction(() => window.fgsgViewer.models >= 1 && window.fgsgViewer.surfaces >= 1, null,
                             { timeout: 150000 });
  return { server, page, frames };
}

// Sends `message` from the page and waits for the model it brings: what the page shows
// then, and the frames that came for it from its header on.
async function edit(side, message) {
  const { page, frames } = side;
  const n = await page.evaluate(() => window.fgsgViewer.models);
  const from = frames.length;
  await page.evaluate((m) => window.fgsgViewer.hooks.send(m), message);
  await page.waitForFunction((k) => window.fgsgViewer.models > k || window.fgsgViewer.errors > 0, n, { timeout: 150000 });
  const shown = await page.evaluate(async () => ({ pieces: window.fgsgViewer.pieces, figures: window.fgsgViewer.figures,
                                                    digests: await window.fgsgViewer.hooks.pieceDigests() }));
  const mine = frames.slice(from);
  const at = mine.findIndex((f) => typeof f === 'string' && f.includes('"type":"pieces"'));
  if (at < 0) fail('no pieces header came for ' + JSON.stringify(message).slice(0, 80));
  shown.header = JSON.parse(mine[at]);
  // The binary frames: playwright reports no empty one (a piece that places no shared
  // mesh has no instance numbers).
  shown.binary = mine.slice(at + 1).filter((f) => typeof f !== 'string');
  shown.expectedFrames = shown.header.sent.reduce((n, p) => n + (p.placing.some(([, c]) => c > 0) ? 2 : 1), 0);
  return shown;
}

const changedAt = (a, b) => a.map((d, k) => (d !== b[k] ? k : -1)).filter((k) => k >= 0);
const same = (a, b) => JSON.stringify(a) === JSON.stringify(b);

async function main() {
  const root = fs.mkdtempSync(path.join(os.tmpdir(), 'fgsg-view-regrow-'));
  const [edited, fresh] = [path.join(root, 'edited'), path.join(root, 'fresh')];
  const text = fs.readFileSync(path.join(source, 'examples/ivy.fgsg'), 'utf8');
  if (!text.includes('const mainSteps = 120;')) fail('examples/ivy.fgsg no longer has mainSteps = 120');
  for (const dir of [edited, fresh]) {
    fs.mkdirSync(dir);
    // Short plants on the unit sphere, far apart.
    fs.writeFileSync(path.join(dir, 'g.fgsg'), text.replace('ivy_anywhere.png', 'mask.png')
      .replace('const mainSteps = 120;', 'const mainSteps = 14;'));
    fs.writeFileSync(path.join(dir, 'mask.png'), whitePng(128));
  }
  const env = Object.assign({}, process.env, { FGSG_CACHE_DIR: path.join(root, 'cache') });
  const seeds = [[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, 0, 1]];
  const browser = await launchChromium(chromium);
  const servers = [];
  try {
    const a = await open(browser, path.join(edited, 'g.fgsg'), env);
    servers.push(a.server);
    // 1. Four seeds: every piece is sent (4 plants and the rest).
    const first = await edit(a, { type: 'seeds', seeds });
    ok(first.header.sent.length === 5 && first.binary.length === first.expectedFrames && first.digests.length === 5,
       'four seeds: 5 pieces sent, a .glb and instance numbers each');
    ok(first.header.bases.length === 5 && first.header.bases[0] === 0, `bases ${first.header.bases}`);

    // 2. Seed 1 dragged: its piece alone comes, the others are kept.
    const moved = seeds.map((s) => s.slice());
    moved[1] = [-0.8, 0.6, 0];
    const drag = await edit(a, { type: 'seeds', seeds: moved });
    ok(same(drag.header.sent.map((s) => s.piece), [1]), `a drag of seed 1 sent piece ${drag.header.sent.map((s) => s.piece)}`);
    ok(drag.binary.length === drag.expectedFrames && drag.expectedFrames <= 2, 'its .glb and its instance numbers only');
    ok(drag.binary[0].length === drag.header.sent[0].bytes, `${drag.binary[0].length} bytes of .glb`);
    ok(same(changedAt(drag.digests, first.digests), [1]), 'the page changed piece 1 and kept the others');
    ok(drag.header.server.built === 1, 'the server assembled and encoded one piece');
    const total = first.header.sent.reduce((sum, p) => sum + p.bytes, 0);
    ok(drag.binary[0].length < total / 2, `sent ${drag.binary[0].length} of the model's ${total} bytes`);

    // 3. A black dab under seed 2: exactly the pieces that changed come, seed 2's among them.
    const dab = await edit(a, { type: 'paint', texture: 'mask', stroke: 1, dabs: [[0, 1, 0]], radius: 0.05,
                                strength: 1, value: 0 });
    const changed = changedAt(dab.digests, drag.digests);
    const sent = dab.header.sent.map((s) => s.piece);
    ok(changed.includes(2) && same(sent, changed), `the dab changed and sent pieces ${sent}`);
    ok(sent.length < 4, 'not every plant');
    ok(dab.figures.triangles < drag.figures.triangles, `the ivy shrank: ${drag.figures.triangles} -> ${dab.figures.triangles}`);

    // 4. Undone: the pieces as they were before the dab, byte for byte.
    const undone = await edit(a, { type: 'undo' });
    ok(same(undone.digests, drag.digests), 'undo brought back every piece as before the dab');
    ok(same(undone.header.sent.map((s) => s.piece), changed), 'and sent only those the dab had changed');
    const redone = await edit(a, { type: 'redo' });
    ok(same(redone.digests, dab.digests), 'redo: the dabbed pieces again');

    // 5. A full regrowth: a fresh server on the files the edits wrote.
    fs.copyFileSync(path.join(edited, 'g.seeds'), path.join(fresh, 'g.seeds'));
    fs.copyFileSync(path.join(edited, 'mask.png'), path.join(fresh, 'mask.png'));
    const b = await open(browser, path.join(fresh, 'g.fgsg'), env);
    servers.push(b.server);
    const full = await b.page.evaluate(async () => ({ figures: window.fgsgViewer.figures,
                                                      digests: await window.fgsgViewer.hooks.pieceDigests() }));
    ok(full.digests.length === 5 && same(full.digests, redone.digests),
       'every piece is byte for byte what a fresh fgsg view derives from the written files');
    ok(full.figures.triangles === redone.figures.triangles, `the same ${full.figures.triangles} triangles`);

    // 6. Out of order: a plain model (one seed) whose reading the page delays, and the four
    // seeds' pieces right after it. The page reads them in the order they came, so it ends
    // on every piece, as the server believes; a drag then sends one piece onto them.
    const modelsNow = await a.page.evaluate(() => window.fgsgViewer.models);
    let from = a.frames.length;
    await a.page.evaluate(() => window.fgsgViewer.hooks.delayNextModel(3000));
    await a.page.evaluate((m) => window.fgsgViewer.hooks.send(m), { type: 'seeds', seeds: [moved[0]] });
    const plainCame = () => a.frames.slice(from).some((f) => typeof f === 'string' && f.includes('"type":"model"'));
    for (let t = 0; !plainCame(); ++t) {
      if (t > 1500) fail('no plain model came for one seed');
      await new Promise((r) => setTimeout(r, 100));
    }
    from = a.frames.length;
    await a.page.evaluate((m) => window.fgsgViewer.hooks.send(m), { type: 'seeds', seeds: moved });
    await a.page.waitForFunction((k) => window.fgsgViewer.models >= k + 2, modelsNow, { timeout: 150000 });
    const reordered = await a.page.evaluate(() => window.fgsgViewer.hooks.pieceDigests());
    ok(a.frames.slice(from).some((f) => typeof f === 'string' && f.includes('"type":"pieces"')),
       'the pieces came while the plain model was still being read');
    ok(same(reordered, redone.digests), 'the delayed plain model did not replace the newer pieces: all 5 shown');
    const moved3 = moved.map((s) => s.slice());
    moved3[3] = [0.6, 0, 0.8];
    const drag3 = await edit(a, { type: 'seeds', seeds: moved3 });
    ok(same(drag3.header.sent.map((s) => s.piece), [3]) && same(changedAt(drag3.digests, redone.digests), [3]) &&
       drag3.digests.every((d) => d), 'a drag after it sends piece 3 alone and the page shows all 5 pieces');

    // 7. Pieces the page cannot read: it asks for all of them again ({"type":"resend"}).
    await a.page.evaluate(() => window.fgsgViewer.hooks.failNextPieces());
    const modelsThen = await a.page.evaluate(() => window.fgsgViewer.models);
    await a.page.evaluate((m) => window.fgsgViewer.hooks.send(m), { type: 'seeds', seeds: moved });
    await a.page.waitForFunction((k) => window.fgsgViewer.models > k, modelsThen, { timeout: 150000 });
    const resent = await a.page.evaluate(async () => ({ resends: window.fgsgViewer.resends, sent: window.fgsgViewer.pieces.sent,
                                                         digests: await window.fgsgViewer.hooks.pieceDigests() }));
    ok(resent.resends === 1 && same(resent.sent, [0, 1, 2, 3, 4]), `one resend asked, pieces ${resent.sent} sent`);
    ok(same(resent.digests, redone.digests), 'after the unreadable piece every piece is the fresh view\'s');

    // 8. A painted file that is also a finish's image (Texture): a piece embeds its bytes,
    // so every piece that holds it is built again though no plant changed.
    const textured = [path.join(root, 'tex'), path.join(root, 'texFresh')];
    for (const dir of textured) {
      fs.mkdirSync(dir);
      fs.writeFileSync(path.join(dir, 'g.fgsg'), text.replace('ivy_anywhere.png', 'mask.png')
        .replace('const mainSteps = 120;', 'const mainSteps = 14;')
        .replace('start = S(1, barkWidth, barkWidth)', 'start = Texture("mask.png") S(1, barkWidth, barkWidth)'));
      fs.writeFileSync(path.join(dir, 'mask.png'), whitePng(128));
      fs.copyFileSync(path.join(edited, 'g.seeds'), path.join(dir, 'g.seeds'));
    }
    const c = await open(browser, path.join(textured[0], 'g.fgsg'), env);
    servers.push(c.server);
    const before = await c.page.evaluate(() => window.fgsgViewer.hooks.pieceDigests());
    // A dab far from every plant's reads (the sphere's bottom): no plant changes, the image does.
    const far = await edit(c, { type: 'paint', texture: 'mask', stroke: 1, dabs: [[0, -1, 0]], radius: 0.1,
                                strength: 1, value: 0 });
    fs.copyFileSync(path.join(textured[0], 'mask.png'), path.join(textured[1], 'mask.png'));
    const d = await open(browser, path.join(textured[1], 'g.fgsg'), env);
    servers.push(d.server);
    const texFresh = await d.page.evaluate(() => window.fgsgViewer.hooks.pieceDigests());
    ok(before.length === 5 && same(far.digests, texFresh), 'after the dab every piece is a fresh view\'s (the new image)');
    ok(changedAt(far.digests, before).length >= 4, `the plants' pieces embed the new image: ${changedAt(far.digests, before)}`);
    console.log('PASS');
  } finally {
    await browser.close();
    for (const s of servers) s.kill('SIGTERM');
    fs.rmSync(root, { recursive: true, force: true });
  }
}

main().catch((e) => {
  if (!process.exitCode) console.error('FAIL: ' + (e && e.stack ? e.stack : e));
  process.exitCode = 1;
});
