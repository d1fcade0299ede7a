// Motion in a 3D view: removed hexes as red ghosts taken from the previous buffers, fading to
// faint. Frames are requested only while something moves.
import * as THREE from 'three';
import { clearGroup } from './overlays.js';

/** Whether the user asked for less motion (then every change is shown at once). */
export function prefersReducedMotion() {
  return typeof matchMedia === 'function' && matchMedia('(prefers-reduced-motion: reduce)').matches;
}

// The triangles of the `removed` hexes in the previous buffers, as a flat position array.
function removedTriangles(prevRb, removed) {
  const want = new Set(removed);
  const pos = [];
  const th = prevRb.triangleHex;
  for (let k = 0; k < th.length / 12; k++) {
    if (!want.has(th[12 * k])) continue;
    for (let t = 12 * k; t < 12 * k + 12; t++)
      for (let j = 0; j < 3; j++) {
        const i = prevRb.indices[3 * t + j];
        pos.push(prevRb.positions[3 * i], prevRb.positions[3 * i + 1], prevRb.positions[3 * i + 2]);
      }
  }
  return new Float32Array(pos);
}

/**
 * Shows the `removed` hexes of the previous buffers in `group` as red ghosts whose opacity goes
 * from `from` to `to` over `ms` (the explorer keeps them faint; a step animation fades them out).
 */
export function showGhosts(group, prevRb, removed, requestRender, { from = 0.6, to = 0.15, ms = 1200 } = {}) {
  clearGroup(group);
  if (!prevRb || !removed || removed.length === 0) return null;
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.BufferAttribute(removedTriangles(prevRb, removed), 3));
  const mat = new THREE.MeshBasicMaterial({ color: 0xd0342c, transparent: true, opacity: from, depthWrite: false, side: THREE.DoubleSide });
  const m = new THREE.Mesh(g, mat);
  m.renderOrder = 3;
  group.add(m);
  const start = performance.now();
  const fade = () => {
    const f = Math.min(1, (performance.now() - start) / ms);
    mat.opacity = from + (to - from) * f;
    requestRender();
    if (f < 1 && group.children.includes(m)) requestAnimationFrame(fade);
  };
  requestAnimationFrame(fade);
  return m;
}
