// Minimal pillow and its inverse (TK03 §4.3, Fig. 7; MOAB atomic_pillow / rev_atomic_pillow).
#include "ops/support.hpp"

namespace hexdual {
using namespace tables;
using namespace ops;

namespace ops {
std::string pillowPrecheck(const Complex& cx, QuadSide q) {
  return interiorQuadProblem(cx, q, opName(OpKind::Pillow), "a pillow needs an interior quad");
}
}  // namespace ops

OpResult pillow(Complex& cx, QuadSide q) {
  const OpKind kind = OpKind::Pillow;
  if (std::string why = pillowPrecheck(cx, q); !why.empty()) throw Error(why);
  Gluing gB = cx.gluing(q);
  const HexId A = q.hex, B = gB.hex;
  const int fA = q.face, fB = gB.face;

  // q's vertices in A's face cycle; the new ones move 30% of the way toward B's centre.
  std::array<VertexId, 4> Q, N;
  Vec3 cB = cx.hexCentroid(B);
  Transaction tx(cx);
  for (int p = 0; p < 4; ++p) {
    Q[size_t(p)] = cx.vertex(A, kFaceCorners[size_t(fA)][size_t(p)]);
    Vec3 x = cx.position(Q[size_t(p)]);
    N[size_t(p)] = cx.addVertex(x + 0.3 * (cB - x));
  }
  // X: q at the bottom (face 4), the new vertices on top; Y: its mirror, q' on top.
  std::array<VertexId, 8> vx, vy;
  for (int p = 0; p < 4; ++p) {
    vx[size_t(kFaceCorners[4][size_t(p)])] = Q[size_t(p)];
    vx[size_t(kFaceCorners[5][size_t(p)])] = N[size_t(p)];
    vy[size_t(kFaceCorners[4][size_t(p)])] = N[size_t(p)];
    vy[size_t(kFaceCorners[5][size_t(p)])] = Q[size_t(p)];
  }
  cx.unglue(A, fA);
  HexId X = cx.addHex(vx), Y = cx.addHex(vy);
  glueByVertices(cx, A, fA, X, 4);
  glueByVertices(cx, X, 5, Y, 4);
  for (int f = 0; f < 4; ++f) glueByVertices(cx, X, f, Y, f);
  glueByVertices(cx, Y, 5, B, fB);

  OpResult r;
  r.op = kind;
  r.createdHexes = {X, Y};
  r.createdVertices.assign(N.begin(), N.end());
  r.inverse = makeStep(OpKind::Unpillow, X);
  // Valid by construction (so no link walks): A != B (a quad glued to another face of its own hex
  // would carry the same 4 of its 8 distinct vertices) and q's 4 vertices are distinct. Each new
  // vertex N_p has the star {X, Y}: two corners glued along all three faces, a sphere link. Each
  // Q_p keeps its star and gains X's and Y's corners, glued to each other along their two side
  // faces and to A and B along the third: in Q_p's link the edge that was q is cut and a bigon of
  // two triangles is sewn in, which leaves a sphere a sphere and a disk a disk. Every gluing is
  // made by glueByVertices, so glued faces carry the same vertices.
  tx.commitValidByConstruction(r, {A, B, X, Y});
  return r;
}

OpResult unpillow(Complex& cx, HexId x) {
  const OpKind kind = OpKind::Unpillow;
  const std::string op = opName(kind);
  if (!cx.isHex(x)) reject(op, hexName(x) + " does not exist");
  // The partner is the hex glued to x across exactly 5 faces; x's sixth face is its free face.
  const HexId y = partnerSharing(cx, x, 5);
  if (y < 0) reject(op, hexName(x) + " is not half of a pillow (no hex shares exactly 5 quads with it)");
  const int freeX = facesNotGluedTo(cx, x, y)[0], freeY = facesNotGluedTo(cx, y, x)[0];
  Gluing gA = cx.gluing(x, freeX), gB = cx.gluing(y, freeY);
  if (gA.boundary() || gB.boundary())
    reject(op, "the pillow of " + hexName(x) + " and " + hexName(y) + " touches the boundary; it must lie between two hexes");
  if (faceVertexSet(cx, x, freeX) != faceVertexSet(cx, y, freeY))
    reject(op, "the free quads of " + hexName(x) + " and " + hexName(y) + " are not on the same 4 vertices");
  // The inner vertices (opposite x's free face) must be used by x and y only.
  std::vector<VertexId> inner;
  for (int p = 0; p < 4; ++p) {
    VertexId v = cx.vertex(x, kFaceCorners[size_t(oppositeFace(freeX))][size_t(p)]);
    if (cx.cornersOfVertex(x, kFaceCorners[size_t(oppositeFace(freeX))][size_t(p)]).size() != 2)
      reject(op, "vertex " + std::to_string(v) + " inside the pillow is used by other hexes");
    inner.push_back(v);
  }
  const HexId A = gA.hex, B = gB.hex;
  const int fA = gA.face, fB = gB.face;
  if (A == y || B == x) reject(op, "the pillow is glued to itself");
  Transaction tx(cx);
  for (int f = 0; f < 6; ++f) cx.unglue(x, f);
  for (int f = 0; f < 6; ++f) cx.unglue(y, f);
  cx.removeHex(x);
  cx.removeHex(y);
  glueByVertices(cx, A, fA, B, fB);
  OpResult r;
  r.op = kind;
  r.removedHexes = {x, y};
  r.removedVertices = inner;
  r.inverse = makeStep(OpKind::Pillow, QuadSide{A, fA});
  tx.commit(r, {A, B});
  return r;
}

}  // namespace hexdual
