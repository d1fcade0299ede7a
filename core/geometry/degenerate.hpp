// Hexes that no embedding makes valid, alone or with a partner. Two kinds, both proofs that hold
// for every vertex placement (edges are straight, corners are measured by their frames):
// - an interior edge of valence <= 2 (a minimal pillow's pair, a chord push's blind pair, TK03):
//   the dihedral angles around it sum to a full turn, so one hex has at least a half turn there;
// - a corner frame shared in opposite orientation: another hex has a corner at the same vertex
//   with the same three neighbours, in the mirrored order (after a face collapse, the hexes on
//   either side of the merged quads). The two corner determinants are then opposite numbers, so
//   at least one of the two hexes is inverted or flat whatever the positions.
// Reports call such hexes degenerate by construction, not inverted, and the smoothing leaves
// them out of its energy (it keeps their neighbours valid instead).
#pragma once
#include <unordered_map>
#include <utility>
#include <vector>

#include "complex/complex.hpp"

namespace hexdual {

// The corners at a vertex (Complex::cornersOfVertex), each vertex's walked once while cx does not
// change: a step's measure asks about the same vertices many times (8 per hex, and a certificate
// asks again for every hex of a star). A manifold vertex's corners are the same set from any of
// them; a tolerated non-manifold vertex's are walked from the corner asked each time (that list
// lives until the next call).
class VertexStars {
 public:
  explicit VertexStars(const Complex& cx) : cx_(cx) {}
  const std::vector<std::pair<HexId, int>>& of(HexId h, int corner);

 private:
  const Complex& cx_;
  std::unordered_map<VertexId, std::vector<std::pair<HexId, int>>> known_;
  std::vector<std::pair<HexId, int>> walked_;
};

// Whether hex h has an interior edge (closed cycle) of valence 2 or less, or shares a corner
// frame in opposite orientation with another hex.
bool degenerateByConstruction(const Complex& cx, HexId h);
// The same, reading the vertices' corners from `stars` (built on cx, which has not changed since).
bool degenerateByConstruction(const Complex& cx, HexId h, VertexStars& stars);

}  // namespace hexdual
