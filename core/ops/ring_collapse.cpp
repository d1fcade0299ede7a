// Ring collapse and ring split (TK03 §4.4): the only atomic operation that cuts and rejoins
// chords and merges sheets.
#include <map>

#include "ops/support.hpp"

namespace hexdual {
using namespace tables;
using namespace ops;

namespace {

struct RingHex {
  HexId hex;
  int axis, entry, exit;
  int diag;  // local edge along the chord whose vertex line merges with its diagonal opposite
  int keep;  // one of the two kept edges, carried round the ring (its side quads form band f)
};

// The edge along `axis` at the corner that `edge`'s end on face `exitFace` maps to across the gluing.
int carryEdge(const Complex& cx, HexId h, int exitFace, int edge, int axis) {
  int c = positionInFace(exitFace, kEdgeCorners[size_t(edge)][0]) >= 0 ? kEdgeCorners[size_t(edge)][0]
                                                                       : kEdgeCorners[size_t(edge)][1];
  return edgesOfCorner(cx.mappedCorner(h, exitFace, c))[size_t(axis)];
}


// Walks the chord through e's hex along e's axis, carrying e's diagonal round the ring.
std::vector<RingHex> walkRing(const Complex& cx, EdgeRef e, const std::string& op) {
  if (!cx.isHex(e.hex)) reject(op, hexName(e.hex) + " does not exist");
  if (e.edge < 0 || e.edge > 11) reject(op, "local edge " + std::to_string(e.edge) + " is not 0..11");
  std::vector<RingHex> ring;
  int axis = axisOfEdge(e.edge);
  RingHex cur{e.hex, axis, 2 * axis, 2 * axis + 1, e.edge, e.edge ^ 2};
  for (;;) {
    for (const RingHex& r : ring)
      if (r.hex == cur.hex) reject(op, "the chord passes " + hexName(cur.hex) + " twice; a ring must not cross itself");
    ring.push_back(cur);
    Gluing g = cx.gluing(cur.hex, cur.exit);
    if (g.boundary())
      reject(op, "the chord through " + entityName(e) + " reaches the boundary; ring collapse needs a closed chord");
    // Carry the diagonal and the kept edge: their corners on the exit face map into the next hex.
    int a2 = axisOfFace(g.face);
    RingHex next{g.hex, a2, g.face, oppositeFace(g.face), carryEdge(cx, cur.hex, cur.exit, cur.diag, a2),
                 carryEdge(cx, cur.hex, cur.exit, cur.keep, a2)};
    if (next.hex == ring[0].hex && next.axis == ring[0].axis) {
      if (next.entry != ring[0].entry) reject(op, "the chord through " + entityName(e) + " returns reversed");
      if (next.diag != ring[0].diag && next.diag != (ring[0].diag ^ 3))
        reject(op, "carried round the ring, the diagonal of " + entityName(e) + " comes back as the other diagonal");
      return ring;
    }
    cur = next;
  }
}

// The inverse: one (f, g) pair per ring hex, the outside sides met at the two kept edges. After
// the collapse two of those quads can have been glued into one, or onto the boundary: the step is
// reported only when it applies and restores the counts (tried, then undone exactly).
void reportInverseIfValid(Complex& cx, OpResult& res, const std::vector<std::pair<QuadSide, QuadSide>>& bands) {
  OpStep inv{OpKind::RingSplit, {}, 0};
  for (auto [f, g] : bands) inv.args.push_back(OpArg::of(f, g));
  try {
    OpResult back = ringSplit(cx, bands);
    cx.undo(back.edits);
    if (back.dV != -res.dV || back.dE != -res.dE || back.dF != -res.dF || back.dH != -res.dH)
      res.noInverse = "the ring split of the collapsed loop would not restore the counts";
    else
      res.inverse = inv;
  } catch (const Error& e) {
    res.noInverse = "the ring split of the collapsed loop does not apply (" + std::string(e.what()) + ")";
  }
}

}  // namespace

OpResult ringCollapse(Complex& cx, EdgeRef e) {
  const OpKind kind = OpKind::RingCollapse;
  const std::string op = opName(kind);
  std::vector<RingHex> ring = walkRing(cx, e, op);
  auto inRing = [&](HexId h) {
    for (const RingHex& r : ring)
      if (r.hex == h) return true;
    return false;
  };
  // Side faces, their collapse partners (the other side face at the same kept corner edge).
  std::map<std::pair<HexId, int>, int> collapsePartner;
  std::map<VertexId, VertexId> merge;  // vertex -> representative (the smallest id of its class)
  auto find = [&](VertexId v) {
    while (merge.count(v) && merge[v] != v) v = merge[v];
    return v;
  };
  std::vector<std::pair<HexId, int>> mergedCorners;
  for (const RingHex& r : ring) {
    for (int s = 0; s < 6; ++s)
      if (axisOfFace(s) != r.axis && cx.gluing(r.hex, s).boundary())
        reject(op, "side quad " + entityName(QuadSide{r.hex, s}) + " of the ring is on the boundary");
    for (int keep : {r.keep, r.keep ^ 3}) {
      auto fs = facesOfEdge(keep);
      collapsePartner[{r.hex, fs[0]}] = fs[1];
      collapsePartner[{r.hex, fs[1]}] = fs[0];
    }
    for (int k = 0; k < 2; ++k) {
      int c1 = kEdgeCorners[size_t(r.diag)][size_t(k)], c2 = kEdgeCorners[size_t(r.diag ^ 3)][size_t(k)];
      VertexId v1 = find(cx.vertex(r.hex, c1)), v2 = find(cx.vertex(r.hex, c2));
      for (auto [v, c] : {std::pair{v1, c1}, std::pair{v2, c2}}) {
        merge.emplace(v, v);
        mergedCorners.push_back({r.hex, c});
      }
      if (v1 != v2) merge[std::max(v1, v2)] = std::min(v1, v2);
    }
  }
  // A class holding a boundary vertex merges into it (id and place kept), so the boundary quad
  // mesh is unchanged; two boundary vertices never merge.
  std::map<VertexId, VertexId> boundaryOf;  // class representative -> its boundary vertex
  for (auto [h, c] : mergedCorners) {
    if (!vertexOnBoundary(cx, h, c)) continue;
    VertexId v = cx.vertex(h, c);
    auto [it, fresh] = boundaryOf.emplace(find(v), v);
    if (!fresh && it->second != v)
      reject(op, "vertices " + std::to_string(it->second) + " and " + std::to_string(v) +
                     " would merge but both are on the boundary");
  }
  auto target = [&](VertexId v) {
    auto it = boundaryOf.find(find(v));
    return it == boundaryOf.end() ? find(v) : it->second;
  };

  // Chase side gluings through collapse pairs: outside side -> ring side -> partner -> ... -> outside side.
  std::vector<std::pair<QuadSide, QuadSide>> outsidePairs;
  std::map<std::pair<HexId, int>, bool> done;
  for (const RingHex& r : ring)
    for (int s = 0; s < 6; ++s) {
      if (axisOfFace(s) == r.axis || done[{r.hex, s}]) continue;
      Gluing g = cx.gluing(r.hex, s);
      if (inRing(g.hex)) continue;  // start only from sides that face outside
      done[{r.hex, s}] = true;
      QuadSide start{g.hex, g.face};
      std::pair<HexId, int> cur{r.hex, collapsePartner[{r.hex, s}]};
      for (;;) {
        done[cur] = true;
        Gluing n = cx.gluing(cur.first, cur.second);
        if (!inRing(n.hex)) {
          outsidePairs.push_back({start, {n.hex, n.face}});
          break;
        }
        done[{n.hex, n.face}] = true;
        cur = {n.hex, collapsePartner[{n.hex, n.face}]};
      }
    }
  // Outside corners whose vertices merge.
  std::vector<std::pair<HexId, int>> renumber;
  std::vector<HexId> touched;
  for (auto [h, c] : mergedCorners)
    for (auto [hh, cc] : cx.cornersOfVertex(h, c))
      if (!inRing(hh)) {
        renumber.push_back({hh, cc});
        touched.push_back(hh);
      }
  for (auto [a, b] : outsidePairs) {
    touched.push_back(a.hex);
    touched.push_back(b.hex);
  }
  // For the inverse: per ring hex, the outside sides met at the two kept edges (f at diag^2, g at diag^1).
  std::vector<std::pair<QuadSide, QuadSide>> bandSides;
  bool allOutside = true;
  for (const RingHex& r : ring) {
    Gluing gf = cx.gluing(r.hex, facesOfEdge(r.keep)[0]), gg = cx.gluing(r.hex, facesOfEdge(r.keep ^ 3)[0]);
    allOutside = allOutside && !inRing(gf.hex) && !inRing(gg.hex);
    bandSides.push_back({{gf.hex, gf.face}, {gg.hex, gg.face}});
  }
  std::vector<VertexId> ringVertices;
  for (const RingHex& r : ring)
    for (VertexId v : cx.hexVertices(r.hex)) ringVertices.push_back(v);

  Transaction tx(cx);
  for (const RingHex& r : ring)
    for (int f = 0; f < 6; ++f) cx.unglue(r.hex, f);
  for (const RingHex& r : ring) cx.removeHex(r.hex);
  for (auto [h, c] : renumber) cx.setCorner(h, c, target(cx.vertex(h, c)));
  OpResult res;
  res.op = kind;
  for (auto [a, b] : outsidePairs) {
    if (a == b) reject(op, "the collapse would glue " + entityName(a) + " to itself");
    int o = orientByVertices(cx, a.hex, a.face, b.hex, b.face);
    if (o < 0) reject(op, "after the collapse " + entityName(a) + " and " + entityName(b) + " do not carry the same vertices");
    cx.glue(a.hex, a.face, b.hex, b.face, o);
  }
  tx.commitIfValid(res, touched, op, "the result would not be a valid complex");
  for (const RingHex& r : ring) res.removedHexes.push_back(r.hex);
  std::sort(ringVertices.begin(), ringVertices.end());
  ringVertices.erase(std::unique(ringVertices.begin(), ringVertices.end()), ringVertices.end());
  for (VertexId v : ringVertices)
    if (!cx.isVertex(v)) res.removedVertices.push_back(v);
  if (!allOutside) {
    res.noInverse = "a side quad of the ring was glued to the ring itself";
    return res;
  }
  std::vector<std::pair<QuadSide, QuadSide>> bands;
  for (auto [f, g] : bandSides) bands.push_back({cx.canonical(f), cx.canonical(g)});
  reportInverseIfValid(cx, res, bands);
  return res;
}

OpResult ringSplit(Complex& cx, const std::vector<std::pair<QuadSide, QuadSide>>& bands) {
  const OpKind kind = OpKind::RingSplit;
  const std::string op = opName(kind);
  const size_t n = bands.size();
  if (n < 2) reject(op, "needs at least 2 quad pairs around a loop");
  std::vector<QuadSide> F(n), G(n), walls;
  for (size_t k = 0; k < n; ++k) {
    for (QuadSide s : {bands[k].first, bands[k].second}) {
      if (!cx.isHex(s.hex)) reject(op, hexName(s.hex) + " does not exist");
      if (s.face < 0 || s.face > 5) reject(op, "local face " + std::to_string(s.face) + " is not 0..5");
      if (cx.gluing(s).boundary()) reject(op, "quad " + entityName(s) + " is on the boundary");
      Gluing g = cx.gluing(s);
      walls.push_back(s);
      walls.push_back({g.hex, g.face});
    }
    F[k] = bands[k].first;
    G[k] = bands[k].second;
  }
  // The loop edge m_k shared by f_k and g_k, and the loop's vertices M_k (m_k runs M_k -> M_k+1).
  auto faceVerts = [&](QuadSide s) {
    std::array<VertexId, 4> v;
    for (int p = 0; p < 4; ++p) v[size_t(p)] = cx.vertex(s.hex, kFaceCorners[size_t(s.face)][size_t(p)]);
    return v;
  };
  auto adjacentIn = [&](QuadSide s, VertexId v, VertexId away) {  // the neighbour of v in s other than `away`
    auto fv = faceVerts(s);
    for (int p = 0; p < 4; ++p)
      if (fv[size_t(p)] == v) return fv[size_t((p + 1) & 3)] == away ? fv[size_t((p + 3) & 3)] : fv[size_t((p + 1) & 3)];
    return VertexId(-1);
  };
  std::vector<std::array<VertexId, 2>> m(n);
  for (size_t k = 0; k < n; ++k) {
    auto fv = faceVerts(F[k]), gv = faceVerts(G[k]);
    std::vector<VertexId> common;
    for (VertexId v : fv)
      if (std::find(gv.begin(), gv.end(), v) != gv.end()) common.push_back(v);
    if (common.size() != 2)
      reject(op, "quads " + entityName(F[k]) + " and " + entityName(G[k]) + " must share exactly one edge");
    m[k] = {common[0], common[1]};
  }
  std::vector<VertexId> M(n);
  auto has = [](const std::array<VertexId, 2>& e, VertexId v) { return e[0] == v || e[1] == v; };
  M[0] = has(m[1], m[0][0]) && !has(m[1], m[0][1]) ? m[0][1] : m[0][0];
  for (size_t k = 0; k < n; ++k) {
    if (!has(m[k], M[k])) reject(op, "the shared edges of the quad pairs do not form a loop");
    VertexId next = m[k][0] == M[k] ? m[k][1] : m[k][0];
    if (k + 1 < n) M[k + 1] = next;
    else if (next != M[0]) reject(op, "the shared edges of the quad pairs do not close into a loop");
  }
  for (size_t k = 0; k < n; ++k)
    for (size_t j = 0; j < k; ++j)
      if (M[j] == M[k]) reject(op, "the loop passes vertex " + std::to_string(M[k]) + " twice");
  std::vector<VertexId> C01(n), C23(n);
  for (size_t k = 0; k < n; ++k) {
    C01[k] = adjacentIn(F[k], M[k], M[(k + 1) % n]);
    C23[k] = adjacentIn(G[k], M[k], M[(k + 1) % n]);
    size_t prev = (k + n - 1) % n;
    if (adjacentIn(F[prev], M[k], M[prev]) != C01[k] || adjacentIn(G[prev], M[k], M[prev]) != C23[k])
      reject(op, "the quads do not form two strips along the loop (pair " + std::to_string(k) + ")");
  }
  // Split each loop vertex: side A is reached from f_k's A side without crossing walls. Side B
  // takes the new vertex, unless the boundary is on side B: then side A does.
  auto cornerOf = [&](QuadSide s, VertexId v) {
    for (int p = 0; p < 4; ++p)
      if (cx.vertex(s.hex, kFaceCorners[size_t(s.face)][size_t(p)]) == v)
        return std::pair<HexId, int>{s.hex, kFaceCorners[size_t(s.face)][size_t(p)]};
    return std::pair<HexId, int>{-1, -1};
  };
  auto partnerOf = [&](QuadSide s) { return QuadSide{cx.gluing(s).hex, cx.gluing(s).face}; };
  std::vector<std::vector<std::pair<HexId, int>>> moved(n);  // per loop vertex: the corners that take the new vertex
  std::vector<bool> movedIsA(n, false);  // side B is on the boundary: side A takes the new vertex
  std::vector<QuadSide> fA(n), gA(n);
  QuadSide seedSide = F[0];
  for (size_t k = 0; k <= n; ++k) {
    size_t kk = k % n;
    auto seed = cornerOf(seedSide, M[kk]);
    if (k == n) {
      auto A = cornersOnSide(cx, seed, walls);
      if (std::find(A.begin(), A.end(), cornerOf(fA[0], M[0])) == A.end())
        reject(op, "the strips are one-sided (a Moebius band); the ring cannot be split");
      break;
    }
    VertexSplit split = splitVertex(cx, seed, walls, op, "the quads");
    movedIsA[kk] = std::find(split.moved.begin(), split.moved.end(), seed) != split.moved.end();
    const auto& A = movedIsA[kk] ? split.moved : split.keep;
    moved[kk] = split.moved;
    auto inA = [&](QuadSide s) { return std::find(A.begin(), A.end(), cornerOf(s, M[kk])) != A.end(); };
    fA[kk] = inA(F[kk]) ? F[kk] : partnerOf(F[kk]);
    gA[kk] = inA(G[kk]) ? G[kk] : partnerOf(G[kk]);
    if (!inA(fA[kk]) || inA(partnerOf(fA[kk])) || !inA(gA[kk]) || inA(partnerOf(gA[kk])))
      reject(op, "the quads do not separate vertex " + std::to_string(M[kk]) + " consistently");
    seedSide = fA[kk];  // carry side A along f_k to M_k+1
  }

  Transaction tx(cx);
  std::vector<QuadSide> fB(n), gB(n);
  for (size_t k = 0; k < n; ++k) {
    fB[k] = partnerOf(fA[k]);
    gB[k] = partnerOf(gA[k]);
  }
  for (size_t k = 0; k < n; ++k) {
    cx.unglue(fA[k].hex, fA[k].face);
    cx.unglue(gA[k].hex, gA[k].face);
  }
  std::vector<VertexId> M2(n), atA(n), atB(n);
  for (size_t k = 0; k < n; ++k) {
    Vec3 c;
    for (auto [h, cc] : moved[k]) c = c + (1.0 / double(moved[k].size())) * cx.hexCentroid(h);
    Vec3 p = cx.position(M[k]);
    M2[k] = cx.addVertex(p + 0.2 * (c - p));
    for (auto [h, cc] : moved[k]) cx.setCorner(h, cc, M2[k]);
    atA[k] = movedIsA[k] ? M2[k] : M[k];
    atB[k] = movedIsA[k] ? M[k] : M2[k];
  }
  std::vector<HexId> ringHexes;
  for (size_t k = 0; k < n; ++k) {
    size_t k1 = (k + 1) % n;
    std::array<VertexId, 8> v;
    v[size_t(cornerAt(0, 0, 0))] = atB[k];
    v[size_t(cornerAt(1, 0, 0))] = atB[k1];
    v[size_t(cornerAt(0, 1, 0))] = C01[k];
    v[size_t(cornerAt(1, 1, 0))] = C01[k1];
    v[size_t(cornerAt(0, 1, 1))] = atA[k];
    v[size_t(cornerAt(1, 1, 1))] = atA[k1];
    v[size_t(cornerAt(0, 0, 1))] = C23[k];
    v[size_t(cornerAt(1, 0, 1))] = C23[k1];
    ringHexes.push_back(cx.addHex(v));
  }
  std::vector<HexId> touched = ringHexes;
  for (size_t k = 0; k < n; ++k) {
    HexId h = ringHexes[k];
    glueByVertices(cx, h, 4, fB[k].hex, fB[k].face);
    glueByVertices(cx, h, 3, fA[k].hex, fA[k].face);
    glueByVertices(cx, h, 5, gA[k].hex, gA[k].face);
    glueByVertices(cx, h, 2, gB[k].hex, gB[k].face);
    glueByVertices(cx, h, 1, ringHexes[(k + 1) % n], 0);
    for (QuadSide s : {fA[k], fB[k], gA[k], gB[k]}) touched.push_back(s.hex);
  }
  OpResult res;
  res.op = kind;
  res.createdHexes = ringHexes;
  res.createdVertices = M2;
  res.inverse = makeStep(OpKind::RingCollapse, EdgeRef{ringHexes[0], 3});
  tx.commitIfValid(res, touched, op, "the result would not be a valid complex");
  return res;
}

}  // namespace hexdual
