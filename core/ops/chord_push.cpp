// Chord push and its inverse (TK03 §4.1, Figs. 2-3).
#include "ops/support.hpp"

namespace hexdual {
using namespace tables;
using namespace ops;

namespace ops {
std::string chordPushPrecheck(const Complex& cx, EdgeRef e, QuadSide f, QuadSide g) {
  thread_local ArcSplit scratch;  // its star's storage is reused: rejected steps allocate nothing
  return arcSplitInto(cx, e, f, g, opName(OpKind::ChordPush), "chord push", scratch);
}
}  // namespace ops

OpResult chordPush(Complex& cx, EdgeRef e, QuadSide f, QuadSide g) {
  const OpKind kind = OpKind::ChordPush;
  const std::string op = opName(kind);
  const ArcSplit sp = arcSplit(cx, e, f, g, op, "chord push");
  const QuadSide fL = sp.fL, fR = sp.fR, gL = sp.gL, gR = sp.gR;
  const VertexId a = sp.a, b = sp.b, fa = sp.fa, fb = sp.fb, ga = sp.ga, gb = sp.gb;

  Transaction tx(cx);
  auto place = [&](VertexId base, VertexId u, VertexId w) {
    Vec3 p = cx.position(base);
    return cx.addVertex(p + 0.3 * (cx.position(u) - p) + 0.3 * (cx.position(w) - p));
  };
  const VertexId na = place(a, fa, ga), nb = place(b, fb, gb);
  // Local frame of X and Y: x along e, face y=0 on f, face z=0 on g.
  std::array<VertexId, 8> v;
  v[size_t(cornerAt(0, 0, 0))] = a;
  v[size_t(cornerAt(1, 0, 0))] = b;
  v[size_t(cornerAt(0, 0, 1))] = fa;
  v[size_t(cornerAt(1, 0, 1))] = fb;
  v[size_t(cornerAt(0, 1, 0))] = ga;
  v[size_t(cornerAt(1, 1, 0))] = gb;
  v[size_t(cornerAt(0, 1, 1))] = na;
  v[size_t(cornerAt(1, 1, 1))] = nb;
  cx.unglue(fL.hex, fL.face);
  cx.unglue(gL.hex, gL.face);
  HexId X = cx.addHex(v), Y = cx.addHex(v);
  glueByVertices(cx, X, 2, fL.hex, fL.face);
  glueByVertices(cx, X, 4, gL.hex, gL.face);
  glueByVertices(cx, Y, 2, fR.hex, fR.face);
  glueByVertices(cx, Y, 4, gR.hex, gR.face);
  for (int k : {0, 1, 3, 5}) glueByVertices(cx, X, k, Y, k);
  OpResult r;
  r.op = kind;
  r.createdHexes = {X, Y};
  r.createdVertices = {na, nb};
  r.inverse = makeStep(OpKind::ChordPull, X);
  tx.commit(r, {X, Y, fL.hex, fR.hex, gL.hex, gR.hex});
  return r;
}

OpResult chordPull(Complex& cx, HexId x) {
  const OpKind kind = OpKind::ChordPull;
  const std::string op = opName(kind);
  if (!cx.isHex(x)) reject(op, hexName(x) + " does not exist");
  const HexId y = partnerSharing(cx, x, 4);
  if (y < 0) reject(op, hexName(x) + " is not half of a blind chord (no hex shares exactly 4 quads with it)");
  const std::vector<int> freeX = facesNotGluedTo(cx, x, y);
  if (axisOfFace(freeX[0]) == axisOfFace(freeX[1]))
    reject(op, "the two quads of " + hexName(x) + " not shared with " + hexName(y) + " are opposite; they must share an edge");
  // y's free faces carry the same vertices as x's.
  std::vector<int> freeY = facesNotGluedTo(cx, y, x);
  if (freeY.size() != 2) reject(op, hexName(y) + " does not share exactly 4 quads with " + hexName(x));
  if (faceVertexSet(cx, y, freeY[0]) != faceVertexSet(cx, x, freeX[0])) std::swap(freeY[0], freeY[1]);
  for (int k = 0; k < 2; ++k) {
    if (faceVertexSet(cx, y, freeY[size_t(k)]) != faceVertexSet(cx, x, freeX[size_t(k)]))
      reject(op, "the free quads of " + hexName(x) + " and " + hexName(y) + " are not on the same vertices");
    if (cx.gluing(x, freeX[size_t(k)]).boundary() || cx.gluing(y, freeY[size_t(k)]).boundary())
      reject(op, "the blind chord of " + hexName(x) + " and " + hexName(y) + " touches the boundary");
  }
  // The two corners of x on neither free face are its inner vertices: used by x and y only.
  std::vector<VertexId> inner;
  for (int c = 0; c < 8; ++c) {
    if (positionInFace(freeX[0], c) >= 0 || positionInFace(freeX[1], c) >= 0) continue;
    if (cx.cornersOfVertex(x, c).size() != 2)
      reject(op, "vertex " + std::to_string(cx.vertex(x, c)) + " inside the blind chord is used by other hexes");
    inner.push_back(cx.vertex(x, c));
  }
  QuadSide f1 = {cx.gluing(x, freeX[0]).hex, cx.gluing(x, freeX[0]).face};
  QuadSide f2 = {cx.gluing(y, freeY[0]).hex, cx.gluing(y, freeY[0]).face};
  QuadSide g1 = {cx.gluing(x, freeX[1]).hex, cx.gluing(x, freeX[1]).face};
  QuadSide g2 = {cx.gluing(y, freeY[1]).hex, cx.gluing(y, freeY[1]).face};
  if (f1.hex == y || f2.hex == x || g1.hex == y || g2.hex == x) reject(op, "the blind chord is glued to itself");
  // The restored edge: the one shared by f and g, named in f1's hex.
  int sharedCorners[2], ns = 0;
  for (int c = 0; c < 8; ++c)
    if (positionInFace(freeX[0], c) >= 0 && positionInFace(freeX[1], c) >= 0) sharedCorners[ns++] = c;
  int e1 = edgeBetween(cx.mappedCorner(x, freeX[0], sharedCorners[0]), cx.mappedCorner(x, freeX[0], sharedCorners[1]));
  Transaction tx(cx);
  for (int k = 0; k < 6; ++k) cx.unglue(x, k);
  for (int k = 0; k < 6; ++k) cx.unglue(y, k);
  cx.removeHex(x);
  cx.removeHex(y);
  glueByVertices(cx, f1.hex, f1.face, f2.hex, f2.face);
  glueByVertices(cx, g1.hex, g1.face, g2.hex, g2.face);
  OpResult r;
  r.op = kind;
  r.removedHexes = {x, y};
  r.removedVertices = inner;
  r.inverse = makeStep(OpKind::ChordPush, EdgeRef{f1.hex, e1}, f1, g1);
  tx.commit(r, {f1.hex, f2.hex, g1.hex, g2.hex});
  return r;
}

}  // namespace hexdual
