#include "dual/dual_tracker.hpp"

#include "complex/huge_pages.hpp"

#include <algorithm>
#include <bit>
#include <climits>
#include <numeric>
#include <unordered_map>
#include <unordered_set>

namespace hexdual {

std::vector<HexId> touchedHexes(const Complex&, const Complex::EditLog& log) {
  std::vector<HexId> out;
  for (const Complex::Edit& e : log.edits) {
    switch (e.kind) {
      case Complex::Edit::AddHex:
      case Complex::Edit::RemoveHex:
      case Complex::Edit::SetCorner:
        out.push_back(e.hex);
        break;
      case Complex::Edit::Glue:  // value: the partner, as glued
        out.push_back(e.hex);
        out.push_back(HexId(e.value >> 6));
        break;
      case Complex::Edit::Unglue:
        out.push_back(e.hex);
        out.push_back(HexId(e.value >> 6));
        break;
      default:
        break;
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

namespace {

constexpr uint16_t kNearBoundary = kEdgeNearBoundary;
constexpr uint16_t kWalkedFan = uint16_t(1u << 15);  // in walked_: one of the hex's edges walked is a fan

// The sheet ids on the slots of these hexes, ascending, once each.
std::vector<int32_t> sheetIdsThrough(const Dual& d, const std::vector<HexId>& hexes) {
  std::vector<int32_t> ids;
  for (HexId h : hexes)
    for (int a = 0; a < 3; ++a)
      if (d.sheetAt(h, a) >= 0) ids.push_back(d.sheetAt(h, a));
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

size_t slotIndex(Slot s) { return 3 * size_t(s.hex) + size_t(s.axis); }

// The incidences of the edge at e, round its cycle or along its fan; false for a fan.
bool edgeIncidences(const Complex& cx, EdgeRef e, std::vector<EdgeRef>& out) {
  out.assign(1, e);
  auto fs = tables::facesOfEdge(e.edge);
  for (int dir = 0; dir < 2; ++dir) {
    EdgeRef cur = e;
    int exit = fs[size_t(dir)];
    while (cx.stepAroundEdge(cur, exit)) {
      if (cur == e) return true;
      out.push_back(cur);
    }
  }
  return false;
}

bool nearBoundary(const Complex& cx, HexId h) {
  for (int e = 0; e < 12; ++e) {
    EdgeRef cur{h, e};
    int exit = tables::facesOfEdge(e)[0];
    for (;;) {
      if (!cx.stepAroundEdge(cur, exit)) return true;
      if (cur.hex == h && cur.edge == e) break;
    }
  }
  return false;
}

// The slot across face f of slot s's hex (f parallel to s's axis), and the orientation flip.
bool sheetNeighbour(const Complex& cx, Slot s, int f, Slot& n, int& flip) {
  Gluing g = cx.gluing(s.hex, f);
  if (g.boundary()) return false;
  const tables::Crossing& c = tables::kCrossings[size_t(tables::crossingIndex(f, s.axis, g.face, g.orient))];
  n = {g.hex, c.axis};
  flip = c.sign;
  return true;
}

}  // namespace

DualTracker::DualTracker(const Complex& cx) {
  DualExtras extras;
  dual_ = extractDual(cx, &extras);
  flooder_.signs() = std::move(extras.slotSigns);
  edgeMarks_ = std::move(extras.edgeMarks);
  const size_t sheets = dual_.sheets.size();
  labels_.resize(sheets);
  labelSlots_.resize(sheets);
  labelFlip_.assign(sheets, 0);
  for (size_t s = 0; s < sheets; ++s) {
    labels_[s].assign(1, int32_t(s));
    labelSlots_[s] = int32_t(dual_.sheets[s].slots.size());
  }
  // A hex's two slots on axes a and b share their sheets with every hex along the chord through its
  // third axis (TK03 §1.1: two sheets cross in chords), so the pairs are counted per chord.
  selfPairs_.assign(sheets, 0);
  for (const Chord& ch : dual_.chords) {
    const Slot t = ch.slots[0];
    const auto& l = dual_.sheetLabel[size_t(t.hex)];
    countPair(l[size_t((t.axis + 1) % 3)], l[size_t((t.axis + 2) % 3)], int32_t(ch.slots.size()));
  }
  share_ = std::move(extras.slotShares);
  // Every chord is one piece: its label's run (extraction numbers labels as chords).
  dual_.chordPlace = std::move(extras.chordPlaces);
  const size_t chords = dual_.chords.size();
  runs_.resize(chords);
  pieces_.resize(chords);
  chordSelf_.resize(chords);
  unsettledMark_.assign(chords, 0);
  dual_.labelCuts.resize(chords);
  for (size_t c = 0; c < chords; ++c) {
    const Chord& ch = dual_.chords[c];
    const int32_t len = int32_t(ch.slots.size());
    runs_[c] = ch.slots;
    pieces_[c].assign(1, Piece{int32_t(c), 0, len, false});
    dual_.labelCuts[c].assign(1, Dual::ChordCut{0, len, int32_t(c)});
    chordSelf_[c] = ch.selfIntersecting;
  }
  delta_.assign(dual_.sheets.size(), 0);
  growPerHexArrays(size_t(cx.hexCapacity()));
}

// The per-hex and per-slot arrays, grown to `cap` hexes with headroom (see growHuge): the first
// steps after a build neither copy nor page-fault a 1M-hex mesh's arrays.
void DualTracker::growPerHexArrays(size_t cap) {
  growHuge(dual_.sheetLabel, cap, {-1, -1, -1});
  growHuge(dual_.chordLabel, cap, {-1, -1, -1});
  growHuge(dual_.chordPlace, 3 * cap, int32_t(0));
  flooder_.reserve(cap);
  growHuge(edgeMarks_, cap, uint16_t(0));
  growHuge(walked_, cap, uint16_t(0));
  growHuge(share_, 3 * cap, int8_t(0));
  growHuge(front_, 3 * cap, int32_t(0));
}

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

void DualTracker::refreshShares(const Complex& cx, const std::vector<HexId>& touched, std::vector<ShareChange>* changes) {
  auto onChange = [&](Slot t, int before, int after) {
    if (changes) changes->push_back({t, before, after});
  };
  bool nearBefore = false;
  std::vector<Slot> dirty;
  std::vector<HexId> met;
  std::vector<EdgeRef> inc;
  for (HexId h : touched) {
    nearBefore = nearBefore || (edgeMarks_[size_t(h)] & kNearBoundary);
    if (cx.isHex(h)) {
      for (int a = 0; a < 3; ++a) dirty.push_back({h, a});
      continue;
    }
    for (int a = 0; a < 3; ++a) {
      int8_t& old = share_[3 * size_t(h) + size_t(a)];
      if (old) onChange(Slot{h, a}, int(old), 0);
      old = 0;
    }
    edgeMarks_[size_t(h)] = 0;
  }
  bool fan = false;
  for (HexId h : touched) {
    if (!cx.isHex(h)) continue;
    for (int e = 0; e < 12; ++e) {
      if ((walked_[size_t(h)] >> e) & 1u) continue;
      const bool closed = edgeIncidences(cx, {h, e}, inc);
      fan = fan || !closed;
      const EdgeRef least = *std::min_element(inc.begin(), inc.end());
      for (EdgeRef r : inc) {
        if (!walked_[size_t(r.hex)]) met.push_back(r.hex);
        walked_[size_t(r.hex)] |= uint16_t((1u << r.edge) | (closed ? 0u : kWalkedFan));
        const uint16_t bit = uint16_t(1u << r.edge);
        if (((edgeMarks_[size_t(r.hex)] & bit) != 0) != (r == least)) {
          edgeMarks_[size_t(r.hex)] ^= bit;
          dirty.push_back({r.hex, tables::axisOfEdge(r.edge)});
        }
      }
    }
  }
  // Only an edge through a touched hex can have reached or left the boundary: a hex met is near
  // it when one of those is a fan now, or (when it was near before) one of its other edges is.
  if (fan || nearBefore)
    for (HexId m : met) {
      const bool near = (walked_[size_t(m)] & kWalkedFan) || ((edgeMarks_[size_t(m)] & kNearBoundary) && nearBoundary(cx, m));
      edgeMarks_[size_t(m)] = uint16_t((edgeMarks_[size_t(m)] & ~kNearBoundary) | (near ? kNearBoundary : 0));
    }
  for (HexId m : met) walked_[size_t(m)] = 0;
  for (Slot s : dirty) {
    const int8_t now = slotShare(cx, s.hex, s.axis, edgeMarks_[size_t(s.hex)]);
    int8_t& old = share_[slotIndex(s)];
    if (now != old) {
      onChange(s, int(old), int(now));
      old = now;
    }
  }
}

bool DualTracker::touchesBoundary(const Complex& cx, const std::vector<HexId>& touched) const {
  for (HexId h : touched)
    if (edgeMarks_[size_t(h)] & kNearBoundary) return true;
  for (HexId h : touched)
    if (cx.isHex(h) && nearBoundary(cx, h)) return true;
  return false;
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

void DualTracker::releaseRetiredTail() {
  while (!dual_.sheets.empty() && !dual_.sheets.back().alive) {
    dual_.sheets.pop_back();
    selfPairs_.pop_back();
    if (labels_.size() > dual_.sheets.size()) {
      for (int32_t l : labels_.back()) freeLabels_.push_back(l);  // carried by no slot: the sheet is retired
      labels_.pop_back();
    }
  }
  while (!dual_.chords.empty() && !dual_.chords.back().alive) dual_.chords.pop_back();
  pieces_.resize(dual_.chords.size());
  chordSelf_.resize(dual_.chords.size());
  unsettledMark_.resize(dual_.chords.size());
  unsettled_.erase(std::remove_if(unsettled_.begin(), unsettled_.end(), [&](int32_t id) { return size_t(id) >= dual_.chords.size(); }),
                   unsettled_.end());
}

DualChange DualTracker::update(const Complex& cx, const Complex::EditLog& edits, bool sheetsKeepTopology) {
  return update(cx, touchedHexes(cx, edits), sheetsKeepTopology);
}

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

// The sheets through the touched hexes after an edit, by a lockstep flood (TK03 §4.4: a collapse
// cuts and re-glues sheets in one place). Every touched slot starts a front; fronts that meet join
// one group; a group whose fronts all run dry is a whole new sheet (a piece). The flood stops once
// every old sheet meets at most one unfinished group: that group is the rest of those old sheets.
// Returns false, changing nothing, when the edit is not one it can follow (boundary, twisted sheets).
bool DualTracker::updateSheetsLockstep(const Complex& cx, const std::vector<HexId>& touched, DualChange& change) {
  auto label = [&](Slot t) { return dual_.sheetAt(t.hex, t.axis); };  // the slot's sheet id
  const std::vector<int32_t> old = sheetIdsThrough(dual_, touched);
  for (int32_t id : old)
    if (!dual_.sheets[size_t(id)].orientable) return false;
  if (touchesBoundary(cx, touched)) return false;
  auto oldIndex = [&](int32_t id) { return size_t(std::lower_bound(old.begin(), old.end(), id) - old.begin()); };

  // ---- explore ----
  struct Reached {
    Slot slot;
    int32_t label;  // the old sheet, -1 for a new slot
    int32_t front;
  };
  std::vector<Reached> reached;
  std::vector<std::vector<Slot>> queue;
  std::vector<size_t> head;
  std::vector<int32_t> parent, active;
  std::vector<std::vector<int32_t>> meets;  // per group root: old sheets reached
  auto find = [&](int32_t x) {
    while (parent[size_t(x)] != x) x = parent[size_t(x)] = parent[size_t(parent[size_t(x)])];
    return x;
  };
  size_t unfinished = 0;
  bool foreign = false;
  std::vector<uint8_t> paused;
  auto reach = [&](Slot t, int32_t f) {
    front_[slotIndex(t)] = f + 1;
    reached.push_back({t, label(t), f});
    queue[size_t(f)].push_back(t);
    const int32_t id = label(t);
    if (id >= 0 && !std::binary_search(old.begin(), old.end(), id)) foreign = true;  // an edit not logged whole
    auto& m = meets[size_t(find(f))];
    if (id >= 0 && std::find(m.begin(), m.end(), id) == m.end()) m.push_back(id);
  };
  auto unite = [&](int32_t a, int32_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (b < a) std::swap(a, b);
    if (active[size_t(a)] && active[size_t(b)]) --unfinished;
    parent[size_t(b)] = a;
    if (size_t(a) < paused.size()) paused[size_t(a)] = 0;
    active[size_t(a)] += active[size_t(b)];
    for (int32_t id : meets[size_t(b)])
      if (std::find(meets[size_t(a)].begin(), meets[size_t(a)].end(), id) == meets[size_t(a)].end()) meets[size_t(a)].push_back(id);
  };
  for (HexId h : touched)
    if (cx.isHex(h))
      for (int a = 0; a < 3; ++a) {
        const int32_t f = int32_t(queue.size());
        queue.emplace_back();
        head.push_back(0);
        parent.push_back(f);
        active.push_back(1);
        meets.emplace_back();
        ++unfinished;
        reach({h, a}, f);
      }
  std::vector<int32_t> owner(old.size(), -1), sharers(old.size(), 0);
  paused.assign(parent.size(), 0);
  // A group pauses when every old sheet it has met meets no other unfinished group: it then is the
  // rest of those sheets (a group joined to it later resumes it). Settled when all have paused.
  auto settled = [&] {
    std::fill(owner.begin(), owner.end(), -1);
    std::fill(sharers.begin(), sharers.end(), 0);
    for (size_t f = 0; f < parent.size(); ++f) {
      if (parent[f] != int32_t(f) || !active[f]) continue;
      for (int32_t id : meets[f]) {
        const size_t k = oldIndex(id);
        ++sharers[k];
        owner[k] = int32_t(f);
      }
    }
    bool all = true;
    for (size_t f = 0; f < parent.size(); ++f) {
      if (parent[f] != int32_t(f) || !active[f]) continue;
      bool alone = !meets[f].empty();
      for (int32_t id : meets[f]) alone = alone && sharers[oldIndex(id)] == 1;
      paused[f] = alone;
      all = all && alone;
    }
    return all;
  };
  while (unfinished > 0 && !foreign) {
    for (size_t f = 0; f < queue.size(); ++f) {
      if (head[f] == queue[f].size() || paused[size_t(find(int32_t(f)))]) continue;
      const Slot cur = queue[f][head[f]++];
      for (int face : kParallelFaces[size_t(cur.axis)]) {
        Slot n;
        int flip;
        if (!sheetNeighbour(cx, cur, face, n, flip)) continue;
        const int32_t m = front_[slotIndex(n)];
        if (m == 0)
          reach(n, int32_t(f));
        else if (m - 1 != int32_t(f))
          unite(int32_t(f), m - 1);
      }
      if (head[f] == queue[f].size()) {
        const int32_t r = find(int32_t(f));
        if (--active[size_t(r)] == 0) --unfinished;
      }
    }
    if (foreign || settled()) break;
  }
  auto clearFronts = [&] {
    for (const Reached& r : reached) front_[slotIndex(r.slot)] = 0;
  };
  if (foreign) {
   
    clearFronts();
    return false;
  }

  // ---- plan: pieces (finished groups), remainders, ids ----
  std::vector<int64_t> remainder(old.size(), 0), loopsTaken(old.size(), 0);
  for (size_t k = 0; k < old.size(); ++k) remainder[k] = int64_t(dual_.sheets[size_t(old[k])].slots.size());
  for (HexId h : touched)
    if (!cx.isHex(h))
      for (int32_t id : dual_.sheetsAt(h))
        if (id >= 0) --remainder[oldIndex(id)];
  std::vector<int32_t> pieceOf(parent.size(), -1);
  std::vector<std::vector<Slot>> pieces;
  std::vector<std::vector<int32_t>> pieceLabels;
  std::vector<Slot> newInRest;  // new slots of unfinished groups
  for (const Reached& r : reached) {
    const int32_t g = find(r.front);
    if (active[size_t(g)]) {
      if (r.label < 0) newInRest.push_back(r.slot);
      continue;
    }
    if (pieceOf[size_t(g)] < 0) {
      pieceOf[size_t(g)] = int32_t(pieces.size());
      pieces.emplace_back();
      pieceLabels.emplace_back();
    }
    pieces[size_t(pieceOf[size_t(g)])].push_back(r.slot);
    pieceLabels[size_t(pieceOf[size_t(g)])].push_back(r.label);
    if (r.label >= 0) --remainder[oldIndex(r.label)];
  }
  for (size_t k = 0; k < old.size(); ++k)
    if ((owner[k] < 0) != (remainder[k] == 0) || sharers[k] > 1) {  // cannot happen on a valid complex; be safe
      clearFronts();
      return false;
    }
  // Orientations of the remainders: each re-glued quad ties the orientation of the old sheets (or
  // new slots) on its two sides; a contradiction is a twist, or a sheet re-glued to itself flipped:
  // re-flood. Old sheets merged into a kept one are flipped as they are re-labelled.
  std::vector<int8_t>& signs = flooder_.signs();
  std::sort(newInRest.begin(), newInRest.end());
  std::vector<int32_t> up(old.size() + newInRest.size());
  std::vector<uint8_t> par(up.size(), 0);
  for (size_t v = 0; v < up.size(); ++v) up[v] = int32_t(v);
  auto root = [&](int32_t x, int& p) {
    p = 0;
    while (up[size_t(x)] != x) {
      p ^= par[size_t(x)];
      x = up[size_t(x)];
    }
    return x;
  };
  // The variable of a slot's orientation and its stored sign (new slots: +1 until solved).
  auto var = [&](Slot t, int& sg) -> int32_t {
    const int32_t id = label(t);
    if (id >= 0) {
      sg = signOf(t);
      return int32_t(oldIndex(id));
    }
    sg = 1;
    auto it = std::lower_bound(newInRest.begin(), newInRest.end(), t);
    return it != newInRest.end() && *it == t ? int32_t(old.size() + size_t(it - newInRest.begin())) : -1;
  };
  bool consistent = true;
  for (const Reached& r : reached) {
    if (!consistent) break;
    if (!active[size_t(find(r.front))] || !(r.label < 0 || std::binary_search(touched.begin(), touched.end(), r.slot.hex))) continue;
    int ss = 0, ps = 0;
    const int32_t vs = var(r.slot, ss);
    for (int face : kParallelFaces[size_t(r.slot.axis)]) {
      Slot n;
      int flip, sn = 0, pn = 0;
      if (!sheetNeighbour(cx, r.slot, face, n, flip)) continue;
      const int32_t vn = var(n, sn);
      if (vs < 0 || vn < 0 || !ss || !sn) {
        consistent = false;
        break;
      }
      const int need = sn != ss * flip;
      const int32_t rs = root(vs, ps), rn = root(vn, pn);
      if (rs == rn) {
        consistent = consistent && (ps ^ pn) == need;
      } else {
        up[size_t(rn)] = rs;
        par[size_t(rn)] = uint8_t(ps ^ pn ^ need);
      }
    }
  }
  if (!consistent) {
   
    clearFronts();
    return false;
  }
  // The rest of each unfinished group keeps the id of its old sheet with most slots left.
  std::vector<int32_t> keepOf(parent.size(), -1);
  for (size_t k = 0; k < old.size(); ++k) {
    const int32_t g = owner[k];
    if (g < 0) continue;
    const int32_t cur = keepOf[size_t(g)];
    if (cur < 0 || remainder[k] > remainder[oldIndex(cur)]) keepOf[size_t(g)] = old[k];
  }
  // Flip of each old sheet and new slot relative to the sheet its group keeps.
  std::vector<uint8_t> flipOf(up.size(), 0);
  for (size_t k = 0; k < old.size(); ++k) {
    if (owner[k] < 0) continue;
    int pk = 0, pkeep = 0;
    if (root(int32_t(k), pk) != root(int32_t(oldIndex(keepOf[size_t(owner[k])])), pkeep)) {
      clearFronts();
      return false;  // joined through no re-glued quad: cannot happen, be safe
    }
    flipOf[k] = uint8_t(pk ^ pkeep);
  }
  for (size_t i = 0; i < newInRest.size(); ++i) {
    const int32_t keep = keepOf[size_t(find(front_[slotIndex(newInRest[i])] - 1))];
    int pv = 0, pkeep = 0;
    if (root(int32_t(old.size() + i), pv) != root(int32_t(oldIndex(keep)), pkeep)) {
      clearFronts();
      return false;
    }
    flipOf[old.size() + i] = uint8_t(pv ^ pkeep);
  }
  // Pieces in the order of their smallest slot; a piece keeps an old id only when it is all that is left of that sheet.
  std::vector<uint64_t> order(pieces.size());  // smallest slot << 32 | piece
  for (size_t p = 0; p < pieces.size(); ++p) {
    std::sort(pieces[p].begin(), pieces[p].end());
    order[p] = uint64_t(slotIndex(pieces[p][0])) << 32 | p;
  }
  std::sort(order.begin(), order.end());
  std::vector<int32_t> pieceId(pieces.size(), -1);
  std::vector<uint8_t> taken(old.size(), 0);
  int32_t fresh = int32_t(dual_.sheets.size());
  for (uint64_t key : order) {
    const size_t p = size_t(key & 0xFFFFFFFFu);
    int32_t best = -1;
    for (int32_t id : pieceLabels[p])
      if (id >= 0 && owner[oldIndex(id)] < 0 && !taken[oldIndex(id)] && (best < 0 || id < best)) best = id;
    if (best >= 0) taken[oldIndex(best)] = 1;
    pieceId[p] = best >= 0 ? best : fresh++;
  }

  // ---- commit ----
  dual_.sheets.resize(size_t(fresh));
  selfPairs_.resize(size_t(fresh), 0);
  if (labels_.size() < size_t(fresh)) labels_.resize(size_t(fresh));
  if (delta_.size() < size_t(fresh)) delta_.resize(size_t(fresh), 0);
  std::vector<int32_t> affected(old.begin(), old.end());
  for (size_t p = 0; p < pieces.size(); ++p) affected.push_back(pieceId[p]);
  std::sort(affected.begin(), affected.end());
  affected.erase(std::unique(affected.begin(), affected.end()), affected.end());
  // Hexes whose slot labels change (dead, in a piece, or new): their pairs of slots are counted
  // again. The other hexes keep their labels, and a merge moves their pairs itself.
  std::vector<HexId> recount;
  for (HexId h : touched)
    if (!cx.isHex(h)) recount.push_back(h);
  for (const auto& piece : pieces)
    for (Slot t : piece) recount.push_back(t.hex);
  for (Slot t : newInRest) recount.push_back(t.hex);
  std::vector<int32_t> merged;
  for (size_t k = 0; k < old.size(); ++k)
    if (owner[k] >= 0 && keepOf[size_t(owner[k])] != old[k]) merged.push_back(old[k]);
  std::sort(recount.begin(), recount.end());
  recount.erase(std::unique(recount.begin(), recount.end()), recount.end());
  countSelfHexes(recount, -1);
  std::vector<ShareChange> shareChanges;
  refreshShares(cx, touched, &shareChanges);
  for (const ShareChange& c : shareChanges) {
    const int32_t id = label(c.slot);
    if (id >= 0) delta_[size_t(id)] += c.after - c.before;
  }
  auto move = [&](Slot t, int32_t toLabel) {  // t gets a label of another sheet; its share follows
    const int32_t from = label(t), to = dual_.labelSheet[size_t(toLabel)];
    const int c = share_[slotIndex(t)];
    if (from >= 0) delta_[size_t(from)] -= c;
    delta_[size_t(to)] += c;
    setLabel(t, toLabel);
  };
  // Slots leaving the old sheets' lists (dead, or in a piece), by old sheet: dropped when next read.
  std::vector<std::vector<Slot>> leaving(old.size());
  for (HexId h : touched)
    if (!cx.isHex(h)) {
      for (int a = 0; a < 3; ++a) {
        const int32_t id = label({h, a});
        if (id >= 0) leaving[oldIndex(id)].push_back({h, a});
        setLabel({h, a}, -1);
        signs[3 * size_t(h) + size_t(a)] = 0;
      }
    }
  // (By each slot's own label: pieces are sorted by now, their pieceLabels are not.)
  for (const auto& piece : pieces)
    for (Slot t : piece)
      if (label(t) >= 0) leaving[oldIndex(label(t))].push_back(t);
  // Pieces: labelled, oriented by a flood of their own slots, loops walked and charged to the old sheet they came from.
  for (size_t p = 0; p < pieces.size(); ++p) {
    const int32_t id = pieceId[p];
    Sheet& sh = dual_.sheets[size_t(id)];
    const bool reused = std::binary_search(old.begin(), old.end(), id);
    int loops = 0;
    for (size_t i = 0; i < pieces[p].size(); ++i) {
      const Slot t = pieces[p][i];
      const int l = flooder_.walkNewLoops(cx, t.hex, t.axis);
      loops += l;
      const int32_t from = label(t);
      if (l && from >= 0) loopsTaken[oldIndex(from)] += l;
    }
    flooder_.clear(pieces[p]);
    const int32_t pieceLabel = newLabel(id);
    for (Slot t : pieces[p]) {
      move(t, pieceLabel);
      signs[slotIndex(t)] = 0;
    }
    bool orientable = true;
    std::vector<Slot> stack{pieces[p][0]};
    signs[slotIndex(pieces[p][0])] = 1;  // the piece's own label is not flipped
    while (!stack.empty()) {
      const Slot t = stack.back();
      stack.pop_back();
      for (int face : kParallelFaces[size_t(t.axis)]) {
        Slot n;
        int flip;
        if (!sheetNeighbour(cx, t, face, n, flip)) continue;
        const int want = signs[slotIndex(t)] * flip;
        if (!signs[slotIndex(n)]) {
          signs[slotIndex(n)] = int8_t(want);
          stack.push_back(n);
        } else if (signs[slotIndex(n)] != want) {
          orientable = false;
        }
      }
    }
    if (!reused) sh.euler = 0;
    sh.id = id;
    sh.alive = true;
    sh.slots = pieces[p];
    sh.boundaryLoops = loops;
    sh.orientable = orientable;
    (reused ? change.sheetsChanged : change.sheetsCreated).push_back(id);
  }
  // Remainders: the kept sheets drop the slots they lost; merged old sheets join them whole (labels
  // re-pointed, lists handed over: no slot written), and new slots join with a kept label.
  for (size_t k = 0; k < old.size(); ++k)
    if (owner[k] >= 0) {
      std::sort(leaving[k].begin(), leaving[k].end());
      dual_.sheets[size_t(old[k])].slots.remove(std::move(leaving[k]));
    }
  for (int32_t x : merged) {
    const size_t g = size_t(owner[oldIndex(x)]);
    mergeSheet(x, keepOf[g], flipOf[oldIndex(x)] != 0);
    dual_.sheets[size_t(x)].slots.clear();
    dual_.sheets[size_t(x)].alive = false;
    change.sheetsRemoved.push_back(x);
  }
  std::vector<std::vector<Slot>> joining(parent.size());
  for (size_t i = 0; i < newInRest.size(); ++i) {
    const Slot t = newInRest[i];
    const int32_t g = find(front_[slotIndex(t)] - 1);
    move(t, labels_[size_t(keepOf[size_t(g)])].front());
    setSign(t, flipOf[old.size() + i] ? -1 : 1);
    joining[size_t(g)].push_back(t);  // sorted: newInRest is
  }
  for (size_t g = 0; g < parent.size(); ++g) {
    const int32_t keep = keepOf[g];
    if (keep < 0) continue;
    int64_t loops = 0;
    for (size_t k = 0; k < old.size(); ++k)
      if (owner[k] == int32_t(g)) loops += dual_.sheets[size_t(old[k])].boundaryLoops - loopsTaken[k];
    dual_.sheets[size_t(keep)].slots.add(std::move(joining[g]));
    dual_.sheets[size_t(keep)].boundaryLoops = int(loops);
    change.sheetsChanged.push_back(keep);
  }
  for (size_t k = 0; k < old.size(); ++k)
    if (owner[k] < 0 && !taken[k]) {
      dual_.sheets[size_t(old[k])].slots.clear();
      dual_.sheets[size_t(old[k])].alive = false;
      change.sheetsRemoved.push_back(old[k]);
    }
  countSelfHexes(recount, +1);
  for (int32_t id : affected) {
    Sheet& sh = dual_.sheets[size_t(id)];
    sh.euler += delta_[size_t(id)] / 2;
    delta_[size_t(id)] = 0;
    pruneLabels(id);
    if (!sh.alive) continue;
    sh.selfIntersecting = selfPairs_[size_t(id)] > 0;
    sh.topology = classifySurface(sh.euler, sh.boundaryLoops, sh.orientable);
  }
  sheetSlotsTouched_ += reached.size();
  clearFronts();
  return true;
}

DualChange DualTracker::update(const Complex& cx, std::vector<HexId> touched, bool sheetsKeepTopology) {
  const size_t cap = std::max(size_t(cx.hexCapacity()), dual_.sheetLabel.size());
  growPerHexArrays(cap);
  slotsTouched_ = 0;
  sheetSlotsTouched_ = 0;
  mergedLabels_ = 0;
  reflooded_ = false;
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  DualChange change;
  if (!(sheetsKeepTopology && updateSheetsLocally(cx, touched, change)) && !updateSheetsLockstep(cx, touched, change)) {
    reflooded_ = true;
    updateSheetsByFlood(cx, touched, change);
  }
  slotsTouched_ = sheetSlotsTouched_;
  updateChords(cx, touched, change);
  return change;
}

namespace {

// Old labels are parked in the per-slot array as -2 - id, so a walk that overwrites them reports
// which old sheets or chords each new one holds (no map of slots).
int32_t parked(int32_t id) { return -2 - id; }

// Picks the id for a recomputed component: the smallest old id it holds that no earlier
// component took, else a fresh id.
int chooseId(const std::vector<int32_t>& previous, std::vector<int>& taken, size_t freshId) {
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
size_t relabel(const Complex& cx, const std::vector<HexId>& touched, std::vector<std::array<int32_t, 3>>& of,
               std::vector<Entity>& list, std::vector<int32_t> old, Walk walk, std::vector<int>& created,
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

}  // namespace

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
  sheetSlotsTouched_ += relabel(cx, touched, dual_.sheetLabel, dual_.sheets, old, walk, change.sheetsCreated,
                                change.sheetsChanged, change.sheetsRemoved, [](int) { return false; }, labelOf);
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

// ---- chords ----

int32_t DualTracker::chordLength(int32_t id) const {
  int32_t n = 0;
  for (const Piece& p : pieces_[size_t(id)]) n += p.hi - p.lo;
  return n;
}

int32_t DualTracker::placeInChord(int32_t id, Slot s) const {
  const int32_t l = dual_.chordLabel[size_t(s.hex)][size_t(s.axis)];
  if (l < 0) return -1;
  const int32_t i = dual_.chordPlace[slotIndex(s)];
  int32_t before = 0;
  for (const Piece& p : pieces_[size_t(id)]) {
    if (p.label == l && i >= p.lo && i < p.hi) return before + (p.reversed ? p.hi - 1 - i : i - p.lo);
    before += p.hi - p.lo;
  }
  return -1;
}

// The chords lose their pieces (their labels' places are cut from them).
void DualTracker::dropPieces(const std::vector<int32_t>& ids) {
  for (int32_t id : ids) {
    for (const Piece& p : pieces_[size_t(id)]) cutLabel(p.label, p.lo, p.hi, id, false);
    pieces_[size_t(id)].clear();
  }
}

// The slots of pieces, in order.
void DualTracker::appendSlots(const std::vector<Piece>& pieces, std::vector<Slot>& out) const {
  for (const Piece& p : pieces)
    for (int32_t k = 0; k < p.hi - p.lo; ++k) out.push_back(runs_[size_t(p.label)][size_t(p.reversed ? p.hi - 1 - k : p.lo + k)]);
}

Slot DualTracker::chordSlotAt(int32_t id, int32_t q) const {
  for (const Piece& p : pieces_[size_t(id)]) {
    const int32_t n = p.hi - p.lo;
    if (q < n) return runs_[size_t(p.label)][size_t(p.reversed ? p.hi - 1 - q : p.lo + q)];
    q -= n;
  }
  return {};
}

void DualTracker::sliceChord(int32_t id, int32_t a, int32_t b, std::vector<Piece>& out) const {
  int32_t before = 0;
  for (const Piece& p : pieces_[size_t(id)]) {
    const int32_t n = p.hi - p.lo, from = std::max(a, before), to = std::min(b + 1, before + n);
    if (from < to) {
      const int32_t x = from - before, y = to - before;  // listed offsets [x, y) in the piece
      out.push_back(p.reversed ? Piece{p.label, p.hi - y, p.hi - x, true} : Piece{p.label, p.lo + x, p.lo + y, false});
    }
    before += n;
  }
}

// A label for a run of slots, written on them with their places.
int32_t DualTracker::newChordLabel(std::vector<Slot> run) {
  int32_t l;
  if (!freeChordLabels_.empty()) {
    l = freeChordLabels_.back();
    freeChordLabels_.pop_back();
  } else {
    l = int32_t(runs_.size());
    runs_.emplace_back();
    dual_.labelCuts.emplace_back();
    dual_.labelChord.push_back(-1);
  }
  for (size_t i = 0; i < run.size(); ++i) {
    dual_.chordLabel[size_t(run[i].hex)][size_t(run[i].axis)] = l;
    dual_.chordPlace[slotIndex(run[i])] = int32_t(i);
  }
  runs_[size_t(l)] = std::move(run);
  dual_.labelCuts[size_t(l)].clear();
  dual_.labelChord[size_t(l)] = -1;
  return l;
}

// Adds or removes a range of a label's places listed in a chord; the label's chord (or -1 when its
// places lie in several) follows. Labels left with no range are released by releaseLabels().
void DualTracker::cutLabel(int32_t label, int32_t lo, int32_t hi, int32_t chord, bool add) {
  auto& cuts = dual_.labelCuts[size_t(label)];
  if (add) {
    cuts.push_back({lo, hi, chord});
  } else {
    for (size_t i = 0; i < cuts.size(); ++i)
      if (cuts[i].lo == lo && cuts[i].hi == hi && cuts[i].chord == chord) {
        cuts.erase(cuts.begin() + std::ptrdiff_t(i));
        break;
      }
    dropped_.push_back(label);
  }
  int32_t c = cuts.empty() ? -1 : cuts[0].chord;
  for (const Dual::ChordCut& k : cuts) c = k.chord == c ? c : -1;
  dual_.labelChord[size_t(label)] = c;
}

// Labels that lost places in this update and lie in no chord any more: no slot carries them.
void DualTracker::releaseLabels() {
  std::sort(dropped_.begin(), dropped_.end());
  dropped_.erase(std::unique(dropped_.begin(), dropped_.end()), dropped_.end());
  for (int32_t l : dropped_)
    if (dual_.labelCuts[size_t(l)].empty()) {
      runs_[size_t(l)] = std::vector<Slot>();
      dual_.labelChord[size_t(l)] = -1;
      freeChordLabels_.push_back(l);
    }
  dropped_.clear();
}

// Lists chord id as these pieces (joined where they continue one another). A chord cut and joined
// so often that it has many pieces is given one run again (its slots re-labelled: a rare, whole pass).
void DualTracker::setChordPieces(int32_t id, std::vector<Piece> pieces) {
  std::vector<Piece> joined;
  for (const Piece& p : pieces) {
    if (!joined.empty()) {
      Piece& q = joined.back();
      if (q.label == p.label && q.reversed == p.reversed && (p.reversed ? p.hi == q.lo : q.hi == p.lo)) {
        q.lo = std::min(q.lo, p.lo);
        q.hi = std::max(q.hi, p.hi);
        continue;
      }
    }
    joined.push_back(p);
  }
  constexpr size_t kMaxPieces = 16;
  if (joined.size() > kMaxPieces) {
    std::vector<Slot> run;
    appendSlots(joined, run);
    for (const Piece& p : joined) dropped_.push_back(p.label);  // they lose these places
    slotsTouched_ += run.size();
    const int32_t n = int32_t(run.size());
    joined.assign(1, Piece{newChordLabel(std::move(run)), 0, n, false});
  }
  for (const Piece& p : joined) cutLabel(p.label, p.lo, p.hi, id, true);
  pieces_[size_t(id)] = std::move(joined);
  if (!unsettledMark_[size_t(id)]) {
    unsettledMark_[size_t(id)] = 1;
    unsettled_.push_back(id);
  }
}

bool DualTracker::chordSelfIntersects(int32_t id) const {
  for (const Piece& p : pieces_[size_t(id)])
    for (int32_t i = p.lo; i < p.hi; ++i) {
      const Slot t = runs_[size_t(p.label)][size_t(i)];
      if (dual_.chordAt(t.hex, (t.axis + 1) % 3) == id || dual_.chordAt(t.hex, (t.axis + 2) % 3) == id) return true;
    }
  return false;
}

// Chord lists (and self-intersection where the update left it open) from their pieces, for readers.
void DualTracker::settleChords() const {
  for (int32_t id : unsettled_) {
    unsettledMark_[size_t(id)] = 0;
    Chord& ch = dual_.chords[size_t(id)];
    ch.slots.clear();
    if (!ch.alive) continue;
    ch.slots.reserve(size_t(chordLength(id)));
    appendSlots(pieces_[size_t(id)], ch.slots);
    if (chordSelf_[size_t(id)] == 2) chordSelf_[size_t(id)] = chordSelfIntersects(id);
    ch.selfIntersecting = chordSelf_[size_t(id)] != 0;
  }
  unsettled_.clear();
}

void DualTracker::updateChords(const Complex& cx, const std::vector<HexId>& touched, DualChange& change) {
  // A chord whose touched slots still have the same neighbours along it is unchanged.
  auto unchanged = [&](int32_t id, const std::vector<Slot>& own) {
    const int32_t len = chordLength(id);
    const bool closed = dual_.chords[size_t(id)].closed;
    for (Slot s : own) {
      const int32_t p = placeInChord(id, s);
      if (!cx.isHex(s.hex) || p < 0) return false;
      auto along = [&](int face, Slot& n) {
        Gluing g = cx.gluing(s.hex, face);
        if (g.boundary()) return false;
        n = {g.hex, tables::axisOfFace(g.face)};
        return true;
      };
      Slot lo, hi, prev, next;
      const bool hasLo = along(2 * s.axis, lo), hasHi = along(2 * s.axis + 1, hi);
      const bool hasPrev = p > 0 || closed, hasNext = p + 1 < len || closed;
      if (hasPrev) prev = chordSlotAt(id, p > 0 ? p - 1 : len - 1);
      if (hasNext) next = chordSlotAt(id, p + 1 < len ? p + 1 : 0);
      auto same = [](bool x, Slot a, bool y, Slot b) { return x == y && (!x || a == b); };
      if (!(same(hasLo, lo, hasPrev, prev) && same(hasHi, hi, hasNext, next)) &&
          !(same(hasLo, lo, hasNext, next) && same(hasHi, hi, hasPrev, prev)))
        return false;
    }
    return true;
  };
  // The touched slots grouped by chord, so each chord reads only its own.
  std::vector<std::pair<int32_t, Slot>> through;
  for (HexId h : touched)
    for (int a = 0; a < 3; ++a) {
      const int32_t c = dual_.chordAt(h, a);
      if (c >= 0) through.push_back({c, Slot{h, a}});
    }
  std::sort(through.begin(), through.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<int32_t> ids;
  std::vector<Slot> own;
  for (size_t i = 0, j = 0; i < through.size(); i = j) {
    const int32_t id = through[i].first;
    own.clear();
    for (j = i; j < through.size() && through[j].first == id; ++j) own.push_back(through[j].second);
    slotsTouched_ += own.size();
    if (!unchanged(id, own)) ids.push_back(id);
  }
  const size_t before = slotsTouched_;
  chordsRewalked_ = !localChords_ || !rejoinChords(cx, touched, ids, change);
  if (chordsRewalked_) {
    slotsTouched_ = before;  // a rejoin that gave up counts nothing: the re-walk is the work done
    rewalkChords(cx, touched, ids, change);
  }
}

// Re-walks the changed chords whole from the touched slots (relabel): the reference, and the way
// out when the local rejoin is not sure.
void DualTracker::rewalkChords(const Complex& cx, const std::vector<HexId>& touched, const std::vector<int32_t>& ids,
                               DualChange& change) {
  settleChords();
  int32_t* chordOf = dual_.chordLabel[0].data();
  auto walk = [&](Slot s, Chord& ch, std::vector<int32_t>& previous) {
    ch.id = kTemp;
    walkChord(cx, s, ch, chordOf, &previous);
    // A hex met twice has another slot labelled kTemp (read from the lines the walk just wrote).
    for (Slot t : ch.slots) {
      const int32_t* of = chordOf + 3 * size_t(t.hex);
      ch.selfIntersecting = ch.selfIntersecting || of[(t.axis + 1) % 3] == kTemp || of[(t.axis + 2) % 3] == kTemp;
    }
  };
  dropPieces(ids);
  std::vector<std::pair<int32_t, int32_t>> made;  // (chord id, label): the runs are set after the walks
  auto labelOf = [&](int id) {
    const int32_t l = newChordLabel({});
    made.push_back({int32_t(id), l});
    return l;
  };
  slotsTouched_ += relabel(
      cx, touched, dual_.chordLabel, dual_.chords, ids, walk, change.chordsCreated, change.chordsChanged,
      change.chordsRemoved, [](int) { return false; }, labelOf);
  const size_t n = dual_.chords.size();
  pieces_.resize(n);
  chordSelf_.resize(n, 0);
  unsettledMark_.resize(n, 0);
  for (auto [id, l] : made) {
    const Chord& ch = dual_.chords[size_t(id)];
    runs_[size_t(l)] = ch.slots;
    for (size_t i = 0; i < ch.slots.size(); ++i) dual_.chordPlace[slotIndex(ch.slots[i])] = int32_t(i);
    const int32_t len = int32_t(ch.slots.size());
    dual_.labelCuts[size_t(l)].assign(1, Dual::ChordCut{0, len, id});
    dual_.labelChord[size_t(l)] = id;
    pieces_[size_t(id)].assign(1, Piece{l, 0, len, false});
    chordSelf_[size_t(id)] = ch.selfIntersecting;
  }
  // Labels of the old pieces are released after the walks, which parked every slot that carried them.
  releaseLabels();
}

// The changed chords rebuilt from what the edit left of them (TK03 §3.2: an edit changes chords
// only through the edited hexes): their untouched stretches keep their labels and places, walks
// through the touched hexes join the stretches' ends (a collapse joins two chords crosswise, TK03
// §4.4), and touched slots no walk meets form chords of their own. Each new chord gets the id and
// the slot order a re-walk from its smallest touched slot gives (relabel); only the touched slots
// are written. False, writing nothing, when the state is not one it can follow.
bool DualTracker::rejoinChords(const Complex& cx, const std::vector<HexId>& touched, const std::vector<int32_t>& ids,
                               DualChange& change) {
  auto inIds = [&](int32_t c) { return c >= 0 && std::binary_search(ids.begin(), ids.end(), c); };
  // The touched slots, by slot (touched is sorted); a slot's old chord, run or own chord.
  struct Touched {
    Slot slot;
    int32_t old;
    bool live;
    int32_t run = -1, entry = -1;  // the walk that met it, and the face it entered through
    int32_t comp = -1;             // the new chord it lies in
  };
  std::vector<Touched> ts;
  ts.reserve(3 * touched.size());
  for (HexId h : touched)
    for (int a = 0; a < 3; ++a) ts.push_back({{h, a}, dual_.chordAt(h, a), cx.isHex(h)});
  auto indexOf = [&](Slot s) -> int32_t {
    if (!std::binary_search(touched.begin(), touched.end(), s.hex)) return -1;
    return int32_t(3 * size_t(std::lower_bound(touched.begin(), touched.end(), s.hex) - touched.begin()) +
                   size_t(s.axis));
  };
  auto faceTo = [&](Slot s, Slot t) {  // the one face of s's hex along its axis glued to slot t, else -1
    int found = -1, count = 0;
    for (int f = 2 * s.axis; f < 2 * s.axis + 2; ++f) {
      Gluing g = cx.gluing(s.hex, f);
      if (!g.boundary() && Slot{g.hex, tables::axisOfFace(g.face)} == t) {
        found = f;
        ++count;
      }
    }
    return count == 1 ? found : -1;
  };
  // ---- stretches: the untouched places of each old chord between touched ones ----
  struct Stretch {
    int32_t chord, a, b;  // places a..b (b >= length wraps round a closed chord)
    Slot end[2];
    int face[2] = {-1, -1};      // the face each end leaves through, -1 at the chord's boundary end
    int32_t link[2] = {-1, -1};  // the walk from or to each end
  };
  std::vector<Stretch> stretches;
  std::vector<int32_t> lengths(ids.size()), liveOld(ids.size(), 0);
  std::vector<uint8_t> contiguous(ids.size(), 0);
  // The touched slots of each changed chord, found once (a sheet operation changes thousands of chords).
  std::vector<std::pair<int32_t, int32_t>> byOld;  // (old chord, index into ts)
  for (size_t i = 0; i < ts.size(); ++i)
    if (inIds(ts[i].old)) byOld.push_back({ts[i].old, int32_t(i)});
  std::sort(byOld.begin(), byOld.end());
  for (size_t k = 0; k < ids.size(); ++k) {
    const int32_t id = ids[k], len = chordLength(id);
    const bool closed = dual_.chords[size_t(id)].closed;
    lengths[k] = len;
    std::vector<int32_t> at;
    for (auto it = std::lower_bound(byOld.begin(), byOld.end(), std::pair<int32_t, int32_t>{id, -1});
         it != byOld.end() && it->first == id; ++it) {
      const Touched& t = ts[size_t(it->second)];
      const int32_t p = placeInChord(id, t.slot);
      if (p < 0) return false;
      at.push_back(p);
      liveOld[k] += t.live;
    }
    if (at.empty()) return false;
    std::sort(at.begin(), at.end());
    contiguous[k] =
        !closed && at.front() > 0 && at.back() + 1 < len && at.back() - at.front() + 1 == int32_t(at.size());
    auto add = [&](int32_t a, int32_t b) {
      Stretch st{id, a, b, {chordSlotAt(id, a % len), chordSlotAt(id, b % len)}};
      for (int side = 0; side < 2; ++side) {
        if (!closed && (side == 0 ? a == 0 : b == len - 1)) continue;  // the chord's boundary end
        const Slot n = chordSlotAt(id, side == 0 ? (a - 1 + len) % len : (b + 1) % len);
        st.face[side] = faceTo(st.end[side], n);
        if (st.face[side] < 0) return false;
      }
      stretches.push_back(st);
      return true;
    };
    bool ok = true;
    if (!closed) {
      if (at.front() > 0) ok = ok && add(0, at.front() - 1);
      if (at.back() + 1 < len) ok = ok && add(at.back() + 1, len - 1);
    }
    for (size_t j = 0; ok && j < at.size(); ++j) {
      if (j + 1 == at.size() && !closed) break;
      const int32_t next = j + 1 < at.size() ? at[j + 1] : at[0] + len;
      if (next > at[j] + 1) ok = add(at[j] + 1, next - 1);
    }
    if (!ok) return false;
  }
  slotsTouched_ += 2 * stretches.size();
  // ---- walks through the touched slots from every stretch end ----
  struct Walk {
    std::vector<int32_t> slots;  // indices into ts, in walk order
    int32_t from, to;            // stretch ends (2 * stretch + side), -1 for the boundary
  };
  std::vector<Walk> walks;
  // The first stretch end at slot s leaving through `face` (hashed: one lookup per walk).
  std::unordered_map<int64_t, int32_t> endIndex;
  auto endKey = [](Slot s, int face) { return (int64_t(s.hex) * 3 + s.axis) * 8 + face; };
  for (size_t r = 0; r < stretches.size(); ++r)
    for (int side = 0; side < 2; ++side)
      if (stretches[r].face[side] >= 0) endIndex.emplace(endKey(stretches[r].end[side], stretches[r].face[side]), int32_t(2 * r + size_t(side)));
  auto endAt = [&](Slot s, int face) -> int32_t {
    auto it = endIndex.find(endKey(s, face));
    return it == endIndex.end() ? -1 : it->second;
  };
  for (size_t r = 0; r < stretches.size(); ++r)
    for (int side = 0; side < 2; ++side) {
      if (stretches[r].face[side] < 0 || stretches[r].link[side] >= 0) continue;
      const int32_t w = int32_t(walks.size());
      walks.push_back({{}, int32_t(2 * r + size_t(side)), -1});
      stretches[r].link[side] = w;
      Slot cur = stretches[r].end[side];
      int exit = stretches[r].face[side];
      for (;;) {
        Gluing g = cx.gluing(cur.hex, exit);
        if (g.boundary()) break;
        const Slot n{g.hex, tables::axisOfFace(g.face)};
        const int32_t k = indexOf(n);
        if (k < 0) {
          const int32_t e = endAt(n, g.face);
          if (e < 0 || stretches[size_t(e / 2)].link[e % 2] >= 0) return false;
          stretches[size_t(e / 2)].link[e % 2] = w;
          walks[size_t(w)].to = e;
          break;
        }
        Touched& t = ts[size_t(k)];
        if (!t.live || t.run >= 0 || (t.old >= 0 && !inIds(t.old)) || walks[size_t(w)].slots.size() >= ts.size())
          return false;
        t.run = w;
        t.entry = g.face;
        walks[size_t(w)].slots.push_back(k);
        cur = n;
        exit = tables::oppositeFace(g.face);
      }
      slotsTouched_ += walks[size_t(w)].slots.size();
    }
  // ---- new chords: chains of stretches and walks, and chords of touched slots alone ----
  struct Item {
    int32_t stretch = -1, slot = -1;  // a stretch (listed a..b when forward), or one touched slot (ts index)
    bool forward = true;
  };
  struct Comp {
    std::vector<Item> items;
    bool closed = false;
    int32_t first = -1;  // its smallest touched slot (ts index)
  };
  std::vector<Comp> comps;
  std::vector<uint8_t> inChain(stretches.size(), 0);
  auto walkItems = [&](int32_t w, bool forward, std::vector<Item>& out) {
    const auto& sl = walks[size_t(w)].slots;
    if (forward)
      for (int32_t k : sl) out.push_back({-1, k, true});
    else
      for (size_t i = sl.size(); i-- > 0;) out.push_back({-1, sl[i], false});
  };
  for (size_t r0 = 0; r0 < stretches.size(); ++r0) {
    if (inChain[r0]) continue;
    inChain[r0] = 1;
    Comp c;
    // Rightwards from side 1, then leftwards from side 0 (listed reversed).
    std::vector<Item> right, left;
    int32_t end = int32_t(2 * r0 + 1);
    for (;;) {
      const int32_t w = stretches[size_t(end / 2)].link[end % 2];
      if (w < 0) break;
      const bool fwd = walks[size_t(w)].from == end;
      walkItems(w, fwd, right);
      const int32_t other = fwd ? walks[size_t(w)].to : walks[size_t(w)].from;
      if (other < 0) break;
      if (size_t(other / 2) == r0) {
        if (other % 2 != 0) return false;
        c.closed = true;
        break;
      }
      if (inChain[size_t(other / 2)]) return false;
      inChain[size_t(other / 2)] = 1;
      right.push_back({other / 2, -1, other % 2 == 0});
      end = other ^ 1;
    }
    end = int32_t(2 * r0);
    while (!c.closed) {
      const int32_t w = stretches[size_t(end / 2)].link[end % 2];
      if (w < 0) break;
      const bool fwd = walks[size_t(w)].from == end;
      std::vector<Item> part;
      walkItems(w, fwd, part);
      for (const Item& it : part) left.push_back({-1, it.slot, !it.forward});  // listed right to left
      const int32_t other = fwd ? walks[size_t(w)].to : walks[size_t(w)].from;
      if (other < 0) break;
      if (inChain[size_t(other / 2)]) return false;
      inChain[size_t(other / 2)] = 1;
      left.push_back({other / 2, -1, other % 2 == 1});
      end = other ^ 1;
    }
    c.items.assign(left.rbegin(), left.rend());
    c.items.push_back({int32_t(r0), -1, true});
    c.items.insert(c.items.end(), right.begin(), right.end());
    comps.push_back(std::move(c));
  }
  // Touched slots no walk met (old chords rebuilt here, or new slots) form chords of their own,
  // walked as walkChord would from the smallest: back through its low face, then forward.
  for (size_t k = 0; k < ts.size(); ++k) {
    Touched& t0 = ts[k];
    if (!t0.live || t0.run >= 0 || t0.comp >= 0 || (t0.old >= 0 && !inIds(t0.old))) continue;
    const Slot start = t0.slot;
    Slot cur = start;
    int back = 2 * start.axis;
    bool closed = false;
    for (size_t steps = 0;; ++steps) {
      Gluing g = cx.gluing(cur.hex, back);
      if (g.boundary()) break;
      cur = {g.hex, tables::axisOfFace(g.face)};
      back = tables::oppositeFace(g.face);
      if (indexOf(cur) < 0 || steps > ts.size()) return false;
      if (cur == start) {
        if (back != 2 * start.axis) return false;  // a twisted return: the re-walk is the reference
        closed = true;
        break;
      }
    }
    if (closed) cur = start;
    Comp c;
    c.closed = closed;
    int exit = closed ? 2 * start.axis + 1 : tables::oppositeFace(back);
    const int32_t ci = int32_t(comps.size());
    bool returned = false;
    for (;;) {
      const int32_t i = indexOf(cur);
      Touched& t = ts[size_t(i)];
      if (!t.live || t.run >= 0 || t.comp >= 0 || (t.old >= 0 && !inIds(t.old))) return false;
      t.comp = ci;
      c.items.push_back({-1, i, true});
      Gluing g = cx.gluing(cur.hex, exit);
      if (g.boundary()) break;
      cur = {g.hex, tables::axisOfFace(g.face)};
      exit = tables::oppositeFace(g.face);
      const int32_t next = indexOf(cur);
      if (next < 0) return false;
      if (ts[size_t(next)].comp == ci) {
        if (!(cur == start)) return false;
        returned = true;
        break;
      }
    }
    if (returned != closed) return false;
    c.first = int32_t(k);
    slotsTouched_ += c.items.size();
    comps.push_back(std::move(c));
  }
  // Each chain is listed as a re-walk from its smallest touched slot lists it: from the end its low
  // face leads to, or (closed) starting there and leaving through its high face.
  for (size_t ci = 0; ci < comps.size(); ++ci) {
    Comp& c = comps[ci];
    if (c.first >= 0) continue;  // a chord of touched slots alone: walked in order
    size_t at = c.items.size();
    for (size_t i = 0; i < c.items.size(); ++i)
      if (c.items[i].slot >= 0 && (at == c.items.size() || c.items[i].slot < c.items[at].slot)) at = i;
    if (at == c.items.size()) return false;
    for (const Item& it : c.items)
      if (it.slot >= 0) ts[size_t(it.slot)].comp = int32_t(ci);
    // The slot before it in this listing is across its low face when the listing runs along the
    // walk that met it and it entered through its low face, or against it and through the high one.
    const Touched& t = ts[size_t(c.items[at].slot)];
    const bool lowBefore = ((t.entry & 1) == 0) == c.items[at].forward;
    if (!lowBefore) {
      std::reverse(c.items.begin(), c.items.end());
      for (Item& it : c.items) it.forward = !it.forward;
      at = c.items.size() - 1 - at;
    }
    if (c.closed) std::rotate(c.items.begin(), c.items.begin() + std::ptrdiff_t(at), c.items.end());
    c.first = c.items[c.closed ? 0 : at].slot;
  }
  // ---- ids: in the order of each new chord's smallest touched slot, the smallest old id it holds
  // that no earlier one took, else a fresh one (relabel's rule) ----
  std::vector<size_t> order(comps.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::sort(order.begin(), order.end(), [&](size_t x, size_t y) { return comps[x].first < comps[y].first; });
  auto oldOf = [&](const Item& it) {
    return it.stretch >= 0 ? stretches[size_t(it.stretch)].chord : ts[size_t(it.slot)].old;
  };
  std::vector<int32_t> compId(comps.size(), -1);
  std::unordered_set<int32_t> taken;  // hashed: a sheet operation re-ids thousands of chords
  int32_t fresh = int32_t(dual_.chords.size());
  for (size_t ci : order) {
    int32_t best = -1;
    for (const Item& it : comps[ci].items) {
      const int32_t o = oldOf(it);
      if (o >= 0 && (best < 0 || o < best) && !taken.count(o)) best = o;
    }
    if (best >= 0) taken.insert(best);
    compId[ci] = best >= 0 ? best : fresh++;
  }
  // ---- self-intersection: a touched hex with two slots in one new chord; untouched hexes only
  // matter when a chord joins stretches of several old chords (or of one that self-intersected):
  // then it is left for the reader (settleChords) ----
  std::vector<uint8_t> self(comps.size(), 0);
  for (size_t i = 0; i + 2 < ts.size(); i += 3)
    for (size_t a = 0; a < 3; ++a)
      for (size_t b = a + 1; b < 3; ++b)
        if (ts[i + a].comp >= 0 && ts[i + a].comp == ts[i + b].comp) self[size_t(ts[i + a].comp)] = 1;
  for (size_t ci = 0; ci < comps.size(); ++ci) {
    int32_t one = -1;
    bool several = false;
    for (const Item& it : comps[ci].items)
      if (it.stretch >= 0) {
        const int32_t o = stretches[size_t(it.stretch)].chord;
        several = several || (one >= 0 && o != one);
        one = o;
      }
    if (!self[ci] && (several || (one >= 0 && chordSelf_[size_t(one)] != 0))) self[ci] = 2;
  }
  // ---- which of them an in-place splice of one old chord would have given (listed first among the
  // changed, as before) ----
  auto splice = [&](size_t ci) {
    const Comp& c = comps[ci];
    const int32_t id = compId[ci];
    const size_t k = size_t(std::lower_bound(ids.begin(), ids.end(), id) - ids.begin());
    if (c.closed || k == ids.size() || ids[k] != id || !contiguous[k] || c.items.size() < 3) return false;
    const Item &head = c.items.front(), &tail = c.items.back();
    if (head.stretch < 0 || tail.stretch < 0 || !head.forward || !tail.forward ||
        stretches[size_t(head.stretch)].chord != id || stretches[size_t(head.stretch)].a != 0 ||
        stretches[size_t(tail.stretch)].chord != id || stretches[size_t(tail.stretch)].b != lengths[k] - 1)
      return false;
    int32_t kept = 0;
    for (size_t i = 1; i + 1 < c.items.size(); ++i) {
      const Item& it = c.items[i];
      if (it.slot < 0 || (ts[size_t(it.slot)].old != id && ts[size_t(it.slot)].old != -1)) return false;
      kept += ts[size_t(it.slot)].old == id;
    }
    if (kept != liveOld[k] || c.items.size() - 2 >= 3 * touched.size()) return false;
    return chordSelf_[size_t(id)] == 0 || (chordSelf_[size_t(id)] == 2 && !chordSelfIntersects(id));
  };
  std::vector<uint8_t> spliced(comps.size(), 0);
  for (size_t ci = 0; ci < comps.size(); ++ci) spliced[ci] = splice(ci);

  // ---- commit: stretches keep their pieces, consecutive touched slots get new labels ----
  std::vector<std::vector<Piece>> stretchPieces(stretches.size());
  for (size_t r = 0; r < stretches.size(); ++r) {
    const Stretch& st = stretches[r];
    const int32_t len = lengths[size_t(std::lower_bound(ids.begin(), ids.end(), st.chord) - ids.begin())];
    sliceChord(st.chord, st.a, std::min(st.b, len - 1), stretchPieces[r]);
    if (st.b >= len) sliceChord(st.chord, 0, st.b - len, stretchPieces[r]);
  }
  dropPieces(ids);
  for (const Touched& t : ts)
    if (!t.live) dual_.chordLabel[size_t(t.slot.hex)][size_t(t.slot.axis)] = -1;
  const size_t n = size_t(fresh);
  if (dual_.chords.size() < n) dual_.chords.resize(n);
  pieces_.resize(std::max(pieces_.size(), n));
  chordSelf_.resize(std::max(chordSelf_.size(), n), 0);
  unsettledMark_.resize(std::max(unsettledMark_.size(), n), 0);
  std::vector<int32_t> splicedIds;
  for (size_t ci : order) {
    const Comp& c = comps[ci];
    std::vector<Piece> pieces;
    std::vector<Slot> run;
    auto flush = [&] {
      if (run.empty()) return;
      const int32_t len = int32_t(run.size());
      slotsTouched_ += run.size();
      pieces.push_back({newChordLabel(std::move(run)), 0, len, false});
      run.clear();
    };
    for (const Item& it : c.items) {
      if (it.slot >= 0) {
        run.push_back(ts[size_t(it.slot)].slot);
        continue;
      }
      flush();
      const std::vector<Piece>& ps = stretchPieces[size_t(it.stretch)];
      if (it.forward) {
        pieces.insert(pieces.end(), ps.begin(), ps.end());
      } else {
        for (size_t i = ps.size(); i-- > 0;) pieces.push_back({ps[i].label, ps[i].lo, ps[i].hi, !ps[i].reversed});
      }
    }
    flush();
    const int32_t id = compId[ci];
    Chord& ch = dual_.chords[size_t(id)];
    ch.id = id;
    ch.alive = true;
    ch.closed = c.closed;
    chordSelf_[size_t(id)] = self[ci];
    if (self[ci] != 2) ch.selfIntersecting = self[ci] != 0;
    setChordPieces(id, std::move(pieces));
    if (!std::binary_search(ids.begin(), ids.end(), id))
      change.chordsCreated.push_back(id);
    else if (spliced[ci])
      splicedIds.push_back(id);
    else
      change.chordsChanged.push_back(id);
  }
  std::sort(splicedIds.begin(), splicedIds.end());
  change.chordsChanged.insert(change.chordsChanged.begin(), splicedIds.begin(), splicedIds.end());
  for (int32_t id : ids)
    if (!taken.count(id)) {
      Chord& ch = dual_.chords[size_t(id)];
      ch.alive = false;
      ch.slots.clear();
      chordSelf_[size_t(id)] = 0;
      change.chordsRemoved.push_back(id);
    }
  releaseLabels();
  return true;
}

}  // namespace hexdual
