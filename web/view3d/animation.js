// Motion in a 3D view: a step's hexes move from where they were drawn before to where they are
// now while the created ones fade in, and removed hexes show as red ghosts taken from the previous
// buffers. Frames are requested only while something moves; prefers-reduced-motion shows the end.
import * as THREE from 'three';
import { clearGroup } from './overlays.js';
import { tween, STEP_MS, prefersReducedMotion } from '../motion.js';

export { prefersReducedMotion };

// Hex id -> buffer slot of a render buffer (12 triangles per hex).
function slotsById(rb) {
  const th = rb.triangleHex;
  const slot = new Map();
  for (let k = 0; k < th.length / 12; k++) slot.set(th[12 * k], k);
  return slot;
}

/**
 * Animates the step from `prevRb` to the layers' buffers: hexes drawn in both move from their old
 * 24 vertices to their new ones, hexes in `created` fade in. `requestRender` draws a frame,
 * `onDone` runs at the end. Returns { cancel() } (jumps to the end), or null when nothing moves.
 */
export function animateStep(layers, prevRb, { created = [], requestRender, onDone, ms = STEP_MS }) {
  if (!prevRb || !layers.rb || prefersReducedMotion()) return null;
  const end = layers.rb.positions, start = new Float32Array(end);
  const before = slotsById(prevRb), th = layers.rb.triangleHex;
  let moves = false;
  for (let k = 0; k < layers.hexCount; k++) {
    const old = before.get(th[12 * k]);
    if (old === undefined) continue;
    start.set(prevRb.positions.subarray(72 * old, 72 * old + 72), 72 * k);
    for (let i = 72 * k; i < 72 * k + 72 && !moves; i++) moves = start[i] !== end[i];
  }
  const fading = created.filter((h) => layers.slotOf(h) >= 0);
  if (!moves && !fading.length) return null;
  const cur = new Float32Array(start);
  const attr = layers.setDrawnPositions(cur);
  layers.holdBack(fading);
  // Edge lines stay where the hexes end, and the x-ray layer would show created hexes at once.
  const shown = { edges: layers.edgeLines.visible, fresh: layers.fresh.visible };
  layers.edgeLines.visible = layers.fresh.visible = false;
  return tween(ms, (t) => {
    for (let i = 0; i < end.length; i++) cur[i] = start[i] + (end[i] - start[i]) * t;
    attr.needsUpdate = true;
    layers.appear.material.opacity = t;
    requestRender();
  }, () => {
    layers.setDrawnPositions(null);
    layers.holdBack(null);
    layers.edgeLines.visible = shown.edges;
    layers.fresh.visible = shown.fresh;
    requestRender();
    onDone?.();
  });
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
  if (prefersReducedMotion()) {
    mat.opacity = to;
    if (to <= 0) clearGroup(group);
    requestRender();
    return group.children.length ? m : null;
  }
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
