// The colour rule of every view, mirrored from core/layout/palette.hpp (the C++ SVG writer):
// golden-angle hues, so consecutive ids differ and a stable id keeps its colour between steps.
// A chord has one colour everywhere (3D view, lists, sheet diagrams): the hue of id + 1000, so
// chord k and sheet k differ. tests/node/palette.test.mjs checks that both sides agree.
export const GOLDEN_ANGLE = 137.508;
export const SATURATION = 65;
export const LIGHTNESS = 50;
export const CHORD_ID_OFFSET = 1000;

function hsl(id) {
  const hue = (id * GOLDEN_ANGLE) % 360;
  return `hsl(${hue.toFixed(1)}, ${SATURATION}%, ${LIGHTNESS}%)`;
}

/** The colour of sheet `id`. */
export function sheetColor(id) {
  return hsl(id);
}

/** The colour of chord `id`, in the 3D view and in every sheet diagram. */
export function chordColor(id) {
  return hsl(id + CHORD_ID_OFFSET);
}
