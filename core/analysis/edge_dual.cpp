#include "analysis/edge_dual.hpp"

#include <algorithm>

namespace hexdual {

namespace {
void addDistinct(std::vector<int>& ids, int id) {
  if (std::find(ids.begin(), ids.end(), id) == ids.end()) ids.push_back(id);
}
}  // namespace

EdgeDual edgeDual(const Complex& cx, const Dual& dual, EdgeRef e) {
  if (!cx.isHex(e.hex) || e.edge < 0 || e.edge > 11)
    throw Error("edgedual: " + std::string(cx.isHex(e.hex) ? "local edge " + std::to_string(e.edge) + " is out of range"
                                                           : "hex " + std::to_string(e.hex) + " does not exist"));
  EdgeDual out;
  bool closed = false;
  const std::vector<EdgeRef> cycle = cx.edgeCycle(e, &closed);
  out.ref = cx.canonical(e);
  out.valence = int(cycle.size());
  out.boundary = !closed;
  out.sheet = dual.sheetAt(e.hex, tables::axisOfEdge(e.edge));
  std::vector<QuadSide> seen;
  for (EdgeRef inc : cycle) {
    out.hexes.push_back(inc.hex);
    const int a = tables::axisOfEdge(inc.edge);
    for (int f : tables::facesOfEdge(inc.edge)) {
      const QuadSide q = cx.canonical(QuadSide{inc.hex, f});
      if (std::find(seen.begin(), seen.end(), q) != seen.end()) continue;
      seen.push_back(q);
      const int b = tables::axisOfFace(f), c = 3 - a - b;
      out.quads.push_back({q, dual.chordAt(inc.hex, b), dual.sheetAt(inc.hex, c)});
    }
  }
  for (const EdgeDual::Quad& q : out.quads) {
    addDistinct(out.chords, q.chord);
    addDistinct(out.sheets, q.sheet);
  }
  addDistinct(out.sheets, out.sheet);
  std::sort(out.chords.begin(), out.chords.end());
  std::sort(out.sheets.begin(), out.sheets.end());
  return out;
}

}  // namespace hexdual
