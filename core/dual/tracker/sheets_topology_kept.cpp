// Sheet update when the operation keeps every sheet's topology (its keepsSheetTopology flag in the
// operation table): new slots form components that join the one old sheet they touch, or form a
// new sheet when they touch none; dead slots leave their sheets. Nothing beyond the new slots is
// explored, and shares move with the edit while each sheet's Euler characteristic stays.
// Refuses, changing nothing, when a component touches two old sheets (a merge): update() then
// runs the lockstep flood.
// Owns nothing between updates but its scratch lists (per thread, emptied at the start of each
// update); marks front_ with component numbers while it runs (cleared after).
#include <algorithm>
#include <span>

#include "complex/sorted_ids.hpp"
#include "dual/dual_tracker.hpp"
#include "dual/tracker/slots.hpp"

namespace hexdual {
using namespace tracker;

// One topology-kept update: the components of new (unlabelled) slots and the old sheets each
// touches, and the steps of updateSheetsLocally below.
struct DualTracker::TopologyKept {
  DualTracker& t;
  const Complex& cx;
  const std::vector<HexId>& touched;
  const size_t cap;  // hexes the dual had labels for before the edit
  // Every list an update fills, kept between updates (one per thread).
  struct Scratch {
    std::vector<Slot> compSlots;
    std::vector<size_t> compAt;
    std::vector<int32_t> joins, changed;
    std::vector<std::pair<int32_t, Slot>> dead;
    std::vector<Slot> gone;
    std::vector<HexId> born;
    std::vector<uint32_t> at;  // dropDeadSlots: per sheet id, where its group of dead slots ends
  };
  static Scratch& scratch() {
    thread_local Scratch s;
    return s;
  }
  Scratch& sc = scratch();
  // Components of the new slots: component ci is compSlots[compAt[ci], compAt[ci + 1]).
  std::vector<Slot>& compSlots = sc.compSlots;
  std::vector<size_t>& compAt = sc.compAt;
  std::vector<int32_t>& joins = sc.joins;    // per component: the old sheet it touches, or -1
  std::vector<int32_t>& changed = sc.changed;  // old sheets that lost or gained slots

  TopologyKept(DualTracker& tracker, const Complex& c, const std::vector<HexId>& hexes)
      : t(tracker), cx(c), touched(hexes), cap(tracker.dual_.sheetLabel.size()) {
    compSlots.clear();
    compAt.assign(1, 0);
    joins.clear();
    changed.clear();
  }
  size_t numComps() const { return joins.size(); }
  std::span<const Slot> comp(size_t ci) const { return {compSlots.data() + compAt[ci], compAt[ci + 1] - compAt[ci]}; }
  bool findNewComponents();
  void clearMarks();
  void dropDeadSlots();
  void formNewSheet(std::span<const Slot> comp, DualChange& change);
  void joinOldSheet(std::span<const Slot> comp, int32_t id);
  void labelNewComponents(DualChange& change);
  void reportChanges(DualChange& change);
};

bool DualTracker::updateSheetsLocally(const Complex& cx, const std::vector<HexId>& touched, DualChange& change) {
  TopologyKept up(*this, cx, touched);
  const bool local = up.findNewComponents();
  up.clearMarks();
  if (!local) return false;
  // Shares move with the edit but each sheet's sum (its Euler characteristic) does not: the
  // operation keeps every sheet's topology.
  refreshShares(cx, touched, nullptr);
  up.dropDeadSlots();
  up.labelNewComponents(change);
  up.reportChanges(change);
  return true;
}

// Components of the unlabelled (new) slots, and the existing sheets each one touches; a new
// slot's component is marked in front_ (ci + 1) until clearMarks. False when a component touches
// two sheets: they would merge, not a local change.
bool DualTracker::TopologyKept::findNewComponents() {
  HugeVector<int32_t>& front = t.front_;
  for (HexId h : touched) {
    if (!cx.isHex(h)) continue;
    for (int a = 0; a < 3; ++a) {
      if (t.dual_.sheetLabel[size_t(h)][size_t(a)] >= 0 || front[slotIndex({h, a})]) continue;
      const size_t ci = joins.size();
      compSlots.push_back({h, a});
      joins.push_back(-1);
      front[slotIndex({h, a})] = int32_t(ci + 1);
      bool merges = false;
      for (size_t i = compAt[ci]; i < compSlots.size(); ++i) {
        const Slot cur = compSlots[i];
        for (int f : kParallelFaces[size_t(cur.axis)]) {
          Slot n;
          int flip;
          if (!sheetNeighbour(cx, cur, f, n, flip)) continue;
          int32_t id = size_t(n.hex) < cap ? t.dual_.sheetAt(n.hex, n.axis) : -1;
          if (id >= 0) {
            merges = merges || (joins[ci] >= 0 && joins[ci] != id);
            if (joins[ci] < 0) joins[ci] = id;
          } else if (!front[slotIndex(n)]) {
            front[slotIndex(n)] = int32_t(ci + 1);
            compSlots.push_back(n);
          }
        }
      }
      compAt.push_back(compSlots.size());
      if (merges) return false;
    }
  }
  return true;
}

void DualTracker::TopologyKept::clearMarks() {
  for (Slot s : compSlots) t.front_[slotIndex(s)] = 0;
}

// The slots of dead hexes lose their labels and orientations, and leave their sheets' lists
// (when next read); their pairs are uncounted.
void DualTracker::TopologyKept::dropDeadSlots() {
  std::vector<std::pair<int32_t, Slot>>& dead = sc.dead;
  dead.clear();
  for (HexId h : touched) {
    if (cx.isHex(h) || size_t(h) >= cap) continue;
    t.countSelfHex(h, -1);
    for (int a = 0; a < 3; ++a) {
      const int32_t id = t.dual_.sheetAt(h, a);
      if (id < 0) continue;
      dead.push_back({id, Slot{h, a}});
      changed.push_back(id);
      t.setLabel({h, a}, -1);
      t.flooder_.signs()[3 * size_t(h) + size_t(a)] = 0;
    }
  }
  std::vector<Slot>& gone = sc.gone;
  if (dead.size() >= 256) {
    // Many (a sheet operation's: 30,000 when a 100³ sheet is extracted): grouped by sheet with a
    // count per sheet id, not sorted. Each group stays in slot order, as touched is ascending.
    std::vector<uint32_t>& at = sc.at;
    at.assign(t.dual_.sheets.size() + 1, 0);
    for (const auto& [id, s] : dead) ++at[size_t(id) + 1];
    for (size_t i = 1; i < at.size(); ++i) at[i] += at[i - 1];
    gone.resize(dead.size());
    for (const auto& [id, s] : dead) gone[at[size_t(id)]++] = s;  // at[id]: now where id's group ends
    size_t from = 0;
    for (size_t id = 0; id + 1 < at.size(); ++id) {
      if (at[id] == from) continue;
      t.dual_.sheets[id].slots.remove(std::span<const Slot>(gone.data() + from, at[id] - from));
      from = at[id];
    }
    return;
  }
  std::sort(dead.begin(), dead.end(),
            [](const auto& x, const auto& y) { return x.first != y.first ? x.first < y.first : x.second < y.second; });
  for (size_t i = 0; i < dead.size();) {
    gone.clear();
    size_t j = i;
    for (; j < dead.size() && dead[j].first == dead[i].first; ++j) gone.push_back(dead[j].second);
    t.dual_.sheets[size_t(dead[i].first)].slots.remove(gone);
    i = j;
  }
}

// A component that touches no old sheet is a new sheet, flooded (labelled, oriented, measured) whole.
void DualTracker::TopologyKept::formNewSheet(std::span<const Slot> comp, DualChange& change) {
  Dual& d = t.dual_;
  const int32_t id = int32_t(d.sheets.size());
  const int32_t label = t.newLabel(id);
  Sheet sh;
  sh.id = id;
  std::vector<Slot> slots;
  SheetStats st = t.flooder_.flood(cx, comp[0], label, d.sheetLabel[0].data(), &slots);
  t.flooder_.clear(slots);
  t.labelSlots_[size_t(label)] += int32_t(slots.size());
  std::sort(slots.begin(), slots.end());
  st.classify(sh);
  t.sheetSlotsTouched_ += slots.size();
  sh.slots = std::move(slots);
  d.sheets.push_back(std::move(sh));
  t.selfPairs_.push_back(0);
  report(change.sheetsCreated, id);
}

// A component that touches one old sheet joins it with its first label, oriented from its neighbours.
void DualTracker::TopologyKept::joinOldSheet(std::span<const Slot> comp, int32_t id) {
  const int32_t label = t.labels_[size_t(id)].front();
  for (Slot s : comp) t.setLabel(s, label);
  t.dual_.sheets[size_t(id)].slots.add(comp);
  t.propagateSigns(cx, comp);
  t.sheetSlotsTouched_ += comp.size();
  changed.push_back(id);
}

// Labels the new components (join the one sheet they touch, or form a new sheet), then counts the
// pairs of the new hexes (all three of their slots are new).
void DualTracker::TopologyKept::labelNewComponents(DualChange& change) {
  std::vector<HexId>& born = sc.born;
  born.clear();
  for (size_t ci = 0; ci < numComps(); ++ci) {
    for (Slot s : comp(ci)) born.push_back(s.hex);
    if (joins[ci] < 0)
      formNewSheet(comp(ci), change);
    else
      joinOldSheet(comp(ci), joins[ci]);
  }
  sortUniqueIds(born);  // (a sheet operation's: tens of thousands, by bitmap)
  t.countSelfHexes(born, +1);
}

// Changed sheets: self-intersection, labels pruned; reported changed, or removed when emptied.
void DualTracker::TopologyKept::reportChanges(DualChange& change) {
  sortUniqueIds(changed);  // (a sheet extraction names a few hundred sheets 30,000 times)
  for (int32_t id : changed) {
    Sheet& sh = t.dual_.sheets[size_t(id)];
    sh.selfIntersecting = t.selfPairs_[size_t(id)] > 0;
    t.pruneLabels(id);
    if (std::find(change.sheetsCreated.begin(), change.sheetsCreated.end(), id) != change.sheetsCreated.end()) continue;
    if (sh.slots.empty()) {
      sh.alive = false;
      report(change.sheetsRemoved, id);
    } else {
      report(change.sheetsChanged, id);
    }
  }
  for (int32_t id : change.sheetsCreated) t.dual_.sheets[size_t(id)].selfIntersecting = t.selfPairs_[size_t(id)] > 0;
}

}  // namespace hexdual
