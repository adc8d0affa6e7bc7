// three.js (the viewer's GLTFLoader) reads what `fgsg run --quantize` writes (#45): six
// lots of the city written as the default glTF scene and with --quantize
// (KHR_mesh_quantization and KHR_texture_transform, both required; instanced windows with
// 16-bit rotations) are both parsed in the page of fgsg view, in Debian's chromium. The
// quantized one must load without error, hold 16-bit position and texture coordinate
// arrays, and place as many vertices (every mesh, every instance), each within 0.5 mm of
// a vertex of the float file's in world space whose texture coordinates (where a texture
// samples them) are its own, scaled by the texture's repeat (three.js's
// KHR_texture_transform), up to whole tiles and 1/64 of a tile. (The order differs: a
// quantized group's baked mesh is a child node of its own beside its instanced nodes.)
// usage: node view_quantized.js FGSG_BINARY SOURCE_DIR
'use strict';
const { spawn, spawnSync } = require('child_process');
const fs = require('fs');
const os = require('os');
const path = require('path');

const [fgsg, source] = process.argv.slice(2);
const { chromiumPath, fail, ok, chromiumOf, viewUrl, launchChromium } = require('./view_test_support');
const chromium = chromiumOf(source);

// In the page: both files parsed by GLTFLoader, walked, compared.
async function compareInPage({ floatBase64, quantizedBase64 }) {
  const THREE = await import('three');
  const { GLTFLoader } = await import('three/addons/loaders/GLTFLoader.js');
  const bytes = (b64) => Uint8Array.from(atob(b64), (c) => c.charCodeAt(0)).buffer;
  const walk = async (b64) => {
    const gltf = await new GLTFLoader().parseAsync(bytes(b64), '');
    gltf.scene.updateMatrixWorld(true);
    const vertices = [];  // x, y, z, u, v (u, v NaN where no texture samples them)
    let shortArrays = 0, uvs = 0;
    const m = new THREE.Matrix4(), v = new THREE.Vector3();
    gltf.scene.traverse((o) => {
      if (!o.isMesh) return;
      const pos = o.geometry.attributes.position;
      if (pos.array instanceof Int16Array || pos.array instanceof Uint16Array) shortArrays++;
      const count = o.isInstancedMesh ? o.count : 1;
      const uv = o.geometry.attributes.uv, map = o.material && o.material.map;
      if (uv && map && uv.array instanceof Int16Array) shortArrays++;
      for (let k = 0; k < count; k++) {
        m.copy(o.matrixWorld);
        if (o.isInstancedMesh) {
          const inst = new THREE.Matrix4();
          o.getMatrixAt(k, inst);
          m.multiply(inst);
        }
        for (let i = 0; i < pos.count; i++) {
          v.fromBufferAttribute(pos, i).applyMatrix4(m);
          const sampled = uv && map;
          if (sampled) uvs++;
          vertices.push([v.x, v.y, v.z, sampled ? uv.getX(i) * map.repeat.x + map.offset.x : NaN,
                         sampled ? uv.getY(i) * map.repeat.y + map.offset.y : NaN]);
        }
      }
    });
    return { vertices, uvs, shortArrays };
  };
  const f = await walk(floatBase64), q = await walk(quantizedBase64);
  // Per quantized vertex the nearest float one (within 1 mm) with the same texture
  // coordinates up to whole tiles and 1/64 of a tile; the worst such distance.
  const tile = (a, b) => { const d = a - b; return Math.abs(d - Math.round(d)); };
  let worstPosition = 0, worstUv = 0;
  for (const a of q.vertices) {
    let best = Infinity, bestUv = Infinity;
    for (const b of f.vertices) {
      const d = Math.max(Math.abs(a[0] - b[0]), Math.abs(a[1] - b[1]), Math.abs(a[2] - b[2]));
      if (d > 1e-3 || Number.isNaN(a[3]) !== Number.isNaN(b[3])) continue;
      const t = Number.isNaN(a[3]) ? 0 : Math.max(tile(a[3], b[3]), tile(a[4], b[4]));
      if (t <= 1 / 64 && d < best) best = d, bestUv = t;
    }
    worstPosition = Math.max(worstPosition, best);
    if (best < Infinity) worstUv = Math.max(worstUv, bestUv);
  }
  return { floatVertices: f.vertices.length, quantizedVertices: q.vertices.length, floatUvs: f.uvs, quantizedUvs: q.uvs,
           floatShort: f.shortArrays, quantizedShort: q.shortArrays, worstPosition, worstUv };
}

async function main() {
  if (!fs.existsSync(chromiumPath)) fail(`${chromiumPath} is missing: scripts/install-deps.sh installs Debian's chromium`);
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'fgsg-view-quantized-'));
  const lots = JSON.parse(fs.readFileSync(path.join(source, 'examples/city/lots.geojson'), 'utf8'));
  lots.features = lots.features.slice(0, 6);
  fs.writeFileSync(path.join(dir, 'lots.geojson'), JSON.stringify(lots));
  const files = {};
  for (const [name, extra] of [['float', []], ['quantized', ['--quantize']]]) {
    const file = path.join(dir, `${name}.glb`);
    const ran = spawnSync(fgsg, ['run', path.join(source, 'examples/city.fgsg'), '--lots', path.join(dir, 'lots.geojson'),
                                 '-o', file, '-q', ...extra], { encoding: 'utf8' });
    if (ran.status !== 0) fail(`fgsg run ${extra.join(' ')} exited with ${ran.status}: ${ran.stderr}`);
    files[name] = fs.readFileSync(file);
  }
  // Any grammar: the page is what is wanted (three.js and its loader).
  const grammar = path.join(dir, 'g.fgsg');
  fs.copyFileSync(path.join(source, 'examples/stem_leaf.fgsg'), grammar);
  const server = spawn(fgsg, ['view', grammar, '--port', '0'], { stdio: ['ignore', 'pipe', 'inherit'] });
  let browser;
  try {
    const url = await viewUrl(server);
    browser = await launchChromium(chromium);
    const page = await browser.newPage({ viewport: { width: 600, height: 400 } });
    page.on('pageerror', (e) => console.error('page error: ' + e.message));
    await page.goto(url);
    await page.waitForFunction(() => window.fgsgViewer && window.fgsgViewer.models >= 1, null, { timeout: 150000 });
    const r = await page.evaluate(compareInPage, { floatBase64: files.float.toString('base64'),
                                                   quantizedBase64: files.quantized.toString('base64') });
    console.log(JSON.stringify(r));
    ok(r.floatShort === 0 && r.quantizedShort > 0, `the quantized file loads with 16-bit arrays (${r.quantizedShort})`);
    ok(r.floatVertices > 0 && r.quantizedVertices === r.floatVertices, `both place ${r.floatVertices} vertices`);
    ok(r.worstPosition <= 5e-4, `every vertex within 0.5 mm of the float file's (${(r.worstPosition * 1000).toFixed(3)} mm)`);
    ok(r.floatUvs > 0 && r.quantizedUvs === r.floatUvs && r.worstUv <= 1 / 64,
       `texture coordinates through the texture transform as the float file's, up to whole tiles (${r.worstUv.toExponential(2)})`);
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
