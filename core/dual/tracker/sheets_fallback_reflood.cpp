// Sheet update when neither the topology-kept update nor the lockstep flood applies
// (non-orientable sheets, states the lockstep cannot follow): every old sheet through
// the touched hexes is re-flooded whole (relabel), its labels freed and new ones given, ids kept
// by the smallest-old-id rule. It costs the touched sheets whole; lastUpdateReflooded() says so.
// Owns nothing between updates.
#include <algorithm>

#include "dual/dual_tracker.hpp"
#include "dual/tracker/relabel.hpp"
#include "dual/tracker/slots.hpp"

namespace hexdual {
using namespace tracker;

void DualTracker::updateSheetsByFlood(const Complex& cx, const std::vector<HexId>& touched, DualChange& change) {
  int32_t* sheetOf = dual_.sheetLabel[0].data();
  auto walk = [&](Slot s, Sheet& sh, std::vector<int32_t>& previous) {
    std::vector<Slot> slots;
    SheetStats st = flooder_.flood(cx, s, kTemp, sheetOf, &slots, &previous);
    flooder_.clear(slots);
    std::sort(slots.begin(), slots.end());
    st.classify(sh);
    sh.slots = std::move(slots);
  };
  refreshShares(cx, touched, nullptr);  // the floods measure each sheet whole
  // Every slot of the re-flooded sheets gets a new label: their hexes' pairs are counted again.
  const std::vector<int32_t> old = sheetIdsThrough(dual_, touched);
  std::vector<HexId> recount(touched.begin(), touched.end());
  for (int32_t id : old)
    for (Slot t : dual_.sheets[size_t(id)].slots) recount.push_back(t.hex);
  std::sort(recount.begin(), recount.end());
  recount.erase(std::unique(recount.begin(), recount.end()), recount.end());
  countSelfHexes(recount, -1);
  for (int32_t id : old) {
    for (int32_t l : labels_[size_t(id)]) {
      labelSlots_[size_t(l)] = 0;
      freeLabels_.push_back(l);  // every slot carrying it is parked below, before any new label
    }
    labels_[size_t(id)].clear();
  }
  auto labelOf = [&](int id) {
    if (dual_.sheets.size() <= size_t(id)) selfPairs_.resize(size_t(id) + 1, 0);
    return newLabel(id);
  };
  sheetSlotsTouched_ += relabel(
      cx, touched, dual_.sheetLabel, dual_.sheets, old, walk, change.sheetsCreated, change.sheetsChanged,
      change.sheetsRemoved, [](int) { return false; }, labelOf);
  for (HexId h : touched)
    if (!cx.isHex(h))
      for (int a = 0; a < 3; ++a) flooder_.signs()[3 * size_t(h) + size_t(a)] = 0;
  selfPairs_.resize(dual_.sheets.size(), 0);
  auto counted = [&](int id) {
    const int32_t l = labels_[size_t(id)].front();
    labelSlots_[size_t(l)] = int32_t(dual_.sheets[size_t(id)].slots.size());
  };
  for (int id : change.sheetsCreated) counted(id);
  for (int id : change.sheetsChanged) counted(id);
  std::vector<HexId> live;
  for (HexId h : recount)
    if (cx.isHex(h)) live.push_back(h);
  countSelfHexes(live, +1);
  auto flag = [&](int id) { dual_.sheets[size_t(id)].selfIntersecting = selfPairs_[size_t(id)] > 0; };
  for (int id : change.sheetsCreated) flag(id);
  for (int id : change.sheetsChanged) flag(id);
}

}  // namespace hexdual
