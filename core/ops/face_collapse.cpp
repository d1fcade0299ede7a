// Face open-collapse and its inverse (TK03 §4.4; MOAB face_open_collapse).
#include "ops/support.hpp"

namespace hexdual {
using namespace tables;
using namespace ops;

namespace {
int cornerWithVertex(const Complex& cx, HexId h, VertexId v) {
  for (int c = 0; c < 8; ++c)
    if (cx.vertex(h, c) == v) return c;
  return -1;
}
}  // namespace

namespace ops {
std::string faceCollapsePrecheck(const Complex& cx, EdgeRef e, QuadSide f, QuadSide g) {
  thread_local ArcSplit scratch;  // its star's storage is reused: rejected steps allocate nothing
  return arcSplitInto(cx, e, f, g, opName(OpKind::FaceCollapse), "face collapse", scratch);
}
}  // namespace ops

OpResult faceCollapse(Complex& cx, EdgeRef e, QuadSide f, QuadSide g) {
  const OpKind kind = OpKind::FaceCollapse;
  const std::string op = opName(kind);
  const ArcSplit sp = arcSplit(cx, e, f, g, op, "face collapse");
  const QuadSide fL = sp.fL, fR = sp.fR, gL = sp.gL, gR = sp.gR;
  const EdgeRef li = sp.li, lj = sp.lj;
  const VertexId c = sp.fa, d = sp.fb, c2 = sp.ga, d2 = sp.gb;
  // c merges with c2 and d with d2. A boundary vertex keeps its id and place, so the boundary quad
  // mesh is unchanged; two boundary vertices never merge. Otherwise the smaller id stays.
  auto survivor = [&](VertexId x, HexId hx, VertexId y, HexId hy) {
    const bool bx = vertexOnBoundary(cx, hx, cornerWithVertex(cx, hx, x));
    const bool by = vertexOnBoundary(cx, hy, cornerWithVertex(cx, hy, y));
    if (bx && by)
      reject(op, "vertices " + std::to_string(x) + " and " + std::to_string(y) + " would merge but both are on the boundary");
    return bx ? x : by ? y : std::min(x, y);
  };
  std::vector<std::pair<HexId, int>> cornersC2, cornersD2, cornersC, cornersD;
  cornersC = cx.cornersOfVertex(li.hex, cornerWithVertex(cx, li.hex, c));
  cornersD = cx.cornersOfVertex(li.hex, cornerWithVertex(cx, li.hex, d));
  cornersC2 = cx.cornersOfVertex(lj.hex, cornerWithVertex(cx, lj.hex, c2));
  cornersD2 = cx.cornersOfVertex(lj.hex, cornerWithVertex(cx, lj.hex, d2));
  const VertexId keepC = survivor(c, li.hex, c2, lj.hex), keepD = survivor(d, li.hex, d2, lj.hex);
  std::vector<HexId> touched;
  Transaction tx(cx);
  cx.unglue(fL.hex, fL.face);
  cx.unglue(gL.hex, gL.face);
  for (const auto& list : {cornersC, cornersC2})
    for (auto [h, k] : list) {
      cx.setCorner(h, k, keepC);
      touched.push_back(h);
    }
  for (const auto& list : {cornersD, cornersD2})
    for (auto [h, k] : list) {
      cx.setCorner(h, k, keepD);
      touched.push_back(h);
    }
  OpResult r;
  r.op = kind;
  r.removedVertices = {keepC == c ? c2 : c, keepD == d ? d2 : d};
  if (fL == gL || fR == gR) reject(op, "the collapse would glue a quad to itself");
  int o1 = orientByVertices(cx, fL.hex, fL.face, gL.hex, gL.face), o2 = orientByVertices(cx, fR.hex, fR.face, gR.hex, gR.face);
  if (o1 < 0 || o2 < 0) reject(op, "after merging, the opened quads do not carry the same vertices");
  cx.glue(fL.hex, fL.face, gL.hex, gL.face, o1);
  cx.glue(fR.hex, fR.face, gR.hex, gR.face, o2);
  for (QuadSide s : {fL, fR, gL, gR}) touched.push_back(s.hex);
  r.inverse = makeStep(OpKind::FaceSplit, fL, fR);
  tx.commitIfValid(r, touched, op, "the result would not be a valid complex");
  return r;
}

OpResult faceSplit(Complex& cx, QuadSide sL, QuadSide sR) {
  const OpKind kind = OpKind::FaceSplit;
  const std::string op = opName(kind);
  for (QuadSide s : {sL, sR}) {
    if (!cx.isHex(s.hex)) reject(op, hexName(s.hex) + " does not exist");
    if (s.face < 0 || s.face > 5) reject(op, "local face " + std::to_string(s.face) + " is not 0..5");
    if (cx.gluing(s).boundary()) reject(op, "quad " + entityName(s) + " is on the boundary");
  }
  if (cx.canonical(sL) == cx.canonical(sR)) reject(op, "the two sides belong to the same quad");
  if (faceVertexSet(cx, sL.hex, sL.face) != faceVertexSet(cx, sR.hex, sR.face))
    reject(op, "quads " + entityName(sL) + " and " + entityName(sR) + " are not on the same 4 vertices");
  const QuadSide gL{cx.gluing(sL).hex, cx.gluing(sL).face}, gR{cx.gluing(sR).hex, cx.gluing(sR).face};
  // The quads share 3 of their 4 edges; the fourth (a doubled edge ab) stays, the vertices c, d
  // opposite it split in two.
  auto edgesOf = [&](QuadSide s) {
    std::vector<EdgeRef> es;
    for (int p = 0; p < 4; ++p) es.push_back(cx.canonical(EdgeRef{s.hex, kFaceEdges[size_t(s.face)][size_t(p)]}));
    return es;
  };
  auto eL = edgesOf(sL), eR = edgesOf(sR);
  int own = -1, owns = 0;
  for (int p = 0; p < 4; ++p)
    if (std::find(eR.begin(), eR.end(), eL[size_t(p)]) == eR.end()) {
      own = p;
      ++owns;
    }
  if (owns != 1) reject(op, "quads " + entityName(sL) + " and " + entityName(sR) + " are not a collapsed face pair");
  const int cA = kFaceCorners[size_t(sL.face)][size_t(own)], cB = kFaceCorners[size_t(sL.face)][size_t((own + 1) & 3)];
  const int cD = kFaceCorners[size_t(sL.face)][size_t((own + 2) & 3)], cC = kFaceCorners[size_t(sL.face)][size_t((own + 3) & 3)];
  // cC and cD are the vertices opposite the doubled edge (cA, cB): they split.
  std::vector<QuadSide> walls{sL, gL, sR, gR};
  struct Split {
    VertexId v;
    std::vector<std::pair<HexId, int>> gSide;
  };
  std::vector<Split> splits;
  for (int corner : {cC, cD}) {
    Split s{cx.vertex(sL.hex, corner), splitVertex(cx, {sL.hex, corner}, walls, op, "the two quads").moved};
    splits.push_back(s);
  }
  Transaction tx(cx);
  cx.unglue(sL.hex, sL.face);
  cx.unglue(sR.hex, sR.face);
  OpResult r;
  r.op = kind;
  std::vector<HexId> touched{sL.hex, sR.hex, gL.hex, gR.hex};
  for (const Split& s : splits) {
    Vec3 c;
    for (auto [h, k] : s.gSide) c = c + (1.0 / double(s.gSide.size())) * cx.hexCentroid(h);
    Vec3 p = cx.position(s.v);
    VertexId nv = cx.addVertex(p + 0.25 * (c - p));
    r.createdVertices.push_back(nv);
    for (auto [h, k] : s.gSide) {
      cx.setCorner(h, k, nv);
      touched.push_back(h);
    }
  }
  int o1 = orientByVertices(cx, sL.hex, sL.face, sR.hex, sR.face), o2 = orientByVertices(cx, gL.hex, gL.face, gR.hex, gR.face);
  if (o1 < 0 || o2 < 0) reject(op, "after splitting, the quads to re-glue do not carry the same vertices");
  cx.glue(sL.hex, sL.face, sR.hex, sR.face, o1);
  cx.glue(gL.hex, gL.face, gR.hex, gR.face, o2);
  // The restored edge ab, named in sL's hex, and f = sL, g = gL's quad.
  r.inverse = makeStep(OpKind::FaceCollapse, EdgeRef{sL.hex, edgeBetween(cA, cB)}, sL, gL);
  tx.commitIfValid(r, touched, op, "the result would not be a valid complex");
  return r;
}

}  // namespace hexdual
