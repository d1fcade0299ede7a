// The atomic dual operations of Tautges & Knoop (TK03 §4) and their inverses (docs/operations.md).
// Every operation checks its preconditions first and is transactional: on any error it throws
// Error (message "<log name>: <rule broken>", e.g. "hexpush: ...") and the complex is exactly as
// before — topology, ids, positions. The operations themselves never move existing vertices and
// put new ones at fixed places inside the opened quads; applyStep (oplog.hpp), when asked (the CLI
// and the package do), then untangles and smooths the vertices around the step
// (geometry/step_geometry.hpp). Topology never depends on positions.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "complex/complex.hpp"
#include "geometry/step_quality.hpp"
#include "ops/op_step.hpp"

namespace hexdual {

struct OpResult {
  std::optional<OpKind> op;  // the atomic operation; empty for composites (flip, pillowRegion, ...)
  std::vector<HexId> createdHexes, removedHexes;
  std::vector<VertexId> createdVertices, removedVertices;
  int64_t dV = 0, dE = 0, dF = 0, dH = 0;  // change in (V, E, F, H); E from Euler's V-E+F-H invariance
  std::optional<OpStep> inverse;  // a step that applies to the result and undoes this one (up to ids)
  std::string noInverse;          // when there is no inverse step: why
  Complex::EditLog edits;         // cx.undo(edits) restores the exact previous state, ids included
  StepQuality quality;            // scaled Jacobians of the touched hexes before and after (applyStep, unless Keep)
};

// ---- 1. minimal pillow (TK03 §4.3) ----
// Opens interior quad q between A and B into two hexes X, Y on the same 8 vertices (q's 4 and 4
// new), sharing 5 quads: A | q | X || Y | q' | B. Delta (+4,+8,+6,+2).
OpResult pillow(Complex& cx, QuadSide q);
// Removes a pillow pair: x and the hex sharing 5 quads with it, whose 4 inner vertices are used by
// the two only; glues the hexes on their free faces to each other. Delta (-4,-8,-6,-2).
OpResult unpillow(Complex& cx, HexId x);

// ---- 2. chord push (TK03 §4.1) ----
// e: an interior edge whose hex cycle closes; f, g: two distinct quads of that cycle, splitting it
// into arcs L (after f, up to g) and R. Cuts f and g and closes each arc with a new hex (X for L,
// Y for R); X and Y share 4 quads and form a blind chord of length 2. Delta (+2,+6,+6,+2).
OpResult chordPush(Complex& cx, EdgeRef e, QuadSide f, QuadSide g);
// Removes such a blind pair (x and the hex sharing 4 quads with it) and re-glues f and g.
OpResult chordPull(Complex& cx, HexId x);

// ---- 3. hex push (TK03 §4.2, the 2-6 flip) ----
// q: an interior quad between distinct hexes A and B that share only q. A and B become 6 hexes
// around a new quad r (4 new vertices inside q). Delta (+4,+12,+12,+4).
OpResult hexPush(Complex& cx, QuadSide q);
// The 6-2 flip: r between A' and B', surrounded by a ring of 4 hexes, whose 4 vertices only those
// 6 hexes use. Delta (-4,-12,-12,-4).
OpResult hexPull(Complex& cx, QuadSide r);

// ---- 4a. ring collapse (TK03 §4.4) ----
// The chord through hex h along the axis of local edge e must be a ring (closed, never on the
// boundary, not passing a hex twice). Collapses its cross-section along the diagonal of e: the
// vertex lines of e and of the diagonally opposite edge merge; side quads meeting at the other
// diagonal's edges glue to each other. A merged class holding a boundary vertex keeps that
// vertex, so the boundary quad mesh never changes. Rejected if the diagonal is not carried
// consistently around the ring, if two boundary vertices would merge, if a side quad is on the
// boundary, or if the result is not a valid complex. Delta (-n,-3n,-3n,-n) for a ring of n hexes
// whose sides all touch other hexes. Its inverse (a ringSplit) is reported only when it applies.
OpResult ringCollapse(Complex& cx, EdgeRef e);
// The inverse: `bands` lists, in order around a closed loop of edges, pairs of interior quads
// (f_k, g_k) sharing the loop's k-th edge; the f's and the g's each form a strip. Cuts the strips
// open, splits the loop's vertices in two (the side on the boundary keeps the id), and inserts a
// ring of n hexes.
OpResult ringSplit(Complex& cx, const std::vector<std::pair<QuadSide, QuadSide>>& bands);

// ---- 4b. face open-collapse (TK03 §4.4; MOAB face_open_collapse) ----
// e = ab interior with a closed cycle; f = (a,b,c,d), g = (a,b,c',d') two distinct quads of it.
// Cuts f and g, glues arc L's two open sides to each other and R's likewise; c merges with c',
// d with d'; a boundary vertex keeps its id, so the boundary quad mesh never changes. Delta
// (-2,-2,0,0). Rejected when two boundary vertices would merge or the result would not be valid.
OpResult faceCollapse(Complex& cx, EdgeRef e, QuadSide f, QuadSide g);
// The inverse: sL is a side of a quad whose two sides will be cut apart, sR a side of a second
// quad on the same 4 vertices; sL is re-glued to sR and their partners to each other, and the two
// vertices not on the quads' shared edge split in two (the side on the boundary keeps the id).
OpResult faceSplit(Complex& cx, QuadSide sL, QuadSide sR);

}  // namespace hexdual
