#include "ops/candidates.hpp"

#include "dual/dual.hpp"
#include "ops/oplog.hpp"
#include "ops/support.hpp"

namespace hexdual {

namespace {

std::vector<OpStep> tries(const Complex& cx, OpKind op, CandidateSet set) {
  std::vector<OpStep> out;
  switch (set) {
    case CandidateSet::None: break;
    case CandidateSet::InteriorQuads:
      for (QuadSide q : cx.quads())
        if (!cx.isBoundary(q)) out.push_back(makeStep(op, q));
      break;
    case CandidateSet::InteriorQuadSides:
      for (HexId h : cx.hexes())
        for (int f = 0; f < 6; ++f)
          if (!cx.isBoundary({h, f})) out.push_back(makeStep(op, QuadSide{h, f}));
      break;
    case CandidateSet::Hexes:
      for (HexId h : cx.hexes()) out.push_back(makeStep(op, h));
      break;
    case CandidateSet::EdgeStarQuadPairs:
      for (EdgeRef e : cx.edges()) {
        bool closed = false;
        cx.edgeCycle(e, &closed);
        if (!closed) continue;
        auto st = ops::closedEdgeStar(cx, e, opName(op));
        size_t n = st.inc.size();
        for (size_t i = 0; i < n; ++i)
          for (size_t j = i + 1; j < n; ++j)
            out.push_back(makeStep(op, e, QuadSide{st.inc[i].hex, st.exitFace[i]}, QuadSide{st.inc[j].hex, st.exitFace[j]}));
      }
      break;
    case CandidateSet::ClosedChordEdges:
      for (const Chord& ch : extractDual(cx).chords)
        if (ch.closed)
          for (int k : {0, 1}) out.push_back(makeStep(op, EdgeRef{ch.slots[0].hex, 4 * ch.slots[0].axis + k}));
      break;
    case CandidateSet::SameVertexQuadPairs: {
      auto qs = cx.quads();
      for (size_t i = 0; i < qs.size(); ++i)
        for (size_t j = i + 1; j < qs.size(); ++j)
          if (!cx.isBoundary(qs[i]) && !cx.isBoundary(qs[j]) &&
              ops::faceVertexSet(cx, qs[i].hex, qs[i].face) == ops::faceVertexSet(cx, qs[j].hex, qs[j].face)) {
            QuadSide other{cx.gluing(qs[j]).hex, cx.gluing(qs[j]).face};
            out.push_back(makeStep(op, qs[i], qs[j]));
            out.push_back(makeStep(op, qs[i], other));
          }
      break;
    }
  }
  return out;
}

}  // namespace

std::vector<OpStep> candidates(const Complex& cx, OpKind op) {
  const OpInfo& info = opInfo(op);
  if (info.candidates == CandidateSet::None)
    throw Error(std::string("candidates: ") + info.name + " steps are not enumerated; ringcollapse prints its inverse");
  Complex work = cx;
  std::vector<OpStep> ok;
  for (const OpStep& t : tries(cx, op, info.candidates))
    if (std::optional<OpResult> r = tryApplyStep(work, t)) {
      work.undo(r->edits);
      ok.push_back(t);
    }
  return ok;
}

}  // namespace hexdual
