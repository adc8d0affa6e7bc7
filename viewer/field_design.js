// Designing the grammar's field in the page (#49, item 3): in the Design mode the first
// field's design elements (the overlay's "elements", cli/view_field.h) are handles on the
// surface. A click on the surface adds an element of the chosen kind, dragging a handle
// moves it, Delete (or the Delete button) removes the selected one, the strength box sets
// its strength. Each edit is one {"type":"fieldElement"} message; the server rewrites that
// element's text in the grammar (cli/view_field_edit.h), compiles again and sends the new
// overlay and model. While a drag lasts, a move goes out whenever the last one's overlay
// has come back, so the streamlines follow the handle; its moves carry the drag's number,
// so that the server keeps them as one step. Undo and Redo (or Ctrl+Z, Ctrl+Shift+Z or
// Ctrl+Y in this mode, viewer.js) ask the server to write back the grammar's text before
// (after) the last edit ({"type":"undo", "history":"field"}, cli/view_field_history.h).
import * as THREE from 'three';

const kindColour = { regular: 0x9be37a, wedge: 0xff9d3c, trisector: 0x4aa8ff, node: 0xf06cf0, centre: 0xfff06a,
                     saddle: 0xff5a5a };

export function createFieldDesign(ctx, overlay) {
  const { scene, canvas, controls, state } = ctx;
  const $ = (id) => document.getElementById(id);
  const handles = new THREE.Group();
  handles.renderOrder = 14;
  scene.add(handles);
  let elements = [];   // the overlay's, as the grammar now has them
  let selected = -1;
  let drag = null;     // {index, position, sent, moved, id}
  let drags = 0;       // numbers the drags: the moves of one are one undo step
  let inFlight = false;  // an edit whose overlay has not come back yet
  let down = null;
  state.design = { elements: [], selected: -1, edits: 0, overlays: 0, undos: 0, redos: 0, timing: [] };

  function draw() {
    for (const m of [...handles.children]) {
      handles.remove(m);
      m.geometry.dispose();
      m.material.dispose();
    }
    const r = ctx.surfaceSize() * 0.012;
    elements.forEach((e, i) => {
      if (!e.position) return;
      const p = drag && drag.index === i ? drag.position : e.position;
      const handle = new THREE.Mesh(new THREE.BoxGeometry(2 * r, 2 * r, 2 * r),
        new THREE.MeshBasicMaterial({ color: i === selected ? 0xffffff : kindColour[e.kind] ?? 0xcccccc, depthTest: false }));
      handle.position.set(...p);
      handle.renderOrder = 14;
      handle.userData.element = i;
      handles.add(handle);
    });
    handles.visible = state.mode === 'design';
    state.design.elements = elements.map((e) => ({ ...e }));
    state.design.selected = selected;
    const e = elements[selected];
    $('design-selected').textContent = e ? `${e.kind} ${selected} at (${e.position.join(', ')})` : 'none selected';
    if (e && document.activeElement !== $('design-strength')) $('design-strength').value = e.strength;
    ctx.requestRender();
  }

  function edit(message) {
    inFlight = true;
    state.design.edits += 1;
    state.design.timing.push({ sent: performance.now() });
    ctx.send({ type: 'fieldElement', ...message });
  }

  function handleAt(e) {
    ctx.raycaster.setFromCamera(ctx.ndc(e), ctx.camera);
    const hit = ctx.raycaster.intersectObjects(handles.children, false)[0];
    return hit ? hit.object.userData.element : -1;
  }

  const point = (p) => p.toArray().map((v) => Number(v.toFixed(6)));

  canvas.addEventListener('pointerdown', (e) => {
    if (state.mode !== 'design' || e.button !== 0) return;
    down = [e.clientX, e.clientY];
    const i = handleAt(e);
    if (i < 0) return;
    selected = i;
    drag = { index: i, position: elements[i].position, sent: elements[i].position, moved: false, id: ++drags };
    controls.enabled = false;  // the drag moves the element, not the camera
    canvas.setPointerCapture(e.pointerId);
    draw();
  });
  canvas.addEventListener('pointermove', (e) => {
    if (!drag) return;
    const hit = ctx.surfaceHit(e);
    if (!hit) return;
    drag.position = point(hit.point);
    drag.moved = true;
    if (!inFlight) {
      drag.sent = drag.position;
      edit({ op: 'move', index: drag.index, position: drag.position, drag: drag.id });
    }
    draw();
  });
  canvas.addEventListener('pointerup', (e) => {
    if (state.mode !== 'design' || e.button !== 0) return;
    const click = down && Math.hypot(e.clientX - down[0], e.clientY - down[1]) <= 4;
    down = null;
    if (drag) {
      const { index, position, sent, moved, id } = drag;
      drag = null;
      controls.enabled = true;
      if (moved && position.some((v, k) => v !== sent[k])) edit({ op: 'move', index, position, drag: id });
      draw();
      return;
    }
    if (!click) return;  // the camera was dragged
    const hit = ctx.surfaceHit(e);
    if (!hit) return;
    const message = { op: 'add', kind: $('design-kind').value, position: point(hit.point) };
    const strength = Number($('design-strength').value);
    if (Number.isFinite(strength) && strength !== 1) message.strength = strength;
    selected = elements.length;
    edit(message);
  });

  function remove() {
    if (selected < 0 || selected >= elements.length) return;
    edit({ op: 'delete', index: selected });
    selected = -1;
    draw();
  }
  window.addEventListener('keydown', (e) => {
    if (state.mode === 'design' && (e.key === 'Delete' || e.key === 'Backspace') &&
        !(e.target instanceof HTMLInputElement)) remove();
  });
  $('design-delete').addEventListener('click', remove);
  // The element an undo brings back or takes away may not be the selected one's index.
  function step(type) {
    if (drag) return;  // the drag's own moves are still going out
    state.design[type === 'undo' ? 'undos' : 'redos'] += 1;
    selected = -1;
    ctx.send({ type, history: 'field' });
    draw();
  }
  const undo = () => step('undo');
  const redo = () => step('redo');
  $('design-undo').addEventListener('click', undo);
  $('design-redo').addEventListener('click', redo);
  $('design-strength').addEventListener('change', () => {
    const strength = Number($('design-strength').value);
    if (selected < 0 || selected >= elements.length || !Number.isFinite(strength)) return;
    edit({ op: 'strength', index: selected, strength });
  });

  return {
    undo,
    redo,
    // The Design mode shows the overlay (asked for once) and the handles.
    modeChanged() {
      if (state.mode === 'design') overlay.showIfHidden();
      draw();
    },
    // A new overlay ({"type":"field"}): its elements are the handles now.
    update(m) {
      inFlight = false;
      state.design.overlays += 1;
      const pending = state.design.timing.find((t) => !t.shown);
      if (pending) pending.shown = performance.now();
      elements = Array.isArray(m.elements) ? m.elements : [];
      if (selected >= elements.length) selected = -1;
      if (drag && drag.index >= elements.length) drag = null;
      if (drag && drag.moved && drag.position.some((v, k) => v !== drag.sent[k])) {  // the drag went on meanwhile
        drag.sent = drag.position;
        edit({ op: 'move', index: drag.index, position: drag.position, drag: drag.id });
      }
      draw();
    },
    // A refused edit brings no overlay: the next may go.
    rejected() { inFlight = false; },
  };
}
