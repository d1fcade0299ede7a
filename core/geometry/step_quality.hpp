// What a step did to the geometry: the scaled Jacobians of the hexes it touched, before and after,
// and which of them are inverted or degenerate by construction (degenerate.hpp).
#pragma once
#include <cstdint>
#include <vector>

#include "complex/complex.hpp"

namespace hexdual {

struct StepQuality {
  bool measured = false;  // false when the step was applied without geometry (StepGeometry::Keep)
  bool smoothed = false;  // whether the local smoothing placed the vertices around the step
  // Minimum scaled Jacobian over the measured hexes (those the step created, re-glued or re-cornered,
  // and those around a vertex the smoothing moved) alive before / after the step; 1 when none.
  double before = 1, after = 1;
  double afterRegular = 1;        // `after` without the hexes degenerate by construction
  std::vector<HexId> inverted;    // measured hexes with scaled Jacobian <= 0, not degenerate by construction
  std::vector<HexId> pinned;      // those of `inverted` certified impossible with the boundary fixed (pinned.hpp)
  std::vector<HexId> degenerate;  // measured hexes degenerate by construction (never valid)
  std::vector<VertexId> moved;    // vertices the smoothing moved, ascending
  int rings = 0;                  // how many times the smoothing widened its region (0..kWideningRings)
  bool kept = false;              // the smoothing kept the operation's own placement: every smoothed one
                                  // left more regular hexes newly inverted (a mesh tangled already)
  int64_t evaluations = 0;        // the smoothing's cost in corner-energy evaluations
};

}  // namespace hexdual
