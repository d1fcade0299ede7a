#include "dual/dual.hpp"

#include <algorithm>
#include <numeric>


namespace hexdual {
using namespace tables;

namespace {

constexpr std::array<std::array<int, 2>, 3> kParallelAxes = {{{1, 2}, {0, 2}, {0, 1}}};
// Bit of boundary mid-edge (face f, slot axis a) in a hex's loop marks.
constexpr int loopBit(int f, int a) { return 2 * f + (a == (axisOfFace(f) + 1) % 3 ? 0 : 1); }

int axisAcrossGluing(int f, int a, const Gluing& g) { return kCrossings[size_t(crossingIndex(f, a, g.face, g.orient))].axis; }

size_t slotIndex(HexId h, int a) { return size_t(3) * size_t(h) + size_t(a); }

}  // namespace

SlotList& SlotList::operator=(std::vector<Slot> sorted) {
  list_ = std::move(sorted);
  runs_.clear();
  adds_.clear();
  gone_.clear();
  size_ = list_.size();
  return *this;
}

void SlotList::clear() {
  list_.clear();
  runs_.clear();
  adds_.clear();
  gone_.clear();
  size_ = 0;
}

namespace {
// Pending runs, additions and removals kept before a list is merged without being read: few runs,
// and additions or removals up to an eighth of the list, so that merging them stays linear in it.
constexpr size_t kMaxRuns = 16;
bool tooMany(size_t pending, size_t size) { return pending > 64 + size / 8; }

// Merges sorted `run` into sorted `base` in place, from the back (no second buffer).
void mergeInto(std::vector<Slot>& base, const std::vector<Slot>& run) {
  size_t i = base.size(), j = run.size(), k = i + j;
  base.resize(k);
  while (j > 0) base[--k] = i > 0 && run[j - 1] < base[i - 1] ? base[--i] : run[--j];
}
}  // namespace

void SlotList::add(std::vector<Slot> sorted) {
  if (sorted.empty()) return;
  size_ += sorted.size();
  if (list_.empty() && runs_.empty() && adds_.empty() && gone_.empty()) {
    list_ = std::move(sorted);
    return;
  }
  mergeInto(adds_, sorted);
  if (tooMany(adds_.size(), size_)) settle();
}

void SlotList::absorb(SlotList&& other) {
  if (other.size_ == 0 && other.gone_.empty()) return;
  if (size_ == 0 && runs_.empty() && adds_.empty() && gone_.empty()) {
    *this = std::move(other);
    other.clear();
    return;
  }
  size_ += other.size_;
  if (!other.list_.empty()) runs_.push_back(std::move(other.list_));
  for (auto& r : other.runs_) runs_.push_back(std::move(r));
  if (!other.adds_.empty()) runs_.push_back(std::move(other.adds_));
  gone_.insert(gone_.end(), other.gone_.begin(), other.gone_.end());
  other.clear();
  if (runs_.size() > kMaxRuns || tooMany(gone_.size(), size_)) settle();
}

void SlotList::remove(std::vector<Slot> listed) {
  if (listed.empty()) return;
  size_ -= listed.size();
  gone_.insert(gone_.end(), listed.begin(), listed.end());
  if (tooMany(gone_.size(), size_)) settle();
}

// Merges the pending runs into the longest list (the smaller ones first, then once into it from
// the back, in place), then the pending additions, and drops the pending removals in one pass
// (one listed copy per removal). The pending buffers keep their capacity.
void SlotList::settle() const {
  if (!runs_.empty()) {
    runs_.push_back(std::move(list_));
    std::sort(runs_.begin(), runs_.end(), [](const auto& a, const auto& b) { return a.size() > b.size(); });
    std::vector<Slot> base = std::move(runs_[0]), rest;
    for (size_t r = runs_.size(); r-- > 1;) {
      if (rest.empty()) {
        rest = std::move(runs_[r]);
        continue;
      }
      std::vector<Slot> both(rest.size() + runs_[r].size());
      std::merge(rest.begin(), rest.end(), runs_[r].begin(), runs_[r].end(), both.begin());
      rest = std::move(both);
    }
    mergeInto(base, rest);
    list_ = std::move(base);
    runs_.clear();
  }
  if (!adds_.empty()) {
    mergeInto(list_, adds_);
    adds_.clear();
  }
  if (!gone_.empty()) {
    std::sort(gone_.begin(), gone_.end());
    size_t w = 0, g = 0;
    for (size_t r = 0; r < list_.size(); ++r) {
      while (g < gone_.size() && gone_[g] < list_[r]) ++g;
      if (g < gone_.size() && gone_[g] == list_[r]) {
        ++g;
        continue;
      }
      list_[w++] = list_[r];
    }
    list_.resize(w);
    gone_.clear();
  }
}

void SheetFlooder::reserve(size_t hexCapacity) {
  if (sign_.size() < 3 * hexCapacity) sign_.resize(3 * hexCapacity, 0);
  if (edgeSeen_.size() < hexCapacity) edgeSeen_.resize(hexCapacity, 0);
  if (loopSeen_.size() < hexCapacity) loopSeen_.resize(hexCapacity, 0);
}

void SheetFlooder::clear(const std::vector<Slot>& slots) {
  for (Slot t : slots) {
    edgeSeen_[size_t(t.hex)] &= uint16_t(~(0xFu << (4 * t.axis)));
    for (int f : kParallelFaces[t.axis]) loopSeen_[size_t(t.hex)] &= uint16_t(~(1u << loopBit(f, t.axis)));
  }
}

// Marks every incidence of the edge at (h, e) (its cycle, or its fan both ways to the boundary).
bool SheetFlooder::walkEdge(const Complex& cx, HexId h, int e) {
  edgeSeen_[size_t(h)] |= uint16_t(1u << e);
  auto fs = facesOfEdge(e);
  for (int dir = 0; dir < 2; ++dir) {
    EdgeRef cur{h, e};
    int exit = fs[size_t(dir)];
    while (cx.stepAroundEdge(cur, exit)) {
      if (cur.hex == h && cur.edge == e) return true;  // round the cycle
      edgeSeen_[size_t(cur.hex)] |= uint16_t(1u << cur.edge);
    }
  }
  return false;
}

// Walks one boundary loop of a sheet's mid-surface from a boundary mid-edge (the side of slot
// (h, a) on boundary face f): mid-edge, fan of the primal edge it ends at, next mid-edge, ...
void SheetFlooder::walkLoop(const Complex& cx, HexId h, int f, int a) {
  HexId ch = h;
  int cf = f, ca = a;
  int leave = kMidSides[size_t(f * 3 + a)].secondEdge;
  const size_t limit = 12 * size_t(cx.hexCapacity()) + 1;  // a valid complex never gets near it
  for (size_t steps = 0; steps < limit; ++steps) {
    loopSeen_[size_t(ch)] |= uint16_t(1u << loopBit(cf, ca));
    // Around the primal edge `leave` from face cf to the fan's other boundary face.
    auto fs = facesOfEdge(leave);
    int exit = fs[0] == cf ? fs[1] : fs[0];
    EdgeRef cur{ch, leave};
    while (cx.stepAroundEdge(cur, exit)) continue;  // to the fan's far end
    ch = cur.hex;
    const int ce = cur.edge;
    cf = exit;
    ca = axisOfEdge(ce);
    if (ch == h && cf == f && ca == a) return;
    const MidSide& m = kMidSides[size_t(cf * 3 + ca)];
    leave = m.firstEdge == ce ? m.secondEdge : m.firstEdge;
  }
}

// Adds one slot's share of its sheet's mid-surface: the quad, its sides, and the primal edges and
// boundary loops it is the first to meet (each is walked whole and marked).
void SheetFlooder::measure(const Complex& cx, HexId h, int a, SheetStats& st) {
  ++st.slots;
  const unsigned unseen = ~unsigned(edgeSeen_[size_t(h)] >> (4 * a)) & 0xFu;
  if (unseen)
    for (int k = 0; k < 4; ++k)
      if ((unseen >> k) & 1u && !((edgeSeen_[size_t(h)] >> (4 * a + k)) & 1u)) {  // the walk may mark a sibling
        const bool closed = walkEdge(cx, h, 4 * a + k);
        ++st.vertices;
        if (edgeMarks) markEdge(cx, h, 4 * a + k, closed);
      }
  for (int f : kParallelFaces[a]) {
    if (!cx.isBoundary({h, f})) {
      ++st.interiorSides;
    } else {
      ++st.boundarySides;
      if (!((loopSeen_[size_t(h)] >> loopBit(f, a)) & 1u)) {
        walkLoop(cx, h, f, a);
        ++st.loops;
      }
    }
  }
}

// In a whole extraction (hexes in id order) the first incidence of an edge measured is its
// smallest; a fan's hexes all reach the boundary.
void SheetFlooder::markEdge(const Complex& cx, HexId h, int e, bool closed) {
  (*edgeMarks)[size_t(h)] |= uint16_t(1u << e);
  if (closed) return;
  (*edgeMarks)[size_t(h)] |= kEdgeNearBoundary;
  auto fs = facesOfEdge(e);
  for (int dir = 0; dir < 2; ++dir) {
    EdgeRef cur{h, e};
    int exit = fs[size_t(dir)];
    while (cx.stepAroundEdge(cur, exit)) (*edgeMarks)[size_t(cur.hex)] |= kEdgeNearBoundary;
  }
}

int8_t slotShare(const Complex& cx, HexId h, int a, uint16_t marks) {
  int s = 2 + 2 * __builtin_popcount((marks >> (4 * a)) & 0xFu);
  for (int f : kParallelFaces[size_t(a)]) s -= cx.isBoundary({h, f}) ? 2 : 1;
  return int8_t(s);
}

int SheetFlooder::walkNewLoops(const Complex& cx, HexId h, int a) {
  int loops = 0;
  for (int f : kParallelFaces[a])
    if (cx.isBoundary({h, f}) && !((loopSeen_[size_t(h)] >> loopBit(f, a)) & 1u)) {
      walkLoop(cx, h, f, a);
      ++loops;
    }
  return loops;
}

SheetStats SheetFlooder::flood(const Complex& cx, Slot start, int32_t id, int32_t* sheetOf, std::vector<Slot>* out,
                               std::vector<int32_t>* previous) {
  SheetStats st;
  if (previous) previous->push_back(sheetOf[slotIndex(start.hex, start.axis)]);
  sheetOf[slotIndex(start.hex, start.axis)] = id;
  sign_[slotIndex(start.hex, start.axis)] = 1;
  stack_.assign(1, start);
  while (!stack_.empty()) {
    Slot cur = stack_.back();
    stack_.pop_back();
    if (out) out->push_back(cur);
    const int a = cur.axis;
    measure(cx, cur.hex, a, st);
    const int sc = sign_[slotIndex(cur.hex, a)];
    for (int f : kParallelFaces[a]) {
      Gluing g = cx.gluing(cur.hex, f);
      if (g.boundary()) continue;
      const Crossing& c = kCrossings[size_t(crossingIndex(f, a, g.face, g.orient))];
      const size_t k = slotIndex(g.hex, c.axis);
      const int want = sc * c.sign;
      if (sheetOf[k] < 0) {
        if (previous) previous->push_back(sheetOf[k]);
        sheetOf[k] = id;
        sign_[k] = int8_t(want);
        stack_.push_back({g.hex, c.axis});
      } else if (sign_[k] != want) {
        st.orientable = false;
      }
    }
  }
  return st;
}

void SheetStats::classify(Sheet& sh) const {
  sh.orientable = orientable;
  sh.boundaryLoops = loops;
  sh.euler = vertices - (interiorSides / 2 + boundarySides) + slots;
  sh.topology = classifySurface(sh.euler, sh.boundaryLoops, sh.orientable);
}

// Walks one chord from a slot: back to a boundary end (or once round), then forward, labelling.
void walkChord(const Complex& cx, Slot start, Chord& ch, int32_t* chordOf, std::vector<int32_t>* previous) {
  Slot cur = start;
  int back = 2 * cur.axis;  // leaving backwards through the low face
  bool closed = false;
  for (;;) {
    Gluing g = cx.gluing(cur.hex, back);
    if (g.boundary()) break;
    cur = {g.hex, axisOfFace(g.face)};
    back = oppositeFace(g.face);
    if (cur == start) {
      closed = back == 2 * start.axis;
      break;  // round once (a twisted return leaves the chord open-ended at start)
    }
  }
  if (closed) {
    cur = start;
    back = 2 * start.axis;
  }
  walkChordForward(cx, cur, oppositeFace(back), ch, chordOf, previous);
  ch.closed = closed;
}

ChordWalk walkChordForward(const Complex& cx, Slot cur, int exitFace, Chord& ch, int32_t* chordOf,
                           std::vector<int32_t>* previous) {
  ChordWalk w;
  w.smallest = slotIndex(cur.hex, cur.axis);
  w.smallestEnteredLow = (oppositeFace(exitFace) & 1) == 0;
  for (;;) {
    ch.slots.push_back(cur);
    if (previous) previous->push_back(chordOf[slotIndex(cur.hex, cur.axis)]);
    chordOf[slotIndex(cur.hex, cur.axis)] = ch.id;
    Gluing g = cx.gluing(cur.hex, exitFace);
    if (g.boundary()) break;
    cur = {g.hex, axisOfFace(g.face)};
    exitFace = oppositeFace(g.face);
    const size_t k = slotIndex(cur.hex, cur.axis);
    if (chordOf[k] == ch.id) break;
    if (k < w.smallest) {
      w.smallest = k;
      w.smallestEnteredLow = (g.face & 1) == 0;
    }
  }
  ch.closed = false;
  return w;
}

int mapAxisAcross(const Complex& cx, HexId h, int face, int axis) { return axisAcrossGluing(face, axis, cx.gluing(h, face)); }

std::string classifySurface(int64_t euler, int loops, bool orientable) {
  if (!orientable) return "other";
  if (loops == 0 && euler == 2) return "sphere";
  if (loops == 0 && euler == 0) return "torus";
  if (loops == 1 && euler == 1) return "disk";
  if (loops == 2 && euler == 0) return "annulus";
  return "other";
}

namespace {

// Union-find over slots that also keeps each slot's orientation relative to its root (the low
// bit of its link), so one sequential pass over glued quads finds the sheets and their
// orientability, as the floor finds the sheets alone. The smaller root wins: a sheet's root is
// its smallest slot.
class OrientedUnionFind {
 public:
  explicit OrientedUnionFind(size_t n) : link_(n), twisted_(n, 0) {
    for (size_t i = 0; i < n; ++i) link_[i] = uint32_t(i) << 1;
  }
  uint32_t find(uint32_t x, uint32_t& parity) {
    parity = 0;
    for (;;) {
      const uint32_t l = link_[x], p = l >> 1;
      if (p == x) return x;
      const uint32_t lp = link_[p], gp = lp >> 1, par = (l ^ lp) & 1u;
      link_[x] = (gp << 1) | par;  // path halving, parity composed
      parity ^= par;
      x = gp;
    }
  }
  // Joins two slots whose orientations differ by `flip`; a conflict marks the sheet twisted.
  void unite(uint32_t a, uint32_t b, uint32_t flip) {
    uint32_t pa, pb;
    uint32_t ra = find(a, pa), rb = find(b, pb);
    if (ra == rb) {
      if ((pa ^ pb) != flip) twisted_[ra] = 1;
      return;
    }
    if (rb < ra) std::swap(ra, rb);
    link_[rb] = (ra << 1) | (pa ^ pb ^ flip);
    twisted_[ra] |= twisted_[rb];
  }
  bool twisted(uint32_t root) const { return twisted_[root] != 0; }

 private:
  std::vector<uint32_t> link_;
  std::vector<uint8_t> twisted_;
};

// Sheets numbered in the order of their smallest slot: labelled by one oriented union-find pass
// over the glued quads, then each slot's share of its mid-surface measured in one more pass.
void extractSheets(const Complex& cx, Dual& d, DualExtras* extras) {
  std::vector<int8_t>* signs = extras ? &extras->slotSigns : nullptr;
  int32_t* sheetOf = d.sheetLabel.empty() ? nullptr : d.sheetLabel[0].data();
  OrientedUnionFind uf(3 * size_t(cx.hexCapacity()));
  for (HexId h : cx.hexes())
    for (int f = 0; f < 6; ++f) {
      Gluing g = cx.gluing(h, f);
      if (g.boundary() || g.hex < h || (g.hex == h && g.face < f)) continue;  // each glued quad once
      for (int a : kParallelAxes[axisOfFace(f)]) {
        const Crossing& c = kCrossings[size_t(crossingIndex(f, a, g.face, g.orient))];
        uf.unite(uint32_t(slotIndex(h, a)), uint32_t(slotIndex(g.hex, c.axis)), c.sign < 0 ? 1u : 0u);
      }
    }
  std::vector<uint32_t> roots;
  for (HexId h : cx.hexes())
    for (int a = 0; a < 3; ++a) {
      const uint32_t i = uint32_t(slotIndex(h, a));
      uint32_t parity;
      const uint32_t r = uf.find(i, parity);
      if (signs) (*signs)[i] = parity ? -1 : 1;
      if (r == i) {
        sheetOf[i] = int32_t(roots.size());
        roots.push_back(r);
      } else {
        sheetOf[i] = sheetOf[r];
      }
    }
  std::vector<SheetStats> stats(roots.size());
  SheetFlooder flooder;
  flooder.reserve(size_t(cx.hexCapacity()));
  if (extras) flooder.edgeMarks = &extras->edgeMarks;
  for (HexId h : cx.hexes())
    for (int a = 0; a < 3; ++a) flooder.measure(cx, h, a, stats[size_t(sheetOf[slotIndex(h, a)])]);
  d.sheets.resize(stats.size());
  d.labelSheet.resize(stats.size());
  for (size_t s = 0; s < stats.size(); ++s) {
    d.labelSheet[s] = int32_t(s);
    d.sheets[s].id = int32_t(s);
    stats[s].orientable = !uf.twisted(roots[s]);
    stats[s].classify(d.sheets[s]);
    d.sheets[s].slots.reserve(size_t(stats[s].slots));
  }
}

// Open chords walked once, forward from the boundary end met first; closed ones after. Ids are
// then renumbered in the order of each chord's smallest slot, and each open chord listed from the
// end its smallest slot's low face leads to (as a walk from that slot would list it).
std::vector<int32_t> extractChords(const Complex& cx, Dual& d) {
  int32_t* chordOf = d.chordOf.empty() ? nullptr : d.chordOf[0].data();
  std::vector<ChordWalk> walks;
  Chord scratch;  // walked into one reused buffer, then copied to an exactly sized list (no regrowth per chord)
  for (HexId h : cx.hexes())
    for (int f = 0; f < 6; ++f) {
      if (!cx.isBoundary({h, f}) || chordOf[slotIndex(h, axisOfFace(f))] >= 0) continue;
      scratch.id = int32_t(d.chords.size());
      scratch.slots.clear();
      walks.push_back(walkChordForward(cx, {h, axisOfFace(f)}, oppositeFace(f), scratch, chordOf));
      Chord ch;
      ch.id = scratch.id;
      if (walks.back().smallestEnteredLow)
        ch.slots.assign(scratch.slots.begin(), scratch.slots.end());
      else
        ch.slots.assign(scratch.slots.rbegin(), scratch.slots.rend());
      d.chords.push_back(std::move(ch));
    }
  for (HexId h : cx.hexes())
    for (int a = 0; a < 3; ++a)
      if (chordOf[slotIndex(h, a)] < 0) {
        Chord ch;
        ch.id = int32_t(d.chords.size());
        walkChord(cx, {h, a}, ch, chordOf);
        walks.push_back({slotIndex(h, a), true});
        d.chords.push_back(std::move(ch));
      }
  // Renumber by smallest slot.
  std::vector<int32_t> order(walks.size()), newId(walks.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = int32_t(i);
  std::sort(order.begin(), order.end(), [&](int32_t x, int32_t y) { return walks[size_t(x)].smallest < walks[size_t(y)].smallest; });
  std::vector<Chord> sorted(order.size());
  for (size_t r = 0; r < order.size(); ++r) {
    newId[size_t(order[r])] = int32_t(r);
    sorted[r] = std::move(d.chords[size_t(order[r])]);
    sorted[r].id = int32_t(r);
  }
  d.chords = std::move(sorted);
  return newId;
}

// Every chord one label, equal to its id (DualTracker cuts and joins them later).
void labelChordsById(Dual& d) {
  d.labelChord.resize(d.chords.size());
  std::iota(d.labelChord.begin(), d.labelChord.end(), 0);
}

}  // namespace

Dual extractDual(const Complex& cx, DualExtras* extras) {
  const size_t n = size_t(cx.hexCapacity());
  Dual d;
  d.sheetLabel.assign(n, {-1, -1, -1});
  d.chordOf.assign(n, {-1, -1, -1});
  if (extras) {
    extras->slotSigns.assign(3 * n, 0);
    extras->edgeMarks.assign(n, 0);
  }
  extractSheets(cx, d, extras);
  const std::vector<int32_t> newChordId = extractChords(cx, d);
  labelChordsById(d);
  if (extras) {  // the tracker's per-slot state, here where whole-mesh passes are compiled for speed
    extras->slotShares.assign(3 * n, 0);
    for (HexId h : cx.hexes())
      for (int a = 0; a < 3; ++a) extras->slotShares[slotIndex(h, a)] = slotShare(cx, h, a, extras->edgeMarks[size_t(h)]);
    extras->chordPlaces.assign(3 * n, 0);
    for (const Chord& ch : d.chords)
      for (size_t i = 0; i < ch.slots.size(); ++i) extras->chordPlaces[slotIndex(ch.slots[i].hex, ch.slots[i].axis)] = int32_t(i);
  }
  for (HexId h : cx.hexes()) {
    auto& c = d.chordOf[size_t(h)];
    for (int32_t& id : c) id = newChordId[size_t(id)];
    const auto& s = d.sheetLabel[size_t(h)];  // labels are ids here
    if (s[0] == s[1] || s[0] == s[2]) d.sheets[size_t(s[0])].selfIntersecting = true;
    if (s[1] == s[2]) d.sheets[size_t(s[1])].selfIntersecting = true;
    if (c[0] == c[1] || c[0] == c[2]) d.chords[size_t(c[0])].selfIntersecting = true;
    if (c[1] == c[2]) d.chords[size_t(c[1])].selfIntersecting = true;
    for (int a = 0; a < 3; ++a) d.sheets[size_t(s[size_t(a)])].slots.push_back({h, a});
  }
  return d;
}

}  // namespace hexdual

namespace hexdual {

void validateDual(const Complex& cx, const Dual& d) {
  auto fail = [](const std::string& m) { throw Error("validateDual: " + m); };
  auto slotName = [](Slot s) { return "slot (hex " + std::to_string(s.hex) + ", axis " + std::to_string(s.axis) + ")"; };
  if (d.sheetLabel.size() < size_t(cx.hexCapacity()) || d.chordOf.size() < size_t(cx.hexCapacity()))
    fail("per-hex arrays are shorter than the hex capacity");
  std::vector<uint8_t> seenSheet(size_t(3) * size_t(cx.hexCapacity()), 0), seenChord(seenSheet.size(), 0);
  auto mark = [&](std::vector<uint8_t>& seen, Slot s, const char* what, int id) {
    if (!cx.isHex(s.hex)) fail(std::string(what) + " " + std::to_string(id) + " lists dead hex " + std::to_string(s.hex));
    uint8_t& m = seen[size_t(3) * size_t(s.hex) + size_t(s.axis)];
    if (m) fail(slotName(s) + " is listed twice among " + what + "s");
    m = 1;
  };
  for (size_t i = 0; i < d.sheets.size(); ++i)
    for (Slot s : d.sheets[i].slots) {
      mark(seenSheet, s, "sheet", d.sheets[i].id);
      if (d.sheetAt(s.hex, s.axis) != d.sheets[i].id) fail(slotName(s) + " is in sheet " + std::to_string(d.sheets[i].id) + " but its label names another");
    }
  for (size_t i = 0; i < d.chords.size(); ++i) {
    const Chord& ch = d.chords[i];
    for (size_t k = 0; k < ch.slots.size(); ++k) {
      Slot s = ch.slots[k];
      mark(seenChord, s, "chord", ch.id);
      if (d.chordAt(s.hex, s.axis) != ch.id) fail(slotName(s) + " is in chord " + std::to_string(ch.id) + " but chordOf says otherwise");
      bool last = k + 1 == ch.slots.size();
      if (last && !ch.closed) continue;
      Slot next = ch.slots[last ? 0 : k + 1];
      Gluing a = cx.gluing(s.hex, 2 * s.axis), b = cx.gluing(s.hex, 2 * s.axis + 1);
      bool adjacent = (!a.boundary() && a.hex == next.hex && axisOfFace(a.face) == next.axis) ||
                      (!b.boundary() && b.hex == next.hex && axisOfFace(b.face) == next.axis);
      if (!adjacent) fail("chord " + std::to_string(ch.id) + ": " + slotName(s) + " is not glued to the next " + slotName(next));
    }
  }
  for (HexId h : cx.hexes())
    for (int a = 0; a < 3; ++a) {
      Slot s{h, a};
      if (!seenSheet[size_t(3) * size_t(h) + size_t(a)]) fail(slotName(s) + " is in no sheet");
      if (!seenChord[size_t(3) * size_t(h) + size_t(a)]) fail(slotName(s) + " is in no chord");
      for (int f = 0; f < 6; ++f) {
        Gluing g = cx.gluing(h, f);
        if (g.boundary()) continue;
        int a2 = mapAxisAcross(cx, h, f, a);
        if (axisOfFace(f) == a) {
          if (d.chordAt(h, a) != d.chordAt(g.hex, a2)) fail(slotName(s) + " and its neighbour across face " + std::to_string(f) + " are in different chords");
        } else if (d.sheetAt(h, a) != d.sheetAt(g.hex, a2)) {
          fail(slotName(s) + " and its neighbour across face " + std::to_string(f) + " are in different sheets");
        }
      }
    }
}

}  // namespace hexdual

#include <unordered_map>

namespace hexdual {

void compareDuals(const Complex& cx, const Dual& a, const Dual& b) {
  auto fail = [](const std::string& m) { throw Error("compareDuals: " + m); };
  std::unordered_map<int32_t, int32_t> sheetMap, chordMap, sheetBack, chordBack;
  auto link = [&](std::unordered_map<int32_t, int32_t>& fwd, std::unordered_map<int32_t, int32_t>& back, int32_t x,
                  int32_t y, const char* what, Slot s) {
    auto [it, ins] = fwd.try_emplace(x, y);
    auto [jt, jns] = back.try_emplace(y, x);
    if (it->second != y || jt->second != x)
      fail(std::string(what) + "s differ at slot (hex " + std::to_string(s.hex) + ", axis " + std::to_string(s.axis) + ")");
  };
  for (HexId h : cx.hexes())
    for (int ax = 0; ax < 3; ++ax) {
      link(sheetMap, sheetBack, a.sheetAt(h, ax), b.sheetAt(h, ax), "sheet", {h, ax});
      link(chordMap, chordBack, a.chordAt(h, ax), b.chordAt(h, ax), "chord", {h, ax});
    }
  size_t liveA = 0, liveB = 0;
  for (const Sheet& s : a.sheets) liveA += s.alive;
  for (const Sheet& s : b.sheets) liveB += s.alive;
  if (liveA != liveB || liveA != sheetMap.size()) fail("different numbers of sheets");
  for (auto [x, y] : sheetMap) {
    const Sheet &p = a.sheets[size_t(x)], &q = b.sheets[size_t(y)];
    if (p.slots.size() != q.slots.size() || p.euler != q.euler || p.boundaryLoops != q.boundaryLoops ||
        p.topology != q.topology || p.selfIntersecting != q.selfIntersecting || p.orientable != q.orientable)
      fail("sheet " + std::to_string(x) + " and sheet " + std::to_string(y) + " are classified differently (" +
           p.topology + " euler " + std::to_string(p.euler) + " vs " + q.topology + " euler " + std::to_string(q.euler) + ")");
  }
  liveA = liveB = 0;
  for (const Chord& c : a.chords) liveA += c.alive;
  for (const Chord& c : b.chords) liveB += c.alive;
  if (liveA != liveB || liveA != chordMap.size()) fail("different numbers of chords");
  for (auto [x, y] : chordMap) {
    const Chord &p = a.chords[size_t(x)], &q = b.chords[size_t(y)];
    if (p.slots.size() != q.slots.size() || p.closed != q.closed || p.selfIntersecting != q.selfIntersecting)
      fail("chord " + std::to_string(x) + " and chord " + std::to_string(y) + " are classified differently");
  }
}

}  // namespace hexdual
