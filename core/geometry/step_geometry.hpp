// Geometry after an operation: places the vertices around it by the local untangling and
// smoothing (smoothing.hpp) and measures the step (step_quality.hpp). Run by applyStep when its
// options ask (oplog.hpp: the CLI and the package do, the flip search and `candidates` do not);
// the position edits join the operation's edit log, so undo stays exact.
#pragma once
#include <cstdint>

#include "complex/complex.hpp"
#include "geometry/step_quality.hpp"

namespace hexdual {

// What a step does about geometry.
enum class StepGeometry {
  Keep,     // nothing: the operation's own placement, not measured (the hot paths)
  Measure,  // the operation's own placement, measured (StepQuality)
  Smooth,   // placed by the local smoothing, then measured
};

// `log` is the committed edit log of the operation just applied to cx (no transaction open).
// With Smooth, the free vertices are the interior vertices (not on the boundary, manifold) of the
// hexes the step touched; while a hex that is not degenerate by construction stays inverted, they
// widen to the interior vertices of the hexes around them, at most kWideningRings times. Boundary
// vertices never move, nor any vertex outside that region. When the operation's own placement
// leaves fewer regular hexes newly inverted (inverted now, not before the step) than the best
// smoothed one, it is kept (StepQuality::kept): never worse than no smoothing.
StepQuality placeStepGeometry(Complex& cx, Complex::EditLog& log, StepGeometry mode);

inline constexpr int kWideningRings = 2;
// At most this many corner-energy evaluations per step (all rings and attempts; about 0.3 s
// natively): a bound for steps in meshes that are tangled already. Typical steps need 10^3-10^5.
inline constexpr int64_t kStepEvaluationBudget = 3000000;

}  // namespace hexdual
