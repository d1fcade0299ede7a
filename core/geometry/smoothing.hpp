// Local untangling and smoothing of a few free vertices (the ones an operation created or moved):
// each is moved, in id order, to raise the minimum scaled Jacobian of the hexes around it that are
// not degenerate by construction (degenerate.hpp), ties broken by the sum over their corners. No vertex's minimum
// ever drops, so the smoothing never makes the worst hex around the free vertices worse; nothing
// else moves. Plain scalar arithmetic in a fixed order: the same bits natively and in wasm.
#pragma once
#include <utility>
#include <vector>

#include "complex/complex.hpp"

namespace hexdual {

struct FreeVertex {
  VertexId vertex;
  HexId hex;   // a hex with the vertex at `corner`: where the walk over its star starts
  int corner;
};

struct SmoothingStats {
  std::vector<VertexId> moved;  // ascending
  int64_t evaluations = 0;      // hex scaled Jacobians computed (the cost: independent of mesh size)
};

// Moves the free vertices (interior ones: the caller leaves boundary vertices out) through
// Complex::setPosition, so an open transaction journals the moves.
SmoothingStats smoothVertices(Complex& cx, std::vector<FreeVertex> free);

}  // namespace hexdual
