// Camera and view (#49): Frame all (or the F key) fits the camera to the model and the
// surface; a double-click on either orbits around the point under the pointer from then
// on; Wireframe draws every mesh's edges. state.view is what the browser tests read.
import * as THREE from 'three';

export function createViewTools(ctx) {
  const { canvas, controls, camera, state } = ctx;
  const $ = (id) => document.getElementById(id);

  function record() {
    state.view = { target: controls.target.toArray(), position: camera.position.toArray(),
                   wireframe: $('wireframe').checked, orbitPoint: state.view ? state.view.orbitPoint : null };
  }
  controls.addEventListener('change', record);

  function frameAll() {
    const all = new THREE.Box3();
    for (const o of ctx.drawn()) all.expandByObject(o);
    if (all.isEmpty()) return;
    ctx.frameBox(all);
    controls.update();
    record();
    ctx.requestRender();
  }
  $('frame-all').addEventListener('click', frameAll);
  window.addEventListener('keydown', (e) => {
    if (e.key === 'f' && !(e.target instanceof HTMLInputElement) && !e.ctrlKey && !e.metaKey) frameAll();
  });

  // Orbit around the picked point: the target moves there, the camera keeps its place.
  canvas.addEventListener('dblclick', (e) => {
    ctx.raycaster.setFromCamera(ctx.ndc(e), camera);
    const hit = ctx.raycaster.intersectObjects(ctx.drawn(), true)[0];
    if (!hit) return;
    controls.target.copy(hit.point);
    controls.update();
    record();
    state.view.orbitPoint = hit.point.toArray();
    ctx.requestRender();
  });

  function applyWireframe() {
    const on = $('wireframe').checked;
    for (const o of ctx.drawn())
      o.traverse((m) => {
        if (!m.material) return;
        for (const mat of Array.isArray(m.material) ? m.material : [m.material]) mat.wireframe = on;
      });
    record();
    ctx.requestRender();
  }
  $('wireframe').addEventListener('change', applyWireframe);

  record();
  return {
    frameAll,
    // A new model or surface takes the current wireframe setting.
    refresh: applyWireframe,
    // How many of the drawn materials are wireframe, of how many (the tests' hook).
    wireframeCount() {
      let on = 0, all = 0;
      for (const o of ctx.drawn())
        o.traverse((m) => {
          if (!m.material) return;
          for (const mat of Array.isArray(m.material) ? m.material : [m.material]) { all += 1; on += mat.wireframe ? 1 : 0; }
        });
      return [on, all];
    },
  };
}
