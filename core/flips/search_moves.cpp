// The candidate moves of a search state: every atomic operation (and inverse) on region hexes,
// ring splits generated forward, and the prefilters that skip moves proven never valid and local
// without trying them (SearchOptions::prefilter).
#include <algorithm>
#include <functional>

#include "flips/search_parts.hpp"
#include "ops/op_table.hpp"
#include "ops/support.hpp"

namespace hexdual::flipsearch {
using namespace tables;

// The star of edge e of hex h when its cycle closes and it was not seen before (`seen` collects
// canonical incidences); `ce` is the canonical incidence.
bool freshClosedStar(const Complex& cx, HexId h, int e, std::vector<EdgeRef>& seen, EdgeRef& ce, ops::EdgeStar& st) {
  ce = cx.canonical(EdgeRef{h, e});
  if (std::find(seen.begin(), seen.end(), ce) != seen.end()) return false;
  seen.push_back(ce);
  bool closed = false;
  cx.edgeCycle(ce, &closed);
  if (!closed) return false;
  st = ops::closedEdgeStar(cx, ce, "search");
  return true;
}

namespace {

using ops::neighbourInQuad;

// Ring splits generated forward (TK03 §4.4, the inverse of a ring collapse): every closed loop of
// region edges, at most `maxLen` long, with two strips of quads along it — f_k and g_k share the
// loop's k-th edge, f_k and f_k+1 share an edge across the loop (so do the g's). Each loop is
// started once, at its smallest edge walked from its smaller vertex; both sides of f_0 are tried
// (the side of f_0 keeps the loop's vertex ids). Every quad must have a region side.
class RingSplits {
 public:
  RingSplits(const Complex& cx, const std::vector<HexId>& host, int maxLen, bool prefilter, std::vector<OpStep>& out)
      : cx_(cx),
        host_(host),
        maxLen_(maxLen),
        prefilter_(prefilter),
        out_(out),
        fq_(size_t(maxLen) + 1),
        gq_(size_t(maxLen) + 1) {}
  void fromEveryEdge();

 private:
  VertexId other(QuadSide s, VertexId v, VertexId away) const { return neighbourInQuad(cx_, s, v, away); }
  int cornerIn(HexId h, VertexId v) const {
    for (int c = 0; c < 8; ++c)
      if (cx_.vertex(h, c) == v) return c;
    return -1;
  }
  // The canonical incidence of the edge a-b of quad s.
  EdgeRef edgeOf(QuadSide s, VertexId a, VertexId b) const {
    return cx_.canonical(EdgeRef{s.hex, edgeBetween(cornerIn(s.hex, a), cornerIn(s.hex, b))});
  }
  bool touchesRegion(QuadSide s) const { return !isHost(host_, s.hex) || !isHost(host_, cx_.gluing(s).hex); }
  void quadsAround(QuadSide s, VertexId a, VertexId b, std::vector<QuadSide>& qs) const;
  void closeLoop(VertexId at, VertexId wf, VertexId wg);
  void extend(VertexId from, VertexId at);

  const Complex& cx_;
  const std::vector<HexId>& host_;
  const int maxLen_;
  const bool prefilter_;
  std::vector<OpStep>& out_;
  std::vector<std::pair<QuadSide, QuadSide>> bands_;  // (f_k, g_k)
  std::vector<VertexId> loop_;
  EdgeRef first_{};
  std::vector<std::vector<QuadSide>> fq_, gq_;  // per band: the quads around its next edge
};

// The quads around edge a-b of quad s (closed stars only), as canonical sides.
void RingSplits::quadsAround(QuadSide s, VertexId a, VertexId b, std::vector<QuadSide>& qs) const {
  qs.clear();
  EdgeRef e = edgeOf(s, a, b);
  bool closed = false;
  cx_.edgeCycle(e, &closed);
  if (!closed) return;
  auto st = ops::closedEdgeStar(cx_, e, "search");
  for (size_t k = 0; k < st.inc.size(); ++k) qs.push_back(cx_.canonical(QuadSide{st.inc[k].hex, st.exitFace[k]}));
}

// Back at the start: f_0 and g_0 must continue the strips (wf, wg: the strips' next vertices).
void RingSplits::closeLoop(VertexId at, VertexId wf, VertexId wg) {
  const size_t k = bands_.size();
  QuadSide f = bands_.back().first, g = bands_.back().second;
  QuadSide f0 = bands_[0].first, g0 = bands_[0].second;
  if (k >= 2 && other(f0, at, loop_[1]) == wf && other(g0, at, loop_[1]) == wg &&
      edgeOf(f0, at, wf) == edgeOf(f, at, wf) && edgeOf(g0, at, wg) == edgeOf(g, at, wg))
    for (QuadSide s0 : {f0, QuadSide{cx_.gluing(f0).hex, cx_.gluing(f0).face}}) {
      // The hex across f_0 from s0 gets new ids for the loop's vertices: never a host hex.
      if (prefilter_ && isHost(host_, cx_.gluing(s0).hex)) continue;
      OpStep st{OpKind::RingSplit, {OpArg::of(s0, g0)}, 0};
      for (size_t j = 1; j < k; ++j) st.args.push_back(OpArg::of(bands_[j].first, bands_[j].second));
      out_.push_back(st);
    }
}

// Extends the strips from band k (ending at vertex `at`, coming from `from`).
void RingSplits::extend(VertexId from, VertexId at) {
  const size_t k = bands_.size();
  QuadSide f = bands_.back().first, g = bands_.back().second;
  VertexId wf = other(f, at, from), wg = other(g, at, from);
  if (at == loop_[0]) return closeLoop(at, wf, wg);
  if (int(k) >= maxLen_) return;
  quadsAround(f, at, wf, fq_[k]);
  quadsAround(g, at, wg, gq_[k]);
  for (QuadSide f2 : fq_[k]) {
    if (f2 == f || !touchesRegion(f2)) continue;
    VertexId u = other(f2, at, wf);
    for (QuadSide g2 : gq_[k]) {
      if (g2 == g || g2 == f2 || !touchesRegion(g2) || other(g2, at, wg) != u) continue;
      EdgeRef e = edgeOf(f2, at, u);
      if (!(edgeOf(g2, at, u) == e) || !(first_ < e)) continue;
      if (u != loop_[0] && std::find(loop_.begin(), loop_.end(), u) != loop_.end()) continue;
      bands_.push_back({f2, g2});
      loop_.push_back(u);
      extend(at, u);
      loop_.pop_back();
      bands_.pop_back();
    }
  }
}

// Every loop started at each closed region edge, from every pair of its quads.
void RingSplits::fromEveryEdge() {
  std::vector<EdgeRef> seen;
  for (HexId h : regionOf(cx_, host_))
    for (int e = 0; e < 12; ++e) {
      EdgeRef ce;
      ops::EdgeStar st;
      if (!freshClosedStar(cx_, h, e, seen, ce, st)) continue;
      VertexId a = cx_.vertex(ce.hex, kEdgeCorners[size_t(ce.edge)][0]),
               b = cx_.vertex(ce.hex, kEdgeCorners[size_t(ce.edge)][1]);
      if (b < a) std::swap(a, b);
      std::vector<QuadSide> qs;
      for (size_t k = 0; k < st.inc.size(); ++k) qs.push_back(cx_.canonical(QuadSide{st.inc[k].hex, st.exitFace[k]}));
      first_ = ce;
      for (size_t i = 0; i < qs.size(); ++i)
        for (size_t j = 0; j < qs.size(); ++j) {
          if (i == j || !touchesRegion(qs[i]) || !touchesRegion(qs[j])) continue;
          if (j < i) continue;  // f and g swapped give the same split
          bands_ = {{qs[i], qs[j]}};
          loop_ = {a, b};
          extend(a, b);
        }
    }
}

}  // namespace

void appendRingSplits(const Complex& cx, const std::vector<HexId>& host, int maxLen, bool prefilter,
                      std::vector<OpStep>& out) {
  if (maxLen < 2) return;
  RingSplits(cx, host, maxLen, prefilter, out).fromEveryEdge();
}

// The vertices of f and g next to a and to b (e = ab), as arcSplit finds them (TK03 §4.1, §4.4):
// chord push and face collapse reject f and g when these meet (the quads share more than e).
struct ArcEnds {
  VertexId fa, fb, ga, gb;
  bool distinct() const {
    return fa >= 0 && fb >= 0 && ga >= 0 && gb >= 0 && fa != ga && fa != gb && fb != ga && fb != gb;
  }
};
ArcEnds arcEnds(const Complex& cx, EdgeRef e, QuadSide f, QuadSide g) {
  const VertexId a = cx.vertex(e.hex, kEdgeCorners[size_t(e.edge)][0]),
                 b = cx.vertex(e.hex, kEdgeCorners[size_t(e.edge)][1]);
  return {neighbourInQuad(cx, f, a, b), neighbourInQuad(cx, f, b, a), neighbourInQuad(cx, g, a, b),
          neighbourInQuad(cx, g, b, a)};
}

// Necessary conditions for faceCollapse(e, f, g) to give a valid local state, cheaper than trying
// it: f = (a,b,c,d) and g = (a,b,c',d') merge c with c' and d with d' (TK03 §4.4; the spec's
// face open-collapse), renaming every corner of the merged vertices. So no hex may have both
// vertices of a pair (it would use one vertex at two corners), and not both may be host vertices
// (a host hex would change its vertices: not local).
bool faceCollapseMayApply(const Complex& cx, const std::vector<HexId>& host, const ArcEnds& ends) {
  auto hexHas = [&](HexId h, VertexId v) {
    for (int c = 0; c < 8; ++c)
      if (cx.vertex(h, c) == v) return true;
    return false;
  };
  for (auto [x, y] : {std::pair{ends.fa, ends.ga}, std::pair{ends.fb, ends.gb}}) {
    bool xHost = false, yHost = false;
    for (HexId h : cx.hexes()) {
      bool hx = hexHas(h, x), hy = hexHas(h, y);
      if (hx && hy) return false;
      if (isHost(host, h)) xHost = xHost || hx, yHost = yHost || hy;
    }
    if (xHost && yHost) return false;
  }
  return true;
}

// Necessary conditions for ringCollapse(e) to give a local state: the chord through e's hex along
// e's axis closes without passing a hex twice (else the operation rejects it), none of its hexes is
// a host hex (the collapse removes them), and no hex of it merges two host vertices (per ring hex,
// the corners of e's diagonal edge, carried round the ring, merge with those of the opposite edge;
// a host hex would change its vertices). The walk is the operation's own (TK03 §4.4).
bool ringCollapseMayApply(const Complex& cx, const std::vector<uint8_t>& hostVertex, const std::vector<HexId>& host,
                          EdgeRef e) {
  const int axis0 = axisOfEdge(e.edge);
  HexId h = e.hex;
  int exit = 2 * axis0 + 1, diag = e.edge;
  std::vector<HexId> ring;
  auto hostV = [&](VertexId v) { return size_t(v) < hostVertex.size() && hostVertex[size_t(v)]; };
  for (;;) {
    if (isHost(host, h) || std::find(ring.begin(), ring.end(), h) != ring.end()) return false;
    ring.push_back(h);
    for (int k = 0; k < 2; ++k) {
      VertexId v1 = cx.vertex(h, kEdgeCorners[size_t(diag)][size_t(k)]),
               v2 = cx.vertex(h, kEdgeCorners[size_t(diag ^ 3)][size_t(k)]);
      if (v1 != v2 && hostV(v1) && hostV(v2)) return false;
    }
    Gluing g = cx.gluing(h, exit);
    if (g.boundary()) return false;
    const int a2 = axisOfFace(g.face);
    const int c = positionInFace(exit, kEdgeCorners[size_t(diag)][0]) >= 0 ? kEdgeCorners[size_t(diag)][0]
                                                                           : kEdgeCorners[size_t(diag)][1];
    diag = edgesOfCorner(cx.mappedCorner(h, exit, c))[size_t(a2)];
    if (g.hex == ring[0] && a2 == axis0) return true;
    h = g.hex;
    exit = oppositeFace(g.face);
  }
}

// Necessary conditions for hexPull(r): the 4 side quads of r's hex are glued to 4 distinct region
// hexes other than the two at r (the ring, which the pull removes: a host hex there is never local).
bool hexPullMayApply(const Complex& cx, const std::vector<HexId>& host, QuadSide r) {
  const HexId a = r.hex, b = cx.gluing(r).hex;
  std::array<HexId, 4> ring{};
  int n = 0;
  for (int s = 0; s < 6; ++s) {
    if (axisOfFace(s) == axisOfFace(r.face)) continue;
    Gluing g = cx.gluing(a, s);
    if (g.boundary() || g.hex == a || g.hex == b || isHost(host, g.hex) ||
        std::find(ring.begin(), ring.begin() + n, g.hex) != ring.begin() + n)
      return false;
    ring[size_t(n++)] = g.hex;
  }
  return true;
}

namespace {

// The candidate steps of one state, by what they are applied to: a region hex, its quads, pairs
// of quads on the same vertices (face splits), its edges (ring collapses, and pairs of quads round
// a closed edge for chord pushes and face collapses). Cheap exact preconditions (a pillow partner,
// a blind-chord partner) are checked here so that most rejections cost no exception.
class MoveList {
 public:
  MoveList(const Complex& cx, const std::vector<HexId>& host, const std::vector<OpKind>& ops, bool prefilter)
      : cx_(cx),
        host_(host),
        ops_(ops),
        prefilter_(prefilter),
        region_(regionOf(cx, host)),
        hostVertex_(size_t(cx.vertexCapacity()), 0) {
    for (HexId h : host)
      for (VertexId v : cx.hexVertices(h)) hostVertex_[size_t(v)] = 1;
    if (use(OpKind::FaceSplit))
      for (HexId h : region_)
        for (int f = 0; f < 6; ++f) faceSets_.push_back(ops::faceVertexSet(cx, h, f));
  }
  bool use(OpKind op) const { return ops_.empty() || std::find(ops_.begin(), ops_.end(), op) != ops_.end(); }
  std::vector<OpStep> list(int ringSplitMax);

 private:
  bool inRegion(HexId h) const { return !isHost(host_, h); }
  void hexMoves(HexId h);
  void faceSplits(size_t i);
  void edgeMoves(HexId h, int e);

  const Complex& cx_;
  const std::vector<HexId>& host_;
  const std::vector<OpKind>& ops_;
  const bool prefilter_;
  const std::vector<HexId> region_;
  std::vector<uint8_t> hostVertex_;
  std::vector<std::array<VertexId, 4>> faceSets_;  // per region hex and face: its sorted vertex ids
  std::vector<QuadSide> seenQuads_;
  std::vector<EdgeRef> seenEdges_;
  std::vector<OpStep> out_;
};

std::vector<OpStep> MoveList::list(int ringSplitMax) {
  for (size_t i = 0; i < region_.size(); ++i) {
    const HexId h = region_[i];
    hexMoves(h);
    if (use(OpKind::FaceSplit)) faceSplits(i);
    for (int e = 0; e < 12; ++e) edgeMoves(h, e);
  }
  if (use(OpKind::RingSplit)) appendRingSplits(cx_, host_, ringSplitMax, prefilter_, out_);
  return std::move(out_);
}

// Unpillow and chord pull at h; pillow and hex push on each of its quads (once per quad), hex pull
// from each of its sides.
void MoveList::hexMoves(HexId h) {
  using K = OpKind;
  if (use(K::Unpillow) && ops::partnerSharing(cx_, h, 5) >= 0) out_.push_back(makeStep(K::Unpillow, h));
  if (use(K::ChordPull) && ops::partnerSharing(cx_, h, 4) >= 0) out_.push_back(makeStep(K::ChordPull, h));
  for (int f = 0; f < 6; ++f) {
    Gluing g = cx_.gluing(h, f);
    if (g.boundary()) continue;
    QuadSide c = cx_.canonical(QuadSide{h, f});
    bool fresh = std::find(seenQuads_.begin(), seenQuads_.end(), c) == seenQuads_.end();
    if (fresh) seenQuads_.push_back(c);
    if (fresh && use(K::Pillow)) out_.push_back(makeStep(K::Pillow, QuadSide{h, f}));
    if (fresh && use(K::HexPush) && inRegion(g.hex)) out_.push_back(makeStep(K::HexPush, QuadSide{h, f}));
    if (use(K::HexPull) && inRegion(g.hex) && (!prefilter_ || hexPullMayApply(cx_, host_, {h, f})))
      out_.push_back(makeStep(K::HexPull, QuadSide{h, f}));
  }
}

// Face splits of each interior quad of region hex i with every later quad on the same vertices.
void MoveList::faceSplits(size_t i) {
  const HexId h = region_[i];
  for (int f = 0; f < 6; ++f) {
    Gluing g = cx_.gluing(h, f);
    if (g.boundary()) continue;
    const auto& key = faceSets_[i * 6 + size_t(f)];
    for (size_t i2 = 0; i2 < region_.size(); ++i2)
      for (int f2 = 0; f2 < 6; ++f2) {
        const HexId h2 = region_[i2];
        if ((h2 == h && f2 == f) || (h2 == g.hex && f2 == g.face) || cx_.gluing(h2, f2).boundary()) continue;
        if (QuadSide{h2, f2} < QuadSide{h, f} || faceSets_[i2 * 6 + size_t(f2)] != key) continue;
        Gluing g2 = cx_.gluing(h2, f2);
        // Every choice of sides: the side of sL keeps the vertex ids (host sides must keep theirs).
        // (The hex across the quad from a's side gets new ids for the split vertices: a host
        // hex there would change its vertices, so that choice is never local.)
        for (QuadSide a : {QuadSide{h, f}, QuadSide{g.hex, g.face}})
          for (QuadSide b : {QuadSide{h2, f2}, QuadSide{g2.hex, g2.face}})
            if (!prefilter_ || !isHost(host_, cx_.gluing(a).hex)) out_.push_back(makeStep(OpKind::FaceSplit, a, b));
      }
  }
}

// The ring collapse along edge e of h, and chord pushes and face collapses of pairs of quads
// round e's closed star (once per edge).
void MoveList::edgeMoves(HexId h, int e) {
  using K = OpKind;
  if (use(K::RingCollapse) && (e & 2) == 0 && (!prefilter_ || ringCollapseMayApply(cx_, hostVertex_, host_, {h, e})))
    out_.push_back(makeStep(K::RingCollapse, EdgeRef{h, e}));
  if (!use(K::ChordPush) && !use(K::FaceCollapse)) return;
  EdgeRef ce;
  ops::EdgeStar st;
  if (!freshClosedStar(cx_, h, e, seenEdges_, ce, st)) return;
  size_t n = st.inc.size();
  auto touches = [&](size_t k) { return inRegion(st.inc[k].hex) || inRegion(st.inc[(k + 1) % n].hex); };
  // Both operations cut e into one edge per arc (arc L: incidences i+1..j, R: the rest): with
  // a host hex on both arcs, a host edge would be split, so the move is never local.
  auto hostOn = [&](size_t from, size_t to) {  // incidences from..to-1, cyclically
    for (size_t k = from; k != to; k = (k + 1) % n)
      if (!inRegion(st.inc[k].hex)) return true;
    return false;
  };
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 1; j < n; ++j) {
      if (!touches(i) || !touches(j)) continue;
      if (prefilter_ && hostOn((i + 1) % n, (j + 1) % n) && hostOn((j + 1) % n, (i + 1) % n)) continue;
      QuadSide fi{st.inc[i].hex, st.exitFace[i]}, fj{st.inc[j].hex, st.exitFace[j]};
      const ArcEnds ends = arcEnds(cx_, ce, fi, fj);
      if (prefilter_ && !ends.distinct()) continue;
      if (use(K::ChordPush)) out_.push_back(makeStep(K::ChordPush, ce, fi, fj));
      if (use(K::FaceCollapse) && (!prefilter_ || faceCollapseMayApply(cx_, host_, ends)))
        out_.push_back(makeStep(K::FaceCollapse, ce, fi, fj));
    }
}

}  // namespace

std::vector<OpStep> moves(const Complex& cx, const std::vector<HexId>& host, const std::vector<OpKind>& ops,
                          int ringSplitMax, bool prefilter) {
  return MoveList(cx, host, ops, prefilter).list(ringSplitMax);
}

}  // namespace hexdual::flipsearch
