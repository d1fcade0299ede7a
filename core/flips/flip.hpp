// Applying a cubical flip inside any mesh, and the composite operations (TK03 §4.3, §4.5).
#pragma once
#include <string>
#include <vector>

#include "complex/complex.hpp"
#include "ops/ops.hpp"

namespace hexdual {

// The named hexes must form the "before" side of flip `name` (an isomorphism with the 4-cube
// pattern that maps their outer quads to its boundary quads); they are replaced by the "after"
// side, glued to the same outside quads. Transactional; Error names why the hexes do not match.
OpResult flip(Complex& cx, const std::string& name, const std::vector<HexId>& hexes);

// Traditional pillow of one hex (the 1-7 flip as pillow + hex push, TK03 Fig. 8): pillow on the
// hex's face `face` (interior), then hex push on the quad between the hex and the new pillow hex.
std::vector<OpResult> traditionalPillow(Complex& cx, HexId hex, int face);

// General pillowing of a shrink set S: every vertex of S's outer surface gets an inner copy, S's
// hexes move onto the copies, and one new hex fills the gap under each outer quad. S must be
// interior (no quad on the mesh boundary) with a manifold outer surface.
// Delta (+V_s, +V_s+E_s, +F_s+E_s, +F_s) for a surface with (V_s, E_s, F_s).
OpResult pillowRegion(Complex& cx, const std::vector<HexId>& hexes);

// Triple-chord push (TK03 §4.5.1): the three quads q1, q2, q3 at interior vertex v (corner `corner`
// of hex `hex`) pairwise sharing an edge are pulled apart; v splits in two, the three edges
// between the quads are doubled, and two new hexes sharing 3 quads around a new vertex w fill the
// gap. Delta (+2,+6,+6,+2).
OpResult tripleChordPush(Complex& cx, HexId hex, int corner, QuadSide q1, QuadSide q2, QuadSide q3);

}  // namespace hexdual
