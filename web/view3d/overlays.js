// What a 3D view draws over the hexes: the marks of the selected (or hovered) quad or edge, and the
// dual overlay of TK03 Fig. 1 (sheet mid-surfaces, chords through dual points, dual vertices).
import * as THREE from 'three';
import { sheetColor, chordColor } from '../colors.js';

export const ACCENT = new THREE.Color('#ff7a00');
export const HOVER = '#1f6feb';

function rgb(css) {
  return new THREE.Color(css);
}

/** Removes and disposes every child of a group. */
export function clearGroup(group) {
  for (const child of [...group.children]) {
    child.geometry?.dispose();
    child.material?.dispose();
    group.remove(child);
  }
}

function cornerPosition(layers, tables, k, corner) {
  const fc = tables.faceCorners;
  for (let f = 0; f < 6; f++) for (let q = 0; q < 4; q++) if (fc[4 * f + q] === corner) return layers.vertexAt(24 * k + 4 * f + q);
  return null;
}

function markQuad(group, layers, k, face, color, opacity) {
  const base = 24 * k + 4 * face;
  const centre = new THREE.Vector3();
  const pts = [0, 1, 2, 3].map((q) => layers.vertexAt(base + q));
  pts.forEach((p) => centre.add(p));
  centre.multiplyScalar(0.25);
  // Slightly inside the face outline and lifted off it so it never z-fights.
  const n = new THREE.Vector3(...layers.rb.normals.slice(3 * base, 3 * base + 3));
  const size = pts[0].distanceTo(pts[2]);
  // A frame, not a filled quad: what a step puts at the quad (a pillow's hexes) stays visible.
  const outer = pts.map((p) => p.clone().lerp(centre, 0.06).addScaledVector(n, 0.01 * size));
  const inner = pts.map((p) => p.clone().lerp(centre, 0.3).addScaledVector(n, 0.01 * size));
  const tri = [];
  for (let q = 0; q < 4; q++) {
    const r = (q + 1) & 3;
    tri.push(outer[q], outer[r], inner[r], outer[q], inner[r], inner[q]);
  }
  const g = new THREE.BufferGeometry().setFromPoints(tri);
  const m = new THREE.Mesh(g, new THREE.MeshBasicMaterial({ color, side: THREE.DoubleSide, transparent: opacity < 1, opacity, depthTest: false }));
  m.renderOrder = 5;
  group.add(m);
}

function markEdge(group, layers, tables, k, edge, color) {
  const ec = tables.edgeCorners;
  const a = cornerPosition(layers, tables, k, ec[2 * edge]), b = cornerPosition(layers, tables, k, ec[2 * edge + 1]);
  const len = a.distanceTo(b);
  const g = new THREE.CylinderGeometry(0.035 * len, 0.035 * len, len, 8);
  const m = new THREE.Mesh(g, new THREE.MeshBasicMaterial({ color, depthTest: false }));
  m.renderOrder = 6;
  m.position.copy(a).add(b).multiplyScalar(0.5);
  m.quaternion.setFromUnitVectors(new THREE.Vector3(0, 1, 0), b.clone().sub(a).normalize());
  group.add(m);
}

/**
 * Redraws `group` with marks: `items` are [pick, color, opacity] with pick a { kind, hex, face | edge };
 * hexes and kinds without a mark (hex, sheet, chord) are skipped.
 */
export function drawMarks(group, layers, tables, items) {
  clearGroup(group);
  if (!layers.rb) return;
  for (const [s, color, opacity, wholeHex = false] of items) {
    if (!s) continue;
    const k = layers.slotOf(s.hex);
    if (k < 0) continue;
    if (s.kind === 'hex' && wholeHex) for (let f = 0; f < 6; f++) markQuad(group, layers, k, f, color, opacity);
    if (s.kind === 'quad') markQuad(group, layers, k, s.face, color, opacity);
    if (s.kind === 'edge') markEdge(group, layers, tables, k, s.edge, color);
  }
}

/** Fills `group` with the dual overlay `o` (mesh.dualOverlay()); clipped by `planes`. */
export function drawDualOverlay(group, o, planes = []) {
  clearGroup(group);
  const nTri = o.sheetTriangle.length;
  const sheetColors = new Float32Array(o.sheetPositions.length);
  const cache = new Map();
  for (let t = 0; t < nTri; t += 2) {
    const id = o.sheetTriangle[t];
    if (!cache.has(id)) cache.set(id, rgb(sheetColor(id)));
    const c = cache.get(id);
    const quad = t >> 1;
    for (let q = 0; q < 4; q++) sheetColors.set([c.r, c.g, c.b], 3 * (4 * quad + q));
  }
  const sg = new THREE.BufferGeometry();
  sg.setAttribute('position', new THREE.BufferAttribute(o.sheetPositions, 3));
  sg.setAttribute('color', new THREE.BufferAttribute(sheetColors, 3));
  sg.setIndex(new THREE.BufferAttribute(o.sheetIndices, 1));
  const sheets = new THREE.Mesh(sg, new THREE.MeshBasicMaterial({ vertexColors: true, transparent: true, opacity: 0.28, depthWrite: false, side: THREE.DoubleSide }));
  sheets.renderOrder = 3;
  const chordColors = new Float32Array(o.chordPositions.length);
  for (let s = 0; s < o.chordSegment.length; s++) {
    const c = rgb(chordColor(o.chordSegment[s]));
    chordColors.set([c.r, c.g, c.b, c.r, c.g, c.b], 6 * s);
  }
  const cg = new THREE.BufferGeometry();
  cg.setAttribute('position', new THREE.BufferAttribute(o.chordPositions, 3));
  cg.setAttribute('color', new THREE.BufferAttribute(chordColors, 3));
  const chords = new THREE.LineSegments(cg, new THREE.LineBasicMaterial({ vertexColors: true }));
  chords.renderOrder = 4;
  const dg = new THREE.BufferGeometry();
  dg.setAttribute('position', new THREE.BufferAttribute(o.dualVertices, 3));
  const dots = new THREE.Points(dg, new THREE.PointsMaterial({ color: 0x111111, size: 5, sizeAttenuation: false }));
  dots.renderOrder = 4;
  group.add(sheets, chords, dots);
  for (const obj of group.children) obj.material.clippingPlanes = planes;
}

// Colours of singular edges by kind and valence (the panel's legend uses the same).
export const SINGULAR_COLORS = {
  interior: { 1: '#8c564b', 2: '#8c564b', 3: '#1f6feb', 5: '#d62728', other: '#9467bd' },
  boundary: { 1: '#ff7f0e', 3: '#17becf', other: '#e377c2' },
};
export function singularColor(edge) {
  const t = edge.boundary ? SINGULAR_COLORS.boundary : SINGULAR_COLORS.interior;
  return t[edge.valence] ?? t.other;
}

/**
 * Fills `group` with the singular edges of `sing` (mesh.singularities()) as tubes, one instance per
 * edge, coloured by kind and valence; `xyz` holds the two ends of each edge (mesh.vertexPositions).
 * Drawn over the hexes (no depth test), as HexaLab shows the singularity graph.
 */
export function drawSingularEdges(group, sing, xyz, planes = []) {
  clearGroup(group);
  const n = sing.edges.length;
  if (!n) return;
  let total = 0;
  for (let i = 0; i < n; i++) total += Math.hypot(xyz[6 * i + 3] - xyz[6 * i], xyz[6 * i + 4] - xyz[6 * i + 1], xyz[6 * i + 5] - xyz[6 * i + 2]);
  const radius = 0.05 * (total / n);
  const tube = new THREE.CylinderGeometry(radius, radius, 1, 6);
  const mesh = new THREE.InstancedMesh(tube, new THREE.MeshBasicMaterial({ depthTest: false, transparent: true, opacity: 0.95 }), n);
  const a = new THREE.Vector3(), b = new THREE.Vector3(), up = new THREE.Vector3(0, 1, 0);
  const m = new THREE.Matrix4(), q = new THREE.Quaternion(), s = new THREE.Vector3();
  for (let i = 0; i < n; i++) {
    a.fromArray(xyz, 6 * i);
    b.fromArray(xyz, 6 * i + 3);
    const len = a.distanceTo(b);
    q.setFromUnitVectors(up, b.clone().sub(a).normalize());
    s.set(1, len, 1);
    m.compose(a.clone().add(b).multiplyScalar(0.5), q, s);
    mesh.setMatrixAt(i, m);
    mesh.setColorAt(i, rgb(singularColor(sing.edges[i])));
  }
  mesh.renderOrder = 7;
  mesh.material.clippingPlanes = planes;
  group.add(mesh);
}
