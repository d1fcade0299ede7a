// A loop of edges is found by walking two strips of quads from the picked edge (each step crosses
// to the next quad of both strips around their shared vertex), then rewritten in the search's
// canonical form so that equal splits are written equally.
#include "ops/ring_splits.hpp"

#include <algorithm>
#include <array>
#include <set>
#include <string>

#include "ops/oplog.hpp"
#include "ops/support.hpp"

namespace hexdual {

namespace {

using tables::kFaceCorners;
using tables::kEdgeCorners;
using tables::edgeBetween;

// One band of a split: the quads of the two strips on one loop edge, that edge's ends in walk order.
struct Band {
  QuadSide f, g;
  VertexId from, to;
};

class LoopWalker {
 public:
  LoopWalker(const Complex& cx, int maxEdges) : cx_(cx), max_(maxEdges) {}

  // Every loop through e with its two strips, walked from e's smaller vertex.
  std::vector<std::vector<Band>> loopsThrough(EdgeRef e) {
    EdgeRef ce = cx_.canonical(e);
    std::vector<QuadSide> qs = starQuads(ce);
    VertexId a = cx_.vertex(ce.hex, kEdgeCorners[size_t(ce.edge)][0]), b = cx_.vertex(ce.hex, kEdgeCorners[size_t(ce.edge)][1]);
    if (b < a) std::swap(a, b);
    for (size_t i = 0; i < qs.size(); ++i)
      for (size_t j = i + 1; j < qs.size(); ++j) {
        bands_ = {{qs[i], qs[j], a, b}};
        loop_ = {a, b};
        extend();
      }
    return std::move(found_);
  }

  // The canonical quad sides around an edge whose cycle closes, in star order (empty otherwise).
  std::vector<QuadSide> starQuads(EdgeRef e) const {
    bool closed = false;
    cx_.edgeCycle(e, &closed);
    if (!closed) return {};
    ops::EdgeStar st = ops::closedEdgeStar(cx_, e, "ringsplit");
    std::vector<QuadSide> qs;
    for (size_t k = 0; k < st.inc.size(); ++k) qs.push_back(cx_.canonical(QuadSide{st.inc[k].hex, st.exitFace[k]}));
    return qs;
  }

  // The canonical edge a-b of quad s.
  EdgeRef edgeOf(QuadSide s, VertexId a, VertexId b) const { return cx_.canonical(EdgeRef{s.hex, edgeBetween(cornerIn(s.hex, a), cornerIn(s.hex, b))}); }

  // v's neighbour in quad s other than `away`.
  VertexId other(QuadSide s, VertexId v, VertexId away) const {
    std::array<VertexId, 4> fv;
    for (int p = 0; p < 4; ++p) fv[size_t(p)] = cx_.vertex(s.hex, kFaceCorners[size_t(s.face)][size_t(p)]);
    for (int p = 0; p < 4; ++p)
      if (fv[size_t(p)] == v) return fv[size_t((p + 1) & 3)] == away ? fv[size_t((p + 3) & 3)] : fv[size_t((p + 1) & 3)];
    return -1;
  }

 private:
  int cornerIn(HexId h, VertexId v) const {
    for (int c = 0; c < 8; ++c)
      if (cx_.vertex(h, c) == v) return c;
    return -1;
  }

  // Continues both strips past the last band's far vertex; records the loop when it closes.
  void extend() {
    const Band last = bands_.back();
    const VertexId at = last.to;
    const VertexId wf = other(last.f, at, last.from), wg = other(last.g, at, last.from);
    if (at == loop_[0]) {
      const Band& b0 = bands_[0];
      if (bands_.size() >= 2 && other(b0.f, at, b0.to) == wf && other(b0.g, at, b0.to) == wg &&
          edgeOf(b0.f, at, wf) == edgeOf(last.f, at, wf) && edgeOf(b0.g, at, wg) == edgeOf(last.g, at, wg))
        found_.push_back(bands_);
      return;
    }
    if (int(bands_.size()) >= max_) return;
    const std::vector<QuadSide> fq = starQuads(edgeOf(last.f, at, wf)), gq = starQuads(edgeOf(last.g, at, wg));
    for (QuadSide f2 : fq) {
      if (f2 == last.f) continue;
      const VertexId u = other(f2, at, wf);
      if (u != loop_[0] && std::find(loop_.begin(), loop_.end(), u) != loop_.end()) continue;
      for (QuadSide g2 : gq) {
        if (g2 == last.g || g2 == f2 || other(g2, at, wg) != u || !(edgeOf(g2, at, u) == edgeOf(f2, at, u))) continue;
        bands_.push_back({f2, g2, at, u});
        loop_.push_back(u);
        extend();
        loop_.pop_back();
        bands_.pop_back();
      }
    }
  }

  const Complex& cx_;
  int max_;
  std::vector<Band> bands_;
  std::vector<VertexId> loop_;
  std::vector<std::vector<Band>> found_;
};

// The loop rewritten as the search writes it: started at its smallest canonical edge, walked from
// that edge's smaller vertex, strip f the one whose quad comes first in that edge's star.
std::vector<Band> canonicalLoop(const LoopWalker& w, std::vector<Band> loop) {
  const size_t n = loop.size();
  size_t m = 0;
  for (size_t k = 1; k < n; ++k)
    if (w.edgeOf(loop[k].f, loop[k].from, loop[k].to) < w.edgeOf(loop[m].f, loop[m].from, loop[m].to)) m = k;
  std::rotate(loop.begin(), loop.begin() + long(m), loop.end());
  if (loop[0].to < loop[0].from) {  // walk the other way round: band 0 stays first
    std::reverse(loop.begin() + 1, loop.end());
    for (Band& b : loop) std::swap(b.from, b.to);
  }
  const std::vector<QuadSide> qs = w.starQuads(w.edgeOf(loop[0].f, loop[0].from, loop[0].to));
  const auto at = [&](QuadSide s) { return std::find(qs.begin(), qs.end(), s) - qs.begin(); };
  if (at(loop[0].g) < at(loop[0].f))
    for (Band& b : loop) std::swap(b.f, b.g);
  return loop;
}

}  // namespace

std::vector<OpStep> ringSplitsThrough(const Complex& cx, EdgeRef e, int maxEdges) {
  if (!cx.isHex(e.hex) || e.edge < 0 || e.edge > 11) throw Error("ringsplit: no edge " + ops::edgeName(e));
  LoopWalker walker(cx, maxEdges);
  std::vector<OpStep> out;
  std::set<std::string> seen;
  Complex work = cx;
  for (const std::vector<Band>& found : walker.loopsThrough(e)) {
    const std::vector<Band> loop = canonicalLoop(walker, found);
    const Gluing across = cx.gluing(loop[0].f);
    for (QuadSide s0 : {loop[0].f, QuadSide{across.hex, across.face}}) {
      OpStep st{OpKind::RingSplit, {OpArg::of(s0, loop[0].g)}, 0};
      for (size_t k = 1; k < loop.size(); ++k) st.args.push_back(OpArg::of(loop[k].f, loop[k].g));
      if (!seen.insert(formatOpStep(st)).second) continue;
      if (std::optional<OpResult> r = tryApplyStep(work, st)) {
        work.undo(r->edits);
        out.push_back(st);
      }
    }
  }
  return out;
}

}  // namespace hexdual
