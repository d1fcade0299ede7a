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
#include "complex/complex.hpp"

namespace hexdual {

// Whether hex h has an interior edge (closed cycle) of valence 2 or less, or shares a corner
// frame in opposite orientation with another hex.
bool degenerateByConstruction(const Complex& cx, HexId h);

}  // namespace hexdual
