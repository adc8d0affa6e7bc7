// fgsg view's field design loop, measured in the page (#49, item 3: goal ≤ 200 ms from a
// design element dragged to its new streamlines on a 26 K-vertex mesh): a tensor design
// with a wedge and a trisector on MESH (default the armadillo, 26 002 vertices), N moves of
// the wedge, each to a surface point it has not been at before (as a drag: the server
// keeps the geodesics of the elements that did not move, never those of a new place),
// each timed in Debian's chromium (headless) from the fieldElement message sent to the new
// overlay received (the grammar rewritten and compiled, its field designed and traced
// again), with the size of the overlay message; median and p95.
// usage: node bench/view_field_latency.js [FGSG_BINARY] [N] [MESH]
'use strict';
const { spawn } = require('child_process');
const fs = require('fs');
const os = require('os');
const path = require('path');

const root = path.resolve(__dirname, '..');
const fgsg = process.argv[2] || path.join(root, 'build/bin/fgsg');
const runs = Math.min(Number(process.argv[3] || 15), 40);  // 40 places to move to
const mesh = process.argv[4] || path.join(root, 'tests/data/meshes/armadillo.off');
const { chromium } = require(path.join(root, 'tools/node/node_modules/playwright-core'));

function median(v) { const s = [...v].sort((a, b) => a - b); return s[Math.floor(s.length / 2)]; }
function p95(v) { const s = [...v].sort((a, b) => a - b); return s[Math.min(s.length - 1, Math.ceil(0.95 * s.length) - 1)]; }

async function main() {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'fgsg-field-latency-'));
  fs.copyFileSync(mesh, path.join(dir, 'mesh' + path.extname(mesh)));
  const grammar = path.join(dir, 'g.fgsg');
  fs.writeFileSync(grammar, `surface "mesh${path.extname(mesh)}";\n` +
    'field F = design tensor { wedge at vertex 100 decay 0.5; trisector at vertex 20000 decay 0.5; };\n' +
    'Axiom ~> I("cube");\n');
  const server = spawn(fgsg, ['view', grammar, '--port', '0'], { stdio: ['ignore', 'pipe', 'inherit'] });
  const url = await new Promise((resolve, reject) => {
    let text = '';
    server.stdout.on('data', (d) => { text += d; const m = text.match(/http:\/\/[^ \n]+/); if (m) resolve(m[0]); });
    server.on('exit', (code) => reject(new Error('fgsg view exited with ' + code)));
  });
  const browser = await chromium.launch({ executablePath: '/usr/bin/chromium',
    args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist'] });
  try {
    const page = await browser.newPage({ viewport: { width: 1000, height: 700 } });
    let bytes = 0;
    page.on('websocket', (ws) => ws.on('framereceived', (f) => {
      if (typeof f.payload === 'string' && f.payload.includes('"type":"field"')) bytes = f.payload.length;
      if (typeof f.payload === 'string' && /"type":"(rejected|error)"/.test(f.payload)) console.error(f.payload.slice(0, 300));
    }));
    await page.goto(url);
    const wait = (f, arg) => page.waitForFunction(f, arg, { timeout: 300000, polling: 2 });
    await wait(() => window.fgsgViewer.models >= 1 && window.fgsgViewer.surfaces >= 1);
    await page.click('[data-mode=design]');
    await wait(() => window.fgsgViewer.design.overlays >= 1);
    const points = await page.evaluate(() => window.fgsgViewer.hooks.surfacePoints(40));
    const times = [];
    for (let k = 0; k < runs; ++k) {
      const before = await page.evaluate(() => window.fgsgViewer.design.overlays);
      const position = points[(5 + 7 * k) % 40];  // 7 and 40 coprime: a new point each move
      const started = await page.evaluate((p) => {
        window.fgsgViewer.hooks.send({ type: 'fieldElement', op: 'move', index: 0, position: p });
        return performance.now();
      }, position);
      const shown = await page.evaluate(async (n) => {
        while (window.fgsgViewer.design.overlays <= n) await new Promise((r) => setTimeout(r, 1));
        return performance.now();
      }, before);
      times.push(shown - started);
    }
    const [load1] = os.loadavg();
    console.log(JSON.stringify({ mesh: path.basename(mesh), moves: runs, medianMs: +median(times).toFixed(1),
      p95Ms: +p95(times).toFixed(1), overlayBytes: bytes, loadAverage: +load1.toFixed(2),
      times: times.map((t) => +t.toFixed(1)) }));
  } finally {
    await browser.close();
    server.kill('SIGTERM');
  }
}

main().catch((e) => { console.error(e); process.exitCode = 1; });
