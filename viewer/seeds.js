// Seeds of on-mesh marching placed on the surface (#49): in the Seeds mode a click on the
// surface adds one, dragging a seed moves it, shift-dragging from it sets its heading, and
// Delete (or the Remove button) removes the selected one. Every change sends the whole
// list ({"type":"seeds"}); the server writes the seed file and derives again, and its
// info message brings the list back (the file's, if another page changed it).
import * as THREE from 'three';

// Files stay readable: a millionth of a unit is far below any march step.
const round = (v) => Number(v.toFixed(6));

export function createSeeds(ctx) {
  const { scene, canvas, controls, state } = ctx;
  const markers = new THREE.Group();
  scene.add(markers);
  let seeds = [];        // [x,y,z] or [x,y,z,dx,dy,dz], as the server has them
  let selected = -1;
  let drag = null;       // {index, heading, moved}
  let down = null;

  function radius() { return ctx.surfaceSize() * 0.012; }

  function draw() {
    for (const m of [...markers.children]) {
      markers.remove(m);
      if (m.isMesh) m.geometry.dispose();  // an ArrowHelper's geometry is shared by all arrows
    }
    const r = radius();
    seeds.forEach((s, i) => {
      const ball = new THREE.Mesh(new THREE.SphereGeometry(r, 16, 12),
        new THREE.MeshBasicMaterial({ color: i === selected ? 0xffd54a : 0xff5a36, depthTest: false }));
      ball.position.set(s[0], s[1], s[2]);
      ball.renderOrder = 10;
      ball.userData.seed = i;
      markers.add(ball);
      if (s.length === 6) {
        const dir = new THREE.Vector3(s[3], s[4], s[5]).normalize();
        const arrow = new THREE.ArrowHelper(dir, ball.position, r * 6, 0xffd54a, r * 2, r * 1.2);
        arrow.traverse((o) => { if (o.material) o.material.depthTest = false; o.renderOrder = 10; });
        markers.add(arrow);
      }
    });
    state.seeds = seeds.map((s) => [...s]);
    state.selectedSeed = selected;
    ctx.requestRender();
  }

  function send() {
    ctx.send({ type: 'seeds', seeds });
    draw();
  }

  function markerAt(e) {
    ctx.raycaster.setFromCamera(ctx.ndc(e), ctx.camera);
    const hit = ctx.raycaster.intersectObjects(markers.children.filter((m) => m.isMesh), false)[0];
    return hit ? hit.object.userData.seed : -1;
  }

  canvas.addEventListener('pointerdown', (e) => {
    if (state.mode !== 'seeds' || e.button !== 0) return;
    down = [e.clientX, e.clientY];
    const i = markerAt(e);
    if (i < 0) return;
    selected = i;
    drag = { index: i, heading: e.shiftKey, moved: false };
    controls.enabled = false;  // the drag moves the seed, not the camera
    canvas.setPointerCapture(e.pointerId);
    draw();
  });
  canvas.addEventListener('pointermove', (e) => {
    if (!drag) return;
    const hit = ctx.surfaceHit(e);
    if (!hit) return;
    const s = seeds[drag.index];
    if (drag.heading) {
      const d = hit.point.clone().sub(new THREE.Vector3(s[0], s[1], s[2]));
      if (d.length() === 0) return;
      d.normalize();
      seeds[drag.index] = [s[0], s[1], s[2], round(d.x), round(d.y), round(d.z)];
    } else {
      seeds[drag.index] = [round(hit.point.x), round(hit.point.y), round(hit.point.z), ...s.slice(3)];
    }
    drag.moved = true;
    draw();
  });
  canvas.addEventListener('pointerup', (e) => {
    if (state.mode !== 'seeds' || e.button !== 0) return;
    const click = down && Math.hypot(e.clientX - down[0], e.clientY - down[1]) <= 4;
    down = null;
    if (drag) {
      const moved = drag.moved;
      drag = null;
      controls.enabled = true;
      if (moved) send();
      return;
    }
    if (!click) return;  // the camera was dragged
    const hit = ctx.surfaceHit(e);
    if (!hit) return;
    seeds.push([round(hit.point.x), round(hit.point.y), round(hit.point.z)]);
    selected = seeds.length - 1;
    send();
  });

  function remove() {
    if (selected < 0 || selected >= seeds.length) return;
    seeds.splice(selected, 1);
    selected = -1;
    send();
  }
  window.addEventListener('keydown', (e) => {
    if (state.mode === 'seeds' && (e.key === 'Delete' || e.key === 'Backspace') &&
        !(e.target instanceof HTMLInputElement)) remove();
  });
  document.getElementById('seed-remove').addEventListener('click', remove);

  return {
    // The server's list (info): taken unless a drag is under way.
    update(list, file) {
      document.getElementById('seed-file').textContent = file || '';
      if (drag || !Array.isArray(list)) return;
      seeds = list.map((s) => [...s]);
      if (selected >= seeds.length) selected = -1;
      draw();
    },
    redraw: draw,
  };
}
