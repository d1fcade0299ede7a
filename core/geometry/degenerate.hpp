// Hexes that no embedding makes valid. Around an interior edge the dihedral angles of its hexes
// sum to a full turn; with two hexes (a minimal pillow's pair, a chord push's blind pair, TK03) one
// of them has an angle of at least a half turn there, so its scaled Jacobian is <= 0 whatever the
// positions. Reports call such hexes degenerate by construction, not inverted.
#pragma once
#include "complex/complex.hpp"

namespace hexdual {

// Whether hex h has an interior edge (closed cycle) of valence 2 or less.
bool degenerateByConstruction(const Complex& cx, HexId h);

}  // namespace hexdual
