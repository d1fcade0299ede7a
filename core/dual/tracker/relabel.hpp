// The whole re-walk of sheets or chords through the touched hexes (relabel), shared by the sheet
// fallback (sheets_fallback_reflood.cpp) and the chord re-walk (chord_update.cpp): old ids are
// parked on their slots, components re-walked from the touched slots keep the smallest old id
// they hold. Owns no state.
#pragma once
#include <algorithm>
#include <array>
#include <climits>
#include <vector>

#include "complex/complex.hpp"
#include "dual/dual.hpp"

namespace hexdual::tracker {

// Old labels are parked in the per-slot array as -2 - id, so a walk that overwrites them reports
// which old sheets or chords each new one holds (no map of slots).
inline int32_t parked(int32_t id) { return -2 - id; }

// Picks the id for a recomputed component: the smallest old id it holds that no earlier
// component took, else a fresh id.
inline int chooseId(const std::vector<int32_t>& previous, std::vector<int>& taken, size_t freshId) {
  int best = -1;
  for (int32_t p : previous) {
    int c = p <= -2 ? parked(p) : -1;
    if (c >= 0 && (best < 0 || c < best) && std::find(taken.begin(), taken.end(), c) == taken.end()) best = c;
  }
  if (best < 0) return int(freshId);
  taken.push_back(best);
  return best;
}

// Re-labels the sheets or chords (`list`, per-slot labels `of`) through the touched hexes: every
// old one touched (`old`, ascending) is cleared and its slots re-walked from seeds (with `walk`,
// labelling kTemp), and each component found keeps the smallest old id it holds; `labelOf(id)`
// gives the label its slots get. Sheets and chords alike.
template <class Entity, class Walk, class Unchanged, class LabelOf>
size_t relabel(const Complex& cx, const std::vector<HexId>& touched, HugeVector<std::array<int32_t, 3>>& of,
               HugeVector<Entity>& list, std::vector<int32_t> old, Walk walk, std::vector<int>& created,
               std::vector<int>& changed, std::vector<int>& removed, Unchanged unchanged, LabelOf labelOf) {
  size_t visited = 0;
  size_t kept = 0;
  for (int32_t id : old)
    if (!unchanged(id)) old[kept++] = id;
  old.resize(kept);
  // Every new component holds a touched slot (its other slots kept their gluings), so the live
  // touched slots are enough seeds.
  for (int id : old) {
    for (Slot s : list[size_t(id)].slots) of[size_t(s.hex)][size_t(s.axis)] = parked(id);
    visited += list[size_t(id)].slots.size();
    list[size_t(id)].alive = false;
    list[size_t(id)].slots.clear();
  }
  std::vector<Slot> seeds;
  for (HexId h : touched) {
    if (!cx.isHex(h)) {
      of[size_t(h)] = {-1, -1, -1};
      continue;
    }
    for (int a = 0; a < 3; ++a) seeds.push_back({h, a});
  }
  std::sort(seeds.begin(), seeds.end());
  seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
  visited += seeds.size();
  std::vector<int> taken;
  std::vector<int32_t> previous;
  for (Slot s : seeds) {
    if (!cx.isHex(s.hex) || of[size_t(s.hex)][size_t(s.axis)] >= 0) continue;
    Entity e;
    previous.clear();
    walk(s, e, previous);
    visited += e.slots.size();
    int id = chooseId(previous, taken, list.size());
    e.id = id;
    const int32_t label = labelOf(id);
    for (Slot t : e.slots) of[size_t(t.hex)][size_t(t.axis)] = label;
    if (id == int(list.size())) {
      list.push_back(std::move(e));
      created.push_back(id);
    } else {
      list[size_t(id)] = std::move(e);
      changed.push_back(id);
    }
  }
  for (int id : old)
    if (!list[size_t(id)].alive) removed.push_back(id);
  return visited;
}

constexpr int32_t kTemp = INT32_MAX - 1;

}  // namespace hexdual::tracker
