#include "ops/support.hpp"

#include "ops/op_table.hpp"

#include "complex/manifold.hpp"
#include "ops/op_table.hpp"

namespace hexdual::ops {
using namespace tables;

std::array<VertexId, 4> faceVertexSet(const Complex& cx, HexId h, int f) {
  std::array<VertexId, 4> s;
  for (int p = 0; p < 4; ++p) s[size_t(p)] = cx.vertex(h, kFaceCorners[size_t(f)][size_t(p)]);
  auto order = [&](size_t i, size_t j) {  // a 4-element sorting network: replaceHexes keys every new face
    if (s[j] < s[i]) std::swap(s[i], s[j]);
  };
  order(0, 1), order(2, 3), order(0, 2), order(1, 3), order(1, 2);
  return s;
}

int orientByVertices(const Complex& cx, HexId a, int fa, HexId b, int fb) {
  auto posInB = [&](int pa) {
    VertexId v = cx.vertex(a, kFaceCorners[size_t(fa)][size_t(pa)]);
    for (int p = 0; p < 4; ++p)
      if (cx.vertex(b, kFaceCorners[size_t(fb)][size_t(p)]) == v) return p;
    return -1;
  };
  int p0 = posInB(0), p1 = posInB(1);
  if (p0 < 0 || p1 < 0) return -1;
  if (((p1 - p0) & 3) != 1 && ((p0 - p1) & 3) != 1) return -1;
  int o = orientFromPositions(p0, p1);
  for (int p = 2; p < 4; ++p)
    if (posInB(p) != mapPosition(p, o)) return -1;
  return o;
}

std::string interiorQuadProblem(const Complex& cx, QuadSide q, const std::string& op, const std::string& needs) {
  if (!cx.isHex(q.hex)) return op + ": " + hexName(q.hex) + " does not exist";
  if (q.face < 0 || q.face > 5) return op + ": local face " + std::to_string(q.face) + " is not 0..5";
  if (cx.isBoundary(q)) return op + ": quad " + entityName(q) + " is on the boundary; " + needs;
  return {};
}

Gluing requireInteriorQuad(const Complex& cx, QuadSide q, const std::string& op, const std::string& needs) {
  if (std::string why = interiorQuadProblem(cx, q, op, needs); !why.empty()) throw Error(why);
  return cx.gluing(q);
}

void glueByVertices(Complex& cx, HexId a, int fa, HexId b, int fb) {
  int o = orientByVertices(cx, a, fa, b, fb);
  if (o < 0)
    throw Error("internal: hex " + std::to_string(a) + " face " + std::to_string(fa) + " and hex " + std::to_string(b) +
                " face " + std::to_string(fb) + " do not carry the same vertices");
  cx.glue(a, fa, b, fb, o);
}

std::string closedEdgeStarInto(const Complex& cx, EdgeRef e, const std::string& op, EdgeStar& st) {
  if (!cx.isHex(e.hex)) return op + ": " + hexName(e.hex) + " does not exist";
  if (e.edge < 0 || e.edge > 11) return op + ": local edge " + std::to_string(e.edge) + " is not 0..11";
  st.inc.clear();
  st.exitFace.clear();
  st.entryFace.clear();
  EdgeRef cur = e;
  int exitFace = facesOfEdge(e.edge)[0];
  int entry = facesOfEdge(e.edge)[1];
  for (size_t guard = 0; guard <= size_t(12) * size_t(cx.numHexes()); ++guard) {
    st.inc.push_back(cur);
    st.entryFace.push_back(entry);
    st.exitFace.push_back(exitFace);
    Gluing g = cx.gluing(cur.hex, exitFace);
    if (g.boundary()) return op + ": edge " + entityName(e) + " is on the boundary; it needs a closed cycle of hexes";
    int c0 = cx.mappedCorner(cur.hex, exitFace, kEdgeCorners[size_t(cur.edge)][0]);
    int c1 = cx.mappedCorner(cur.hex, exitFace, kEdgeCorners[size_t(cur.edge)][1]);
    cur = {g.hex, edgeBetween(c0, c1)};
    entry = g.face;
    auto fs = facesOfEdge(cur.edge);
    exitFace = fs[0] == g.face ? fs[1] : fs[0];
    if (cur == e) {
      st.entryFace[0] = entry;
      return {};
    }
  }
  return op + ": the cycle around edge " + entityName(e) + " does not close";
}

EdgeStar closedEdgeStar(const Complex& cx, EdgeRef e, const std::string& op) {
  EdgeStar st;
  if (std::string why = closedEdgeStarInto(cx, e, op, st); !why.empty()) throw Error(why);
  return st;
}

int quadIndexInStar(const Complex& cx, const EdgeStar& st, QuadSide side) {
  (void)cx;
  size_t n = st.inc.size();
  for (size_t k = 0; k < n; ++k) {
    QuadSide a{st.inc[k].hex, st.exitFace[k]}, b{st.inc[(k + 1) % n].hex, st.entryFace[(k + 1) % n]};
    if (a == side || b == side) return int(k);
  }
  return -1;
}

std::vector<int> facesNotGluedTo(const Complex& cx, HexId h, HexId other) {
  std::vector<int> out;
  for (int f = 0; f < 6; ++f)
    if (cx.gluing(h, f).boundary() || cx.gluing(h, f).hex != other) out.push_back(f);
  return out;
}

HexId partnerSharing(const Complex& cx, HexId x, int shared) {
  for (int f = 0; f < 6; ++f) {
    Gluing g = cx.gluing(x, f);
    if (!g.boundary() && g.hex != x && int(facesNotGluedTo(cx, x, g.hex).size()) == 6 - shared) return g.hex;
  }
  return -1;
}

bool cornersOnBoundary(const Complex& cx, const std::vector<std::pair<HexId, int>>& corners) {
  for (auto [h, c] : corners)
    for (int f : facesOfCorner(c))
      if (cx.gluing(h, f).boundary()) return true;
  return false;
}

bool vertexOnBoundary(const Complex& cx, HexId h, int c) { return cornersOnBoundary(cx, cx.cornersOfVertex(h, c)); }

namespace {
// The vertex of face f of hex h next to corner c, on the side away from corner `away`.
VertexId neighbourInFace(const Complex& cx, HexId h, int f, int c, int away) {
  int p = positionInFace(f, c);
  int n1 = kFaceCorners[size_t(f)][size_t((p + 1) & 3)], n3 = kFaceCorners[size_t(f)][size_t((p + 3) & 3)];
  return cx.vertex(h, n1 == away ? n3 : n1);
}
}  // namespace

std::string arcSplitInto(const Complex& cx, EdgeRef e, QuadSide f, QuadSide g, const std::string& op, const char* what,
                         ArcSplit& s) {
  if (std::string why = closedEdgeStarInto(cx, e, op, s.star); !why.empty()) return why;
  const int n = int(s.star.inc.size());
  int i = quadIndexInStar(cx, s.star, f), j = quadIndexInStar(cx, s.star, g);
  if (i < 0) return op + ": quad " + entityName(f) + " is not in the cycle around edge " + entityName(e);
  if (j < 0) return op + ": quad " + entityName(g) + " is not in the cycle around edge " + entityName(e);
  if (i == j) return op + ": f and g are the same quad; " + what + " needs two distinct quads";
  // Quad k lies between incidence k (exit face) and k+1 (entry face).
  const auto& st = s.star;
  s.li = st.inc[size_t((i + 1) % n)];
  s.lj = st.inc[size_t(j)];
  s.fL = {s.li.hex, st.entryFace[size_t((i + 1) % n)]};
  s.fR = {st.inc[size_t(i)].hex, st.exitFace[size_t(i)]};
  s.gL = {s.lj.hex, st.exitFace[size_t(j)]};
  s.gR = {st.inc[size_t((j + 1) % n)].hex, st.entryFace[size_t((j + 1) % n)]};
  const int ca = kEdgeCorners[size_t(s.li.edge)][0], cb = kEdgeCorners[size_t(s.li.edge)][1];
  s.a = cx.vertex(s.li.hex, ca);
  s.b = cx.vertex(s.li.hex, cb);
  s.fa = neighbourInFace(cx, s.li.hex, s.fL.face, ca, cb);
  s.fb = neighbourInFace(cx, s.li.hex, s.fL.face, cb, ca);
  // In arc L's last hex the edge may be numbered the other way round.
  int da = kEdgeCorners[size_t(s.lj.edge)][0], db = kEdgeCorners[size_t(s.lj.edge)][1];
  if (cx.vertex(s.lj.hex, da) != s.a) std::swap(da, db);
  s.ga = neighbourInFace(cx, s.lj.hex, s.gL.face, da, db);
  s.gb = neighbourInFace(cx, s.lj.hex, s.gL.face, db, da);
  if (s.fa == s.ga || s.fa == s.gb || s.fb == s.ga || s.fb == s.gb)
    return op + ": quads " + entityName(f) + " and " + entityName(g) + " share more than edge " + entityName(e);
  return {};
}

ArcSplit arcSplit(const Complex& cx, EdgeRef e, QuadSide f, QuadSide g, const std::string& op, const char* what) {
  ArcSplit s;
  if (std::string why = arcSplitInto(cx, e, f, g, op, what, s); !why.empty()) throw Error(why);
  return s;
}

std::vector<HexId> withNeighbours(const Complex& cx, const std::vector<HexId>& hexes) {
  std::vector<HexId> out;
  out.reserve(7 * hexes.size());  // one allocation
  out.assign(hexes.begin(), hexes.end());
  for (HexId h : hexes)
    for (int f = 0; f < 6; ++f)
      if (!cx.gluing(h, f).boundary()) out.push_back(cx.gluing(h, f).hex);
  return out;
}

namespace {
thread_local int deferredValidation = 0;
}
DeferValidation::DeferValidation() { ++deferredValidation; }
DeferValidation::~DeferValidation() { --deferredValidation; }
bool DeferValidation::active() { return deferredValidation > 0; }

void Transaction::commit(OpResult& r, const std::vector<HexId>& touched) { commitChecked(r, touched, true); }

void Transaction::commitValidByConstruction(OpResult& r, const std::vector<HexId>& touched) {
  commitChecked(r, touched, false);
}

void Transaction::commitChecked(OpResult& r, const std::vector<HexId>& touched, bool walkLinks) {
  if (!DeferValidation::active()) {
    requireManifoldVertices(cx_, touched, r.op ? opName(*r.op) : "operation");
#ifdef HEXDUAL_CHECK_INVARIANTS
    (void)walkLinks;
    cx_.validate();
#else
    if (walkLinks) cx_.validateAround(touched);
#endif
  }
  r.dV = cx_.numVertices() - v0_;
  r.dF = cx_.numQuads() - f0_;
  r.dH = cx_.numHexes() - h0_;
  r.dE = r.dV + r.dF - r.dH;  // V - E + F - H is invariant under every local operation
  r.edits = cx_.commitTransaction();
  open_ = false;
}

void Transaction::commitIfValid(OpResult& r, const std::vector<HexId>& touched, const std::string& op,
                                const std::string& why) {
  try {
    commit(r, touched);
  } catch (const Error& err) {
    reject(op, why + " (" + err.what() + ")");
  }
}

std::vector<std::pair<HexId, int>> cornersOnSide(const Complex& cx, std::pair<HexId, int> seed,
                                                 const std::vector<QuadSide>& walls) {
  auto isWall = [&](HexId h, int f) { return std::find(walls.begin(), walls.end(), QuadSide{h, f}) != walls.end(); };
  std::vector<std::pair<HexId, int>> out{seed};
  for (size_t i = 0; i < out.size(); ++i) {
    auto [h, c] = out[i];
    for (int f : facesOfCorner(c)) {
      if (cx.gluing(h, f).boundary() || isWall(h, f)) continue;
      std::pair<HexId, int> n{cx.gluing(h, f).hex, cx.mappedCorner(h, f, c)};
      if (std::find(out.begin(), out.end(), n) == out.end()) out.push_back(n);
    }
  }
  return out;
}

VertexSplit splitVertex(const Complex& cx, std::pair<HexId, int> seed, const std::vector<QuadSide>& walls,
                        const std::string& op, const std::string& what) {
  const VertexId v = cx.vertex(seed.first, seed.second);
  std::vector<std::vector<std::pair<HexId, int>>> pieces;
  std::vector<std::pair<HexId, int>> left = cx.cornersOfVertex(seed.first, seed.second);
  for (auto start = seed; !left.empty(); start = left.front()) {
    pieces.push_back(cornersOnSide(cx, start, walls));
    for (auto c : pieces.back()) left.erase(std::remove(left.begin(), left.end(), c), left.end());
  }
  if (pieces.size() < 2) reject(op, what + " do not cut vertex " + std::to_string(v) + " into two sides");
  VertexSplit s;
  if (pieces.size() == 2) {
    s.keep = pieces[0];
    s.moved = pieces[1];
    if (cornersOnBoundary(cx, s.moved)) {
      if (cornersOnBoundary(cx, s.keep))
        reject(op, "vertex " + std::to_string(v) + " is on the boundary on both sides; splitting it would change the boundary");
      std::swap(s.keep, s.moved);
    }
    return s;
  }
  for (auto& p : pieces) {
    if (!cornersOnBoundary(cx, p)) {
      if (!s.moved.empty()) reject(op, what + " cut vertex " + std::to_string(v) + " into more than two sides");
      s.moved = p;
    } else {
      s.keep.insert(s.keep.end(), p.begin(), p.end());
    }
  }
  if (s.moved.empty()) reject(op, what + " cut vertex " + std::to_string(v) + " into more than two sides");
  return s;
}

}  // namespace hexdual::ops

namespace hexdual::ops {

namespace {
// The removed hexes unglued and removed, the new ones added (ids in order), nothing glued yet.
std::vector<HexId> swapHexes(Complex& cx, const std::vector<HexId>& removed, const std::vector<std::array<VertexId, 8>>& added) {
  for (HexId h : removed)
    for (int f = 0; f < 6; ++f) cx.unglue(h, f);
  for (HexId h : removed) cx.removeHex(h);
  std::vector<HexId> created;
  created.reserve(added.size());
  for (const auto& v : added) created.push_back(cx.addHex(v));
  return created;
}
}  // namespace

std::vector<HexId> replaceHexes(Complex& cx, const std::string& op, const std::vector<HexId>& removed,
                                const std::vector<std::array<VertexId, 8>>& added) {
  using Key = std::array<VertexId, 4>;
  // Scratch kept between calls (every hex push runs this): no allocation once warm but the result.
  struct Scratch {
    std::vector<std::pair<Key, QuadSide>> outside, open;
    std::vector<Key> formerBoundary;
    std::vector<int32_t> firstOf, nextOf, lastOf;
    std::vector<uint8_t> taken;
    std::vector<QuadSide> hits;
  };
  thread_local Scratch sc;
  auto &outside = sc.outside, &open = sc.open;
  auto& formerBoundary = sc.formerBoundary;
  auto &firstOf = sc.firstOf, &nextOf = sc.nextOf, &lastOf = sc.lastOf;
  auto& taken = sc.taken;
  auto& hits = sc.hits;
  auto isRemoved = [&](HexId h) { return std::find(removed.begin(), removed.end(), h) != removed.end(); };
  outside.clear();
  formerBoundary.clear();
  for (HexId h : removed)
    for (int f = 0; f < 6; ++f) {
      Gluing g = cx.gluing(h, f);
      if (g.boundary()) formerBoundary.push_back(faceVertexSet(cx, h, f));
      else if (!isRemoved(g.hex)) outside.push_back({faceVertexSet(cx, h, f), {g.hex, g.face}});
    }
  std::vector<HexId> created = swapHexes(cx, removed, added);
  open.clear();
  for (HexId h : created)
    for (int f = 0; f < 6; ++f) open.push_back({faceVertexSet(cx, h, f), {h, f}});
  // The new faces by key: an open-addressing table of each key's first face, and each face's next
  // with the same key, in list order. Faces are taken in list order and marked, not erased: the
  // same hits in the same order as a scan of the list.
  auto hashOf = [](const Key& k) {
    uint64_t x = uint64_t(uint32_t(k[0])) << 32 | uint32_t(k[1]);
    uint64_t y = uint64_t(uint32_t(k[2])) << 32 | uint32_t(k[3]);
    return (x * 0x9E3779B97F4A7C15ull) ^ (y * 0xC2B2AE3D27D4EB4Full);
  };
  size_t cap = 16;
  while (cap < 2 * open.size()) cap *= 2;
  const size_t mask = cap - 1;
  firstOf.assign(cap, -1);
  nextOf.assign(open.size(), -1);
  lastOf.assign(open.size(), -1);
  auto slotOfKey = [&](const Key& k) {  // the table entry of k, or the empty one where it belongs
    size_t i = size_t(hashOf(k) >> 40) & mask;
    while (firstOf[i] >= 0 && open[size_t(firstOf[i])].first != k) i = (i + 1) & mask;
    return i;
  };
  for (size_t j = 0; j < open.size(); ++j) {
    const size_t i = slotOfKey(open[j].first);
    if (firstOf[i] < 0) {
      firstOf[i] = int32_t(j);
    } else {
      const size_t head = size_t(firstOf[i]);
      nextOf[size_t(lastOf[head] < 0 ? head : size_t(lastOf[head]))] = int32_t(j);
      lastOf[head] = int32_t(j);
    }
  }
  taken.assign(open.size(), 0);
  auto take = [&](const Key& k) {
    hits.clear();
    for (int32_t j = firstOf[slotOfKey(k)]; j >= 0; j = nextOf[size_t(j)])
      if (!taken[size_t(j)]) {
        taken[size_t(j)] = 1;
        hits.push_back(open[size_t(j)].second);
      }
  };
  for (const auto& [key, side] : outside) {
    take(key);
    if (hits.size() != 1)
      reject(op, "the new hexes do not fit the neighbour " + entityName(side) + " (" + std::to_string(hits.size()) +
                     " faces carry its vertices)");
    int o = orientByVertices(cx, hits[0].hex, hits[0].face, side.hex, side.face);
    if (o < 0) reject(op, "the new hexes meet " + entityName(side) + " in a different cyclic order");
    cx.glue(hits[0].hex, hits[0].face, side.hex, side.face, o);
  }
  for (size_t first = 0; first < open.size(); ++first) {
    if (taken[first]) continue;
    const Key key = open[first].first;
    take(key);
    if (hits.size() == 2) {
      int o = orientByVertices(cx, hits[0].hex, hits[0].face, hits[1].hex, hits[1].face);
      if (o < 0) reject(op, "two new faces carry the same vertices in different cyclic orders");
      cx.glue(hits[0].hex, hits[0].face, hits[1].hex, hits[1].face, o);
    } else if (hits.size() == 1) {
      auto it = std::find(formerBoundary.begin(), formerBoundary.end(), key);
      if (it == formerBoundary.end()) reject(op, "the new hexes would change the boundary quad mesh");
      formerBoundary.erase(it);
    } else {
      reject(op, "more than two new faces carry the same 4 vertices");
    }
  }
  if (!formerBoundary.empty()) reject(op, "the new hexes would change the boundary quad mesh");
  return created;
}

}  // namespace hexdual::ops

namespace hexdual::ops {

std::vector<HexId> replaceHexesByPlan(Complex& cx, const std::string& op, const std::vector<HexId>& removed,
                                      const std::vector<std::array<VertexId, 8>>& added,
                                      std::span<const PlannedGluing> plan) {
  auto isRemoved = [&](HexId h) { return std::find(removed.begin(), removed.end(), h) != removed.end(); };
  std::array<Gluing, 64> across;  // what was across each outside face of the plan
  if (plan.size() > across.size()) return replaceHexes(cx, op, removed, added);
  for (size_t i = 0; i < plan.size(); ++i) {
    const PlannedGluing& g = plan[i];
    across[i] = g.other < 0 ? cx.gluing(removed[size_t(-1 - g.other)], g.otherFace) : Gluing{};
    if (!across[i].boundary() && isRemoved(across[i].hex)) return replaceHexes(cx, op, removed, added);
  }
  std::vector<HexId> created = swapHexes(cx, removed, added);
  for (size_t i = 0; i < plan.size(); ++i) {
    const PlannedGluing& g = plan[i];
    const HexId h = created[size_t(g.hex)];
    const QuadSide to = g.other >= 0 ? QuadSide{created[size_t(g.other)], g.otherFace} : QuadSide{across[i].hex, across[i].face};
    if (to.hex < 0) continue;  // a former boundary quad stays on the boundary
    const int o = orientByVertices(cx, h, g.face, to.hex, to.face);
    if (o < 0) reject(op, "a new hex does not meet " + entityName(to) + " as planned");
    cx.glue(h, g.face, to.hex, to.face, o);
  }
  return created;
}

}  // namespace hexdual::ops
