// fgsg view draws the glTF scene fgsg run writes (#45): a grammar of many repeated assets
// (examples/stem_leaf.fgsg: stems of cubes, leaves of spheres) written with
// `fgsg run -o scene.glb` (--instancing auto --group-by symbol, the defaults, which the
// viewer takes too) and read here, on its own, as GLB; then
// opened in fgsg view in Debian's chromium. The page's three.js scene must hold one
// InstancedMesh per EXT_mesh_gpu_instancing node of the file, with the same names and
// instance counts, and the .glb it received must be that file, byte for byte. A click on
// an instance in sight picks that instance (the number the page's placing table gives).
// usage: node view_instances.js FGSG_BINARY SOURCE_DIR
'use strict';
const { spawn, spawnSync } = require('child_process');
const fs = require('fs');
const os = require('os');
const path = require('path');

const [fgsg, source] = process.argv.slice(2);
const { chromiumPath, fail, ok, chromiumOf, viewUrl, launchChromium } = require('./view_test_support');
const chromium = chromiumOf(source);

// The JSON chunk of a GLB (glTF 2.0 §4.4: a 12-byte header 'glTF', 2, length; then
// chunks of length, type, data, the first one 'JSON').
function glbJson(bytes) {
  if (bytes.readUInt32LE(0) !== 0x46546c67 || bytes.readUInt32LE(4) !== 2) fail('not a GLB 2 file');
  if (bytes.readUInt32LE(8) !== bytes.length) fail('the GLB header gives another length');
  const length = bytes.readUInt32LE(12);
  if (bytes.readUInt32LE(16) !== 0x4e4f534a) fail('the first GLB chunk is not JSON');
  return JSON.parse(bytes.toString('utf8', 20, 20 + length));
}

// Per node with EXT_mesh_gpu_instancing: its name and instance count (the TRANSLATION
// accessor's count), sorted, as "name count".
function instancedNodes(gltf) {
  const out = [];
  for (const node of gltf.nodes || []) {
    const ext = node.extensions && node.extensions.EXT_mesh_gpu_instancing;
    if (!ext) continue;
    out.push(`${node.name} ${gltf.accessors[ext.attributes.TRANSLATION].count}`);
  }
  return out.sort();
}

async function main() {
  if (!fs.existsSync(chromiumPath)) fail(`${chromiumPath} is missing: scripts/install-deps.sh installs Debian's chromium`);
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'fgsg-view-instances-'));
  const grammar = path.join(dir, 'g.fgsg');
  fs.copyFileSync(path.join(source, 'examples/stem_leaf.fgsg'), grammar);

  // 1. The file, read without the page's code.
  const file = path.join(dir, 'scene.glb');
  const ran = spawnSync(fgsg, ['run', grammar, '-o', file], { encoding: 'utf8' });
  const run = ran.stdout + ran.stderr;  // "wrote FILE (N instances, T triangles)"
  process.stdout.write(run);
  if (ran.status !== 0) fail(`fgsg run exited with ${ran.status}`);
  const instances = Number((run.match(/\((\d+) instances/) || [])[1]);
  const written = fs.readFileSync(file);
  const gltf = glbJson(written);
  const expected = instancedNodes(gltf);
  ok((gltf.extensionsUsed || []).includes('EXT_mesh_gpu_instancing'), 'the file declares EXT_mesh_gpu_instancing');
  const total = expected.reduce((sum, e) => sum + Number(e.split(' ').pop()), 0);
  // stem_leaf places every Seg as a cube and every Leaf as a sphere by a rigid transform
  // (T, RS, S on the surface's frame), and its surface once (baked: one instance is
  // smaller written whole): every instance the run counts but one is in an instanced
  // node, and there is a node for cube and one for sphere.
  console.log(`the file: ${expected.join(', ')}`);
  ok(total === instances - 1, `the instanced nodes place ${instances} - 1 instances of the run (${total})`);
  ok(expected.some((e) => e.startsWith('cube ')) && expected.some((e) => e.startsWith('sphere ')),
     'cube and sphere are instanced');

  const server = spawn(fgsg, ['view', grammar, '--port', '0'], { stdio: ['ignore', 'pipe', 'inherit'] });
  let browser;
  try {
    const url = await viewUrl(server);
    browser = await launchChromium(chromium);
    const page = await browser.newPage({ viewport: { width: 900, height: 700 } });
    page.on('pageerror', (e) => console.error('page error: ' + e.message));
    await page.goto(url);
    await page.waitForFunction(() => window.fgsgViewer && window.fgsgViewer.models >= 1, null, { timeout: 150000 });

    // 2. The page's scene: its InstancedMesh objects, walked in the page.
    const shown = await page.evaluate(() => window.fgsgViewer.hooks.instancedMeshes());
    const got = shown.map((m) => `${m.name} ${m.count}`).sort();
    console.log(`page: ${got.join(', ')}`);
    ok(got.length === expected.length, `${got.length} InstancedMesh objects in the page, ${expected.length} instanced nodes in the file`);
    ok(JSON.stringify(got) === JSON.stringify(expected), 'each InstancedMesh has its node\'s name and instance count');
    const bytes = await page.evaluate(() => window.fgsgViewer.glbBytes);
    const digest = await page.evaluate(() => window.fgsgViewer.hooks.glbDigest());
    const fileDigest = require('crypto').createHash('sha256').update(written).digest('hex');
    ok(bytes === written.length && digest === fileDigest,
       `the page received the file's .glb (${bytes} bytes, sha-256 ${digest.slice(0, 12)}...)`);

    // 3. Picking through the scene: an instance of the largest InstancedMesh that is in
    // front where it is drawn, clicked, is the instance the server names.
    const target = await page.evaluate(() => window.fgsgViewer.hooks.visibleInstance());
    ok(target !== null, 'an instance of the largest InstancedMesh is in sight');
    const box = await page.locator('#canvas').boundingBox();
    await page.mouse.click(box.x + target.screen[0], box.y + target.screen[1]);
    await page.waitForFunction(() => window.fgsgViewer.picked, null, { timeout: 10000 });
    const picked = await page.evaluate(() => window.fgsgViewer.picked);
    console.log(`picked: instance ${picked.instance}, symbol ${picked.symbol}, asset ${picked.asset}`);
    ok(picked.instance === target.instance && picked.asset === target.asset,
       `a click on instance ${target.instance} (${target.asset}) picks it`);
    console.log('PASS');
  } finally {
    if (browser) await browser.close();
    server.kill('SIGTERM');
    fs.rmSync(dir, { recursive: true, force: true });
  }
}

main().catch((e) => {
  if (!process.exitCode) console.error('FAIL: ' + (e && e.stack ? e.stack : e));
  process.exitCode = 1;
});
