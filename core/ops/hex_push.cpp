// Hex push (the 2-6 flip) and hex pull (6-2), TK03 §4.2, Figs. 4-5; MOAB face_shrink.
#include "ops/support.hpp"

namespace hexdual {
using namespace tables;
using namespace ops;

namespace {
int sharedQuads(const Complex& cx, HexId a, HexId b) {
  int n = 0;
  for (int f = 0; f < 6; ++f) n += !cx.gluing(a, f).boundary() && cx.gluing(a, f).hex == b;
  return n;
}
}  // namespace

namespace ops {
std::string hexPushPrecheck(const Complex& cx, QuadSide q) {
  const std::string op = opName(OpKind::HexPush);
  if (std::string why = interiorQuadProblem(cx, q, op, "hex push needs an interior quad"); !why.empty()) return why;
  const HexId A = q.hex, B = cx.gluing(q).hex;
  if (A == B) return op + ": quad " + entityName(q) + " joins " + hexName(A) + " to itself";
  int shared = sharedQuads(cx, A, B);
  if (shared != 1)
    return op + ": hexes " + std::to_string(A) + " and " + std::to_string(B) + " share " + std::to_string(shared) +
           " quads; hex push needs exactly one";
  int common = 0;
  for (VertexId v : cx.hexVertices(A))
    for (VertexId w : cx.hexVertices(B)) common += v == w;
  if (common != 4)
    return op + ": hexes " + std::to_string(A) + " and " + std::to_string(B) + " share " + std::to_string(common) +
           " vertices; hex push needs exactly the 4 of the quad";
  return {};
}
// The 2-6 flip's 23 gluings, in the order of hexPush's new hexes: A' = 0 (on A's corners), B' = 1
// (on B's), and 2 + k the ring hex of A's k-th side face s (on A's corners). A' keeps A's far face
// and meets B' across r; ring hex s keeps A's side quad s (its face s) and B's side quad t beside
// it (its face fA), and meets A' (its face opposite fA, A's face s), B' (its face opposite s, B's
// face t) and, across its face u, the ring hex of A's side face u (its face s). hex_push's comment
// on the corners says which vertices each of these faces carries.
std::array<PlannedGluing, 23> hexPushGluings(int fA, int fB, const std::array<int, 4>& cA, const std::array<int, 4>& cB) {
  const int na = axisOfFace(fA);
  std::array<int, 4> side{};  // A's side faces, in the ring hexes' order
  for (int f = 0, k = 0; f < 6; ++f)
    if (axisOfFace(f) != na) side[size_t(k++)] = f;
  // B's side face beside A's side face s: the one of B's faces other than fB through the B corners
  // of the two q corners on s.
  auto besideInB = [&](int s) {
    std::array<int, 2> onS{};
    for (int p = 0, n = 0; p < 4; ++p)
      if (positionInFace(s, cA[size_t(p)]) >= 0) onS[size_t(n++)] = cB[size_t(p)];
    for (int f = 0; f < 6; ++f)
      if (f != fB && positionInFace(f, onS[0]) >= 0 && positionInFace(f, onS[1]) >= 0) return f;
    return -1;
  };
  constexpr int8_t kA = -1, kB = -2;  // the removed hexes, as PlannedGluing::other
  std::array<PlannedGluing, 23> plan{};
  size_t i = 0;
  auto add = [&](int hex, int face, int other, int otherFace) {
    plan[i++] = {int8_t(hex), int8_t(face), int8_t(other), int8_t(otherFace)};
  };
  add(0, fA, 1, fB);
  add(0, oppositeFace(fA), kA, oppositeFace(fA));
  add(1, oppositeFace(fB), kB, oppositeFace(fB));
  for (int k = 0; k < 4; ++k) {
    const int s = side[size_t(k)], t = besideInB(s);
    add(2 + k, s, kA, s);
    add(2 + k, fA, kB, t);
    add(0, s, 2 + k, oppositeFace(fA));
    add(1, t, 2 + k, oppositeFace(s));
    for (int m = k + 1; m < 4; ++m)
      if (axisOfFace(side[size_t(m)]) != axisOfFace(s)) add(2 + k, side[size_t(m)], 2 + m, s);
  }
  return plan;
}
}  // namespace ops

OpResult hexPush(Complex& cx, QuadSide q) {
  const OpKind kind = OpKind::HexPush;
  const std::string op = opName(kind);
  if (std::string why = hexPushPrecheck(cx, q); !why.empty()) throw Error(why);
  const Gluing gB = cx.gluing(q);
  const HexId A = q.hex, B = gB.hex;
  const int fA = q.face, fB = gB.face;

  // Q: q's vertices (A's face positions); P: across A; R: across B; N: new, halfway to q's centre.
  const int na = axisOfFace(fA), nb = axisOfFace(fB);
  std::array<int, 4> cA, cB;
  Vec3 centre;
  for (int p = 0; p < 4; ++p) {
    cA[size_t(p)] = kFaceCorners[size_t(fA)][size_t(p)];
    cB[size_t(p)] = cx.mappedCorner(A, fA, cA[size_t(p)]);
    centre = centre + 0.25 * cx.position(cx.vertex(A, cA[size_t(p)]));
  }
  Transaction tx(cx);
  std::array<VertexId, 4> N;
  for (int p = 0; p < 4; ++p) N[size_t(p)] = cx.addVertex(0.5 * (cx.position(cx.vertex(A, cA[size_t(p)])) + centre));
  auto qIndexOfA = [&](int c) { return positionInFace(fA, c); };  // corner of A on q -> p
  // A' and B': A and B with q's vertices replaced by N.
  std::array<VertexId, 8> a2 = cx.hexVertices(A), b2 = cx.hexVertices(B);
  for (int p = 0; p < 4; ++p) {
    a2[size_t(cA[size_t(p)])] = N[size_t(p)];
    b2[size_t(cB[size_t(p)])] = N[size_t(p)];
  }
  std::vector<std::array<VertexId, 8>> added{a2, b2};
  // Ring hex for each side face s of A: A's corners on s stay; a corner off s takes R (if its partner
  // on s is a q corner) or N (if its partner is a corner of the face opposite q).
  for (int s = 0; s < 6; ++s) {
    if (axisOfFace(s) == na) continue;
    std::array<VertexId, 8> ring = cx.hexVertices(A);
    for (int c = 0; c < 8; ++c) {
      if (positionInFace(s, c) >= 0) continue;
      int partner = flipAxis(c, axisOfFace(s));
      int p = qIndexOfA(partner);
      if (p >= 0) {
        ring[size_t(c)] = cx.vertex(B, flipAxis(cB[size_t(p)], nb));  // R_p
      } else {
        ring[size_t(c)] = N[size_t(qIndexOfA(flipAxis(partner, na)))];  // N_p
      }
    }
    added.push_back(ring);
  }
  auto created = replaceHexesByPlan(cx, op, {A, B}, added, hexPushGluings(fA, fB, cA, cB));
  OpResult r;
  r.op = kind;
  r.removedHexes = {A, B};
  r.createdHexes = created;
  r.createdVertices.assign(N.begin(), N.end());
  r.inverse = makeStep(OpKind::HexPull, QuadSide{created[0], fA});
  // Valid by construction (so no link walks): the precheck leaves A and B sharing one quad and
  // only its 4 vertices, so the region R = A + B has 12 distinct vertices, no two of its faces
  // glued to each other but q, and no two of its edges the same edge: R is an embedded ball.
  // replaceHexes swaps it for the 2-6 flip's 6 hexes, a ball with the same boundary quads, each
  // glued to the same outside face (or left on the boundary) with the same vertices. A vertex v on
  // R's boundary had a valid link made of the part outside R and a disk inside R; the new inside
  // part is again a disk with the same boundary circle, so v's link keeps its topology. The 4 new
  // vertices lie inside the 6 hexes, each with a sphere link (4 corners, a tetrahedron's boundary).
  tx.commitValidByConstruction(r, withNeighbours(cx, created));
  return r;
}

OpResult hexPull(Complex& cx, QuadSide r) {
  const OpKind kind = OpKind::HexPull;
  const std::string op = opName(kind);
  Gluing gB = requireInteriorQuad(cx, r, op, "hex pull needs an interior quad");
  const HexId A2 = r.hex, B2 = gB.hex;
  const int fr = r.face;
  if (A2 == B2) reject(op, "quad " + entityName(r) + " joins " + hexName(A2) + " to itself");
  // The 4 hexes on A''s sides form the ring; each is glued to B' as well.
  std::vector<HexId> ring;
  for (int s = 0; s < 6; ++s) {
    if (axisOfFace(s) == axisOfFace(fr)) continue;
    Gluing g = cx.gluing(A2, s);
    if (g.boundary() || g.hex == B2 || g.hex == A2 || std::find(ring.begin(), ring.end(), g.hex) != ring.end())
      reject(op, "the 4 side quads of " + hexName(A2) + " must be glued to 4 distinct ring hexes");
    if (sharedQuads(cx, g.hex, B2) != 1 || sharedQuads(cx, g.hex, A2) != 1)
      reject(op, "ring " + hexName(g.hex) + " must share one quad with each of " + hexName(A2) + " and " + hexName(B2));
    ring.push_back(g.hex);
  }
  // The 4 vertices of r: used by A', B' and two ring hexes each.
  std::array<VertexId, 4> N, Q;
  for (int p = 0; p < 4; ++p) {
    int c = kFaceCorners[size_t(fr)][size_t(p)];
    N[size_t(p)] = cx.vertex(A2, c);
    if (cx.cornersOfVertex(A2, c).size() != 4)
      reject(op, "vertex " + std::to_string(N[size_t(p)]) + " of quad " + entityName(r) + " is used by other hexes");
    // Q_p: in a ring hex holding P_p and N_p, the edge-neighbour of P_p outside A'.
    int cp = c;
    {
      int bits[3] = {cornerBit(c, 0), cornerBit(c, 1), cornerBit(c, 2)};
      bits[axisOfFace(fr)] ^= 1;
      cp = cornerAt(bits[0], bits[1], bits[2]);
    }
    VertexId P = cx.vertex(A2, cp);
    Q[size_t(p)] = -1;
    for (HexId h : ring) {
      int ch = -1;
      for (int k = 0; k < 8; ++k)
        if (cx.vertex(h, k) == P) ch = k;
      if (ch < 0) continue;
      bool hasN = false;
      for (int k = 0; k < 8; ++k) hasN |= cx.vertex(h, k) == N[size_t(p)];
      if (!hasN) continue;
      for (int ed : edgesOfCorner(ch)) {
        int other = kEdgeCorners[size_t(ed)][0] == ch ? kEdgeCorners[size_t(ed)][1] : kEdgeCorners[size_t(ed)][0];
        VertexId w = cx.vertex(h, other);
        bool inA2 = false;
        for (VertexId u : cx.hexVertices(A2)) inA2 |= u == w;
        if (!inA2) Q[size_t(p)] = w;
      }
      break;
    }
    if (Q[size_t(p)] < 0) reject(op, "the hexes around " + entityName(r) + " do not form a hex push");
  }
  std::array<VertexId, 8> a = cx.hexVertices(A2), b = cx.hexVertices(B2);
  for (int p = 0; p < 4; ++p) {
    a[size_t(kFaceCorners[size_t(fr)][size_t(p)])] = Q[size_t(p)];
    b[size_t(cx.mappedCorner(A2, fr, kFaceCorners[size_t(fr)][size_t(p)]))] = Q[size_t(p)];
  }
  Transaction tx(cx);
  std::vector<HexId> removed{A2, B2};
  removed.insert(removed.end(), ring.begin(), ring.end());
  auto created = replaceHexes(cx, op, removed, {a, b});
  OpResult res;
  res.op = kind;
  res.removedHexes = removed;
  res.createdHexes = created;
  res.removedVertices.assign(N.begin(), N.end());
  res.inverse = makeStep(OpKind::HexPush, QuadSide{created[0], fr});
  tx.commit(res, withNeighbours(cx, created));
  return res;
}

}  // namespace hexdual
