// fgsg view's page: draws the models the server pushes (binary glTF) with three.js,
// keeps the camera across models, and sends attribute and seed changes back. The
// messages are described in cli/view_session.h. window.fgsgViewer is what the browser
// tests read (tests/viewer/). Seeds, painting and the camera tools are modules of their
// own (seeds.js, paint.js, view_tools.js) sharing `ctx` below.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { createSeeds } from './seeds.js';
import { createPaint } from './paint.js';
import { createViewTools } from './view_tools.js';
import { createFieldOverlay } from './field_overlay.js';
import { createDerivationSteps } from './derivation_steps.js';
import { createFieldDesign } from './field_design.js';

const $ = (id) => document.getElementById(id);
// timing: when the last change was sent, its model announced, its bytes received and
// shown (performance.now() milliseconds); serverMilliseconds: the server's part.
const state = { models: 0, errors: 0, figures: null, info: null, seed: 1, size: null, timing: {}, serverMilliseconds: 0,
                instanced: 0, picked: null, mode: 'pick', seeds: [], surfaceTriangles: 0, written: [] };
window.fgsgViewer = state;

const canvas = $('canvas');
const renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(window.devicePixelRatio);
const scene = new THREE.Scene();
scene.background = new THREE.Color(0x20242a);
scene.add(new THREE.HemisphereLight(0xffffff, 0x404450, 1.6));
const sun = new THREE.DirectionalLight(0xffffff, 1.8);
sun.position.set(3, 5, 4);
scene.add(sun);
const camera = new THREE.PerspectiveCamera(45, 1, 0.01, 1e6);
camera.position.set(3, 2, 4);
const controls = new OrbitControls(camera, canvas);
let model = null;
let surface = null;  // the surface the grammar grows on (seeds, paint), when it has one

function resize() {
  const w = canvas.clientWidth, h = canvas.clientHeight;
  if (canvas.width !== Math.floor(w * devicePixelRatio) || canvas.height !== Math.floor(h * devicePixelRatio)) {
    renderer.setSize(w, h, false);
    camera.aspect = w / Math.max(h, 1);
    camera.updateProjectionMatrix();
  }
}
// Frames are drawn on demand (the camera moved, a model came, the window changed), so
// an idle page costs nothing and a new model is never queued behind frames.
let frameRequested = false;
function requestRender() {
  if (frameRequested) return;
  frameRequested = true;
  requestAnimationFrame(() => {
    frameRequested = false;
    resize();
    renderer.render(scene, camera);
  });
}
controls.addEventListener('change', requestRender);
window.addEventListener('resize', requestRender);
requestRender();

// The first model decides the view; later ones keep the camera the user chose.
function frame(object) {
  frameBox(new THREE.Box3().setFromObject(object));
}
function frameBox(box) {
  if (box.isEmpty()) return;
  const centre = box.getCenter(new THREE.Vector3()), size = box.getSize(new THREE.Vector3()).length();
  controls.target.copy(centre);
  camera.position.copy(centre).add(new THREE.Vector3(0.7, 0.5, 0.9).multiplyScalar(size));
  camera.near = size / 1000;
  camera.far = size * 100;
  camera.updateProjectionMatrix();
}

function setStatus(text, kind) {
  $('status').textContent = text;
  $('status').className = kind || '';
}

let header = null;  // the JSON that announced the model whose parts are arriving
let piecesHeader = null;  // or the pieces whose parts are arriving
let parts = [];
const loader = new GLTFLoader();

// The first mesh's geometry of a .glb (an asset's mesh, for its instances).
async function geometryOf(buffer) {
  const gltf = await loader.parseAsync(buffer, '');
  let geometry = null;
  gltf.scene.traverse((o) => { if (!geometry && o.isMesh) geometry = o.geometry; });
  return geometry;
}

// The model from its parts (cli/view_session.h): the glTF scene fgsg run writes (a node
// per start shape and group; GLTFLoader makes each EXT_mesh_gpu_instancing node an
// InstancedMesh), then the instance numbers its placing nodes hold, which picking sends.
const placedIds = new WeakMap();  // object -> its instances' numbers in the derivation
let lastGlb = null;  // the shown model's .glb, for the tests' digest
async function buildModel(announced, buffers) {
  const gltf = await loader.parseAsync(buffers[0], '');
  const ids = new Uint32Array(buffers[1]);
  const byNode = new Map();
  let offset = 0;
  for (const [node, count] of announced.placing) {
    byNode.set(node, ids.subarray(offset, offset + count));
    offset += count;
  }
  const instancedMeshes = [];
  gltf.scene.traverse((o) => {
    const node = (gltf.parser.associations.get(o) || {}).nodes;
    if (byNode.has(node)) placedIds.set(o, byNode.get(node));
    if (o.isInstancedMesh) instancedMeshes.push({ name: o.name, asset: o.userData.asset, count: o.count });
  });
  state.instancedMeshes = instancedMeshes;
  state.instanced = instancedMeshes.reduce((sum, m) => sum + m.count, 0);
  state.glbBytes = buffers[0].byteLength;
  lastGlb = buffers[0];
  return gltf.scene;
}

// Everything a model holds on the GPU: its geometries, materials and their textures.
function dispose(object) {
  object.traverse((o) => {
    if (o.geometry) o.geometry.dispose();
    if (o.isInstancedMesh) o.dispose();
    for (const m of Array.isArray(o.material) ? o.material : o.material ? [o.material] : []) {
      for (const value of Object.values(m)) if (value && value.isTexture) value.dispose();
      m.dispose();
    }
  });
}

// Models and pieces are read (parsed) one after another in the order they came, on one
// chain: the page then shows what the server believes it shows. A plain model replaces all
// pieces, so one read while a newer plain model has come is dropped; pieces never are (the
// server sends only those the page lacks), and after a piece that cannot be read, or
// pieces that leave a hole, the page asks for all of them again ({"type":"resend"}).
let modelsShown = Promise.resolve();
let modelsReceived = 0, newestPlain = 0;
let resendAsked = false;
let testDelay = 0;  // tests: milliseconds the next model waits before it is read
function inOrder(read) {
  const seq = ++modelsReceived, delay = testDelay;
  testDelay = 0;
  modelsShown = modelsShown.then(async () => {
    if (delay) await new Promise((resolve) => setTimeout(resolve, delay));
    if (seq < newestPlain) return;  // a newer plain model replaces whatever this shows
    await read(seq);
  }).catch((err) => { setStatus('cannot read the model: ' + err, 'error'); });
  return seq;
}
function askResend() {
  state.resends = (state.resends || 0) + 1;
  if (resendAsked) return;
  resendAsked = true;
  ws.send(JSON.stringify({ type: 'resend' }));
}

function showModel(buffer) {
  parts.push(buffer);
  if (!header || parts.length < 2) return;
  const announced = header, buffers = parts;
  header = null;
  parts = [];
  state.timing.received = performance.now();
  newestPlain = inOrder(async () => {
    const built = await buildModel(announced, buffers);
    if (model) {
      scene.remove(model);
      dispose(model);
    }
    pieces.length = 0;
    model = built;
    scene.add(model);
    modelShown(announced);
  });
}

// A model of seeds derived apart comes as pieces, a seed's each and the rest after them
// ({"type":"pieces"}): only those that changed are sent, each replacing the one the page
// shows at its place (a seed dragged: that seed's plant). Each piece's instance numbers
// count from its base in the derivation, which other seeds' changes move.
const pieces = [];  // per piece: { object, ids: [[object, local numbers], ...], glb }
let testFailPieces = false;  // tests: the next pieces cannot be read
function showPieces(buffer) {
  parts.push(buffer);
  if (parts.length < 2 * piecesHeader.sent.length) return;
  const announced = piecesHeader, buffers = parts;
  piecesHeader = null;
  parts = [];
  state.timing.received = performance.now();
  const fail = testFailPieces;
  testFailPieces = false;
  inOrder(async () => {
    let built;
    try {
      if (fail) throw new Error('a test made these pieces unreadable');
      built = await Promise.all(announced.sent.map(async (s, k) => {
        const gltf = await loader.parseAsync(buffers[2 * k], '');
        const ids = new Uint32Array(buffers[2 * k + 1]), byNode = new Map();
        let offset = 0;
        for (const [node, count] of s.placing) byNode.set(node, ids.subarray(offset, offset + count)), offset += count;
        const own = [];
        gltf.scene.traverse((o) => {
          const node = (gltf.parser.associations.get(o) || {}).nodes;
          if (byNode.has(node)) own.push([o, byNode.get(node)]);
        });
        return { index: s.piece, object: gltf.scene, ids: own, glb: buffers[2 * k] };
      }));
    } catch (err) {  // the pieces the server believes shown are not: all of them again
      setStatus('cannot read the model: ' + err + ', asking for it again', 'error');
      for (const s of announced.sent) {
        if (pieces[s.piece]) { model.remove(pieces[s.piece].object); dispose(pieces[s.piece].object); }
        pieces[s.piece] = undefined;
      }
      return askResend();
    }
    if (!model || !model.userData.pieces) {  // the first pieces: a group of them replaces the model
      if (model) { scene.remove(model); dispose(model); }
      model = new THREE.Group();
      model.userData.pieces = true;
      scene.add(model);
    }
    for (const p of built) {
      if (pieces[p.index]) { model.remove(pieces[p.index].object); dispose(pieces[p.index].object); }
      pieces[p.index] = p;
      model.add(p.object);
    }
    for (const p of pieces.splice(announced.bases.length)) if (p) { model.remove(p.object); dispose(p.object); }
    let holes = pieces.length < announced.bases.length;
    for (let k = 0; k < pieces.length; ++k) {
      if (!pieces[k]) { holes = true; continue; }
      for (const [o, local] of pieces[k].ids) placedIds.set(o, Array.from(local, (i) => i + announced.bases[k]));
    }
    if (holes) askResend();  // the server sent fewer pieces than the page lacks
    else resendAsked = false;
    const instancedMeshes = [];
    model.traverse((o) => { if (o.isInstancedMesh) instancedMeshes.push({ name: o.name, asset: o.userData.asset, count: o.count }); });
    state.instancedMeshes = instancedMeshes;
    state.instanced = instancedMeshes.reduce((sum, m) => sum + m.count, 0);
    state.pieces = { count: pieces.length, sent: built.map((p) => p.index),
                     bytes: built.reduce((sum, p) => sum + p.glb.byteLength, 0), server: announced.server };
    state.glbBytes = pieces.reduce((sum, p) => sum + (p ? p.glb.byteLength : 0), 0);
    lastGlb = null;
    modelShown(announced);
  });
}

function modelShown(announced) {
  if (state.models === 0) {
    if (surface) frameBox(new THREE.Box3().setFromObject(model).union(new THREE.Box3().setFromObject(surface)));
    else frame(model);
    controls.update();
  }
  tools.refresh();
  requestRender();
  state.timing.shown = performance.now();
  steps.shown(announced ? announced.steps : undefined);
  state.serverMilliseconds = announced ? announced.milliseconds : 0;
  state.models += 1;
  state.size = new THREE.Box3().setFromObject(model).getSize(new THREE.Vector3()).toArray();
  state.figures = announced ? announced.figures : null;
  const f = state.figures || {};
  $('stats').textContent = Object.entries(f).map(([k, v]) => `${k} ${v}`).join('\n') +
    (announced ? `\nmilliseconds ${announced.milliseconds.toFixed(1)}` : '');
  $('diagnostics').textContent = '';
  setStatus(`${f.triangles ?? 0} triangles`, '');
}

// Picking: a click (not a drag) on an instance asks the server who placed it.
const raycaster = new THREE.Raycaster();
let downAt = null;
canvas.addEventListener('pointerdown', (e) => { downAt = [e.clientX, e.clientY]; });
canvas.addEventListener('pointerup', (e) => {
  if (state.mode !== 'pick') return;
  if (!downAt || Math.hypot(e.clientX - downAt[0], e.clientY - downAt[1]) > 4 || !model) return;
  const r = canvas.getBoundingClientRect();
  const ndc = new THREE.Vector2(((e.clientX - r.left) / r.width) * 2 - 1, -((e.clientY - r.top) / r.height) * 2 + 1);
  raycaster.setFromCamera(ndc, camera);
  // The nearest surface that a placing node draws (an instance of an InstancedMesh, a
  // mirrored instance's mesh or a primitive under its node); baked geometry is no one's.
  for (const h of raycaster.intersectObject(model, true)) {
    for (let o = h.object; o; o = o.parent) {
      const ids = placedIds.get(o);
      if (!ids) continue;
      ws.send(JSON.stringify({ type: 'pick', instance: ids[o === h.object && h.instanceId !== undefined ? h.instanceId : 0] }));
      return;
    }
  }
  $('picked').textContent = 'nothing instanced here';
});

function showPicked(m) {
  state.picked = m;
  const fmt = (v) => (typeof v === 'number' ? +v.toFixed(4) : JSON.stringify(v));
  $('picked').textContent = `instance ${m.instance}\nsymbol ${m.symbol}\nrule ${m.rule ?? '(none)'}\n` +
    `depth ${m.depth ?? '(not known)'}\nasset ${m.asset}\n` +
    `params (${m.params.map(fmt).join(', ')})\ncentre (${m.centre.map(fmt).join(', ')})`;
}

// Sends the values the user has set (the others follow the grammar's defaults, also
// when an edit of the file changes them) and the seed.
function send(changed) {
  if (changed) changed.dataset.touched = '1';
  const attrs = {};
  for (const input of document.querySelectorAll('[data-attr][data-touched]')) {
    if (input.dataset.kind === 'range') continue;
    attrs[input.dataset.attr] = input.type === 'checkbox' ? String(input.checked) : input.value;
  }
  sendMessage({ type: 'set', attrs, seed: state.seed });
}

// Every change goes out here: the bench (bench/view_latency.js) times from this to the
// model shown.
function sendMessage(message) {
  state.timing = { sent: performance.now() };
  ws.send(JSON.stringify(message));
}

// The surface: drawn in grey under the model, what seeds and the brush land on.
async function showSurface(buffer) {
  const geometry = await geometryOf(buffer);
  if (surface) { scene.remove(surface); surface.geometry.dispose(); }
  surface = null;
  if (!geometry) return;
  surface = new THREE.Mesh(geometry, new THREE.MeshStandardMaterial({ color: 0x8a939e, roughness: 0.9,
    polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 }));
  surface.geometry.computeBoundingSphere();
  surface.geometry.computeBoundingBox();
  scene.add(surface);
  state.surfaceTriangles = geometry.index ? geometry.index.count / 3 : geometry.attributes.position.count / 3;
  state.surfaces = (state.surfaces || 0) + 1;
  seeds.redraw();
  tools.refresh();
  requestRender();
}

function ndc(e) {
  const r = canvas.getBoundingClientRect();
  return new THREE.Vector2(((e.clientX - r.left) / r.width) * 2 - 1, -((e.clientY - r.top) / r.height) * 2 + 1);
}

const ctx = {
  scene, camera, canvas, controls, state, raycaster, ndc, requestRender, frameBox,
  send: sendMessage,
  surfaceHit(e) {
    if (!surface) return null;
    raycaster.setFromCamera(ndc(e), camera);
    return raycaster.intersectObject(surface, false)[0] || null;
  },
  surfaceSize() { return surface ? surface.geometry.boundingSphere.radius * 2 : 1; },
  drawn() { return [model, surface].filter(Boolean); },
};
const seeds = createSeeds(ctx);
const paint = createPaint(ctx);
const tools = createViewTools(ctx);
const fieldOverlay = createFieldOverlay(ctx);
const steps = createDerivationSteps(ctx);  // with --steps: an L-system's slider
const fieldDesign = createFieldDesign(ctx, fieldOverlay);
// Undo and redo: one history per kind of edit, kept by the server ({"type":"undo"}):
// the Design mode's keys step through the field's element edits, the other modes' through
// paint strokes (each panel has its own buttons).
window.addEventListener('keydown', (e) => {
  const key = e.key.toLowerCase();
  if (e.target instanceof HTMLInputElement || !(e.ctrlKey || e.metaKey) || (key !== 'z' && key !== 'y')) return;
  e.preventDefault();
  const history = state.mode === 'design' ? fieldDesign : paint;
  (key === 'y' || e.shiftKey ? history.redo : history.undo)();
});
// What the browser tests read besides `state`.
state.hooks = {
  wireframeCount: () => tools.wireframeCount(),
  drawnBox() {
    const box = new THREE.Box3();
    for (const o of ctx.drawn()) box.expandByObject(o);
    return [box.min.toArray(), box.max.toArray()];
  },
  // Points of the surface spread through its vertices (the bench's seeds).
  surfacePoints(count) {
    if (!surface) return [];
    const p = surface.geometry.attributes.position;
    return Array.from({ length: count }, (_, k) => {
      const v = Math.floor(((k + 0.5) / count) * p.count);
      return [p.getX(v), p.getY(v), p.getZ(v)].map((x) => Number(x.toFixed(6)));
    });
  },
  send: (message) => sendMessage(message),  // the bench times the server's loop alone
  // The shown model's InstancedMesh objects (name, asset, instance count), walked now.
  instancedMeshes() {
    const out = [];
    if (model) model.traverse((o) => { if (o.isInstancedMesh) out.push({ name: o.name, asset: o.userData.asset, count: o.count }); });
    return out;
  },
  // What the shown model draws, walked now: triangles, line segments (a turtle's
  // `segments "lines"`) and the vertices of both, each instance counted.
  drawnCounts() {
    const counts = { triangles: 0, segments: 0, vertices: 0 };
    if (model) model.traverse((o) => {
      if (!o.geometry || !(o.isMesh || o.isLineSegments)) return;
      const copies = o.isInstancedMesh ? o.count : 1;
      const g = o.geometry, corners = g.index ? g.index.count : g.attributes.position.count;
      counts.vertices += copies * g.attributes.position.count;
      if (o.isLineSegments) counts.segments += copies * corners / 2;
      else counts.triangles += copies * corners / 3;
    });
    return counts;
  },
  async glbDigest() {
    const hash = new Uint8Array(await crypto.subtle.digest('SHA-256', lastGlb));
    return Array.from(hash, (b) => b.toString(16).padStart(2, '0')).join('');
  },
  // The next model (or pieces) waits `ms` before it is read; the next pieces cannot be read.
  delayNextModel(ms) { testDelay = ms; },
  failNextPieces() { testFailPieces = true; },
  // A model shown as pieces: each piece's .glb digest, in piece order (null: a hole),
  // once every model that came is shown.
  async pieceDigests() {
    await modelsShown;
    return Promise.all(Array.from(pieces, async (p) => {
      if (!p) return null;
      const hash = new Uint8Array(await crypto.subtle.digest('SHA-256', p.glb));
      return Array.from(hash, (b) => b.toString(16).padStart(2, '0')).join('');
    }));
  },
  // An instance of the largest InstancedMesh that is the first thing drawn under its
  // centre: where it is on the canvas, and the number picking should send for it.
  visibleInstance() {
    let largest = null;
    if (model) model.traverse((o) => { if (o.isInstancedMesh && (!largest || o.count > largest.count)) largest = o; });
    if (!largest) return null;
    largest.geometry.computeBoundingBox();
    const centre = largest.geometry.boundingBox.getCenter(new THREE.Vector3()), m = new THREE.Matrix4();
    for (let k = 0; k < largest.count; ++k) {
      largest.getMatrixAt(k, m);
      const p = centre.clone().applyMatrix4(m).applyMatrix4(largest.matrixWorld);
      const screen = state.hooks.toScreen(p.toArray());
      const v = p.clone().project(camera);
      if (Math.abs(v.x) > 0.9 || Math.abs(v.y) > 0.9) continue;
      raycaster.setFromCamera(new THREE.Vector2(v.x, v.y), camera);
      const hit = raycaster.intersectObject(model, true)[0];
      if (hit && hit.object === largest && hit.instanceId === k)
        return { screen, instance: placedIds.get(largest)[k], asset: largest.userData.asset };
    }
    return null;
  },
  // A world point's position on the canvas, in CSS pixels from its top left corner.
  toScreen(p) {
    const v = new THREE.Vector3(...p).project(camera);
    return [(v.x + 1) / 2 * canvas.clientWidth, (1 - v.y) / 2 * canvas.clientHeight];
  },
};

// Pick, Seeds, Paint or Design: what a click or drag on the surface does.
for (const button of document.querySelectorAll('[data-mode]'))
  button.addEventListener('click', () => {
    state.mode = button.dataset.mode;
    for (const b of document.querySelectorAll('[data-mode]')) b.classList.toggle('on', b === button);
    for (const box of document.querySelectorAll('[data-for-mode]')) box.hidden = box.dataset.forMode !== state.mode;
    fieldDesign.modeChanged();
  });

// A number attribute gets a slider around its default and a field for exact values.
function numberRange(d) {
  if (d === 0) return [-1, 1];
  return d > 0 ? [0, 3 * d] : [3 * d, 0];
}

function buildInspector(info) {
  const box = $('attrs');
  const shape = JSON.stringify(info.attrs.map((a) => [a.name, a.type, a.default]));
  if (box.dataset.shape !== shape) {  // new attributes: rebuild; else only refresh values
    box.dataset.shape = shape;
    box.textContent = '';
    for (const a of info.attrs) {
      const row = document.createElement('div');
      row.className = 'attr';
      const label = document.createElement('label');
      label.textContent = a.name;
      row.append(label);
      if (a.type === 'number') {
        const field = document.createElement('input');
        field.type = 'number';
        field.step = 'any';
        field.dataset.attr = a.name;
        const slider = document.createElement('input');
        slider.type = 'range';
        const [lo, hi] = numberRange(Number(a.default));
        slider.min = lo; slider.max = hi; slider.step = (hi - lo) / 300;
        slider.dataset.attr = a.name;
        slider.dataset.kind = 'range';
        slider.addEventListener('input', () => { field.value = slider.value; send(field); });
        field.addEventListener('change', () => { slider.value = field.value; send(field); });
        label.append(field);
        row.append(slider);
      } else if (a.type === 'boolean') {
        const box2 = document.createElement('input');
        box2.type = 'checkbox';
        box2.dataset.attr = a.name;
        box2.addEventListener('change', () => send(box2));
        label.append(box2);
      } else {
        const field = document.createElement('input');
        field.type = 'text';
        field.dataset.attr = a.name;
        field.addEventListener('change', () => send(field));
        label.append(field);
      }
      box.append(row);
    }
  }
  for (const a of info.attrs)
    for (const input of box.querySelectorAll(`[data-attr="${CSS.escape(a.name)}"]`)) {
      if (input === document.activeElement) continue;
      if (String(a.value) !== String(a.default)) input.dataset.touched = '1';  // --set, or set before
      if (input.type === 'checkbox') input.checked = a.value === true || a.value === 'true';
      else input.value = a.value;
    }
}

$('seed').addEventListener('change', () => { state.seed = Math.max(0, Math.floor(Number($('seed').value))); send(); });
$('prev').addEventListener('click', () => { state.seed = Math.max(0, state.seed - 1); $('seed').value = state.seed; send(); });
$('next').addEventListener('click', () => { state.seed += 1; $('seed').value = state.seed; send(); });

// The session token came in the page's address (fgsg view prints it); the WebSocket
// carries it too (the server also set it as a cookie with the page).
const token = (new URLSearchParams(location.search).get('token') || '').replace(/[^0-9a-f]/g, '');
const ws = new WebSocket(`ws://${location.host}/` + (token ? `?token=${token}` : ''));
ws.binaryType = 'arraybuffer';
ws.onopen = () => setStatus('deriving', 'deriving');
ws.onclose = () => setStatus('disconnected: fgsg view stopped', 'error');
let surfaceHeader = null;  // a "surface" message whose .glb comes next
ws.onmessage = (event) => {
  if (typeof event.data !== 'string') {
    if (surfaceHeader) {
      surfaceHeader = null;
      return showSurface(event.data);
    }
    return piecesHeader ? showPieces(event.data) : showModel(event.data);
  }
  const m = JSON.parse(event.data);
  if (m.type === 'info') {
    state.info = m;
    state.seed = m.seed;
    $('seed').value = m.seed;
    $('file').textContent = m.file;
    document.title = `fgsg view - ${m.file}`;
    buildInspector(m);
    seeds.update(m.seeds, m.seedFile);
  } else if (m.type === 'progress') {
    setStatus('deriving', 'deriving');
  } else if (m.type === 'surface') {
    surfaceHeader = m;
    paint.textures(m.textures);
  } else if (m.type === 'written') {
    state.written.push(m.file);
    setStatus('wrote ' + m.file + ', deriving', 'deriving');
  } else if (m.type === 'field') {
    fieldOverlay.show(m);
    fieldDesign.update(m);
  } else if (m.type === 'picked') {
    showPicked(m);
  } else if (m.type === 'model') {
    header = m;
    parts = [];
    state.timing.announced = performance.now();
  } else if (m.type === 'pieces') {
    piecesHeader = m;
    parts = [];
    state.timing.announced = performance.now();
    if (m.sent.length === 0) showPieces(null);
  } else if (m.type === 'rejected') {  // a message of ours the server refused: nothing changed
    state.rejected = (state.rejected || 0) + 1;
    state.lastRejected = m.reason;
    steps.refused();
    fieldDesign.rejected();
    setStatus('refused: ' + m.reason, 'error');
  } else if (m.type === 'error') {
    state.errors += 1;
    $('diagnostics').textContent = m.diagnostics;
    setStatus(model ? 'error: the last good model is shown' : 'error', 'error');
  }
};
