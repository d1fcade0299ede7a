// Picking in JavaScript against the hex layers: per-hex bounding spheres first, then the 12
// triangles of each candidate hex, nearest first; faint hexes are picked only when no opaque hex
// is hit. A hit is then classified as a hex, a quad, or an edge when it lands near a side of a face.
import * as THREE from 'three';

/** Distance along the ray (origin o, direction d) to triangle i0 i1 i2 of `p`, or Infinity. */
export function rayHitsTriangle(o, d, p, i0, i1, i2) {
  const ax = p[3 * i0], ay = p[3 * i0 + 1], az = p[3 * i0 + 2];
  const e1x = p[3 * i1] - ax, e1y = p[3 * i1 + 1] - ay, e1z = p[3 * i1 + 2] - az;
  const e2x = p[3 * i2] - ax, e2y = p[3 * i2 + 1] - ay, e2z = p[3 * i2 + 2] - az;
  const px = d.y * e2z - d.z * e2y, py = d.z * e2x - d.x * e2z, pz = d.x * e2y - d.y * e2x;
  const det = e1x * px + e1y * py + e1z * pz;
  if (Math.abs(det) < 1e-12) return Infinity;
  const inv = 1 / det;
  const tx = o.x - ax, ty = o.y - ay, tz = o.z - az;
  const u = (tx * px + ty * py + tz * pz) * inv;
  if (u < 0 || u > 1) return Infinity;
  const qx = ty * e1z - tz * e1y, qy = tz * e1x - tx * e1z, qz = tx * e1y - ty * e1x;
  const v = (d.x * qx + d.y * qy + d.z * qz) * inv;
  if (v < 0 || u + v > 1) return Infinity;
  const t = (e2x * qx + e2y * qy + e2z * qz) * inv;
  return t > 0 ? t : Infinity;
}

// Hexes whose bounding sphere the ray meets, by where the ray enters the sphere.
function candidateSlots(layers, o, d) {
  const { centres, radii, hexCount } = layers;
  const cand = [];
  for (let k = 0; k < hexCount; k++) {
    const cx = centres[3 * k] - o.x, cy = centres[3 * k + 1] - o.y, cz = centres[3 * k + 2] - o.z;
    const along = cx * d.x + cy * d.y + cz * d.z;
    const off2 = cx * cx + cy * cy + cz * cz - along * along;
    if (off2 <= radii[k] * radii[k]) cand.push([along - radii[k], k]);
  }
  return cand.sort((a, b) => a[0] - b[0]);
}

/**
 * The hex, face and point where `ray` first meets the layers, preferring opaque hexes;
 * `visible(k)` can skip buffer slots (a slicing plane). Returns null when nothing is hit.
 */
export function pickRay(layers, ray, visible = () => true) {
  if (!layers.rb) return null;
  const o = ray.origin, d = ray.direction, rb = layers.rb;
  const colors = layers.solid.geometry.getAttribute('color').array;
  let best = null, bestFaint = null;
  for (const [enter, k] of candidateSlots(layers, o, d)) {
    if (best && enter > best.t) break;
    if (!visible(k)) continue;
    const isFaint = colors[4 * 24 * k + 3] < 128;
    for (let t = 12 * k; t < 12 * k + 12; t++) {
      const hitT = rayHitsTriangle(o, d, rb.positions, rb.indices[3 * t], rb.indices[3 * t + 1], rb.indices[3 * t + 2]);
      if (hitT === Infinity) continue;
      const hit = { t: hitT, k, tri: t };
      if (isFaint) {
        if (!bestFaint || hitT < bestFaint.t) bestFaint = hit;
      } else if (!best || hitT < best.t) best = hit;
    }
  }
  const h = best || bestFaint;
  if (!h) return null;
  const point = o.clone().addScaledVector(d, h.t);
  return { hex: rb.triangleHex[h.tri], face: rb.triangleFace[h.tri], faceIndex: h.tri >> 1, point };
}

/** The local edge of face f between its buffer corners q and q+1. */
export function faceSideEdge(tables, f, q) {
  const fc = tables.faceCorners, ec = tables.edgeCorners;
  const a = fc[4 * f + q], b = fc[4 * f + ((q + 1) & 3)];
  for (let e = 0; e < 12; e++) if ((ec[2 * e] === a && ec[2 * e + 1] === b) || (ec[2 * e] === b && ec[2 * e + 1] === a)) return e;
  return -1;
}

/**
 * Classifies a hit as { kind: 'hex' | 'quad' | 'edge', hex, face | edge }: mode 'hex', 'quad' or
 * 'edge' fixes the kind; 'auto' gives an edge when the hit is near a side of the face.
 */
export function classifyHit(layers, tables, hit, mode) {
  if (!hit) return null;
  if (mode === 'hex') return { kind: 'hex', hex: hit.hex };
  const corners = [0, 1, 2, 3].map((q) => layers.vertexAt(4 * hit.faceIndex + q));
  let nearest = -1, nearestD = Infinity, size = 0;
  for (let q = 0; q < 4; q++) {
    const seg = new THREE.Line3(corners[q], corners[(q + 1) & 3]);
    const d = seg.closestPointToPoint(hit.point, true, new THREE.Vector3()).distanceTo(hit.point);
    size += seg.distance() / 4;
    if (d < nearestD) (nearestD = d), (nearest = q);
  }
  if (mode === 'edge' || (mode === 'auto' && nearestD < 0.14 * size)) {
    return { kind: 'edge', hex: hit.hex, edge: faceSideEdge(tables, hit.face, nearest) };
  }
  return { kind: 'quad', hex: hit.hex, face: hit.face };
}

/** A point on face `face` of buffer slot k near its side along local edge `edge` (for tests and hints). */
export function pointNearEdge(layers, tables, k, face, edge) {
  for (let q = 0; q < 4; q++) {
    if (faceSideEdge(tables, face, q) !== edge) continue;
    const a = layers.vertexAt(24 * k + 4 * face + q), b = layers.vertexAt(24 * k + 4 * face + ((q + 1) & 3));
    const centre = layers.faceCentre(k, face);
    return a.add(b).multiplyScalar(0.5).lerp(centre, 0.06);
  }
  return null;
}
