// What a step did to the geometry: the scaled Jacobians of the hexes it touched, before and after,
// and which of them are inverted or degenerate by construction (degenerate.hpp).
#pragma once
#include <vector>

#include "complex/complex.hpp"

namespace hexdual {

struct StepQuality {
  bool smoothed = false;  // whether the step's new and moved vertices were placed by the smoothing
  // Minimum scaled Jacobian over the measured hexes (those the step created, re-glued or re-cornered,
  // and those around a vertex the smoothing moved) alive before / after the step; 1 when none.
  double before = 1, after = 1;
  double afterRegular = 1;           // `after` without the hexes degenerate by construction
  std::vector<HexId> inverted;       // measured hexes with scaled Jacobian <= 0, not degenerate by construction
  std::vector<HexId> degenerate;     // measured hexes degenerate by construction (never valid)
  std::vector<VertexId> moved;       // vertices the smoothing placed (new ones and moved ones), ascending
  int64_t evaluations = 0;           // the smoothing's cost in hex scaled-Jacobian evaluations
};

}  // namespace hexdual
