// Per-hex geometry for the tutorial figures, read from the engine's lossless .hxd text: corners,
// gluings, and a dual point per hex (its centroid pulled toward its distinct glued neighbours), so
// degenerate hexes that share all 8 vertices (a pillow's X and Y) are drawn apart.

// VTK hex corner order: faces as 2*axis+side (docs/oplog.md), each as a corner cycle.
export const HEX_FACES = [
  [0, 3, 7, 4], [1, 2, 6, 5], // x = 0, x = 1
  [0, 1, 5, 4], [3, 2, 6, 7], // y = 0, y = 1
  [0, 1, 2, 3], [4, 5, 6, 7], // z = 0, z = 1
];
export const HEX_EDGES = [
  [0, 1], [3, 2], [4, 5], [7, 6], [0, 3], [1, 2], [4, 7], [5, 6], [0, 4], [1, 5], [3, 7], [2, 6],
];

/** Parses `hexdual 1` text; `ids` maps dense index -> engine hex id (live ids ascending). */
export function parseHxd(text) {
  const tok = text.split(/\s+/).filter(Boolean);
  let i = 0;
  const expect = (word) => {
    if (tok[i++] !== word) throw new Error(`hxd: expected '${word}' at token ${i - 1}`);
  };
  expect('hexdual');
  i++; // version
  expect('vertices');
  const nv = Number(tok[i++]);
  const vertices = new Float64Array(3 * nv);
  for (let k = 0; k < 3 * nv; k++) vertices[k] = Number(tok[i++]);
  expect('hexes');
  const nh = Number(tok[i++]);
  const corners = new Int32Array(8 * nh);
  for (let k = 0; k < 8 * nh; k++) corners[k] = Number(tok[i++]);
  expect('gluings');
  const ng = Number(tok[i++]);
  const gluings = [];
  for (let k = 0; k < ng; k++) {
    gluings.push({ a: Number(tok[i]), fa: Number(tok[i + 1]), b: Number(tok[i + 2]), fb: Number(tok[i + 3]) });
    i += 5;
  }
  return { vertices, corners, gluings, hexCount: nh };
}

/**
 * Builds the per-hex model: positions of corners, neighbours per face, dual points. `liveIds`
 * (ascending live hex ids) saves asking the engine for them.
 */
export function hexModel(mesh, liveIds = null) {
  const { vertices, corners, gluings, hexCount } = parseHxd(new TextDecoder().decode(mesh.save('hxd')));
  const ids = liveIds ?? liveHexIds(mesh, hexCount);
  if (ids.length !== hexCount) throw new Error(`figure: ${ids.length} live hexes but ${hexCount} in the file`);
  const index = new Map(ids.map((id, k) => [id, k]));
  const neighbour = Array.from({ length: hexCount }, () => new Array(6).fill(-1));
  for (const g of gluings) {
    neighbour[g.a][g.fa] = g.b;
    neighbour[g.b][g.fb] = g.a;
  }
  const centroid = new Float64Array(3 * hexCount);
  for (let h = 0; h < hexCount; h++) {
    for (let c = 0; c < 8; c++) for (let d = 0; d < 3; d++) centroid[3 * h + d] += vertices[3 * corners[8 * h + c] + d] / 8;
  }
  const dual = smoothDualPoints(centroid, neighbour, hexCount);
  return { vertices, corners, neighbour, centroid, dual, ids, index, hexCount };
}

// Hex ids in the engine's dense order: the writer numbers live hexes by ascending id.
function liveHexIds(mesh, hexCount) {
  const rb = mesh.renderBuffers({ shrink: 0 });
  const ids = [...new Set(rb.triangleHex)].sort((a, b) => a - b);
  if (ids.length !== hexCount) throw new Error(`figure: ${ids.length} rendered hexes but ${hexCount} in the file`);
  return ids;
}

// A hex's dual point: its centroid moved halfway toward the mean of its distinct glued
// neighbours' centroids when that mean differs from the centroid (pillows, blind chords).
function smoothDualPoints(centroid, neighbour, n) {
  const out = new Float64Array(centroid);
  for (let h = 0; h < n; h++) {
    const others = [...new Set(neighbour[h].filter((x) => x >= 0 && x !== h))];
    if (others.length === 0 || others.length >= 4) continue;
    for (let d = 0; d < 3; d++) {
      let m = 0;
      for (const o of others) m += centroid[3 * o + d];
      m /= others.length;
      out[3 * h + d] = centroid[3 * h + d] + 0.45 * (m - centroid[3 * h + d]);
    }
  }
  return out;
}

/** Incidences at the dual vertex of hex `h` (dense index): TK03 §2, Theorems 1-2. */
export function incidences(model, h) {
  const cs = [...model.corners.slice(8 * h, 8 * h + 8)];
  const quadKeys = new Set(HEX_FACES.map((f) => f.map((c) => cs[c]).sort((a, b) => a - b).join(',')));
  const edgeKeys = new Set(HEX_EDGES.map(([a, b]) => [cs[a], cs[b]].sort((x, y) => x - y).join(',')));
  const glued = model.neighbour[h].filter((x) => x >= 0);
  const perNeighbour = new Map();
  for (const x of glued) perNeighbour.set(x, (perNeighbour.get(x) || 0) + 1);
  return {
    quads: quadKeys.size,
    edges: edgeKeys.size,
    vertices: new Set(cs).size,
    boundaryQuads: 6 - glued.length,
    neighbours: perNeighbour.size,
    mostSharedWithOne: Math.max(0, ...perNeighbour.values()),
    mostSharedWith: [...perNeighbour.entries()].sort((a, b) => b[1] - a[1])[0]?.[0] ?? -1,
  };
}
