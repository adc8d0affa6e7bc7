// The field overlay (#49, item 3): the Field button asks the server for what `fgsg field`
// shows of the grammar's first field ({"type":"field"}, cli/view_field.h): its
// streamlines drawn as lines over the surface and its singularities as markers coloured
// by kind (wedge orange, trisector blue, others white). The server sends it again after
// each recompile while it is asked for; the button shows or hides it.
import * as THREE from 'three';

const kindColour = { wedge: 0xff9d3c, trisector: 0x4aa8ff };

export function createFieldOverlay(ctx) {
  const { scene, state } = ctx;
  const $ = (id) => document.getElementById(id);
  const group = new THREE.Group();
  group.renderOrder = 12;
  group.visible = false;
  scene.add(group);
  let asked = false;
  state.field = { shown: false, lines: 0, singularities: [], error: null };

  function clear() {
    for (const o of [...group.children]) {
      group.remove(o);
      o.geometry.dispose();
      o.material.dispose();
    }
  }

  function toggle() {
    group.visible = !group.visible;
    $('field-overlay').classList.toggle('on', group.visible);
    state.field.shown = group.visible;
    if (group.visible && !asked) {
      asked = true;
      ctx.send({ type: 'field' });
    }
    ctx.requestRender();
  }
  $('field-overlay').addEventListener('click', toggle);

  return {
    // The Design mode (field_design.js) edits what the overlay shows.
    showIfHidden() { if (!group.visible) toggle(); },
    // The server's {"type":"field"} message.
    show(m) {
      clear();
      state.field = { shown: group.visible, lines: 0, drawn: 0, singularities: [], error: m.error || null, name: m.name,
                      truncated: !!m.truncated };
      if (m.error) return ctx.requestRender();
      const segments = [];
      for (const line of m.lines)
        for (let k = 0; k + 5 < line.length; k += 3) segments.push(...line.slice(k, k + 6));
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute('position', new THREE.Float32BufferAttribute(segments, 3));
      group.add(new THREE.LineSegments(geometry, new THREE.LineBasicMaterial({ color: 0x7ee0ff })));
      const size = ctx.surfaceSize() * 0.015;
      for (const s of m.singularities) {
        const marker = new THREE.Mesh(new THREE.OctahedronGeometry(size),
          new THREE.MeshBasicMaterial({ color: kindColour[s.kind] ?? 0xffffff, depthTest: false }));
        marker.position.set(...s.position);
        marker.renderOrder = 13;
        group.add(marker);
      }
      state.field.lines = m.lines.length;
      state.field.drawn = group.children.length;  // the lines, then a marker per singularity
      state.field.singularities = m.singularities;
      ctx.requestRender();
    },
  };
}
