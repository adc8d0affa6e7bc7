// fgsg view's live loop, measured in the page (#20: goal under 100 ms from a change to
// the new model shown, for a 100 K-triangle result): examples/mueller_building.fgsg with
// lot_width alternating between two values near 100 K triangles, N changes, each timed
// in Debian's chromium (headless, software WebGL) from the page sending the change to the
// new model parsed and in the scene; the server's part (derive, assemble, encode) too.
// usage: node bench/view_latency.js [FGSG_BINARY] [N]   (prints one JSON line)
'use strict';
const { spawn } = require('child_process');
const path = require('path');

const root = path.resolve(__dirname, '..');
const fgsg = process.argv[2] || path.join(root, 'build/bin/fgsg');
const runs = Number(process.argv[3] || 20);
const { chromium } = require(path.join(root, 'tools/node/node_modules/playwright-core'));

function median(v) { const s = [...v].sort((a, b) => a - b); return s[Math.floor(s.length / 2)]; }

(async () => {
  const server = spawn(fgsg, ['view', path.join(root, 'examples/mueller_building.fgsg'), '--port', '0',
                              '--set', 'lot_width=31'], { stdio: ['ignore', 'pipe', 'inherit'] });
  const url = await new Promise((resolve) => {
    let text = '';
    server.stdout.on('data', (d) => { text += d; const m = text.match(/http:\/\/[^ \n]+/); if (m) resolve(m[0]); });
  });
  const browser = await chromium.launch({ executablePath: '/usr/bin/chromium',
    args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader'] });
  try {
    const page = await browser.newPage({ viewport: { width: 1100, height: 700 } });
    await page.goto(url);
    await page.waitForFunction(() => window.fgsgViewer && window.fgsgViewer.models >= 1, null, { timeout: 60000 });
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
  } finally {
    await browser.close();
    server.kill('SIGTERM');
  }
})();
