// Ring collapse and ring split (TK03 §4.4): the only atomic operation that cuts and rejoins
// chords and merges sheets.
#include <algorithm>
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
    RingHex next{g.hex,
                 a2,
                 g.face,
                 oppositeFace(g.face),
                 carryEdge(cx, cur.hex, cur.exit, cur.diag, a2),
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

// A ring collapse worked out before anything is edited (TK03 §4.4): the ring's diagonal vertex
// lines merge (classes of vertices, a boundary vertex kept as the class's id), each outside quad
// of the ring is glued, through the ring's collapse pairs of side quads, to the outside quad across
// it, and the quads of the two kept edges are the inverse's bands.
class RingCollapsePlan {
 public:
  RingCollapsePlan(const Complex& cx, EdgeRef e, const std::string& op) : cx_(cx), op_(op), ring_(walkRing(cx, e, op)) {
    mergeDiagonals();
    keepBoundaryVertices();
    chaseSideGluings();
    collectOutsideCorners();
    collectBands();
  }
  OpResult apply(Complex& cx, OpKind kind) const;

 private:
  bool inRing(HexId h) const {
    for (const RingHex& r : ring_)
      if (r.hex == h) return true;
    return false;
  }
  VertexId find(VertexId v) const {
    for (auto it = merge_.find(v); it != merge_.end() && it->second != v; it = merge_.find(v)) v = it->second;
    return v;
  }
  VertexId target(VertexId v) const {  // the merged vertex v becomes
    auto it = boundaryOf_.find(find(v));
    return it == boundaryOf_.end() ? find(v) : it->second;
  }
  void mergeDiagonals();
  void keepBoundaryVertices();
  void chaseSideGluings();
  void collectOutsideCorners();
  void collectBands();

  const Complex& cx_;
  const std::string& op_;
  const std::vector<RingHex> ring_;
  std::map<std::pair<HexId, int>, int> collapsePartner_;  // side face -> the other side face at its kept edge
  std::map<VertexId, VertexId> merge_;                    // vertex -> representative (the smallest id of its class)
  std::vector<std::pair<HexId, int>> mergedCorners_;
  std::map<VertexId, VertexId> boundaryOf_;  // class representative -> its boundary vertex
  std::vector<std::pair<QuadSide, QuadSide>> outsidePairs_;
  std::vector<std::pair<HexId, int>> renumber_;  // outside corners whose vertices merge
  std::vector<HexId> touched_;
  std::vector<std::pair<QuadSide, QuadSide>> bandSides_;  // per ring hex: the outside sides at the kept edges
  bool allOutside_ = true;
  std::vector<VertexId> ringVertices_;
};

// Side faces and their collapse partners (the other side face at the same kept corner edge); the
// corners of each ring hex's diagonal merge with those of the opposite edge.
void RingCollapsePlan::mergeDiagonals() {
  for (const RingHex& r : ring_) {
    for (int s = 0; s < 6; ++s)
      if (axisOfFace(s) != r.axis && cx_.gluing(r.hex, s).boundary())
        reject(op_, "side quad " + entityName(QuadSide{r.hex, s}) + " of the ring is on the boundary");
    for (int keep : {r.keep, r.keep ^ 3}) {
      auto fs = facesOfEdge(keep);
      collapsePartner_[{r.hex, fs[0]}] = fs[1];
      collapsePartner_[{r.hex, fs[1]}] = fs[0];
    }
    for (int k = 0; k < 2; ++k) {
      int c1 = kEdgeCorners[size_t(r.diag)][size_t(k)], c2 = kEdgeCorners[size_t(r.diag ^ 3)][size_t(k)];
      VertexId v1 = find(cx_.vertex(r.hex, c1)), v2 = find(cx_.vertex(r.hex, c2));
      for (auto [v, c] : {std::pair{v1, c1}, std::pair{v2, c2}}) {
        merge_.emplace(v, v);
        mergedCorners_.push_back({r.hex, c});
      }
      if (v1 != v2) merge_[std::max(v1, v2)] = std::min(v1, v2);
    }
  }
}

// A class holding a boundary vertex merges into it (id and place kept), so the boundary quad
// mesh is unchanged; two boundary vertices never merge.
void RingCollapsePlan::keepBoundaryVertices() {
  for (auto [h, c] : mergedCorners_) {
    if (!vertexOnBoundary(cx_, h, c)) continue;
    VertexId v = cx_.vertex(h, c);
    auto [it, fresh] = boundaryOf_.emplace(find(v), v);
    if (!fresh && it->second != v)
      reject(op_, "vertices " + std::to_string(it->second) + " and " + std::to_string(v) +
                      " would merge but both are on the boundary");
  }
}

// Chase side gluings through collapse pairs: outside side -> ring side -> partner -> ... -> outside side.
void RingCollapsePlan::chaseSideGluings() {
  std::map<std::pair<HexId, int>, bool> done;
  for (const RingHex& r : ring_)
    for (int s = 0; s < 6; ++s) {
      if (axisOfFace(s) == r.axis || done[{r.hex, s}]) continue;
      Gluing g = cx_.gluing(r.hex, s);
      if (inRing(g.hex)) continue;  // start only from sides that face outside
      done[{r.hex, s}] = true;
      QuadSide start{g.hex, g.face};
      std::pair<HexId, int> cur{r.hex, collapsePartner_[{r.hex, s}]};
      for (;;) {
        done[cur] = true;
        Gluing n = cx_.gluing(cur.first, cur.second);
        if (!inRing(n.hex)) {
          outsidePairs_.push_back({start, {n.hex, n.face}});
          break;
        }
        done[{n.hex, n.face}] = true;
        cur = {n.hex, collapsePartner_[{n.hex, n.face}]};
      }
    }
}

// Outside corners whose vertices merge, and the hexes the collapse touches.
void RingCollapsePlan::collectOutsideCorners() {
  for (auto [h, c] : mergedCorners_)
    for (auto [hh, cc] : cx_.cornersOfVertex(h, c))
      if (!inRing(hh)) {
        renumber_.push_back({hh, cc});
        touched_.push_back(hh);
      }
  for (auto [a, b] : outsidePairs_) {
    touched_.push_back(a.hex);
    touched_.push_back(b.hex);
  }
}

// For the inverse: per ring hex, the outside sides met at the two kept edges (f at diag^2, g at
// diag^1); and the ring's vertices (those that go are reported removed).
void RingCollapsePlan::collectBands() {
  for (const RingHex& r : ring_) {
    Gluing gf = cx_.gluing(r.hex, facesOfEdge(r.keep)[0]), gg = cx_.gluing(r.hex, facesOfEdge(r.keep ^ 3)[0]);
    allOutside_ = allOutside_ && !inRing(gf.hex) && !inRing(gg.hex);
    bandSides_.push_back({{gf.hex, gf.face}, {gg.hex, gg.face}});
  }
  for (const RingHex& r : ring_)
    for (VertexId v : cx_.hexVertices(r.hex)) ringVertices_.push_back(v);
}

// The ring removed, merged vertices renumbered, the outside pairs glued; then the inverse.
OpResult RingCollapsePlan::apply(Complex& cx, OpKind kind) const {
  Transaction tx(cx);
  for (const RingHex& r : ring_)
    for (int f = 0; f < 6; ++f) cx.unglue(r.hex, f);
  for (const RingHex& r : ring_) cx.removeHex(r.hex);
  for (auto [h, c] : renumber_) cx.setCorner(h, c, target(cx.vertex(h, c)));
  OpResult res;
  res.op = kind;
  for (auto [a, b] : outsidePairs_) {
    if (a == b) reject(op_, "the collapse would glue " + entityName(a) + " to itself");
    int o = orientByVertices(cx, a.hex, a.face, b.hex, b.face);
    if (o < 0)
      reject(op_, "after the collapse " + entityName(a) + " and " + entityName(b) + " do not carry the same vertices");
    cx.glue(a.hex, a.face, b.hex, b.face, o);
  }
  tx.commitIfValid(res, touched_, op_, "the result would not be a valid complex");
  for (const RingHex& r : ring_) res.removedHexes.push_back(r.hex);
  std::vector<VertexId> ringVertices = ringVertices_;
  std::sort(ringVertices.begin(), ringVertices.end());
  ringVertices.erase(std::unique(ringVertices.begin(), ringVertices.end()), ringVertices.end());
  for (VertexId v : ringVertices)
    if (!cx.isVertex(v)) res.removedVertices.push_back(v);
  if (!allOutside_) {
    res.noInverse = "a side quad of the ring was glued to the ring itself";
    return res;
  }
  std::vector<std::pair<QuadSide, QuadSide>> bands;
  for (auto [f, g] : bandSides_) bands.push_back({cx.canonical(f), cx.canonical(g)});
  reportInverseIfValid(cx, res, bands);
  return res;
}

// A ring split worked out before anything is edited (TK03 §4.4, the inverse of a ring collapse):
// the loop of edges the quad pairs share, the strips' corners along it, and how each loop vertex
// splits between the strips' two sides.
class RingSplitPlan {
 public:
  RingSplitPlan(const Complex& cx, const std::vector<std::pair<QuadSide, QuadSide>>& bands, const std::string& op)
      : cx_(cx), op_(op), n_(bands.size()) {
    readBands(bands);
    findLoop();
    findStrips();
    splitLoopVertices();
  }
  OpResult apply(Complex& cx, OpKind kind) const;

 private:
  std::array<VertexId, 4> faceVerts(QuadSide s) const {
    std::array<VertexId, 4> v;
    for (int p = 0; p < 4; ++p) v[size_t(p)] = cx_.vertex(s.hex, kFaceCorners[size_t(s.face)][size_t(p)]);
    return v;
  }
  std::pair<HexId, int> cornerOf(QuadSide s, VertexId v) const {
    for (int p = 0; p < 4; ++p)
      if (cx_.vertex(s.hex, kFaceCorners[size_t(s.face)][size_t(p)]) == v)
        return std::pair<HexId, int>{s.hex, kFaceCorners[size_t(s.face)][size_t(p)]};
    return std::pair<HexId, int>{-1, -1};
  }
  QuadSide partnerOf(QuadSide s) const { return QuadSide{cx_.gluing(s).hex, cx_.gluing(s).face}; }
  void readBands(const std::vector<std::pair<QuadSide, QuadSide>>& bands);
  void findLoop();
  void findStrips();
  void splitLoopVertices();
  std::vector<HexId> addRingHexes(Complex& cx, std::vector<VertexId>& created) const;

  const Complex& cx_;
  const std::string& op_;
  const size_t n_;
  std::vector<QuadSide> F_, G_, walls_;
  std::vector<VertexId> M_;          // the loop's vertices: m_k, shared by f_k and g_k, runs M_k -> M_k+1
  std::vector<VertexId> C01_, C23_;  // f_k's and g_k's corners next to M_k, off the loop
  std::vector<std::vector<std::pair<HexId, int>>> moved_;  // per loop vertex: the corners that take the new vertex
  std::vector<bool> movedIsA_;                             // side B is on the boundary: side A takes the new vertex
  std::vector<QuadSide> fA_, gA_;
};

void RingSplitPlan::readBands(const std::vector<std::pair<QuadSide, QuadSide>>& bands) {
  if (n_ < 2) reject(op_, "needs at least 2 quad pairs around a loop");
  F_.resize(n_);
  G_.resize(n_);
  for (size_t k = 0; k < n_; ++k) {
    for (QuadSide s : {bands[k].first, bands[k].second}) {
      if (!cx_.isHex(s.hex)) reject(op_, hexName(s.hex) + " does not exist");
      if (s.face < 0 || s.face > 5) reject(op_, "local face " + std::to_string(s.face) + " is not 0..5");
      if (cx_.gluing(s).boundary()) reject(op_, "quad " + entityName(s) + " is on the boundary");
      Gluing g = cx_.gluing(s);
      walls_.push_back(s);
      walls_.push_back({g.hex, g.face});
    }
    F_[k] = bands[k].first;
    G_[k] = bands[k].second;
  }
}

// The loop edge m_k shared by f_k and g_k, and the loop's vertices M_k (m_k runs M_k -> M_k+1).
void RingSplitPlan::findLoop() {
  std::vector<std::array<VertexId, 2>> m(n_);
  for (size_t k = 0; k < n_; ++k) {
    auto fv = faceVerts(F_[k]), gv = faceVerts(G_[k]);
    std::vector<VertexId> common;
    for (VertexId v : fv)
      if (std::find(gv.begin(), gv.end(), v) != gv.end()) common.push_back(v);
    if (common.size() != 2)
      reject(op_, "quads " + entityName(F_[k]) + " and " + entityName(G_[k]) + " must share exactly one edge");
    m[k] = {common[0], common[1]};
  }
  M_.resize(n_);
  auto has = [](const std::array<VertexId, 2>& e, VertexId v) { return e[0] == v || e[1] == v; };
  M_[0] = has(m[1], m[0][0]) && !has(m[1], m[0][1]) ? m[0][1] : m[0][0];
  for (size_t k = 0; k < n_; ++k) {
    if (!has(m[k], M_[k])) reject(op_, "the shared edges of the quad pairs do not form a loop");
    VertexId next = m[k][0] == M_[k] ? m[k][1] : m[k][0];
    if (k + 1 < n_)
      M_[k + 1] = next;
    else if (next != M_[0])
      reject(op_, "the shared edges of the quad pairs do not close into a loop");
  }
  for (size_t k = 0; k < n_; ++k)
    for (size_t j = 0; j < k; ++j)
      if (M_[j] == M_[k]) reject(op_, "the loop passes vertex " + std::to_string(M_[k]) + " twice");
}

// The two strips: f_k's and g_k's corners next to M_k off the loop, shared with f_k-1 and g_k-1.
void RingSplitPlan::findStrips() {
  C01_.resize(n_);
  C23_.resize(n_);
  for (size_t k = 0; k < n_; ++k) {
    C01_[k] = neighbourInQuad(cx_, F_[k], M_[k], M_[(k + 1) % n_]);
    C23_[k] = neighbourInQuad(cx_, G_[k], M_[k], M_[(k + 1) % n_]);
    size_t prev = (k + n_ - 1) % n_;
    if (neighbourInQuad(cx_, F_[prev], M_[k], M_[prev]) != C01_[k] ||
        neighbourInQuad(cx_, G_[prev], M_[k], M_[prev]) != C23_[k])
      reject(op_, "the quads do not form two strips along the loop (pair " + std::to_string(k) + ")");
  }
}

// Split each loop vertex: side A is reached from f_k's A side without crossing walls. Side B
// takes the new vertex, unless the boundary is on side B: then side A does.
void RingSplitPlan::splitLoopVertices() {
  moved_.resize(n_);
  movedIsA_.assign(n_, false);
  fA_.resize(n_);
  gA_.resize(n_);
  QuadSide seedSide = F_[0];
  for (size_t k = 0; k <= n_; ++k) {
    size_t kk = k % n_;
    auto seed = cornerOf(seedSide, M_[kk]);
    if (k == n_) {
      auto A = cornersOnSide(cx_, seed, walls_);
      if (std::find(A.begin(), A.end(), cornerOf(fA_[0], M_[0])) == A.end())
        reject(op_, "the strips are one-sided (a Moebius band); the ring cannot be split");
      break;
    }
    VertexSplit split = splitVertex(cx_, seed, walls_, op_, "the quads");
    movedIsA_[kk] = std::find(split.moved.begin(), split.moved.end(), seed) != split.moved.end();
    const auto& A = movedIsA_[kk] ? split.moved : split.keep;
    moved_[kk] = split.moved;
    auto inA = [&](QuadSide s) { return std::find(A.begin(), A.end(), cornerOf(s, M_[kk])) != A.end(); };
    fA_[kk] = inA(F_[kk]) ? F_[kk] : partnerOf(F_[kk]);
    gA_[kk] = inA(G_[kk]) ? G_[kk] : partnerOf(G_[kk]);
    if (!inA(fA_[kk]) || inA(partnerOf(fA_[kk])) || !inA(gA_[kk]) || inA(partnerOf(gA_[kk])))
      reject(op_, "the quads do not separate vertex " + std::to_string(M_[kk]) + " consistently");
    seedSide = fA_[kk];  // carry side A along f_k to M_k+1
  }
}

// The strips unglued, each loop vertex split (its moved corners take a new vertex), and one ring
// hex per pair; returns the ring hexes, the new vertices in `created`.
std::vector<HexId> RingSplitPlan::addRingHexes(Complex& cx, std::vector<VertexId>& created) const {
  for (size_t k = 0; k < n_; ++k) {
    cx.unglue(fA_[k].hex, fA_[k].face);
    cx.unglue(gA_[k].hex, gA_[k].face);
  }
  std::vector<VertexId> atA(n_), atB(n_);
  created.resize(n_);
  for (size_t k = 0; k < n_; ++k) {
    Vec3 c;
    for (auto [h, cc] : moved_[k]) c = c + (1.0 / double(moved_[k].size())) * cx.hexCentroid(h);
    Vec3 p = cx.position(M_[k]);
    created[k] = cx.addVertex(p + 0.2 * (c - p));
    for (auto [h, cc] : moved_[k]) cx.setCorner(h, cc, created[k]);
    atA[k] = movedIsA_[k] ? created[k] : M_[k];
    atB[k] = movedIsA_[k] ? M_[k] : created[k];
  }
  std::vector<HexId> ringHexes;
  for (size_t k = 0; k < n_; ++k) {
    size_t k1 = (k + 1) % n_;
    std::array<VertexId, 8> v;
    v[size_t(cornerAt(0, 0, 0))] = atB[k];
    v[size_t(cornerAt(1, 0, 0))] = atB[k1];
    v[size_t(cornerAt(0, 1, 0))] = C01_[k];
    v[size_t(cornerAt(1, 1, 0))] = C01_[k1];
    v[size_t(cornerAt(0, 1, 1))] = atA[k];
    v[size_t(cornerAt(1, 1, 1))] = atA[k1];
    v[size_t(cornerAt(0, 0, 1))] = C23_[k];
    v[size_t(cornerAt(1, 0, 1))] = C23_[k1];
    ringHexes.push_back(cx.addHex(v));
  }
  return ringHexes;
}

// The ring hexes glued to the strips' sides and to each other round the loop.
OpResult RingSplitPlan::apply(Complex& cx, OpKind kind) const {
  Transaction tx(cx);
  std::vector<QuadSide> fB(n_), gB(n_);
  for (size_t k = 0; k < n_; ++k) {
    fB[k] = partnerOf(fA_[k]);
    gB[k] = partnerOf(gA_[k]);
  }
  std::vector<VertexId> created;
  const std::vector<HexId> ringHexes = addRingHexes(cx, created);
  std::vector<HexId> touched = ringHexes;
  for (size_t k = 0; k < n_; ++k) {
    HexId h = ringHexes[k];
    glueByVertices(cx, h, 4, fB[k].hex, fB[k].face);
    glueByVertices(cx, h, 3, fA_[k].hex, fA_[k].face);
    glueByVertices(cx, h, 5, gA_[k].hex, gA_[k].face);
    glueByVertices(cx, h, 2, gB[k].hex, gB[k].face);
    glueByVertices(cx, h, 1, ringHexes[(k + 1) % n_], 0);
    for (QuadSide s : {fA_[k], fB[k], gA_[k], gB[k]}) touched.push_back(s.hex);
  }
  OpResult res;
  res.op = kind;
  res.createdHexes = ringHexes;
  res.createdVertices = created;
  res.inverse = makeStep(OpKind::RingCollapse, EdgeRef{ringHexes[0], 3});
  tx.commitIfValid(res, touched, op_, "the result would not be a valid complex");
  return res;
}

}  // namespace

OpResult ringCollapse(Complex& cx, EdgeRef e) {
  const OpKind kind = OpKind::RingCollapse;
  const std::string op = opName(kind);
  return RingCollapsePlan(cx, e, op).apply(cx, kind);
}

OpResult ringSplit(Complex& cx, const std::vector<std::pair<QuadSide, QuadSide>>& bands) {
  const OpKind kind = OpKind::RingSplit;
  const std::string op = opName(kind);
  return RingSplitPlan(cx, bands, op).apply(cx, kind);
}

}  // namespace hexdual
