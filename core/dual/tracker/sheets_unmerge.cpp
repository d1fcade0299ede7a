// Sheet update for the exact undo of a step that kept every sheet: a face or ring collapse joining
// two layers (TK03 §4.4), a ring collapse's new sheet. The lockstep follows the merge by re-pointing
// labels (no slot written), but the undo has to split the merged sheet again, and a split floods
// the smaller part: n² slots for a layer of an n³ grid, where the step itself touched a few dozen.
// The complex after cx.undo(edits) is exactly the one before the step, so its sheets are exactly
// the ones before it; what the tracker needs is what it held then. recordUnmerge keeps that, before
// the lockstep commits such a plan: each old sheet's labels, their flips, its measures and pair
// counts, the free labels, the labels and orientations of the touched slots (every slot of a new
// sheet is one: the plan is recorded only then), and each slot list's pending edits as counts (a
// merge hands the merged list over whole, as pending runs, and the step's additions and removals
// are appended: SlotList::Mark) with copies of the few pending additions and removals. No list is
// read or merged. unmergeSheets gives it all back (the lists rolled back to their marks, each
// merged one rebuilt from the runs it handed over) and retires the new sheets, in time proportional
// to the step, when no update changed the sheets in between (sheetState_ is the step's). A list
// read since (which merges its pending runs) is split by the labels given back, in one pass over
// it (relistByLabels). Steps undone in LIFO order each find their state.
// Owns DualUnmergeMemo; between updates it owns nothing of the tracker.
#include <algorithm>

#include "dual/dual_tracker.hpp"
#include "dual/tracker/slots.hpp"

namespace hexdual {
using namespace tracker;

struct DualUnmergeMemo {
  uint64_t stateBefore = 0, stateAfter = 0;  // the tracker's sheetState_ before and after the merge
  std::vector<HexId> touched;
  std::vector<std::array<int32_t, 3>> labels;  // per touched hex: its slots' labels before (-1: none)
  std::vector<std::array<int8_t, 3>> signs;    // and their stored orientations
  struct SheetBefore {
    int32_t id = -1;
    int64_t euler = 0;
    int boundaryLoops = 0;
    bool orientable = true, selfIntersecting = false;
    std::string topology;
    int32_t selfPairs = 0;
    std::vector<int32_t> labels;
    std::vector<uint8_t> flips;  // labelFlip_ of each label
    SlotList::Mark mark;  // its slot list's pending edits: how many of each
    size_t listed = 0;    // and their contents: the merged part's size, each pending run's size
    std::vector<size_t> runSizes;
    std::vector<Slot> adds, gone;  // its pending additions and removals (a merge hands them over)
  };
  std::vector<SheetBefore> sheets;                 // every sheet through the touched hexes, ascending
  std::vector<std::array<int32_t, 3>> crossPairs;  // pairs_ between labels of two of them: (a, b, count), non-zero
  std::vector<std::pair<int32_t, int32_t>> merges;  // (merged, kept), in the order the lockstep merges them
  size_t sheetsBefore = 0, pieces = 0;  // sheet ids before; the new sheets (ids from sheetsBefore on)
  size_t labelCount = 0;
  std::vector<int32_t> freeLabels, freeSheet;  // the free labels, in order, and their labelSheet
  std::vector<uint8_t> freeFlip;               // and their labelFlip_
};

namespace {
constexpr size_t kCopiedEdits = 64;  // pending additions and removals a memo copies; more are merged first
}  // namespace

// update() asked to record, for its undo, a step that keeps every sheet.
DualChange DualTracker::update(const Complex& cx, const Complex::EditLog& edits, bool sheetsKeepTopology,
                              DualIdMemo& memo) {
  recordUnmerge_ = true;
  recorded_.reset();
  DualChange change;
  try {
    change = update(cx, edits, sheetsKeepTopology);
  } catch (...) {
    recordUnmerge_ = false;
    recorded_.reset();
    throw;
  }
  recordUnmerge_ = false;
  if (recorded_) recorded_->stateAfter = sheetState_;
  memo.unmerge = std::move(recorded_);
  return change;
}

void DualTracker::recordUnmerge(const std::vector<HexId>& touched, const std::vector<int32_t>& old,
                                const std::vector<std::pair<int32_t, int32_t>>& merges, size_t pieces) {
  auto u = std::make_shared<DualUnmergeMemo>();
  u->stateBefore = sheetState_;
  u->touched = touched;
  u->labels.reserve(touched.size());
  u->signs.reserve(touched.size());
  const HugeVector<int8_t>& signs = flooder_.signs();
  for (HexId h : touched) {
    u->labels.push_back(dual_.sheetLabel[size_t(h)]);
    u->signs.push_back({signs[slotIndex({h, 0})], signs[slotIndex({h, 1})], signs[slotIndex({h, 2})]});
  }
  for (int32_t id : old) {
    const Sheet& sh = dual_.sheets[size_t(id)];
    // Many pending additions and removals (other steps' edits nothing read yet) are merged now
    // rather than copied into every memo: this list's read comes once, not once per step.
    if (sh.slots.pendingAdds().size() + sh.slots.pendingGone().size() > kCopiedEdits) sh.slots.get();
    DualUnmergeMemo::SheetBefore b;
    b.id = id;
    b.euler = sh.euler;
    b.boundaryLoops = sh.boundaryLoops;
    b.orientable = sh.orientable;
    b.selfIntersecting = sh.selfIntersecting;
    b.topology = sh.topology;
    b.selfPairs = selfPairs_[size_t(id)];
    b.labels = labels_[size_t(id)];
    for (int32_t l : b.labels) b.flips.push_back(labelFlip_[size_t(l)]);
    b.mark = sh.slots.mark();
    b.listed = sh.slots.listedSize();
    for (size_t r = 0; r < sh.slots.pendingRuns(); ++r) b.runSizes.push_back(sh.slots.runSize(r));
    b.adds = sh.slots.pendingAdds();
    b.gone = sh.slots.pendingGone();
    u->sheets.push_back(std::move(b));
  }
  for (size_t i = 0; i < old.size(); ++i)
    for (size_t j = i + 1; j < old.size(); ++j)
      for (int32_t a : labels_[size_t(old[i])])
        for (int32_t b : labels_[size_t(old[j])])
          if (const int32_t n = pairs_.count(a, b)) u->crossPairs.push_back({a, b, n});
  u->merges = merges;
  u->sheetsBefore = dual_.sheets.size();
  u->pieces = pieces;
  u->labelCount = dual_.labelSheet.size();
  u->freeLabels = freeLabels_;
  for (int32_t l : freeLabels_) {
    u->freeSheet.push_back(dual_.labelSheet[size_t(l)]);
    u->freeFlip.push_back(labelFlip_[size_t(l)]);
  }
  recorded_ = std::move(u);
}

// The step's new sheets (all of whose slots were in touched hexes, now given their labels back)
// retired as an update retires a sheet left without slots, their pairs with the old sheets gone.
void DualTracker::retirePieces(const DualUnmergeMemo& u, DualChange& change) {
  std::vector<int32_t> labels;  // of the old sheets and the pieces
  for (const auto& b : u.sheets) labels.insert(labels.end(), b.labels.begin(), b.labels.end());
  for (size_t id = u.sheetsBefore; id < dual_.sheets.size(); ++id)
    labels.insert(labels.end(), labels_[id].begin(), labels_[id].end());
  for (size_t id = u.sheetsBefore; id < dual_.sheets.size(); ++id) {
    for (int32_t pl : labels_[id])
      for (int32_t l : labels) pairs_.take(pl, l);
    Sheet& sh = dual_.sheets[id];
    sh.slots.clear();
    sh.alive = false;
    selfPairs_[id] = 0;
    labels_[id].clear();
    change.sheetsRemoved.push_back(int(id));
  }
}

namespace {
// Where sheet id is in the memo's list (ascending), or -1.
const DualUnmergeMemo::SheetBefore* sheetBefore(const DualUnmergeMemo& u, int32_t id) {
  auto it = std::lower_bound(u.sheets.begin(), u.sheets.end(), id,
                             [](const DualUnmergeMemo::SheetBefore& b, int32_t x) { return b.id < x; });
  return it != u.sheets.end() && it->id == id ? &*it : nullptr;
}
bool mergedAway(const DualUnmergeMemo& u, int32_t id) {
  return std::any_of(u.merges.begin(), u.merges.end(), [&](const auto& m) { return m.first == id; });
}
}  // namespace

// Sheet keep's list, read since the step (so its pending runs and edits are merged), and the lists
// of the sheets merged into it, split again by the labels given back: one pass over it, the touched
// hexes' slots taken from their restored labels.
void DualTracker::relistByLabels(const std::vector<HexId>& touched, const DualUnmergeMemo& u, int32_t keep) {
  std::vector<int32_t> group{keep};
  for (const auto& [x, k] : u.merges)
    if (k == keep) group.push_back(x);
  auto member = [&](int32_t id) {
    return int(std::find(group.begin(), group.end(), id) - group.begin());  // group.size() if none
  };
  std::vector<std::vector<Slot>> rest(group.size()), near(group.size());
  const std::span<const Slot> listed = dual_.sheets[size_t(keep)].slots.view();
  sheetSlotsTouched_ += listed.size();
  for (const Slot& s : listed) {
    if (std::binary_search(touched.begin(), touched.end(), s.hex)) continue;
    const auto g = size_t(member(dual_.sheetAt(s.hex, s.axis)));
    if (g < group.size()) rest[g].push_back(s);
  }
  for (HexId h : touched)
    for (int a = 0; a < 3; ++a)
      if (const int32_t l = dual_.sheetLabel[size_t(h)][size_t(a)]; l >= 0) {
        const auto g = size_t(member(dual_.labelSheet[size_t(l)]));
        if (g < group.size()) near[g].push_back({h, a});
      }
  for (size_t g = 0; g < group.size(); ++g) {
    std::vector<Slot> both(rest[g].size() + near[g].size());
    std::merge(rest[g].begin(), rest[g].end(), near[g].begin(), near[g].end(), both.begin());
    dual_.sheets[size_t(group[g])].slots = std::move(both);
  }
}

// False, changing nothing, unless the tracker is as the merge left it: then every sheet the step
// touched is given back as the memo has it, and the touched slots their labels and orientations.
bool DualTracker::unmergeSheets(const Complex& cx, const std::vector<HexId>& touched, const DualUnmergeMemo& u,
                                DualChange& change) {
  // ---- is it the state the merge left? (nothing is written until all of it holds) ----
  if (sheetState_ != u.stateAfter || touched != u.touched || dual_.labelSheet.size() < u.labelCount ||
      dual_.sheets.size() != u.sheetsBefore + u.pieces)
    return false;
  for (size_t id = u.sheetsBefore; id < dual_.sheets.size(); ++id)
    if (!dual_.sheets[id].alive) return false;
  for (const auto& b : u.sheets) {
    const Sheet& sh = dual_.sheets[size_t(b.id)];
    if (mergedAway(u, b.id)) {
      if (sh.alive || sh.slots.size() != 0) return false;
      continue;
    }
    if (!sh.alive) return false;
    if (sh.slots.version() != b.mark.version) continue;  // read since (its runs merged): relisted by label
    size_t r = b.mark.runs;  // the runs the merges handed over since: each merged list's parts, in order
    auto handed = [&](size_t n) { return r < sh.slots.pendingRuns() && sh.slots.runSize(r++) == n; };
    for (const auto& [x, keep] : u.merges) {
      if (keep != b.id) continue;
      const auto* xb = sheetBefore(u, x);
      if (!xb || (xb->listed && !handed(xb->listed))) return false;
      for (size_t n : xb->runSizes)
        if (!handed(n)) return false;
      if (!xb->adds.empty() && !handed(xb->adds.size())) return false;
    }
    if (r != sh.slots.pendingRuns()) return false;
  }

  // ---- give it back ----
  HugeVector<int8_t>& signs = flooder_.signs();
  for (size_t i = 0; i < touched.size(); ++i)
    for (int a = 0; a < 3; ++a) {
      setLabel({touched[i], a}, u.labels[i][size_t(a)]);
      signs[slotIndex({touched[i], a})] = u.signs[i][size_t(a)];
    }
  retirePieces(u, change);
  for (size_t i = 0; i < u.freeLabels.size(); ++i) {  // the labels as they were (the pieces' are free again)
    const auto l = size_t(u.freeLabels[i]);
    dual_.labelSheet[l] = u.freeSheet[i];
    labelFlip_[l] = u.freeFlip[i];
  }
  freeLabels_ = u.freeLabels;
  dual_.labelSheet.resize(u.labelCount);
  labelSlots_.resize(u.labelCount);
  labelFlip_.resize(u.labelCount);
  for (const auto& b : u.sheets) {
    Sheet& sh = dual_.sheets[size_t(b.id)];
    const bool revived = !sh.alive;
    sh.id = b.id;
    sh.alive = true;
    sh.euler = b.euler;
    sh.boundaryLoops = b.boundaryLoops;
    sh.orientable = b.orientable;
    sh.selfIntersecting = b.selfIntersecting;
    sh.topology = b.topology;
    selfPairs_[size_t(b.id)] = b.selfPairs;
    labels_[size_t(b.id)] = b.labels;
    for (size_t k = 0; k < b.labels.size(); ++k) {
      dual_.labelSheet[size_t(b.labels[k])] = b.id;
      labelFlip_[size_t(b.labels[k])] = b.flips[k];
    }
    (revived ? change.sheetsCreated : change.sheetsChanged).push_back(b.id);
  }
  // The lists: each rolled back to its mark, each merged one rebuilt from the runs it handed over;
  // a list read since the step (its runs merged) is split by the labels given back instead.
  for (const auto& b : u.sheets) {
    if (mergedAway(u, b.id)) continue;
    Sheet& sh = dual_.sheets[size_t(b.id)];
    if (sh.slots.version() != b.mark.version) {
      relistByLabels(touched, u, b.id);
      continue;
    }
    std::vector<std::vector<Slot>> handed = sh.slots.rollBack(b.mark);
    size_t r = 0;
    for (const auto& [x, keep] : u.merges) {
      if (keep != b.id) continue;
      const auto* xb = sheetBefore(u, x);
      std::vector<Slot> listed;
      if (xb->listed) listed = std::move(handed[r++]);
      std::vector<std::vector<Slot>> runs;
      for (size_t k = 0; k < xb->runSizes.size(); ++k) runs.push_back(std::move(handed[r++]));
      r += !xb->adds.empty();  // its additions, sorted by the merge: the memo's copy is given back
      dual_.sheets[size_t(x)].slots.reset(std::move(listed), std::move(runs), xb->adds, xb->gone, xb->mark);
    }
  }
  // Pairs of slots in one hex on two of these sheets: the counts before (the merge took some into
  // its self-intersection count; the touched hexes' pairs moved with their labels).
  for (size_t i = 0; i < u.sheets.size(); ++i)
    for (size_t j = i + 1; j < u.sheets.size(); ++j)
      for (int32_t a : u.sheets[i].labels)
        for (int32_t b : u.sheets[j].labels) {
          pairs_.take(a, b);
          for (const auto& [p, q, n] : u.crossPairs)  // a few: searched, not sorted
            if ((p == a && q == b) || (p == b && q == a)) pairs_.add(a, b, n);
        }
  refreshShares(cx, touched, nullptr);  // the slots' shares and edge marks (the Euler characteristics are the memo's)
  sheetSlotsTouched_ += 3 * touched.size();
  sheetState_ = u.stateBefore;
  unmerged_ = true;
  return true;
}

}  // namespace hexdual
