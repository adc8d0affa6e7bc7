// fgsg view in a real browser: Debian's chromium, headless, driven by playwright-core.
// The page loads and draws a non-empty model, its repeated assets instanced; a click on
// it names the symbol, rule and depth that placed what is under it; an attribute changed in
// the inspector, an edit of the grammar file and a save of a mesh it names from a folder of
// its own each bring a new model; an edit with an error shows its diagnostic
// (file:line:col, the line, a caret) and keeps the last model.
// usage: node view_page.js FGSG_BINARY SOURCE_DIR OUT_DIR
'use strict';
const { spawn } = require('child_process');
const fs = require('fs');
const os = require('os');
const path = require('path');

const [fgsg, source, out] = process.argv.slice(2);
const { chromiumPath, fail, chromiumOf, viewUrl, launchChromium } = require('./view_test_support');
const chromium = chromiumOf(source);

async function main() {
  if (!fs.existsSync(chromiumPath)) fail(`${chromiumPath} is missing: scripts/install-deps.sh installs Debian's chromium`);
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'fgsg-view-'));
  const grammar = path.join(dir, 'g.fgsg');
  fs.copyFileSync(path.join(source, 'examples/mueller_building.fgsg'), grammar);
  fs.symlinkSync(path.join(source, 'examples/assets'), path.join(dir, 'assets'));

  const server = spawn(fgsg, ['view', grammar, '--port', '0'], { stdio: ['ignore', 'pipe', 'inherit'] });
  let browser;
  try {
    const url = await viewUrl(server);
    // The address carries the session token; without it the page is refused (the rest of
    // the server's checks: tests/viewer/view_security.py).
    if (!/\/\?token=[0-9a-f]{48}$/.test(url)) fail(`the printed address has no token: ${url}`);
    const status = await new Promise((resolve) => {
      const u = new URL(url);
      require('http').get({ host: u.hostname, port: u.port, path: '/' }, (r) => {
        r.resume();
        resolve(r.statusCode);
      }).on('error', () => resolve(0));
    });
    if (status !== 403) fail(`the page without its token answered ${status}`);

    browser = await launchChromium(chromium);
    const page = await browser.newPage({ viewport: { width: 1100, height: 700 } });
    page.on('pageerror', (e) => console.error('page error: ' + e.message));
    await page.goto(url);
    const models = (n, timeout = 60000) =>
      page.waitForFunction((k) => window.fgsgViewer && window.fgsgViewer.models >= k, n, { timeout });

    // 1. The model is drawn: a good share of the canvas is not the background.
    await models(1);
    await page.waitForTimeout(300);  // a frame or two
    const drawn = await page.evaluate(() => {
      const c = document.getElementById('canvas');
      const copy = document.createElement('canvas');
      copy.width = c.width; copy.height = c.height;
      const g = copy.getContext('2d');
      g.drawImage(c, 0, 0);
      const px = g.getImageData(0, 0, copy.width, copy.height).data;
      let other = 0;
      for (let i = 0; i < px.length; i += 4)
        if (Math.abs(px[i] - 0x20) + Math.abs(px[i + 1] - 0x24) + Math.abs(px[i + 2] - 0x2a) > 24) ++other;
      return other / (px.length / 4);
    });
    console.log(`drawn: ${(100 * drawn).toFixed(1)}% of the canvas`);
    if (!(drawn > 0.05)) fail(`the canvas is nearly empty (${(100 * drawn).toFixed(2)}% drawn)`);
    const first = await page.evaluate(() => window.fgsgViewer.figures);
    const instanced = await page.evaluate(() => window.fgsgViewer.instanced);
    console.log(`instanced: ${instanced} of ${first.instances} instances drawn as InstancedMesh`);
    if (!(instanced > 0)) fail('no instances were drawn instanced');

    // Picking: a click on the building says which symbol placed what is under it.
    const box = await page.locator('#canvas').boundingBox();
    await page.mouse.click(box.x + box.width * 0.45, box.y + box.height * 0.55);
    await page.waitForFunction(() => window.fgsgViewer.picked, null, { timeout: 10000 });
    const picked = await page.evaluate(() => window.fgsgViewer.picked);
    console.log(`picked: instance ${picked.instance}, symbol ${picked.symbol}, rule ${picked.rule}, ` +
                `depth ${picked.depth}, asset ${picked.asset}`);
    if (!picked.symbol || !picked.asset || !Array.isArray(picked.params)) fail('the picked instance lacks its symbol');
    // The rule that placed it is one of the picked symbol's ("15: flatbrick (line 68)": the
    // Mueller building numbers its rules as the paper does); the building is a few levels deep.
    if (typeof picked.rule !== 'string' || !picked.rule.includes(': ' + picked.symbol + ' (line ') ||
        !/\(line \d+\)$/.test(picked.rule))
      fail(`the picked instance's rule is '${picked.rule}', not one of ${picked.symbol}'s`);
    if (!Number.isInteger(picked.depth) || picked.depth < 1 || picked.depth > 20)
      fail(`the picked instance's depth is ${picked.depth}`);
    const panel = await page.textContent('#picked');
    if (!panel.includes('symbol ' + picked.symbol) || !panel.includes('rule ' + picked.rule) ||
        !panel.includes('depth ' + picked.depth))
      fail('the panel does not show the pick');
    fs.mkdirSync(out, { recursive: true });
    await page.screenshot({ path: path.join(out, 'fgsg_view.png') });  // README's picture, the pick shown

    // 2. An attribute changed in the inspector: a wider lot, more windows.
    const t0 = Date.now();
    await page.fill('input[type=number][data-attr="lot_width"]', '28');
    await page.dispatchEvent('input[type=number][data-attr="lot_width"]', 'change');
    await models(2);
    const wider = await page.evaluate(() => window.fgsgViewer.figures);
    const wideHeight = await page.evaluate(() => window.fgsgViewer.size[1]);
    const timing = await page.evaluate(() => window.fgsgViewer.timing);
    const serverMs = await page.evaluate(() => window.fgsgViewer.serverMilliseconds);
    console.log(`attribute change to new model: ${(timing.shown - timing.sent).toFixed(0)} ms in the page ` +
                `(server ${serverMs.toFixed(0)} ms, bytes received at ${(timing.received - timing.sent).toFixed(0)} ms; ` +
                `${Date.now() - t0} ms seen by the test), triangles ${first.triangles} -> ${wider.triangles}`);
    if (!(wider.triangles > first.triangles)) fail('lot_width 28 did not give a larger building');

    // 2b. A second tab has values of its own: it starts from the defaults, and its seed
    // does not move the first tab's model.
    const tab2 = await browser.newPage({ viewport: { width: 800, height: 600 } });
    tab2.on('pageerror', (e) => console.error('tab 2 page error: ' + e.message));
    await tab2.goto(url);
    await tab2.waitForFunction(() => window.fgsgViewer && window.fgsgViewer.models >= 1, null, { timeout: 60000 });
    const tab2Width = await tab2.evaluate(() => window.fgsgViewer.info.attrs.find((a) => a.name === 'lot_width').value);
    const tab2Triangles = await tab2.evaluate(() => window.fgsgViewer.figures.triangles);
    console.log(`tab 2: lot_width ${tab2Width}, triangles ${tab2Triangles} (tab 1: 28, ${wider.triangles})`);
    if (String(tab2Width) === '28' || tab2Triangles !== first.triangles) fail('a new tab inherited the first tab\'s values');
    const tab1Models = await page.evaluate(() => window.fgsgViewer.models);
    await tab2.click('#next');
    await tab2.waitForFunction(() => window.fgsgViewer.models >= 2, null, { timeout: 60000 });
    if ((await tab2.evaluate(() => window.fgsgViewer.info.seed)) !== 2) fail('tab 2 did not step its seed');
    await page.waitForTimeout(500);
    if ((await page.evaluate(() => window.fgsgViewer.models)) !== tab1Models) fail('tab 2\'s seed re-derived tab 1');
    if ((await page.evaluate(() => window.fgsgViewer.info.seed)) !== 1) fail('tab 2\'s seed reached tab 1');

    // 3. The file edited and saved: a taller building by default.
    let text = fs.readFileSync(grammar, 'utf8');
    if (!/attr building_height = 6;/.test(text)) fail('the example no longer declares building_height = 6');
    fs.writeFileSync(grammar, text.replace('attr building_height = 6;', 'attr building_height = 12;'));
    await models(3);
    const info = await page.evaluate(() => window.fgsgViewer.info.attrs.find((a) => a.name === 'building_height'));
    if (info.default !== 12) fail(`the page did not take the edited default (building_height ${info.default})`);
    const taller = await page.evaluate(() => window.fgsgViewer.size[1]);
    console.log(`model height ${wideHeight.toFixed(2)} -> ${taller.toFixed(2)}`);
    if (!(Math.abs(taller - wideHeight - 6) < 0.01)) fail('building_height 12 did not raise the walls by 6');
    // The edit re-derived the second tab too, with its own values.
    await tab2.waitForFunction(() => window.fgsgViewer.models >= 3, null, { timeout: 60000 });
    const tab2Info = await tab2.evaluate(() => window.fgsgViewer.info);
    if (tab2Info.seed !== 2 || tab2Info.attrs.find((a) => a.name === 'building_height').default !== 12)
      fail('the edit did not re-derive tab 2 with its own seed');
    await tab2.close();

    // 3b. A mesh the grammar uses from a folder of its own: saving it derives again.
    await page.waitForTimeout(1000);
    fs.mkdirSync(path.join(dir, 'parts'));
    fs.copyFileSync(path.join(source, 'examples/assets/flatbrick.obj'), path.join(dir, 'parts/brick.obj'));
    text = fs.readFileSync(grammar, 'utf8');
    if (!text.includes('I("flatbrick.obj")')) fail('the example no longer places flatbrick.obj');
    fs.writeFileSync(grammar, text.replace('I("flatbrick.obj")', 'I("parts/brick.obj")'));
    await models(4);
    await page.waitForTimeout(1500);  // the page may ask once more for the new grammar's values
    const bricks = await page.evaluate(() => window.fgsgViewer.figures.triangles);
    fs.writeFileSync(path.join(dir, 'parts/brick.obj'), 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n');
    await page.waitForFunction((n) => window.fgsgViewer.figures.triangles !== n, bricks, { timeout: 30000 })
      .catch(() => {});
    const tetrahedra = await page.evaluate(() => window.fgsgViewer.figures.triangles);
    console.log(`parts/brick.obj saved as a tetrahedron: triangles ${bricks} -> ${tetrahedra}`);
    if (!(tetrahedra < bricks)) fail('saving a mesh the grammar uses did not derive again');

    // 4. An edit with an error: the diagnostic in the page, the last model kept.
    await page.waitForTimeout(1000);  // an editor's save may come as two writes: let both land
    const before = await page.evaluate(() => window.fgsgViewer.models);
    text = fs.readFileSync(grammar, 'utf8');
    fs.writeFileSync(grammar, text + '\nBroken ~> S(1, 1;\n');
    await page.waitForFunction(() => window.fgsgViewer.errors >= 1, null, { timeout: 30000 });
    const diagnostics = await page.textContent('#diagnostics');
    console.log('diagnostic shown:\n' + diagnostics);
    if (!/g\.fgsg:\d+:\d+: error\[E\d+\]/.test(diagnostics)) fail('no file:line:col error in the page');
    if (!/\^/.test(diagnostics) || !/Broken/.test(diagnostics)) fail('the diagnostic lacks the line and its caret');
    await page.waitForTimeout(1000);
    if ((await page.evaluate(() => window.fgsgViewer.models)) !== before) fail('an erroneous edit replaced the model');
    if (!(await page.textContent('#status')).includes('last good model')) fail('the status does not say the model is kept');
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
