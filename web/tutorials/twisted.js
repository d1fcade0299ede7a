// A twisted ring as legacy VTK text: `around` hexes in a loop whose square cross-section turns a
// quarter turn before the loop closes, so the radial and axial layers join into one sheet that
// passes through every hex twice (a self-intersecting sheet, TK03 §1.1).
export function twistedRingVtk(around) {
  const r0 = 2 + (0.3 * around) / Math.PI;
  const points = [];
  for (let t = 0; t < around; t++) {
    const turn = (0.5 * Math.PI * t) / around, ang = (2 * Math.PI * t) / around;
    for (let k = 0; k < 2; k++) {
      for (let s = 0; s < 2; s++) {
        const u = s - 0.5, v = k - 0.5;
        const ru = u * Math.cos(turn) - v * Math.sin(turn), rv = u * Math.sin(turn) + v * Math.cos(turn);
        points.push([(r0 + ru) * Math.cos(ang), (r0 + ru) * Math.sin(ang), rv]);
      }
    }
  }
  // Corner (s, k) of station t; past the last station the loop closes on station 0, turned.
  const vid = (t, s, k) => (t === around ? 0 + k + 2 * (1 - s) : 4 * t + s + 2 * k);
  const cells = [];
  for (let t = 0; t < around; t++) {
    // VTK corners: bottom face (k = 0) then top face (k = 1), each counter-clockwise.
    const c = (dt, s, k) => vid(t + dt, s, k);
    cells.push([c(0, 0, 0), c(0, 1, 0), c(1, 1, 0), c(1, 0, 0), c(0, 0, 1), c(0, 1, 1), c(1, 1, 1), c(1, 0, 1)]);
  }
  return [
    '# vtk DataFile Version 3.0',
    `twisted ring of ${around}`,
    'ASCII',
    'DATASET UNSTRUCTURED_GRID',
    `POINTS ${points.length} double`,
    ...points.map((p) => p.map((x) => x.toFixed(6)).join(' ')),
    `CELLS ${cells.length} ${cells.length * 9}`,
    ...cells.map((c) => `8 ${c.join(' ')}`),
    `CELL_TYPES ${cells.length}`,
    ...cells.map(() => '12'),
    '',
  ].join('\n');
}
