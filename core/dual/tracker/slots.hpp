// Slots and their neighbours, shared by the tracker's units (tracker/*.cpp): a slot's index in the
// per-slot arrays, the sheet slot across a face, the sheets through a set of hexes; how the
// invariant checks name a slot and fail. Owns no state.
#pragma once
#include <algorithm>
#include <string>
#include <vector>

#include "complex/complex.hpp"
#include "complex/sorted_ids.hpp"
#include "dual/dual.hpp"

namespace hexdual::tracker {

// The sheet ids on the slots of these hexes, ascending, once each.
inline std::vector<int32_t> sheetIdsThrough(const Dual& d, const std::vector<HexId>& hexes) {
  std::vector<int32_t> ids;
  for (HexId h : hexes)
    for (int a = 0; a < 3; ++a)
      if (d.sheetAt(h, a) >= 0) ids.push_back(d.sheetAt(h, a));
  sortUniqueIds(ids);
  return ids;
}

// Appends an id to a DualChange list, starting it with room for 8: an update reports a few ids per
// list, and a fresh DualChange's lists would otherwise reallocate at 1, 2 and 4.
inline void report(std::vector<int32_t>& list, int32_t id) {
  if (list.capacity() == 0) list.reserve(8);
  list.push_back(id);
}

inline size_t slotIndex(Slot s) { return 3 * size_t(s.hex) + size_t(s.axis); }

// The slot across face f of slot s's hex (f parallel to s's axis), and the orientation flip.
inline bool sheetNeighbour(const Complex& cx, Slot s, int f, Slot& n, int& flip) {
  Gluing g = cx.gluing(s.hex, f);
  if (g.boundary()) return false;
  const tables::Crossing& c = tables::kCrossings[size_t(tables::crossingIndex(f, s.axis, g.face, g.orient))];
  n = {g.hex, c.axis};
  flip = c.sign;
  return true;
}

// Whether one of h's edges marked in `edges` (bit e: edge e) reaches the boundary (its cycle is a
// fan); h live (tracker/shares.cpp).
bool edgesNear(const Complex& cx, HexId h, unsigned edges);

// For checkInvariants: a slot named as in messages, and the error naming a broken invariant.
inline std::string slotName(Slot s) { return "h" + std::to_string(s.hex) + " axis " + std::to_string(s.axis); }
[[noreturn]] inline void invariantBroken(const std::string& what) { throw Error("dual tracker invariant: " + what); }

}  // namespace hexdual::tracker
