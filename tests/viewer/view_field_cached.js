// fgsg view keeps a surface's mesh, frames and factorisation across recompiles (#49,
// backend/commands/surface_geometry.h): a design element moved in the page redesigns the
// field on the kept geometry. This checks that nothing changes but the speed: after two
// moves of a wedge on a mesh file, the field overlay and the model's glTF the page got are
// byte for byte those a fresh fgsg view sends for the written grammar, the singularities
// are those `fgsg field --singularities` lists for it (to 1e-4), and the unchanged surface
// was sent to the page once, not again after each edit.
// usage: node view_field_cached.js FGSG_BINARY SOURCE_DIR
'use strict';
const { spawn, execFileSync } = require('child_process');
const fs = require('fs');
const os = require('os');
const path = require('path');

const [fgsg, source] = process.argv.slice(2);
const { ok, chromiumOf, viewUrl, launchChromium } = require('./view_test_support');
const chromium = chromiumOf(source);

// A torus (R 2, r 0.7) as a 48 x 24 quad grid cut into triangles, counter-clockwise seen
// from outside: 1 152 vertices, closed.
function torusOff() {
  const n = 48, m = 24, lines = [];
  for (let i = 0; i < n; ++i)
    for (let j = 0; j < m; ++j) {
      const u = (2 * Math.PI * i) / n, v = (2 * Math.PI * j) / m, ring = 2 + 0.7 * Math.cos(v);
      lines.push([ring * Math.cos(u), ring * Math.sin(u), 0.7 * Math.sin(v)].map((x) => x.toFixed(6)).join(' '));
    }
  const at = (i, j) => ((i + n) % n) * m + ((j + m) % m);
  for (let i = 0; i < n; ++i)
    for (let j = 0; j < m; ++j) {
      lines.push(`3 ${at(i, j)} ${at(i + 1, j)} ${at(i + 1, j + 1)}`);
      lines.push(`3 ${at(i, j)} ${at(i + 1, j + 1)} ${at(i, j + 1)}`);
    }
  return `OFF\n${n * m} ${2 * n * m} 0\n${lines.join('\n')}\n`;
}

// A server on `grammar` and a page on it, the frames it receives kept in order.
async function open(browser, grammar) {
  const server = spawn(fgsg, ['view', grammar, '--port', '0'], { stdio: ['ignore', 'pipe', 'inherit'] });
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
  const wait = (f, arg) => page.waitForFunction(f, arg, { timeout: 240000 });
  await wait(() => window.fgsgViewer.models >= 1 && window.fgsgViewer.surfaces >= 1);
  await page.click('[data-mode=design]');
  await wait(() => window.fgsgViewer.design.overlays >= 1);
  return { server, page, frames, wait };
}

const isText = (f, type) => typeof f === 'string' && f.startsWith('{') && f.includes(`"type":"${type}"`);
const lastOverlay = (frames) => frames.filter((f) => isText(f, 'field')).pop();
// The model's glTF: the first binary frame after the last model header.
function lastModelGlb(frames) {
  let at = -1;
  frames.forEach((f, k) => { if (isText(f, 'model')) at = k; });
  return at >= 0 ? Buffer.from(frames[at + 1]) : null;
}

async function main() {
  const root = fs.mkdtempSync(path.join(os.tmpdir(), 'fgsg-view-cached-'));
  const [edited, fresh] = [path.join(root, 'edited'), path.join(root, 'fresh')];
  for (const dir of [edited, fresh]) {
    fs.mkdirSync(dir);
    fs.writeFileSync(path.join(dir, 'torus.off'), torusOff());
  }
  const grammar = path.join(edited, 'g.fgsg');
  fs.writeFileSync(grammar, 'surface "torus.off";\nfield F = design tensor { wedge at vertex 10 decay 1; ' +
    'trisector at vertex 600 decay 1; };\nAxiom ~> I("cube");\n');
  const browser = await launchChromium(chromium);
  const servers = [];
  try {
    const a = await open(browser, grammar);
    servers.push(a.server);
    const points = await a.page.evaluate(() => window.fgsgViewer.hooks.surfacePoints(40));
    for (const [k, p] of [[1, points[5]], [2, points[30]]]) {
      await a.page.evaluate((q) => window.fgsgViewer.hooks.send({ type: 'fieldElement', op: 'move', index: 0, position: q }), p);
      await a.wait((n) => window.fgsgViewer.design.overlays >= n + 1 && window.fgsgViewer.models >= n + 1, k);
    }
    // The model may come after the overlay: wait until both are in for the second edit.
    for (let t = 0; t < 600 && a.frames.filter((f) => isText(f, 'model')).length < 3; ++t) await a.page.waitForTimeout(100);
    const text = fs.readFileSync(grammar, 'utf8');
    ok(/wedge at \([^)]*\) decay 1;/.test(text), 'the wedge was moved twice: ' + text.split('\n')[1]);
    ok(a.frames.filter((f) => isText(f, 'surface')).length === 1,
       'the unchanged surface went to the page once, not again after each edit');

    fs.writeFileSync(path.join(fresh, 'g.fgsg'), text);
    const b = await open(browser, path.join(fresh, 'g.fgsg'));
    servers.push(b.server);
    const [overlayA, overlayB] = [lastOverlay(a.frames), lastOverlay(b.frames)];
    ok(overlayA && JSON.parse(overlayA).lines.length > 10 && overlayA === overlayB,
       `the overlay after the edits is a fresh fgsg view's, byte for byte (${overlayA.length} bytes)`);
    const [glbA, glbB] = [lastModelGlb(a.frames), lastModelGlb(b.frames)];
    ok(glbA && glbB && glbA.length > 1000 && glbA.equals(glbB),
       `the model's glTF after the edits is a fresh fgsg view's, byte for byte (${glbA.length} bytes)`);
    const listing = path.join(root, 's.json');
    execFileSync(fgsg, ['field', grammar, '--singularities', listing], { encoding: 'utf8' });
    const listed = JSON.parse(fs.readFileSync(listing, 'utf8')).singularities;
    const shown = JSON.parse(overlayA).singularities;
    ok(shown.length >= 2 && listed.length === shown.length && listed.every((g, k) => g.kind === shown[k].kind &&
       g.position.every((v, i) => Math.abs(v - shown[k].position[i]) < 1e-4)),
       `the ${shown.length} singularities are those fgsg field --singularities lists for the written grammar`);
    console.log('PASS');
  } finally {
    await browser.close();
    for (const s of servers) s.kill('SIGTERM');
  }
}

main().catch((e) => {
  console.error(e);
  process.exitCode = 1;
});
