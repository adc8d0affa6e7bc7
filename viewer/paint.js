// Painting the grammar's textures on the surface (#49): in the Paint mode a drag on the
// surface is a brush stroke. Its dabs (surface points) go to the server in pieces
// ({"type":"paint"}), which paints the texels within the radius in the texture's own UV
// space, writes the PNG and derives again; Undo and Redo (or Ctrl+Z, Ctrl+Shift+Z or
// Ctrl+Y outside the Design mode) step through whole strokes.
import * as THREE from 'three';

const round = (v) => Number(v.toFixed(6));
const kMaxDabs = 256;  // per message (cli/view_message.h)

export function createPaint(ctx) {
  const { scene, canvas, controls, state } = ctx;
  const $ = (id) => document.getElementById(id);
  let stroke = 0;
  let dabs = null;       // the stroke's dabs not sent yet; null: not painting
  let last = null;       // the last dab, to space them
  let timer = null;

  // The brush's outline where the pointer is on the surface.
  const ring = new THREE.Mesh(new THREE.RingGeometry(0.92, 1, 48),
    new THREE.MeshBasicMaterial({ color: 0x7ee0ff, side: THREE.DoubleSide, depthTest: false }));
  ring.visible = false;
  ring.renderOrder = 11;
  scene.add(ring);

  function settings() {
    return {
      texture: $('paint-texture').value,
      radius: Number($('paint-radius').value) * ctx.surfaceSize(),
      strength: Number($('paint-strength').value),
      value: Number($('paint-value').value),
      erase: $('paint-erase').checked,
    };
  }

  function flush() {
    timer = null;
    if (!dabs || dabs.length === 0) return;
    const s = settings();
    while (dabs.length) {
      const piece = dabs.splice(0, kMaxDabs);
      ctx.send({ type: 'paint', texture: s.texture, stroke, dabs: piece, radius: s.radius, strength: s.strength,
                 value: s.value, erase: s.erase });
    }
  }

  function addDab(point) {
    const r = settings().radius;
    if (last && last.distanceTo(point) < r * 0.3) return;  // dabs a third of the radius apart
    last = point.clone();
    dabs.push([round(point.x), round(point.y), round(point.z)]);
    if (!timer) timer = setTimeout(flush, 40);  // a piece per 40 ms while the brush moves
  }

  function showRing(hit) {
    ring.visible = !!hit && state.mode === 'paint';
    if (!ring.visible) return ctx.requestRender();
    const r = settings().radius;
    ring.scale.setScalar(r);
    ring.position.copy(hit.point);
    const n = hit.face ? hit.face.normal.clone().transformDirection(hit.object.matrixWorld) : new THREE.Vector3(0, 0, 1);
    ring.quaternion.setFromUnitVectors(new THREE.Vector3(0, 0, 1), n);
    ctx.requestRender();
  }

  canvas.addEventListener('pointerdown', (e) => {
    if (state.mode !== 'paint' || e.button !== 0 || !$('paint-texture').value) return;
    const hit = ctx.surfaceHit(e);
    if (!hit) return;  // off the surface: the camera turns
    controls.enabled = false;
    canvas.setPointerCapture(e.pointerId);
    stroke += 1;
    dabs = [];
    last = null;
    addDab(hit.point);
  });
  canvas.addEventListener('pointermove', (e) => {
    if (state.mode !== 'paint') return;
    const hit = ctx.surfaceHit(e);
    showRing(hit);
    if (dabs && hit) addDab(hit.point);
  });
  canvas.addEventListener('pointerup', () => {
    if (!dabs) return;
    clearTimeout(timer);
    flush();
    dabs = null;
    controls.enabled = true;
  });

  // The server keeps the strokes (cli/view_paint.h); the keys are viewer.js's, by mode.
  const undo = () => ctx.send({ type: 'undo' });
  const redo = () => ctx.send({ type: 'redo' });
  $('paint-undo').addEventListener('click', undo);
  $('paint-redo').addEventListener('click', redo);

  return {
    undo,
    redo,
    // The surface's textures (its "surface" message): the paintable ones to choose from.
    textures(list) {
      const select = $('paint-texture');
      const chosen = select.value;
      select.textContent = '';
      for (const t of list) {
        const option = document.createElement('option');
        option.value = t.name;
        option.textContent = t.why ? `${t.name} (${t.why})` : `${t.name} (${t.file}, ${t.width}x${t.height})`;
        option.disabled = !!t.why;
        select.append(option);
      }
      const usable = list.filter((t) => !t.why).map((t) => t.name);
      select.value = usable.includes(chosen) ? chosen : (usable[0] || '');
      state.textures = list;
    },
  };
}
