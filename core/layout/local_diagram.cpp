#include "layout/local_diagram.hpp"

#include <algorithm>
#include <unordered_map>

#include "layout/assemble_diagram.hpp"
#include "layout/check_diagram.hpp"
#include "layout/circle_placement.hpp"
#include "layout/mid_surface.hpp"

namespace hexdual {
using namespace tables;

namespace {

// Slots of the sheet within `rings` rings of the seeds, with their ring number, breadth first.
std::vector<std::pair<Slot, int>> ringsAround(const Complex& cx, const Dual& dual, int sheet,
                                              const std::vector<Slot>& seeds, int rings) {
  std::vector<std::pair<Slot, int>> out;
  std::unordered_map<int64_t, bool> seen;
  auto key = [](Slot s) { return int64_t(s.hex) * 3 + s.axis; };
  for (Slot s : seeds)
    if (seen.emplace(key(s), true).second) out.push_back({s, 0});
  for (size_t i = 0; i < out.size(); ++i) {
    auto [slot, depth] = out[i];
    if (depth >= rings) continue;
    for (int e : midCycle(slot.axis))
      for (EdgeRef x : cx.edgeCycle({slot.hex, e})) {
        Slot n{x.hex, axisOfEdge(x.edge)};
        if (dual.sheetAt(n.hex, n.axis) != sheet) continue;
        if (seen.emplace(key(n), true).second) out.push_back({n, depth + 1});
      }
  }
  return out;
}

// The layout of the slots within k rings, or false when that piece is not of genus 0 (a
// neighbourhood reaching round a handle): it is then drawn with fewer rings.
bool tryRings(const Dual& dual, int sheet, const Complex& cx, const std::vector<std::pair<Slot, int>>& ring, int k,
              SheetDiagram& d) {
  std::vector<Slot> slots;
  for (auto [s, depth] : ring)
    if (depth <= k) slots.push_back(s);
  MidSurface s = buildMidSurface(cx, slots);
  Placement pl;
  if (!placeSurface(s, pl)) return false;
  d = assembleDiagram(dual, sheet, s, pl, true);
  d.euler = eulerCharacteristic(s);
  checkDiagram(d, d.crossings.size());
  return true;
}

}  // namespace

SheetDiagram layoutAround(const Complex& cx, const Dual& dual, int sheet, const std::vector<Slot>& seeds, int rings) {
  auto ring = ringsAround(cx, dual, sheet, seeds, std::max(rings, 0));
  int deepest = 0;
  for (auto [s, depth] : ring) deepest = std::max(deepest, depth);
  SheetDiagram d;
  int k = deepest;  // more rings than that add nothing
  if (!tryRings(dual, sheet, cx, ring, k, d)) {
    int lo = -1, hi = k;  // bisection: the largest ring count that draws, assuming fewer rings draw too
    SheetDiagram best;
    while (hi - lo > 1) {
      int mid = (lo + hi) / 2;
      SheetDiagram t;
      if (tryRings(dual, sheet, cx, ring, mid, t)) {
        lo = mid;
        best = std::move(t);
      } else {
        hi = mid;
      }
    }
    if (lo < 0) {
      if (seeds.size() > 1) return layoutAround(cx, dual, sheet, {seeds[0]}, rings);
      throw Error("sheet diagram: no neighbourhood of hex " + std::to_string(seeds[0].hex) + " on sheet " +
                  std::to_string(sheet) + " draws as a planar disk");
    }
    k = lo;
    d = std::move(best);
  }
  if (k == deepest) k = std::max(rings, deepest);  // the whole neighbourhood asked for
  d.note = "the sheet within " + std::to_string(k) + " ring(s) of the chosen hexes" +
           (k < rings ? " (more rings reach round a handle of the sheet)" : "") + (d.openedHex >= 0 ? "; " + d.note : "");
  return d;
}

SheetDiagram layoutLocal(const Complex& cx, const Dual& dual, int sheet, const std::vector<HexId>& hexes, int rings) {
  if (sheet < 0 || size_t(sheet) >= dual.sheets.size() || !dual.sheets[size_t(sheet)].alive)
    throw Error("sheet diagram: sheet " + std::to_string(sheet) + " does not exist");
  std::vector<Slot> seeds;
  for (HexId h : hexes) {
    if (!cx.isHex(h)) throw Error("sheet diagram: hex " + std::to_string(h) + " does not exist");
    for (int a = 0; a < 3; ++a)
      if (dual.sheetAt(h, a) == sheet) seeds.push_back({h, a});
  }
  if (seeds.empty()) throw Error("sheet diagram: none of the given hexes lies on sheet " + std::to_string(sheet));
  return layoutAround(cx, dual, sheet, seeds, rings);
}

}  // namespace hexdual
