// Picking sheets by what they contain or what they are, for the figures' stage definitions.

/** The first sheet (by id) that contains every hex in `hexes`, or null. */
export function sheetWith(mesh, hexes) {
  for (const s of mesh.sheets) {
    const on = new Set(mesh.sheetHexes(s.id));
    if (hexes.every((h) => on.has(h))) return s.id;
  }
  return null;
}

/** The `nth` sheet (by id) satisfying `pred(info)`, or null. */
export function sheetOf(mesh, pred, nth = 0) {
  return mesh.sheets.filter(pred)[nth]?.id ?? null;
}
