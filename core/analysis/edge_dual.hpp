// The dual through one edge: the sheet that crosses it and, for each quad around it, the chord
// through that quad and the second sheet that chord lies in. What a picked (singular) edge shows.
#pragma once
#include <vector>

#include "complex/complex.hpp"
#include "dual/dual.hpp"

namespace hexdual {

struct EdgeDual {
  EdgeRef ref;  // the edge's smallest incidence
  int valence = 0;
  bool boundary = false;
  int sheet = -1;           // the sheet crossing the edge (dual to it)
  std::vector<HexId> hexes;  // around the edge, in cycle (fan) order
  struct Quad {
    QuadSide quad;  // canonical side
    int chord = -1;  // the chord through the quad
    int sheet = -1;  // the chord's other sheet (besides `sheet`)
  };
  std::vector<Quad> quads;             // the quads containing the edge, in cycle order
  std::vector<int> chords, sheets;     // distinct ids, ascending; `sheets` includes `sheet`
};

// Throws Error "edgedual: ..." when e is not an edge of a live hex.
EdgeDual edgeDual(const Complex& cx, const Dual& dual, EdgeRef e);

}  // namespace hexdual
