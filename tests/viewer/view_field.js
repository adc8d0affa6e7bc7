// fgsg view's field overlay in a real browser (#49, item 3): the Field button shows the
// grammar's first field as streamlines over the surface and its singularities, as
// `fgsg field` computes them; an edit of the grammar brings the new field's overlay.
// usage: node view_field.js FGSG_BINARY SOURCE_DIR
'use strict';
const { spawn, execFileSync } = require('child_process');
const fs = require('fs');
const os = require('os');
const path = require('path');

const [fgsg, source] = process.argv.slice(2);
const { fail, ok, chromiumOf, viewUrl, launchChromium } = require('./view_test_support');
const chromium = chromiumOf(source);

// A tensor field designed on a 10 x 10 plane. Each singular design element is one
// singularity where it is put, and nothing else is singular (a regular element would add
// one between them: tests/cli/field_command.sh's design has three for two elements):
// a wedge (+1/2) at (-2, 0, 0) and a trisector (-1/2) at (2, 0, 0), so two; with the
// trisector removed, the wedge alone, so one.
const grammarText = (elements) =>
  `surface plane(10, 10, 48);\nfield F = design tensor { ${elements} };\nAxiom ~> I("cube");\n`;
const wedge = 'wedge at (-2, 0, 0) decay 1;';
const trisector = 'trisector at (2, 0, 0) decay 1;';
const near = (s, x, y) => Math.hypot(s.position[0] - x, s.position[1] - y) < 0.1 && Math.abs(s.position[2]) < 1e-6;

async function main() {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'fgsg-view-field-'));
  const grammar = path.join(dir, 'g.fgsg');
  fs.writeFileSync(grammar, grammarText(wedge + ' ' + trisector));
  // What `fgsg field` traces with its defaults: the overlay's number of streamlines.
  const cli = execFileSync(fgsg, ['field', grammar, '--singularities', path.join(dir, 's.json')], { encoding: 'utf8' });
  const cliLines = Number(cli.match(/: (\d+) streamlines/)[1]);
  const server = spawn(fgsg, ['view', grammar, '--port', '0'], { stdio: ['ignore', 'pipe', 'inherit'] });
  let browser;
  try {
    const url = await viewUrl(server);
    browser = await launchChromium(chromium);
    const page = await browser.newPage({ viewport: { width: 1000, height: 700 } });
    page.on('pageerror', (e) => console.error('page error: ' + e.message));
    const sizes = [];
    page.on('websocket', (ws) => ws.on('framereceived', (f) => {
      if (typeof f.payload !== 'string') return;
      if (/"type":"(rejected|error)"/.test(f.payload)) console.log('server: ' + f.payload.slice(0, 500));
      if (f.payload.includes('"type":"field"')) sizes.push(f.payload.length);
    }));
    await page.goto(url);
    const get = (f) => page.evaluate(f);
    const wait = (f, arg) => page.waitForFunction(f, arg, { timeout: 120000 });
    await wait(() => window.fgsgViewer.models >= 1 && window.fgsgViewer.surfaces >= 1);
    ok(!(await get(() => window.fgsgViewer.field.shown)), 'no overlay before the Field button');

    await page.click('#field-overlay');
    await wait(() => window.fgsgViewer.field.lines > 0 || window.fgsgViewer.field.error);
    const field = await get(() => window.fgsgViewer.field);
    ok(!field.error && field.shown && field.name === 'F', `the overlay shows field ${field.name} (${field.error || 'no error'})`);
    ok(field.lines === cliLines, `${field.lines} streamlines, as fgsg field traces (${cliLines})`);
    ok(!field.truncated && sizes[0] < 4 << 20, `one message of ${sizes[0]} bytes, nothing left out`);
    const s = field.singularities;
    ok(s.length === 2, `two singularities for the two singular elements (${s.map((g) => g.kind).join(', ')})`);
    ok(s.some((g) => g.kind === 'wedge' && g.index === 0.5 && near(g, -2, 0)), 'the wedge (+1/2) where it was put');
    ok(s.some((g) => g.kind === 'trisector' && g.index === -0.5 && near(g, 2, 0)), 'the trisector (-1/2) where it was put');
    const listed = JSON.parse(fs.readFileSync(path.join(dir, 's.json'), 'utf8')).singularities;
    ok(listed.length === s.length && listed.every((g, k) => g.kind === s[k].kind &&
       g.position.every((v, i) => Math.abs(v - s[k].position[i]) < 1e-4)), 'the same as fgsg field --singularities lists');
    ok(field.drawn === 1 + 2, 'drawn: the lines and a marker per singularity');

    // The grammar edited: its field again, the wedge alone.
    fs.writeFileSync(grammar, grammarText(wedge));
    await wait(() => window.fgsgViewer.field.singularities.length === 1);
    const one = (await get(() => window.fgsgViewer.field)).singularities;
    ok(one[0].kind === 'wedge' && near(one[0], -2, 0), 'after the edit, the wedge alone');

    await page.click('#field-overlay');
    ok(!(await get(() => window.fgsgViewer.field.shown)), 'the Field button hides it again');
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
