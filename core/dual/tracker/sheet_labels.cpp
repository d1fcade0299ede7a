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
#include "dual/dual_tracker.hpp"

#include <algorithm>
#include <bit>

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
  const size_t mask = keys_.size() - 1;
  size_t i = size_t((key * 0x9E3779B97F4A7C15ull) >> shift_);  // the product's top bits (Fibonacci hashing)
  while (keys_[i] != key && keys_[i] != kNoKey) i = (i + 1) & mask;
  return i;
}

void DualTracker::PairCounts::add(int32_t a, int32_t b, int32_t n) {
  if (2 * (used_ + 1) > keys_.size()) {  // rehashed without the zero counts (pairs of labels gone)
    std::vector<uint64_t> keys = std::move(keys_);
    std::vector<int32_t> counts = std::move(counts_);
    size_t live = 0;
    for (size_t i = 0; i < keys.size(); ++i) live += keys[i] != kNoKey && counts[i] != 0;
    size_t size = 64;
    while (size < 4 * (live + 1)) size *= 2;
    keys_.assign(size, kNoKey);
    shift_ = 64 - std::countr_zero(keys_.size());
    counts_.assign(keys_.size(), 0);
    used_ = live;
    for (size_t i = 0; i < keys.size(); ++i)
      if (keys[i] != kNoKey && counts[i] != 0) {
        const size_t j = find(keys[i]);
        keys_[j] = keys[i];
        counts_[j] = counts[i];
      }
  }
  const uint64_t key = pairKey(a, b);
  const size_t i = find(key);
  if (keys_[i] == kNoKey) {
    keys_[i] = key;
    ++used_;
  }
  counts_[i] += n;
}

int32_t DualTracker::PairCounts::take(int32_t a, int32_t b) {
  if (keys_.empty()) return 0;
  const size_t i = find(pairKey(a, b));
  const int32_t n = keys_[i] == kNoKey ? 0 : counts_[i];
  if (keys_[i] != kNoKey) counts_[i] = 0;
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
void DualTracker::propagateSigns(const Complex& cx, const std::vector<Slot>& slots) {
  std::vector<int8_t>& sign = flooder_.signs();
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

}  // namespace hexdual
