// The sheet operations (docs/operations.md "Sheet operations"): a family apart from the atomic
// operations of ops.hpp. They remove, insert, collapse or split whole sheets and chords, and
// where those meet the mesh boundary they change the boundary quad mesh, which no atomic
// operation does. Like the atomic operations they check their rules first and are
// transactional: every refusal reads "<log name>: <rule>: <details>" with a stable rule name
// (ruleOf() reads it back), and the complex is then exactly as before. Each result carries its
// edit journal (exact undo) and, when there is one, an inverse step.
#pragma once
#include <string>
#include <vector>

#include "complex/complex.hpp"
#include "ops/ops.hpp"

namespace hexdual {

// ---- sheet extraction (Borden, Benzley & Shepherd 2002) ----
// Collapses every edge of the edge class of e (the sheet crossed by e's axis in e's hex): the
// sheet's hexes vanish and the quads on either side of it are glued. Each collapsed edge keeps
// one vertex (the boundary one, else the smaller id) at the edge's midpoint (or at the boundary
// vertex when only one end is on the boundary). Refused for a sheet that passes a hex twice
// (self-intersecting), touches itself at a vertex (self-touching), is crossed by a chord that
// never leaves it (no-sides), or whose collapse would merge two vertices of a remaining hex
// (hex-vertices-merge), change the mesh's topology (topology-change) or leave an invalid complex
// (non-manifold-result, invalid-result). Inverse: the sheet
// insertion along the glued quads (a pillow for a sheet of 2 hexes folded on itself).
OpResult sheetExtract(Complex& cx, EdgeRef e);
// Whether sheetExtract(cx, e) would commit without walking vertex links: its result is then valid
// by the argument in sheet_extract.cpp (the common case: no fold, no run ending on the boundary, a
// simple collapse at every vertex). False when it would be refused. For the tests of that claim.
bool sheetExtractValidByConstruction(const Complex& cx, EdgeRef e);

// ---- sheet insertion (pillowing a surface of quads) ----
// `quads` names a surface: every quad by one of its sides. Each vertex of the surface splits in
// two; the side of the first quad named (and the sides that continue it across the surface)
// moves onto the new vertices, and one new hex per quad fills the gap. The surface may contain
// boundary quads and may end on the mesh boundary (the new sheet is then a disk or annulus
// ending there, and the boundary quad mesh gains the new hexes' side quads); it may not end
// inside the mesh (open-surface), branch or pinch (non-manifold-surface) or be one-sided.
// Delta (+V_s, +V_s+E_s, +F_s+E_s, +F_s). Inverse: sheet-extract of the new sheet.
OpResult sheetInsert(Complex& cx, const std::vector<QuadSide>& quads);
// Pillowing a shrink set: the surface is every quad between the set and the rest of the mesh
// (faces on the mesh boundary are not part of it), the set's side moves. The general form of
// pillowRegion (flips/flip.hpp), which refuses sets touching the boundary.
OpResult sheetPillow(Complex& cx, const std::vector<HexId>& hexes);

// ---- column (chord) collapse (Merkley et al. 2007) ----
// The chord through e's hex along e's axis, open (boundary to boundary) or closed, collapses
// along the diagonal of e as ring collapse does: its hexes vanish, the vertex line of e merges
// with the diagonally opposite one, side quads meeting at the other diagonal glue pairwise.
// At an open chord's ends the two boundary quads collapse along that diagonal. On a closed
// chord whose ring collapse applies, the result is the ring collapse's. No inverse step.
OpResult columnCollapse(Complex& cx, EdgeRef e);

// ---- sheet dicing ----
// Splits the sheet through e into k parallel sheets (2 <= k <= 64): every edge of its class is
// cut into k, every hex of it into k along that edge. The sheet keeps its hexes (as the first
// layer); the k-1 other layers are new. Refused for self-intersecting or one-sided sheets.
OpResult sheetDice(Complex& cx, EdgeRef e, Count k);

// The rule of a refusal ("self-touching" from "sheet-extract: self-touching: ..."), or "".
std::string ruleOf(const std::string& message);

}  // namespace hexdual
