#include "ops/candidates.hpp"

#include "ops/oplog.hpp"
#include "ops/support.hpp"
#include "dual/dual.hpp"

namespace hexdual {
using namespace tables;

std::vector<std::string> candidates(const Complex& cx, const std::string& op) {
  static const std::vector<std::string> known = {"pillow",       "unpillow",     "chordpush", "chordpull", "hexpush",
                                                 "hexpull",      "ringcollapse", "facecollapse", "facesplit"};
  if (std::find(known.begin(), known.end(), op) == known.end()) {
    if (op == "ringsplit") throw Error("candidates: ringsplit steps are not enumerated; ringcollapse prints its inverse");
    throw Error("candidates: unknown operation '" + op + "'");
  }
  Complex work = cx;
  std::vector<std::string> tries;
  auto H = [](HexId h) { return "h" + std::to_string(h); };
  auto Q = [](QuadSide s) { return "h" + std::to_string(s.hex) + "f" + std::to_string(s.face); };
  if (op == "pillow" || op == "hexpush")
    for (QuadSide q : cx.quads())
      if (!cx.isBoundary(q)) tries.push_back(op + " " + Q(q));
  if (op == "hexpull")
    for (HexId h : cx.hexes())
      for (int f = 0; f < 6; ++f)
        if (!cx.isBoundary({h, f})) tries.push_back(op + " " + Q({h, f}));
  if (op == "unpillow" || op == "chordpull")
    for (HexId h : cx.hexes()) tries.push_back(op + " " + H(h));
  if (op == "chordpush" || op == "facecollapse")
    for (EdgeRef e : cx.edges()) {
      bool closed = false;
      cx.edgeCycle(e, &closed);
      if (!closed) continue;
      auto st = ops::closedEdgeStar(cx, e, op);
      size_t n = st.inc.size();
      for (size_t i = 0; i < n; ++i)
        for (size_t j = i + 1; j < n; ++j)
          tries.push_back(op + " h" + std::to_string(e.hex) + "e" + std::to_string(e.edge) + " " +
                          Q({st.inc[i].hex, st.exitFace[i]}) + " " + Q({st.inc[j].hex, st.exitFace[j]}));
    }
  if (op == "ringcollapse") {
    Dual d = extractDual(cx);
    for (const Chord& ch : d.chords)
      if (ch.closed)
        for (int k : {0, 1}) tries.push_back(op + " h" + std::to_string(ch.slots[0].hex) + "e" + std::to_string(4 * ch.slots[0].axis + k));
  }
  if (op == "facesplit") {
    auto qs = cx.quads();
    for (size_t i = 0; i < qs.size(); ++i)
      for (size_t j = i + 1; j < qs.size(); ++j)
        if (!cx.isBoundary(qs[i]) && !cx.isBoundary(qs[j]) &&
            ops::faceVertexSet(cx, qs[i].hex, qs[i].face) == ops::faceVertexSet(cx, qs[j].hex, qs[j].face)) {
          QuadSide other{cx.gluing(qs[j]).hex, cx.gluing(qs[j]).face};
          tries.push_back(op + " " + Q(qs[i]) + " " + Q(qs[j]));
          tries.push_back(op + " " + Q(qs[i]) + " " + Q(other));
        }
  }
  std::vector<std::string> ok;
  for (const std::string& t : tries) {
    try {
      OpResult r = applyStep(work, t);
      work.undo(r.edits);
      ok.push_back(t);
    } catch (const Error&) {
    }
  }
  return ok;
}

}  // namespace hexdual
