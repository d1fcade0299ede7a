// Local untangling and smoothing of a few free vertices (the interior vertices around a step;
// step_geometry.hpp chooses them). Minimises the sum of the corner energies (corner_energy.hpp:
// Knupp's squared condition number with Escobar's modified determinant) of the hexes around them
// that are not degenerate by construction (degenerate.hpp): Gauss-Seidel sweeps over the free
// vertices in id order, each a Newton step (Hessian by forward differences of the exact gradient)
// with backtracking. While a corner is tangled (determinant below epsilon) delta > 0 softens the
// barrier so vertices can pass through it (untangling); once none is, delta = 0 and the energy is a
// barrier no step crosses. When the sweeps stall tangled, Freitag & Plassmann's max-min untangling
// (max_min.hpp) runs and the sweeps again; failing that, the whole attempt again from the start with
// the max-min first; failing that, once more from the faces' parallelogram completions (kept only
// when it untangles every counted hex); the best positions any phase reached are kept. Nothing
// else moves. Plain scalar arithmetic in a fixed order: the same bits natively and in wasm.
#pragma once
#include <cstdint>
#include <vector>

#include "complex/complex.hpp"
#include "geometry/smoothing_region.hpp"

namespace hexdual {

struct SmoothingStats {
  std::vector<VertexId> moved;  // ascending
  int64_t evaluations = 0;      // corner energies evaluated (the cost: independent of mesh size)
  int sweeps = 0;
  int invertedBefore = 0, invertedAfter = 0;  // counted hexes with a corner determinant <= 0
};

// Moves the free vertices (interior ones: the caller leaves boundary vertices out) through
// Complex::setPosition, so an open transaction journals the moves. When the sweeps would leave
// more counted hexes inverted than there were, nothing moves.
// `near` (ascending): the hexes sharing a vertex with a hex the step touched (buildSmoothingRegion).
// Sweeps stop once `budget` corner energies were evaluated (a bound on the worst case).
// `validBefore`: no hex around the free vertices was inverted before the step; only then does a
// tangled result get the third start (from the faces' parallelograms).
SmoothingStats smoothVertices(Complex& cx, std::vector<FreeVertex> free, const std::vector<HexId>& near,
                              int64_t budget, bool validBefore);

}  // namespace hexdual
