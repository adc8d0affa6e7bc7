// fgsg view's live loop, measured in the page (#20: goal under 100 ms from a change to
// the new model shown, for a 100 K-triangle result): examples/mueller_building.fgsg with
// lot_width alternating between two values near 100 K triangles, N changes, each timed
// in Debian's chromium (headless, software WebGL) from the page sending the change to the
// new model parsed and in the scene; the server's part (derive, assemble, encode) too.
// usage: node bench/view_latency.js [FGSG_BINARY] [N]   (prints one JSON line)
//
// With `edits` (#49): the editing loop instead. examples/ivy.fgsg (its mask a white 256²
// PNG in a folder of its own) on MESH (default the bunny, --surface-size 2) from K seeds
// spread over the surface; N seed drags (seed 0 moved between two surface points) and N
// paint dabs (black, then white again, under seed 0), each timed in the page from the
// message sent to the new model in the scene; median and p95 of each, and the server's part.
// STEPS (default the example's 120) shortens each plant's main branch: a software-WebGL
// page on a small machine holds a few million triangles, not the 4.5 M.
// A model of seeds comes as pieces (#49, item 5: only the changed seeds' plants are
// derived again and sent): the pieces and bytes each edit sent are reported, and the
// server's part split into deriving and the pieces' assembly and encoding.
// usage: node bench/view_latency.js FGSG_BINARY N edits [MESH] [K] [STEPS]
//
// With `million` (#45): the first model of a SIDE^3 grid of instanced cubes (default 100:
// a million, 12 M triangles), N page loads, each timed from the page's start (navigation)
// to the model announced, its bytes received and the model in the scene, with the
// server's part (derive, the scene, its .glb) as the page was told it.
// usage: node bench/view_latency.js FGSG_BINARY N million [SIDE]
'use strict';
const { spawn } = require('child_process');
const fs = require('fs');
const os = require('os');
const path = require('path');
const zlib = require('zlib');

const root = path.resolve(__dirname, '..');
const fgsg = process.argv[2] || path.join(root, 'build/bin/fgsg');
const runs = Number(process.argv[3] || 20);
const { chromium } = require(path.join(root, 'tools/node/node_modules/playwright-core'));

function median(v) { const s = [...v].sort((a, b) => a - b); return s[Math.floor(s.length / 2)]; }
function p95(v) { const s = [...v].sort((a, b) => a - b); return s[Math.min(s.length - 1, Math.ceil(0.95 * s.length) - 1)]; }

// A white 8-bit grey PNG (filter 0 rows; the CRCs computed: no library here).
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

// `fgsg view GRAMMAR --port 0 EXTRA...` and a headless chromium (software WebGL): calls
// use(browser, url), then closes both, whatever happens.
async function withViewer(grammar, extra, use) {
  const server = spawn(fgsg, ['view', grammar, '--port', '0', ...extra], { stdio: ['ignore', 'pipe', 'inherit'] });
  try {
    const url = await new Promise((resolve) => {
      let text = '';
      server.stdout.on('data', (d) => { text += d; const m = text.match(/http:\/\/[^ \n]+/); if (m) resolve(m[0]); });
    });
    const browser = await chromium.launch({ executablePath: '/usr/bin/chromium',
      args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader'] });
    try {
      return await use(browser, url);
    } finally {
      await browser.close();
    }
  } finally {
    server.kill('SIGTERM');
  }
}

// Run in the page: the first model is in the scene.
const firstModelShown = () => window.fgsgViewer && window.fgsgViewer.models >= 1;

// A new page on the viewer, once `ready` (run in the page) holds; a crash is reported
// with `crashHint` (what to make smaller).
async function openViewer(browser, url, ready, timeout, crashHint = '') {
  const page = await browser.newPage({ viewport: { width: 1100, height: 700 } });
  page.on('crash', () => console.error(`the page crashed (out of memory?)${crashHint}`));
  await page.goto(url);
  await page.waitForFunction(ready, null, { timeout });
  return page;
}

async function edits() {
  const mesh = path.resolve(process.argv[5] || path.join(root, 'tests/data/meshes/bunny00.off'));
  const seedCount = Number(process.argv[6] || 25);
  const steps = Number(process.argv[7] || 120);
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'fgsg-view-bench-'));
  fs.writeFileSync(path.join(dir, 'ivy.fgsg'),
                   fs.readFileSync(path.join(root, 'examples/ivy.fgsg'), 'utf8').replace('ivy_anywhere.png', 'mask.png')
                     .replace('const mainSteps = 120;', `const mainSteps = ${steps};`));
  fs.writeFileSync(path.join(dir, 'mask.png'), whitePng(256));
  try {
    await withViewer(path.join(dir, 'ivy.fgsg'), ['--surface', mesh, '--surface-size', '2'], async (browser, url) => {
      const surfaceShown = () => window.fgsgViewer && window.fgsgViewer.models >= 1 && window.fgsgViewer.surfaces >= 1;
      const page = await openViewer(browser, url, surfaceShown, 600000, ': fewer seeds or STEPS');
      // Seeds on surface vertices spread through the mesh's order.
      const points = await page.evaluate((k) => window.fgsgViewer.hooks.surfacePoints(k), seedCount + 2);
      const seeds = points.slice(0, seedCount);
      const timed = async (message) => {
        const n = await page.evaluate(() => window.fgsgViewer.models);
        await page.evaluate((m) => window.fgsgViewer.hooks.send(m), message);
        await page.waitForFunction((k) => window.fgsgViewer.models > k, n, { timeout: 600000 });
        return page.evaluate(() => ({ t: window.fgsgViewer.timing, s: window.fgsgViewer.serverMilliseconds,
                                      f: window.fgsgViewer.figures, p: window.fgsgViewer.pieces,
                                      bytes: window.fgsgViewer.glbBytes }));
      };
      await timed({ type: 'seeds', seeds });  // the first derivation of K seeds: not counted
      const result = { bench: 'view_edit_latency', mesh: path.basename(mesh), seeds: seedCount, main_steps: steps,
                       edits: runs };
      for (const kind of ['seed_drag', 'paint']) {
        const page_ms = [], server_ms = [], received_ms = [], sent_pieces = [], sent_bytes = [], derive_ms = [];
        let polygons = 0;
        for (let i = 0; i < runs; ++i) {
          const message = kind === 'seed_drag'
            ? { type: 'seeds', seeds: [points[seedCount + (i % 2)], ...seeds.slice(1)] }
            : { type: 'paint', texture: 'mask', stroke: i, dabs: [seeds[0]], radius: 0.1, strength: 1,
                value: i % 2 ? 1 : 0 };
          const r = await timed(message);
          page_ms.push(r.t.shown - r.t.sent);
          received_ms.push(r.t.received - r.t.sent);
          server_ms.push(r.s);
          polygons = Math.max(polygons, r.f.triangles);
          // Pieces: those sent; a whole model: all of it.
          sent_pieces.push(r.p ? r.p.sent.length : 1);
          sent_bytes.push(r.p ? r.p.bytes : r.bytes);
          if (r.p && r.p.server) derive_ms.push(r.p.server.derive);
        }
        Object.assign(result, { [`${kind}_triangles`]: polygons,
          [`${kind}_page_ms_median`]: +median(page_ms).toFixed(1), [`${kind}_page_ms_p95`]: +p95(page_ms).toFixed(1),
          [`${kind}_received_ms_median`]: +median(received_ms).toFixed(1),
          [`${kind}_server_ms_median`]: +median(server_ms).toFixed(1),
          [`${kind}_server_ms_p95`]: +p95(server_ms).toFixed(1),
          [`${kind}_pieces_sent_median`]: median(sent_pieces), [`${kind}_bytes_sent_median`]: median(sent_bytes) });
        if (derive_ms.length) result[`${kind}_server_derive_ms_median`] = +median(derive_ms).toFixed(1);
      }
      result.surfaces_sent = await page.evaluate(() => window.fgsgViewer.surfaces);  // 1: no edit recompiled
      result.load_average = os.loadavg().map((x) => +x.toFixed(2));
      console.log(JSON.stringify(result));
    });
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
}

async function million() {
  const side = Number(process.argv[5] || 100);
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'fgsg-view-bench-'));
  const grammar = path.join(dir, 'cubes.fgsg');
  fs.writeFileSync(grammar, `const n = ${side};
Axiom ~> Layer(0);
Layer(k) : k < n ~> [ Row(0) ] T(0, 0, 2) Layer(k + 1);
Row(j) : j < n ~> [ Cube(0) ] T(0, 2, 0) Row(j + 1);
Cube(i) : i < n ~> [ I("cube") ] T(2, 0, 0) Cube(i + 1);
`);
  try {
    await withViewer(grammar, [], async (browser, url) => {
      const result = { bench: 'view_million', cubes: side ** 3, loads: runs, server_ms: [], announced_ms: [],
                       received_ms: [], shown_ms: [] };
      for (let i = 0; i < runs; ++i) {
        const page = await openViewer(browser, url, firstModelShown, 300000, ': a smaller SIDE');
        const r = await page.evaluate(() => ({ t: window.fgsgViewer.timing, s: window.fgsgViewer.serverMilliseconds,
                                               n: window.fgsgViewer.instanced }));
        result.server_ms.push(Math.round(r.s));
        result.announced_ms.push(Math.round(r.t.announced));
        result.received_ms.push(Math.round(r.t.received));
        result.shown_ms.push(Math.round(r.t.shown));
        result.instanced = r.n;
        await page.close();
      }
      console.log(JSON.stringify(result));
    });
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
}

if (process.argv[4] === 'edits') edits();
else if (process.argv[4] === 'million') million();
else (async () => {
  const building = path.join(root, 'examples/mueller_building.fgsg');
  await withViewer(building, ['--set', 'lot_width=31'], async (browser, url) => {
    const page = await openViewer(browser, url, firstModelShown, 60000);
    const page_ms = [], server_ms = [];
    let triangles = 0;
    for (let i = 0; i < runs; ++i) {
      const n = await page.evaluate(() => window.fgsgViewer.models);
      await page.fill('input[type=number][data-attr="lot_width"]', i % 2 ? '31' : '32');
      await page.dispatchEvent('input[type=number][data-attr="lot_width"]', 'change');
      await page.waitForFunction((k) => window.fgsgViewer.models > k, n, { timeout: 30000 });
      const r = await page.evaluate(() => ({ t: window.fgsgViewer.timing, s: window.fgsgViewer.serverMilliseconds,
                                             tri: window.fgsgViewer.figures.triangles }));
      page_ms.push(r.t.shown - r.t.sent);
      server_ms.push(r.s);
      triangles = Math.max(triangles, r.tri);
    }
    console.log(JSON.stringify({ bench: 'view_latency', triangles, changes: runs,
      page_ms_median: +median(page_ms).toFixed(1), page_ms_max: +Math.max(...page_ms).toFixed(1),
      server_ms_median: +median(server_ms).toFixed(1) }));
  });
})();
