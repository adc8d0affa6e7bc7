// fgsg view --steps (#48, lpfg's animate mode): an L-system's derivation step by step.
// The plant F -> F [ + F ] F [ - F ] F, drawn as line segments, has 5^k segments after k
// steps (counted by hand: 1, 5, 25, 125); they form a tree (branches start where the
// turtle stood), whose 5^k + 1 vertices the scene's lines share. Opened in
// Debian's chromium with --steps --step 1, the page shows a slider 0..3 at 1; moving it
// shows that step's model (segments and vertices walked in the page's three.js scene),
// a step asked for again comes from the server's cache (the same header, its
// milliseconds included), Play runs to the last step and stops, a step past the length
// or not a whole number is refused and changes nothing, and a shorter length set through
// the attr n moves the slider's end. A server without --steps refuses any step.
// usage: node view_steps.js FGSG_BINARY SOURCE_DIR
'use strict';
const { spawn } = require('child_process');
const fs = require('fs');
const os = require('os');
const path = require('path');

const [fgsg, source] = process.argv.slice(2);
const { chromiumPath, fail, ok, chromiumOf, viewUrl, launchChromium } = require('./view_test_support');
const chromium = chromiumOf(source);

const plant = `attr n = 3;
derive parallel n;
turtle angle 25.7 segments "lines";
axiom: F;
F -> F [ + F ] F [ - F ] F;
`;

async function openPage(browser, url) {
  const page = await browser.newPage({ viewport: { width: 900, height: 700 } });
  page.on('pageerror', (e) => console.error('page error: ' + e.message));
  await page.goto(url);
  await page.waitForFunction(() => window.fgsgViewer && window.fgsgViewer.models >= 1, null, { timeout: 150000 });
  return page;
}

// The page shows step `step`: its header said so and its scene is built.
async function shownStep(page, step) {
  await page.waitForFunction((s) => { const v = window.fgsgViewer; return v.steps && v.steps.step === s; }, step,
                             { timeout: 60000 });
  return page.evaluate(() => window.fgsgViewer.hooks.drawnCounts());
}

// Sends `message` and waits for the server's refusal; returns its reason.
async function refusal(page, message) {
  const before = await page.evaluate(() => window.fgsgViewer.rejected || 0);
  await page.evaluate((m) => window.fgsgViewer.hooks.send(m), message);
  await page.waitForFunction((n) => (window.fgsgViewer.rejected || 0) > n, before, { timeout: 10000 });
  return page.evaluate(() => window.fgsgViewer.lastRejected);
}

async function main() {
  if (!fs.existsSync(chromiumPath)) fail(`${chromiumPath} is missing: scripts/install-deps.sh installs Debian's chromium`);
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'fgsg-view-steps-'));
  const grammar = path.join(dir, 'plant.fgsg');
  fs.writeFileSync(grammar, plant);
  const servers = [];
  let browser;
  try {
    const server = spawn(fgsg, ['view', grammar, '--port', '0', '--steps', '--step', '1'],
                         { stdio: ['ignore', 'pipe', 'inherit'] });
    servers.push(server);
    const url = await viewUrl(server);
    browser = await launchChromium(chromium);
    const page = await openPage(browser, url);

    // 1. The first model is step 1 of 3, the slider there.
    let counts = await shownStep(page, 1);
    const first = await page.evaluate(() => ({ steps: window.fgsgViewer.steps, ms: window.fgsgViewer.serverMilliseconds,
      slider: [document.getElementById('step-slider').min, document.getElementById('step-slider').max,
               document.getElementById('step-slider').value], hidden: document.getElementById('steps').hidden }));
    ok(!first.hidden && first.steps.length === 3, `the step slider is shown for the derivation's length 3`);
    ok(JSON.stringify(first.slider) === '["0","3","1"]', `the slider runs 0..3 and stands at 1 (${first.slider})`);
    ok(counts.segments === 5 && counts.vertices === 6, `step 1: 5 segments, 6 vertices (${JSON.stringify(counts)})`);

    // 2. The slider moved to 2, then to 0 (the axiom).
    await page.locator('#step-slider').fill('2');
    counts = await shownStep(page, 2);
    ok(counts.segments === 25 && counts.vertices === 26, `step 2: 25 segments, 26 vertices (${JSON.stringify(counts)})`);
    await page.locator('#step-slider').fill('0');
    counts = await shownStep(page, 0);
    ok(counts.segments === 1 && counts.vertices === 2, `step 0, the axiom: 1 segment, 2 vertices (${JSON.stringify(counts)})`);

    // 3. Back at 1: the model the server kept, its header unchanged.
    await page.locator('#step-slider').fill('1');
    counts = await shownStep(page, 1);
    const again = await page.evaluate(() => window.fgsgViewer.serverMilliseconds);
    ok(counts.segments === 5 && again === first.ms, `step 1 again comes from the cache (${again} ms as first sent)`);

    // 4. Refused: past the length, not a whole number; the page still shows step 1.
    let reason = await refusal(page, { type: 'set', step: 4 });
    ok(/step 4 is past the derivation's length 3 \(steps 0 to 3\)/.test(reason), `step 4 is refused: ${reason}`);
    reason = await refusal(page, { type: 'set', step: -1 });
    ok(/"step" must be a whole number from 0/.test(reason), `step -1 is refused: ${reason}`);
    reason = await refusal(page, { type: 'set', step: 1.5 });
    ok(/"step" must be a whole number from 0/.test(reason), `step 1.5 is refused: ${reason}`);
    const still = await page.evaluate(() => window.fgsgViewer.steps.step);
    ok(still === 1, 'a refused step changes nothing');

    // 5. Play: step after step to the last, then it stops.
    await page.click('#step-play');
    counts = await shownStep(page, 3);
    await page.waitForFunction(() => document.getElementById('step-play').textContent === 'Play', null, { timeout: 10000 });
    const played = await page.evaluate(() => window.fgsgViewer.steps.shown.slice(-3));
    ok(JSON.stringify(played) === '[1,2,3]', `Play showed steps 2 and 3 after 1, then stopped (${played})`);
    ok(counts.segments === 125 && counts.vertices === 126, `step 3: 125 segments, 126 vertices (${JSON.stringify(counts)})`);

    // 6. n = 2: the derivation is 2 steps long, the slider ends there, step 3 is past it.
    await page.evaluate(() => window.fgsgViewer.hooks.send({ type: 'set', attrs: { n: '2' }, step: 2 }));
    counts = await shownStep(page, 2);
    const max = await page.evaluate(() => [window.fgsgViewer.steps.length, document.getElementById('step-slider').max]);
    ok(max[0] === 2 && max[1] === '2' && counts.segments === 25, `n = 2: the slider ends at 2 (${max})`);
    reason = await refusal(page, { type: 'set', step: 3 });
    ok(/past the derivation's length 2/.test(reason), `with n = 2, step 3 is refused: ${reason}`);

    // 7. Without --steps: no slider, and no step is taken.
    const plain = spawn(fgsg, ['view', grammar, '--port', '0'], { stdio: ['ignore', 'pipe', 'inherit'] });
    servers.push(plain);
    const other = await openPage(browser, await viewUrl(plain));
    const hidden = await other.evaluate(() => document.getElementById('steps').hidden);
    ok(hidden, 'without --steps the page has no step slider');
    reason = await refusal(other, { type: 'set', step: 1 });
    ok(/started without --steps/.test(reason), `without --steps a step is refused: ${reason}`);
    console.log('PASS');
  } finally {
    if (browser) await browser.close();
    for (const s of servers) s.kill('SIGTERM');
    fs.rmSync(dir, { recursive: true, force: true });
  }
}

main().catch((e) => {
  if (!process.exitCode) console.error('FAIL: ' + (e && e.stack ? e.stack : e));
  process.exitCode = 1;
});
