// Geometry after an operation: places the vertices it created or re-used (merged) by the local
// smoothing (smoothing.hpp) and measures the step (step_quality.hpp). Run by applyStep after every
// operation (oplog.hpp); the position edits join the operation's edit log, so undo stays exact.
#pragma once
#include "complex/complex.hpp"
#include "geometry/step_quality.hpp"

namespace hexdual {

// `log` is the committed edit log of the operation just applied to cx (no transaction open). With
// `smooth`, the free vertices are the interior ones among those it created or set as a hex corner;
// when a hex not degenerate by construction is still inverted after placing them, every interior
// vertex of the touched hexes is freed and placed again. Boundary vertices never move.
StepQuality placeStepGeometry(Complex& cx, Complex::EditLog& log, bool smooth);

}  // namespace hexdual
