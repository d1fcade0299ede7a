// The boundary of the 4-cube drawn so that a student can tell its eight cubes apart: the engine
// places it as a Schlegel projection (an inner cube, six frustums around it, and the outer cube
// that wraps around them all). Here every cube is pulled away from the centre along its own
// direction (an exploded view), the outer cube is drawn as a large translucent shell around the
// rest, each cube is labelled with its number, and the flip's before and after sides take two
// colour families (blues and oranges), one shade per cube.

// Shades per side: neighbouring cubes (ids differ) get different shades of the same family.
const BEFORE = ['#1f5fd1', '#4d8ef0', '#7fb0ff', '#2b4f9e'];
const AFTER = ['#e8590c', '#f59f00', '#f76707', '#ffb347'];
export const CREATED = '#2f9e44';
export const SIDE_COLORS = { before: BEFORE[1], after: AFTER[1], created: CREATED };

// Per hex id: [min x, min y, min z, max x, max y, max z] of its corners (shrink 0: the hex itself).
function hexBoxes(mesh) {
  const rb = mesh.renderBuffers({ shrink: 0 });
  const boxes = new Map();
  const p = rb.positions;
  for (let k = 0; k < rb.triangleHex.length / 12; k++) {
    const b = [Infinity, Infinity, Infinity, -Infinity, -Infinity, -Infinity];
    for (let v = 24 * k; v < 24 * k + 24; v++)
      for (let d = 0; d < 3; d++) (b[d] = Math.min(b[d], p[3 * v + d])), (b[d + 3] = Math.max(b[d + 3], p[3 * v + d]));
    boxes.set(rb.triangleHex[12 * k], b);
  }
  return boxes;
}

// The hexes whose box is the whole complex's: the outer cube of the projection.
function outerHexes(boxes) {
  const all = [Infinity, Infinity, Infinity, -Infinity, -Infinity, -Infinity];
  for (const b of boxes.values()) for (let d = 0; d < 3; d++) (all[d] = Math.min(all[d], b[d])), (all[d + 3] = Math.max(all[d + 3], b[d + 3]));
  const outer = new Set([...boxes].filter(([, b]) => b.every((x, i) => Math.abs(x - all[i]) < 1e-6)).map(([h]) => h));
  return { outer, centre: [0, 1, 2].map((d) => (all[d] + all[d + 3]) / 2) };
}

/**
 * The exploded layout for figure.js (`layout` option): a per-hex transform. A hex is moved away
 * from the centre by `spread` times its centroid's offset; the outer cube of the projection (found
 * in `startMesh`, and kept by id while steps reshape it) is scaled by `shell` about the centre.
 */
export function explodedLayout(startMesh, { spread = 1.8, shell = 2.9 } = {}) {
  const start = outerHexes(hexBoxes(startMesh));
  return (mesh) => {
    const boxes = hexBoxes(mesh);
    const outer = new Set([...outerHexes(boxes).outer, ...[...start.outer].filter((h) => boxes.has(h))]);
    const centre = start.centre;
    const move = new Map();
    for (const [h, b] of boxes) move.set(h, [0, 1, 2].map((d) => spread * ((b[d] + b[d + 3]) / 2 - centre[d])));
    const transform = (h, x, y, z) => {
      if (outer.has(h)) return [centre[0] + shell * (x - centre[0]), centre[1] + shell * (y - centre[1]), centre[2] + shell * (z - centre[2])];
      const m = move.get(h) ?? [0, 0, 0];
      return [x + m[0], y + m[1], z + m[2]];
    };
    transform.outer = outer;
    return transform;
  };
}

/** Whether hex `id` is drawn as the outer shell in the figure's current layout. */
export function isOuter(fig, id) {
  return !!fig.view?.layoutInfo?.outer?.has(id);
}

/**
 * Colours for a flip in the 4-cube: `before` (hex ids of its before side among the 8 cubes) solid
 * blue, hexes a step created solid green, the other original cubes (the after side, which the steps
 * never change) translucent orange, so the flip's region stays in front and pickable; the outer
 * shell is fainter still.
 */
export function flipColors(before) {
  const inBefore = new Set(before);
  return (fig, id) => {
    const c = id >= 8 ? CREATED : inBefore.has(id) ? BEFORE[id % BEFORE.length] : AFTER[id % AFTER.length];
    if (isOuter(fig, id)) return [c, 60];
    return id < 8 && !inBefore.has(id) ? [c, 110] : c;
  };
}

/** Labels: every original cube by its number (and side), hexes created by steps by their id. */
export function cubeLabels(before) {
  const inBefore = new Set(before);
  return (fig) =>
    fig.liveIds().map((h) => ({
      hex: h,
      text: isOuter(fig, h) ? `${h} (outer)` : `${h}`,
      cls: h >= 8 ? 'created' : inBefore.has(h) ? 'before' : 'after',
      anchor: isOuter(fig, h) ? 'corner' : 'centre',
      title: h >= 8 ? `hex ${h}, made by a step` : `cube ${h} (${inBefore.has(h) ? 'before' : 'after'} side)${isOuter(fig, h) ? ': the outer cube, it wraps around the others' : ''}`,
    }));
}
