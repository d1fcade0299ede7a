// Sheet labels and orientations (Dual::sheetLabel, labelSheet). A sheet is named by one or more
// labels, so that a merge re-points the labels of one sheet instead of writing its slots; a slot's
// orientation is stored relative to its label, which a merge may flip.
// Owns: labels_, labelSlots_, labelFlip_, freeLabels_; selfPairs_ and pairs_ (self-intersection);
// the orientation convention of the flooder's signs.
// Keeps: every live slot carries a label of its sheet and every dead slot none; labels_[id] lists
// exactly the labels naming sheet id; labelSlots_ counts the slots carrying each label; a free
// label is carried by no slot; on an orientable sheet, slots glued across a parallel face have
// orientations (signOf) that agree up to the crossing's flip; selfPairs_[id] counts the (hex,
// pair of axes) with both slots on sheet id, and pairs_ the same per pair of labels of two sheets.
#include <algorithm>
#include <bit>
#include <map>

#include "complex/huge_pages.hpp"
#include "dual/dual_tracker.hpp"
#include "dual/tracker/slots.hpp"

namespace hexdual {
using namespace tracker;

namespace {
uint64_t pairKey(int32_t a, int32_t b) {
  if (a > b) std::swap(a, b);
  return uint64_t(uint32_t(a)) << 32 | uint32_t(b);
}
constexpr uint64_t kNoKey = ~uint64_t(0);
}  // namespace

// Open addressing with linear probing; counts that drop to zero keep their entry (the same pairs
// come back after an undo).
size_t DualTracker::PairCounts::find(uint64_t key) const {
  const size_t mask = table_.size() - 1;
  size_t i = size_t((key * 0x9E3779B97F4A7C15ull) >> shift_);  // the product's top bits (Fibonacci hashing)
  while (table_[i].key != key && table_[i].key != kNoKey) i = (i + 1) & mask;
  return i;
}

void DualTracker::PairCounts::add(int32_t a, int32_t b, int32_t n) {
  if (2 * (used_ + 1) > table_.size()) {  // rehashed without the zero counts (pairs of labels gone)
    HugeVector<Entry> old = std::move(table_);
    size_t live = 0;
    for (const Entry& e : old) live += e.key != kNoKey && e.count != 0;
    size_t size = 64;
    while (size < 4 * (live + 1)) size *= 2;
    table_.assign(size, Entry{kNoKey, 0});
    shift_ = 64 - std::countr_zero(table_.size());
    used_ = live;
    for (const Entry& e : old)
      if (e.key != kNoKey && e.count != 0) table_[find(e.key)] = e;
  }
  const uint64_t key = pairKey(a, b);
  Entry& e = table_[find(key)];
  if (e.key == kNoKey) {
    e.key = key;
    ++used_;
  }
  e.count += n;
}

int32_t DualTracker::PairCounts::count(int32_t a, int32_t b) const {
  if (table_.empty()) return 0;
  const Entry& e = table_[find(pairKey(a, b))];
  return e.key == kNoKey ? 0 : e.count;
}

std::vector<std::array<int32_t, 3>> DualTracker::PairCounts::entries() const {
  std::vector<std::array<int32_t, 3>> out;
  for (const Entry& e : table_)
    if (e.key != kNoKey && e.count != 0) out.push_back({int32_t(uint32_t(e.key >> 32)), int32_t(uint32_t(e.key)), e.count});
  return out;
}

int32_t DualTracker::PairCounts::take(int32_t a, int32_t b) {
  if (table_.empty()) return 0;
  Entry& e = table_[find(pairKey(a, b))];
  const int32_t n = e.key == kNoKey ? 0 : e.count;
  if (e.key != kNoKey) e.count = 0;
  return n;
}

void DualTracker::countPair(int32_t la, int32_t lb, int32_t n) {
  if (la < 0 || lb < 0) return;
  const int32_t a = dual_.labelSheet[size_t(la)], b = dual_.labelSheet[size_t(lb)];
  if (a == b)
    selfPairs_[size_t(a)] += n;
  else
    pairs_.add(la, lb, n);
}

int32_t DualTracker::newLabel(int32_t id) {
  int32_t l;
  if (!freeLabels_.empty()) {
    l = freeLabels_.back();
    freeLabels_.pop_back();
    dual_.labelSheet[size_t(l)] = id;
    labelSlots_[size_t(l)] = 0;
    labelFlip_[size_t(l)] = 0;
  } else {
    l = int32_t(dual_.labelSheet.size());
    dual_.labelSheet.push_back(id);
    labelSlots_.push_back(0);
    labelFlip_.push_back(0);
  }
  if (labels_.size() <= size_t(id)) labels_.resize(size_t(id) + 1);
  labels_[size_t(id)].push_back(l);
  return l;
}

void DualTracker::setLabel(Slot t, int32_t label) {
  int32_t& l = dual_.sheetLabel[size_t(t.hex)][size_t(t.axis)];
  if (l >= 0) --labelSlots_[size_t(l)];
  if (label >= 0) ++labelSlots_[size_t(label)];
  l = label;
}

int DualTracker::signOf(Slot t) const {
  const int s = flooder_.signs()[slotIndex(t)];
  return labelFlip_[size_t(dual_.sheetLabel[size_t(t.hex)][size_t(t.axis)])] ? -s : s;
}

void DualTracker::setSign(Slot t, int sign) {
  const bool flip = labelFlip_[size_t(dual_.sheetLabel[size_t(t.hex)][size_t(t.axis)])];
  flooder_.signs()[slotIndex(t)] = int8_t(flip ? -sign : sign);
}

void DualTracker::pruneLabels(int32_t id) {
  auto& ls = labels_[size_t(id)];
  auto gone = [&](int32_t l) {
    if (labelSlots_[size_t(l)] != 0) return false;
    freeLabels_.push_back(l);
    return true;
  };
  ls.erase(std::remove_if(ls.begin(), ls.end(), gone), ls.end());
}

// Sheet x joins sheet `keep` (flipped when `flip`) without writing its slots: its labels are
// re-pointed, its slot list handed over, its Euler share moved whole, and the slots it shares
// with `keep` in one hex become the merged sheet's self-intersections.
void DualTracker::mergeSheet(int32_t x, int32_t keep, bool flip) {
  for (int32_t lx : labels_[size_t(x)])
    for (int32_t lk : labels_[size_t(keep)]) selfPairs_[size_t(keep)] += pairs_.take(lx, lk);
  selfPairs_[size_t(keep)] += selfPairs_[size_t(x)];
  selfPairs_[size_t(x)] = 0;
  const int64_t share = 2 * dual_.sheets[size_t(x)].euler + delta_[size_t(x)];
  delta_[size_t(keep)] += share;
  delta_[size_t(x)] -= share;
  for (int32_t lx : labels_[size_t(x)]) {
    dual_.labelSheet[size_t(lx)] = keep;
    labelFlip_[size_t(lx)] ^= uint8_t(flip);
    labels_[size_t(keep)].push_back(lx);
  }
  mergedLabels_ += labels_[size_t(x)].size();
  labels_[size_t(x)].clear();
  dual_.sheets[size_t(keep)].slots.absorb(std::move(dual_.sheets[size_t(x)].slots));
}

// Orients slots without an orientation from oriented neighbours on the same sheet (new slots
// joining an orientable sheet).
void DualTracker::propagateSigns(const Complex& cx, std::span<const Slot> slots) {
  HugeVector<int8_t>& sign = flooder_.signs();
  for (Slot s : slots) sign[slotIndex(s)] = 0;
  for (bool progress = true; progress;) {
    progress = false;
    for (Slot s : slots) {
      if (sign[slotIndex(s)]) continue;
      Slot n;
      int flip;
      for (int f : kParallelFaces[size_t(s.axis)])
        if (sheetNeighbour(cx, s, f, n, flip) && sign[slotIndex(n)]) {
          setSign(s, signOf(n) * flip);
          progress = true;
          break;
        }
    }
  }
}

// Adds (sign +1) or removes (-1) these hexes' pairs of slots in selfPairs_ and pairs_.
void DualTracker::countSelfHexes(const std::vector<HexId>& hexes, int sign) {
  for (HexId h : hexes) countSelfHex(h, sign);
}

void DualTracker::countSelfHex(HexId h, int sign) {
  const auto l = dual_.sheetLabel[size_t(h)];
  countPair(l[0], l[1], sign);
  countPair(l[0], l[2], sign);
  countPair(l[1], l[2], sign);
}

// ---- invariants ----

// Every label is in exactly one sheet's list (naming that sheet) or free; every slot carries a
// label of an alive sheet exactly when its hex is live; labelSlots_ and the lists' sizes agree.
void DualTracker::checkLabelsOf(const Complex& cx) const {
  const Dual& d = dual_;
  const size_t labels = d.labelSheet.size();
  if (labelSlots_.size() != labels || labelFlip_.size() != labels)
    invariantBroken("the per-label arrays have " + std::to_string(labelSlots_.size()) + " and " +
                    std::to_string(labelFlip_.size()) + " entries for " + std::to_string(labels) + " labels");
  std::vector<uint8_t> seen(labels, 0);
  auto once = [&](int32_t l, const std::string& where) {
    if (l < 0 || size_t(l) >= labels || seen[size_t(l)]++)
      invariantBroken("label " + std::to_string(l) + " " + where + " is out of range or listed twice");
  };
  for (size_t id = 0; id < labels_.size(); ++id)
    for (int32_t l : labels_[id]) {
      once(l, "of sheet " + std::to_string(id));
      if (d.labelSheet[size_t(l)] != int32_t(id))
        invariantBroken("label " + std::to_string(l) + " is listed for sheet " + std::to_string(id) +
                        " but names sheet " + std::to_string(d.labelSheet[size_t(l)]));
    }
  for (int32_t l : freeLabels_) once(l, "(free)");
  for (size_t l = 0; l < labels; ++l)
    if (!seen[l]) invariantBroken("label " + std::to_string(l) + " is neither a sheet's nor free");
  std::vector<int32_t> carried(labels, 0), slots(d.sheets.size(), 0);
  for (HexId h = 0; h < HexId(d.sheetLabel.size()); ++h)
    for (int a = 0; a < 3; ++a) {
      const int32_t l = d.sheetLabel[size_t(h)][size_t(a)];
      if ((l >= 0) != cx.isHex(h))
        invariantBroken("slot " + slotName({h, a}) + (l >= 0 ? " of a dead hex carries a label" : " carries no label"));
      if (l < 0) continue;
      const int32_t id = d.labelSheet[size_t(l)];
      if (id < 0 || size_t(id) >= d.sheets.size() || !d.sheets[size_t(id)].alive)
        invariantBroken("slot " + slotName({h, a}) + " carries label " + std::to_string(l) + " of no alive sheet");
      ++carried[size_t(l)];
      ++slots[size_t(id)];
    }
  for (size_t l = 0; l < labels; ++l)
    if (carried[l] != labelSlots_[l])
      invariantBroken("label " + std::to_string(l) + " is carried by " + std::to_string(carried[l]) +
                      " slots, labelSlots_ says " + std::to_string(labelSlots_[l]));
  for (size_t id = 0; id < d.sheets.size(); ++id)
    if (d.sheets[id].alive ? d.sheets[id].id != int(id) || size_t(slots[id]) != d.sheets[id].slots.size()
                           : slots[id] != 0 || (id < labels_.size() && !labels_[id].empty()))
      invariantBroken("sheet " + std::to_string(id) + " (" + (d.sheets[id].alive ? "alive" : "retired") + ") lists " +
                      std::to_string(d.sheets[id].slots.size()) + " slots; " + std::to_string(slots[id]) +
                      " carry its labels");
}

// On an orientable sheet, slots glued across a parallel face agree in orientation up to the
// crossing's flip; a dead slot has none.
void DualTracker::checkOrientations(const Complex& cx) const {
  const HugeVector<int8_t>& signs = flooder_.signs();
  for (HexId h = 0; h < HexId(dual_.sheetLabel.size()); ++h)
    for (int a = 0; a < 3; ++a) {
      const Slot s{h, a};
      if (!cx.isHex(h)) {
        if (signs[slotIndex(s)] != 0) invariantBroken("dead slot " + slotName(s) + " keeps an orientation");
        continue;
      }
      if (!dual_.sheets[size_t(dual_.sheetAt(h, a))].orientable) continue;
      if (signOf(s) != 1 && signOf(s) != -1)
        invariantBroken("slot " + slotName(s) + " of an orientable sheet has no orientation");
      Slot n;
      int flip;
      for (int f : kParallelFaces[size_t(a)])
        if (sheetNeighbour(cx, s, f, n, flip) && signOf(n) != signOf(s) * flip)
          invariantBroken("slots " + slotName(s) + " and " + slotName(n) + " disagree in orientation across face " +
                          std::to_string(f));
    }
}

// selfPairs_ and pairs_ count the (hex, pair of axes) on one sheet and per pair of labels of two
// sheets; each alive sheet's selfIntersecting says whether it has a pair.
void DualTracker::checkPairCounts(const Complex& cx) const {
  const Dual& d = dual_;
  if (selfPairs_.size() != d.sheets.size())
    invariantBroken("selfPairs_ has " + std::to_string(selfPairs_.size()) + " entries for " +
                    std::to_string(d.sheets.size()) + " sheets");
  std::vector<int32_t> self(d.sheets.size(), 0);
  std::map<std::pair<int32_t, int32_t>, int32_t> across;
  for (HexId h : cx.hexes()) {
    const auto& l = d.sheetLabel[size_t(h)];
    for (int a = 0; a < 3; ++a)
      for (int b = a + 1; b < 3; ++b) {
        const int32_t la = l[size_t(a)], lb = l[size_t(b)];
        if (d.labelSheet[size_t(la)] == d.labelSheet[size_t(lb)])
          ++self[size_t(d.labelSheet[size_t(la)])];
        else
          ++across[{std::min(la, lb), std::max(la, lb)}];
      }
  }
  for (size_t id = 0; id < d.sheets.size(); ++id) {
    if (self[id] != selfPairs_[id])
      invariantBroken("sheet " + std::to_string(id) + " has " + std::to_string(self[id]) +
                      " self-intersecting pairs of slots, selfPairs_ says " + std::to_string(selfPairs_[id]));
    if (d.sheets[id].alive && d.sheets[id].selfIntersecting != (self[id] > 0))
      invariantBroken("sheet " + std::to_string(id) + "'s selfIntersecting disagrees with its pairs of slots");
  }
  for (const auto& [la, lb, n] : pairs_.entries())
    if (across.count({la, lb}) == 0)
      invariantBroken("labels " + std::to_string(la) + " and " + std::to_string(lb) + " are counted " +
                      std::to_string(n) + " pairs but share no hex");
  for (const auto& [key, n] : across)
    if (pairs_.count(key.first, key.second) != n)
      invariantBroken("labels " + std::to_string(key.first) + " and " + std::to_string(key.second) + " share " +
                      std::to_string(n) + " hexes, pairs_ says " + std::to_string(pairs_.count(key.first, key.second)));
}

void DualTracker::checkSheetLabels(const Complex& cx) const {
  checkLabelsOf(cx);
  checkOrientations(cx);
  checkPairCounts(cx);
}

}  // namespace hexdual
