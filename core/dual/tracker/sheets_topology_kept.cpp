// Sheet update when the operation keeps every sheet's topology (its keepsSheetTopology flag in the
// operation table): new slots form components that join the one old sheet they touch, or form a
// new sheet when they touch none; dead slots leave their sheets. Nothing beyond the new slots is
// explored, and shares move with the edit while each sheet's Euler characteristic stays.
// Refuses, changing nothing, when a component touches two old sheets (a merge): update() then
// runs the lockstep flood.
// Owns nothing between updates; marks front_ with component numbers while it runs (cleared after).
#include "dual/dual_tracker.hpp"

#include <algorithm>

#include "dual/tracker/slots.hpp"

namespace hexdual {
using namespace tracker;

bool DualTracker::updateSheetsLocally(const Complex& cx, const std::vector<HexId>& touched, DualChange& change) {
  const size_t cap = dual_.sheetLabel.size();
  // Components of the unlabelled (new) slots, and the existing sheets each one touches.
  std::vector<std::vector<Slot>> comps;
  std::vector<std::vector<int32_t>> joins;
  // A new slot's component is marked in front_ (ci + 1) while this runs.
  auto clearMarks = [&] {
    for (const auto& comp : comps)
      for (Slot t : comp) front_[slotIndex(t)] = 0;
  };
  for (HexId h : touched) {
    if (!cx.isHex(h)) continue;
    for (int a = 0; a < 3; ++a) {
      if (dual_.sheetLabel[size_t(h)][size_t(a)] >= 0 || front_[slotIndex({h, a})]) continue;
      size_t ci = comps.size();
      comps.push_back({{h, a}});
      joins.emplace_back();
      front_[slotIndex({h, a})] = int32_t(ci + 1);
      for (size_t i = 0; i < comps[ci].size(); ++i) {
        Slot cur = comps[ci][i];
        for (int f : kParallelFaces[size_t(cur.axis)]) {
          Slot n;
          int flip;
          if (!sheetNeighbour(cx, cur, f, n, flip)) continue;
          int32_t id = size_t(n.hex) < cap ? dual_.sheetAt(n.hex, n.axis) : -1;
          if (id >= 0) {
            if (std::find(joins[ci].begin(), joins[ci].end(), id) == joins[ci].end()) joins[ci].push_back(id);
          } else if (!front_[slotIndex(n)]) {
            front_[slotIndex(n)] = int32_t(ci + 1);
            comps[ci].push_back(n);
          }
        }
      }
      if (joins[ci].size() > 1) {  // two sheets would merge: not a local change
        clearMarks();
        return false;
      }
    }
  }
  clearMarks();
  // Shares move with the edit but each sheet's sum (its Euler characteristic) does not: the
  // operation keeps every sheet's topology.
  refreshShares(cx, touched, nullptr);
  // Remove the slots of dead hexes (from their lists when next read).
  std::vector<int32_t> changed;
  std::vector<std::pair<int32_t, Slot>> dead;
  for (HexId h : touched) {
    if (cx.isHex(h) || size_t(h) >= cap) continue;
    countSelfHex(h, -1);
    for (int a = 0; a < 3; ++a) {
      const int32_t id = dual_.sheetAt(h, a);
      if (id < 0) continue;
      dead.push_back({id, Slot{h, a}});
      changed.push_back(id);
      setLabel({h, a}, -1);
      flooder_.signs()[3 * size_t(h) + size_t(a)] = 0;
    }
  }
  std::sort(dead.begin(), dead.end(), [](const auto& x, const auto& y) { return x.first != y.first ? x.first < y.first : x.second < y.second; });
  for (size_t i = 0; i < dead.size();) {
    std::vector<Slot> gone;
    size_t j = i;
    for (; j < dead.size() && dead[j].first == dead[i].first; ++j) gone.push_back(dead[j].second);
    dual_.sheets[size_t(dead[i].first)].slots.remove(std::move(gone));
    i = j;
  }
  // Label the new components: join the one sheet they touch, or form a new sheet.
  std::vector<HexId> born;
  for (size_t ci = 0; ci < comps.size(); ++ci) {
    for (Slot t : comps[ci]) born.push_back(t.hex);
    if (joins[ci].empty()) {
      const int32_t id = int32_t(dual_.sheets.size());
      const int32_t label = newLabel(id);
      Sheet sh;
      sh.id = id;
      std::vector<Slot> slots;
      SheetStats st = flooder_.flood(cx, comps[ci][0], label, dual_.sheetLabel[0].data(), &slots);
      flooder_.clear(slots);
      labelSlots_[size_t(label)] += int32_t(slots.size());
      std::sort(slots.begin(), slots.end());
      st.classify(sh);
      sheetSlotsTouched_ += slots.size();
      sh.slots = std::move(slots);
      dual_.sheets.push_back(std::move(sh));
      selfPairs_.push_back(0);
      change.sheetsCreated.push_back(id);
    } else {
      const int32_t id = joins[ci][0];
      const int32_t label = labels_[size_t(id)].front();
      for (Slot t : comps[ci]) setLabel(t, label);
      std::vector<Slot> run = comps[ci];
      std::sort(run.begin(), run.end());
      dual_.sheets[size_t(id)].slots.add(std::move(run));
      propagateSigns(cx, comps[ci]);
      sheetSlotsTouched_ += comps[ci].size();
      changed.push_back(id);
    }
  }
  // Self-intersection counts for the new hexes (all three of their slots are new).
  std::sort(born.begin(), born.end());
  born.erase(std::unique(born.begin(), born.end()), born.end());
  countSelfHexes(born, +1);
  std::sort(changed.begin(), changed.end());
  changed.erase(std::unique(changed.begin(), changed.end()), changed.end());
  for (int32_t id : changed) {
    Sheet& sh = dual_.sheets[size_t(id)];
    sh.selfIntersecting = selfPairs_[size_t(id)] > 0;
    pruneLabels(id);
    if (std::find(change.sheetsCreated.begin(), change.sheetsCreated.end(), id) != change.sheetsCreated.end()) continue;
    if (sh.slots.empty()) {
      sh.alive = false;
      change.sheetsRemoved.push_back(id);
    } else {
      change.sheetsChanged.push_back(id);
    }
  }
  for (int32_t id : change.sheetsCreated) dual_.sheets[size_t(id)].selfIntersecting = selfPairs_[size_t(id)] > 0;
  return true;
}

}  // namespace hexdual
