// The hexes of a 3D view as three.js layers over the engine's render buffers (every hex shrunk
// toward its dual point, 24 vertices and 12 triangles per hex): solid, faint (hexes with alpha
// < 128, drawn translucent), fresh (created hexes drawn over the dimmed rest) and edge lines. Keeps
// per-hex bounding spheres for picking. Colours are rewritten without rebuilding geometry.
import * as THREE from 'three';

// Above this many hexes only the shell is drawn (hexes with a face on the boundary or on the cut of
// the slicing plane) plus the hexes the last step created: 47^3 draws 13k hexes, not 104k.
export const SHELL_MIN_HEXES = 20000;
export const EDGE_LINES_MAX_HEXES = 8000;

/** Per-hex bounding spheres (hex k of the buffer owns vertices 24k..24k+23) and id -> slot. */
export function indexHexes(rb) {
  const n = rb.triangleHex.length / 12;
  let cap = 0;
  for (let k = 0; k < n; k++) cap = Math.max(cap, rb.triangleHex[12 * k] + 1);
  const hexSlot = new Int32Array(cap).fill(-1);
  const centres = new Float32Array(3 * n), radii = new Float32Array(n);
  const p = rb.positions;
  for (let k = 0; k < n; k++) {
    hexSlot[rb.triangleHex[12 * k]] = k;
    let x = 0, y = 0, z = 0;
    for (let i = 72 * k, end = i + 72; i < end; i += 3) (x += p[i]), (y += p[i + 1]), (z += p[i + 2]);
    x /= 24, y /= 24, z /= 24;
    let r2 = 0;
    for (let i = 72 * k, end = i + 72; i < end; i += 3) {
      const dx = p[i] - x, dy = p[i + 1] - y, dz = p[i + 2] - z;
      r2 = Math.max(r2, dx * dx + dy * dy + dz * dz);
    }
    centres[3 * k] = x, centres[3 * k + 1] = y, centres[3 * k + 2] = z;
    radii[k] = Math.sqrt(r2);
  }
  return { hexSlot, centres, radii, hexCount: n };
}

/** Hex ids on the far side of the slicing plane (shell mode cuts by leaving them out). */
export function hiddenBySlice(mesh, slice) {
  const c = mesh.hexCenters();
  const n = c.length / 3;
  let lo = Infinity, hi = -Infinity;
  for (let h = 0; h < n; h++) {
    const v = c[3 * h + slice.axis]; // NaN for removed hexes: never hidden, never the range
    if (v < lo) lo = v;
    if (v > hi) hi = v;
  }
  const at = lo + slice.at * (hi - lo);
  const hidden = new Uint8Array(n);
  for (let h = 0; h < n; h++) hidden[h] = c[3 * h + slice.axis] > at ? 1 : 0;
  return hidden;
}

/** The layers of one view; add `layers.objects` to the scene. */
export function createHexLayers() {
  const solid = new THREE.Mesh(
    new THREE.BufferGeometry(),
    // Lambert and front faces: SwiftShader (software GL) spends its frame on fragments. A slice
    // turns on both sides so the cut hexes show their insides.
    new THREE.MeshLambertMaterial({ vertexColors: true, alphaTest: 0.5 }),
  );
  const faint = new THREE.Mesh(
    solid.geometry,
    new THREE.MeshLambertMaterial({ vertexColors: true, transparent: true, depthWrite: false }),
  );
  faint.renderOrder = 2;
  // The hexes the last step created, drawn again over everything while the rest is dimmed (x-ray):
  // a change deep inside is otherwise washed out by the faint layers in front of it. Front faces
  // only, so each (convex) hex draws as itself.
  const fresh = new THREE.Mesh(
    new THREE.BufferGeometry(),
    new THREE.MeshLambertMaterial({ vertexColors: true, transparent: true, depthWrite: false, depthTest: false }),
  );
  fresh.renderOrder = 2.5;
  fresh.visible = false;
  const edgeLines = new THREE.LineSegments(new THREE.BufferGeometry(), new THREE.LineBasicMaterial({ color: 0x44506a, transparent: true, opacity: 0.45 }));
  // Hexes held back from the other layers while they fade in (a step animation).
  const appear = new THREE.Mesh(
    new THREE.BufferGeometry(),
    new THREE.MeshLambertMaterial({ vertexColors: true, transparent: true, depthWrite: false, opacity: 0 }),
  );
  appear.renderOrder = 2.2;
  appear.visible = false;
  // Animation frames move vertices outside the bounding spheres three.js computed once.
  for (const m of [solid, faint, fresh, appear]) m.frustumCulled = false;
  // A geometry over the solid's attributes with only these slots' triangles.
  const subset = (slots) => {
    const src = layers.rb.indices;
    const idx = new Uint32Array(36 * slots.length);
    slots.forEach((k, i) => idx.set(src.subarray(36 * k, 36 * k + 36), 36 * i));
    const g = new THREE.BufferGeometry();
    for (const name of ['position', 'normal', 'color']) g.setAttribute(name, solid.geometry.getAttribute(name));
    g.setIndex(new THREE.BufferAttribute(idx, 1));
    return g;
  };
  const layers = {
    solid, faint, fresh, edgeLines, appear,
    objects: [solid, faint, fresh, edgeLines, appear],
    rb: null, hexSlot: null, centres: null, radii: null, hexCount: 0, hasFaint: false,

    /** Takes new render buffers (edge lines when `edges` and the buffers have them). */
    setBuffers(rb, edges) {
      layers.rb = rb;
      const g = new THREE.BufferGeometry();
      g.setAttribute('position', new THREE.BufferAttribute(rb.positions, 3));
      g.setAttribute('normal', new THREE.BufferAttribute(rb.normals, 3));
      g.setAttribute('color', new THREE.BufferAttribute(new Uint8Array((rb.positions.length / 3) * 4), 4, true));
      g.setIndex(new THREE.BufferAttribute(rb.indices, 1));
      solid.geometry.dispose();
      solid.geometry = g;
      faint.geometry = g;
      edgeLines.geometry.dispose();
      edgeLines.geometry = new THREE.BufferGeometry();
      if (edges) edgeLines.geometry.setAttribute('position', new THREE.BufferAttribute(rb.edgePositions, 3));
      edgeLines.visible = edges;
      Object.assign(layers, indexHexes(rb));
    },

    /** Writes one RGBA per hex (`colorOf(hexId)`, 0..255) into the colour attribute. */
    paint(colorOf) {
      const attr = solid.geometry.getAttribute('color');
      // One RGBA word per vertex: fill 24 words per hex.
      const words = new Uint32Array(attr.array.buffer, attr.array.byteOffset, attr.array.length / 4);
      const th = layers.rb.triangleHex;
      const word = new Uint32Array(1), bytes = new Uint8Array(word.buffer);
      layers.hasFaint = false;
      for (let k = 0; k < layers.hexCount; k++) {
        const c = colorOf(th[12 * k]);
        if (c[3] < 128) layers.hasFaint = true;
        bytes.set(c);
        words.fill(word[0], 24 * k, 24 * k + 24);
      }
      attr.needsUpdate = true;
      faint.visible = layers.hasFaint;
    },

    /** Draws `created` hexes over everything; shares the solid's attributes, only the index differs. */
    showFresh(created) {
      const ks = (created || []).map(layers.slotOf).filter((k) => k >= 0);
      fresh.visible = ks.length > 0;
      if (fresh.visible) fresh.geometry = subset(ks);
    },

    /**
     * Takes these hex ids out of the solid and faint layers and draws them in the `appear` layer,
     * whose opacity an animation raises; `holdBack(null)` puts them back.
     */
    holdBack(ids) {
      const held = new Set((ids || []).map(layers.slotOf).filter((k) => k >= 0));
      appear.visible = held.size > 0;
      if (!held.size) {
        solid.geometry.setIndex(new THREE.BufferAttribute(layers.rb.indices, 1));
        return;
      }
      appear.geometry = subset([...held]);
      const rest = [...Array(layers.hexCount).keys()].filter((k) => !held.has(k));
      solid.geometry.setIndex(subset(rest).index);
    },

    /**
     * Draws from `array` instead of the buffers' positions (an animation writes its frames there and
     * sets the returned attribute's needsUpdate); null restores the buffers' own.
     */
    setDrawnPositions(array) {
      const attr = new THREE.BufferAttribute(array ?? layers.rb.positions, 3);
      for (const g of new Set([solid.geometry, fresh.geometry, appear.geometry])) if (g.getAttribute('position')) g.setAttribute('position', attr);
      return attr;
    },

    /** The buffer slot of a hex id, or -1 when it is not drawn. */
    slotOf(h) {
      return layers.hexSlot && h >= 0 && h < layers.hexSlot.length ? layers.hexSlot[h] : -1;
    },
    vertexAt(i) {
      const p = layers.rb.positions;
      return new THREE.Vector3(p[3 * i], p[3 * i + 1], p[3 * i + 2]);
    },
    /** The drawn centre of buffer slot k. */
    centreOf(k) {
      const c = layers.centres;
      return new THREE.Vector3(c[3 * k], c[3 * k + 1], c[3 * k + 2]);
    },
    /** The centre of face f of buffer slot k. */
    faceCentre(k, face) {
      const p = new THREE.Vector3();
      for (let q = 0; q < 4; q++) p.add(layers.vertexAt(24 * k + 4 * face + q));
      return p.multiplyScalar(0.25);
    },
    drawnHexIds() {
      const th = layers.rb.triangleHex;
      const ids = new Int32Array(layers.hexCount);
      for (let k = 0; k < ids.length; k++) ids[k] = th[12 * k];
      return ids;
    },
  };
  return layers;
}
