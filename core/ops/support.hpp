// Helpers shared by the operations (not part of the public API).
#pragma once
#include <algorithm>
#include <span>
#include <string>
#include <vector>

#include "complex/complex.hpp"
#include "ops/op_table.hpp"
#include "ops/ops.hpp"

namespace hexdual::ops {

[[noreturn]] inline void reject(const std::string& op, const std::string& why) { throw Error(op + ": " + why); }

inline std::string hexName(HexId h) { return "hex " + std::to_string(h); }
inline std::string sideName(QuadSide s) { return "h" + std::to_string(s.hex) + "f" + std::to_string(s.face); }
inline std::string edgeName(EdgeRef e) { return "h" + std::to_string(e.hex) + "e" + std::to_string(e.edge); }

// The quad's other side, after checking that the hex exists, the face is 0..5 and the quad is
// interior; `needs` completes the boundary message ("a pillow needs an interior quad").
Gluing requireInteriorQuad(const Complex& cx, QuadSide q, const std::string& op, const std::string& needs);
// The same check without throwing: the message requireInteriorQuad would throw, or empty.
std::string interiorQuadProblem(const Complex& cx, QuadSide q, const std::string& op, const std::string& needs);

// The orientation code that maps face fa of hex a onto face fb of hex b vertex for vertex, or -1.
int orientByVertices(const Complex& cx, HexId a, int fa, HexId b, int fb);
// Glues two boundary faces that carry the same 4 vertices in cyclic order (throws otherwise).
void glueByVertices(Complex& cx, HexId a, int fa, HexId b, int fb);
// The sorted vertex ids of a face.
std::array<VertexId, 4> faceVertexSet(const Complex& cx, HexId h, int f);
// v's neighbour in quad q other than `away`, -1 when v is not on q.
inline VertexId neighbourInQuad(const Complex& cx, QuadSide q, VertexId v, VertexId away) {
  std::array<VertexId, 4> fv;
  for (int p = 0; p < 4; ++p) fv[size_t(p)] = cx.vertex(q.hex, tables::kFaceCorners[size_t(q.face)][size_t(p)]);
  for (int p = 0; p < 4; ++p)
    if (fv[size_t(p)] == v) return fv[size_t((p + 1) & 3)] == away ? fv[size_t((p + 3) & 3)] : fv[size_t((p + 1) & 3)];
  return VertexId(-1);
}

// The closed cycle of hexes and quads around an interior edge: incidence k, then quad k between
// incidence k (its face exitFace[k]) and incidence k+1 (its face entryFace[k+1]).
struct EdgeStar {
  std::vector<EdgeRef> inc;
  std::vector<int> exitFace, entryFace;
};
// Throws (as op) when e is not an edge of a live hex or its cycle does not close.
EdgeStar closedEdgeStar(const Complex& cx, EdgeRef e, const std::string& op);
// The same into `st` (its storage reused) without throwing: the message, or empty.
std::string closedEdgeStarInto(const Complex& cx, EdgeRef e, const std::string& op, EdgeStar& st);
// Index k of quad k of the star that has `side` as one of its sides, or -1.
int quadIndexInStar(const Complex& cx, const EdgeStar& st, QuadSide side);

// The faces of h not glued to `other`.
std::vector<int> facesNotGluedTo(const Complex& cx, HexId h, HexId other);
// The first hex (by x's faces) glued to x across exactly `shared` of x's faces, or -1: the other
// half of a pillow (5) or of a blind chord (4).
HexId partnerSharing(const Complex& cx, HexId x, int shared);

// Whether any of these (hex, corner) incidences has a face on the boundary.
bool cornersOnBoundary(const Complex& cx, const std::vector<std::pair<HexId, int>>& corners);
// Whether the vertex at corner c of hex h lies on the boundary (walks its corners).
bool vertexOnBoundary(const Complex& cx, HexId h, int c);

// The arc split shared by chord push and face collapse: edge e = ab with a closed cycle, two
// distinct quads f and g of it; arc L runs from after f up to g, arc R the rest. Sides: fL/gL
// face arc L, fR/gR arc R. fa, fb (ga, gb) are f's (g's) vertices next to a and b.
struct ArcSplit {
  EdgeStar star;
  EdgeRef li, lj;  // the incidences of e in L's first and last hex
  QuadSide fL, fR, gL, gR;
  VertexId a, b, fa, fb, ga, gb;
};
ArcSplit arcSplit(const Complex& cx, EdgeRef e, QuadSide f, QuadSide g, const std::string& op, const char* what);
// The same into `s` (its storage reused) without throwing: the message arcSplit would throw, or empty.
std::string arcSplitInto(const Complex& cx, EdgeRef e, QuadSide f, QuadSide g, const std::string& op, const char* what,
                         ArcSplit& s);

// The first checks of an operation, as the operation table's `precheck` (op_table.hpp): the
// message the operation would throw for them, or empty. The operations run the same functions.
std::string pillowPrecheck(const Complex& cx, QuadSide q);
std::string hexPushPrecheck(const Complex& cx, QuadSide q);
std::string chordPushPrecheck(const Complex& cx, EdgeRef e, QuadSide f, QuadSide g);
std::string faceCollapsePrecheck(const Complex& cx, EdgeRef e, QuadSide f, QuadSide g);

// The hexes an edit touched: `hexes` and every hex glued to one of them.
std::vector<HexId> withNeighbours(const Complex& cx, const std::vector<HexId>& hexes);

// While one is alive on a thread, Transaction::commit skips its invariant check (the manifold
// vertices and validateAround): for a caller that checks the results it keeps itself, as the
// decomposition search does once per new state. Results committed meanwhile may be invalid.
class DeferValidation {
 public:
  DeferValidation();
  ~DeferValidation();
  DeferValidation(const DeferValidation&) = delete;
  DeferValidation& operator=(const DeferValidation&) = delete;
  static bool active();
};

// Opens a transaction; rolls back unless commit() is reached. Also fills the result's counts.
class Transaction {
 public:
  explicit Transaction(Complex& cx) : cx_(cx) {
    cx_.beginTransaction();
    v0_ = cx.numVertices();
    f0_ = cx.numQuads();
    h0_ = cx.numHexes();
  }
  // The same with room for about `edits` edits (Complex::reserveEdits): for the sheet operations,
  // whose edits are counted in thousands.
  Transaction(Complex& cx, size_t edits) : Transaction(cx) { cx_.reserveEdits(edits); }
  ~Transaction() {
    if (open_) cx_.rollbackTransaction();
  }
  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;
  // Checks the invariants around `touched` (debug builds: everywhere), fills counts, commits.
  void commit(OpResult& r, const std::vector<HexId>& touched);
  // The same for edits whose validity is only known afterwards: a broken invariant rolls back
  // and rejects as "<op>: <why> (<the invariant>)".
  void commitIfValid(OpResult& r, const std::vector<HexId>& touched, const std::string& op, const std::string& why);
  // The same for an edit that is valid whenever the complex was valid before it and the
  // operation's precheck passed: a proof that sits with the operation (pillow.cpp, hex_push.cpp),
  // not a test run on every step. It still refuses non-manifold vertices; debug builds
  // (HEXDUAL_CHECK_INVARIANTS) still validate everything, and tests/test_valid_by_construction.cpp
  // checks the claim on random steps.
  void commitValidByConstruction(OpResult& r, const std::vector<HexId>& touched);

 private:
  void commitChecked(OpResult& r, const std::vector<HexId>& touched, bool walkLinks);
  Complex& cx_;
  bool open_ = true;
  int64_t v0_, f0_, h0_;
};

// Partition of the corners of vertex v (given one of its corners) into the two sides of a loop of
// quads through v: corners reachable from `seed` without crossing any of `walls` (quad sides).
std::vector<std::pair<HexId, int>> cornersOnSide(const Complex& cx, std::pair<HexId, int> seed,
                                                 const std::vector<QuadSide>& walls);

// How a vertex splits along walls (quad sides through it): `keep` keeps its id, `moved` takes a
// new vertex. Normally the walls cut its corners in two and the seed's side keeps the id. The
// side on the boundary always keeps it, so the boundary quad mesh is unchanged: if only the other
// side is on the boundary the two swap, and at a boundary vertex the walls may cut off pieces
// touching the boundary around one piece inside, which alone moves. Rejects (as op) otherwise,
// naming the walls as `walls` ("the two quads").
struct VertexSplit {
  std::vector<std::pair<HexId, int>> keep, moved;
};
VertexSplit splitVertex(const Complex& cx, std::pair<HexId, int> seed, const std::vector<QuadSide>& walls,
                        const std::string& op, const std::string& what);

}  // namespace hexdual::ops

namespace hexdual::ops {
// Replaces `removed` hexes by hexes on the given vertex arrays (ids assigned in order). Gluings
// are rebuilt from vertex sets: each former outside neighbour is glued to the one new face with
// its 4 vertices; new faces with equal vertex sets pair up; a face left over must carry the
// vertices of a former boundary quad of the removed hexes (the boundary quad mesh is kept).
// Throws (as op) when the new hexes do not fit. Call inside a Transaction.
std::vector<HexId> replaceHexes(Complex& cx, const std::string& op, const std::vector<HexId>& removed,
                                const std::vector<std::array<VertexId, 8>>& added);

// One gluing of replaceHexesByPlan: face `face` of new hex `hex` (an index into `added`) meets face
// `otherFace` of new hex `other`, or, when other < 0, whatever was across face `otherFace` of
// removed hex -1 - other (nothing, when that was the boundary).
struct PlannedGluing {
  int8_t hex, face, other, otherFace;
};
// replaceHexes for an operation that knows by construction which faces meet (hex push): the same
// complex, ids and gluings, without keying every new face by its vertices. Each gluing's
// orientation is still read from the vertices, and one that does not fit rejects (as op). Where a
// removed hex was glued to a removed hex other than as planned (a degenerate input) it is
// replaceHexes itself. Call inside a Transaction.
std::vector<HexId> replaceHexesByPlan(Complex& cx, const std::string& op, const std::vector<HexId>& removed,
                                      const std::vector<std::array<VertexId, 8>>& added,
                                      std::span<const PlannedGluing> plan);
}  // namespace hexdual::ops
