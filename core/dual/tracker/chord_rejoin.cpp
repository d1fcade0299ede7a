// The local chord update (TK03 §3.2: an edit changes chords only through the edited hexes): the
// changed chords' untouched stretches keep their labels and places, walks through the touched
// hexes join the stretches' ends (a collapse joins two chords crosswise, TK03 §4.4), and touched
// slots no walk meets form chords of their own. Each new chord gets the id and slot order a
// re-walk from its smallest touched slot gives; only the touched slots are written.
// Owns nothing between updates but its scratch (per thread, like validateAround's: cleared at the
// start of each rejoin, so a warm step allocates only the new label runs and the report); refuses,
// writing nothing, when the state is not one it can follow.
#include <algorithm>
#include <numeric>
#include <utility>
#include <span>

#include "complex/id_map.hpp"
#include "dual/dual_tracker.hpp"
#include "dual/tracker/slots.hpp"

namespace hexdual {
using namespace tracker;

// One rejoin: the touched slots, the stretches, the walks joining them and the new chords, with
// the steps of rejoinChords below in the order they run. A step returning false gives up (nothing
// written yet: only commit writes).
struct DualTracker::ChordRejoin {
  // The touched slots, by slot (touched is sorted); a slot's old chord, run or own chord.
  struct Touched {
    Slot slot;
    int32_t old;
    bool live;
    int32_t run = -1, entry = -1;  // the walk that met it, and the face it entered through
    int32_t comp = -1;             // the new chord it lies in
  };
  // The untouched places of each old chord between touched ones.
  struct Stretch {
    int32_t chord, a, b;  // places a..b (b >= length wraps round a closed chord)
    Slot end[2];
    int face[2] = {-1, -1};      // the face each end leaves through, -1 at the chord's boundary end
    int32_t link[2] = {-1, -1};  // the walk from or to each end
  };
  // Walks through the touched slots from stretch ends: slots [begin, end) of walkSlots.
  struct Walk {
    int32_t begin, end;  // indices into walkSlots (which holds indices into ts), in walk order
    int32_t from, to;    // stretch ends (2 * stretch + side), -1 for the boundary
  };
  // The new chords: items in order, each a stretch or one touched slot.
  struct Item {
    int32_t stretch = -1, slot = -1;  // a stretch (listed a..b when forward), or one touched slot (ts index)
    bool forward = true;
  };
  struct Comp {
    int32_t begin = 0, end = 0;  // its items: [begin, end) of items
    bool closed = false;
    int32_t first = -1;  // its smallest touched slot (ts index)
  };
  // Every list a rejoin fills, kept between rejoins (one per thread).
  struct Scratch {
    std::vector<Touched> ts;
    std::vector<Stretch> stretches;
    std::vector<std::pair<int32_t, int32_t>> byOld;
    IdMap<int32_t> endIndex;
    std::vector<int32_t> lengths, liveOld, at, walkSlots;
    std::vector<uint8_t> contiguous, inChain, self, spliced, takenMark;
    std::vector<Walk> walks;
    std::vector<Item> items, right, left;
    std::vector<Comp> comps;
    std::vector<size_t> order;
    std::vector<int32_t> compId, taken, stretchPieceAt, splicedIds;
    std::vector<Piece> stretchPieces, pieces;
    std::vector<Slot> run;
    // Per hex id: its index in `touched`; per chord id: its index in `ids`; -1 for the others
    // (outside a rejoin every entry is -1: the destructor resets what the constructor set).
    // hexPos is as long as the complex: whole huge pages, grown with headroom (growHuge), so the
    // first rejoin and the complex's growth do not fault it in 4 KiB pages (2,000 faults at 100³).
    HugeVector<int32_t> hexPos;
    std::vector<int32_t> idPos;
    std::vector<int32_t> byOldEnd;  // per changed chord: where its range of byOld ends (cutStretches)
  };
  static Scratch& scratch() {
    thread_local Scratch s;
    return s;
  }

  DualTracker& tr;
  const Complex& cx;
  const std::vector<HexId>& touched;
  const std::vector<int32_t>& ids;  // the changed chords, ascending
  Scratch& sc = scratch();

  std::vector<Touched>& ts = sc.ts;
  std::vector<Stretch>& stretches = sc.stretches;
  // The touched slots of each changed chord, found once (a sheet operation changes thousands of
  // chords): (old chord, index into ts), by chord in ids order and by ts index within (cutStretches).
  std::vector<std::pair<int32_t, int32_t>>& byOld = sc.byOld;
  // The first stretch end (2 * stretch + side) at a slot leaving through a face, by endKey.
  IdMap<int32_t>& endIndex = sc.endIndex;
  // A slot's face along its axis is its low or high one: two keys per slot (int32 up to 357M hexes).
  static int32_t endKey(Slot t, int face) { return int32_t(slotIndex(t) * 2 + size_t(face & 1)); }
  std::vector<int32_t>&lengths = sc.lengths, &liveOld = sc.liveOld;  // per changed chord: its length, its live touched slots
  std::vector<uint8_t>& contiguous = sc.contiguous;  // per changed chord: touched in one run away from its ends
  std::vector<Walk>& walks = sc.walks;
  std::vector<int32_t>& walkSlots = sc.walkSlots;
  std::vector<Item>& items = sc.items;  // every comp's items, comp after comp
  std::vector<Comp>& comps = sc.comps;
  std::vector<size_t>& order = sc.order;  // comps by smallest touched slot
  std::vector<int32_t>& compId = sc.compId;
  // Old ids a new chord took: flags by chord id (cleared after the rejoin) and their list.
  std::vector<uint8_t>& takenMark = sc.takenMark;
  std::vector<int32_t>& taken = sc.taken;
  int32_t fresh = 0;
  std::vector<uint8_t>& self = sc.self;        // per comp: 0/1 self-intersecting, 2 left for the reader
  std::vector<uint8_t>& spliced = sc.spliced;  // per comp: what an in-place splice of one old chord gives

  std::span<Item> itemsOf(const Comp& c) { return {items.data() + c.begin, size_t(c.end - c.begin)}; }
  std::span<const Item> itemsOf(const Comp& c) const { return {items.data() + c.begin, size_t(c.end - c.begin)}; }
  bool isTaken(int32_t id) const { return size_t(id) < takenMark.size() && takenMark[size_t(id)]; }

  ChordRejoin(DualTracker& tracker, const Complex& c, const std::vector<HexId>& hexes,
              const std::vector<int32_t>& changed)
      : tr(tracker), cx(c), touched(hexes), ids(changed) {
    ts.clear();
    stretches.clear();
    byOld.clear();
    endIndex.clear();
    walks.clear();
    walkSlots.clear();
    items.clear();
    comps.clear();
    taken.clear();
    // Both arrays grown before either is marked (a failed allocation leaves no mark behind). The
    // touched hexes can lie beyond the complex's capacity: an undo's log names the hexes it took
    // away. touched and ids are ascending, without repeats.
    const size_t reach = std::max(size_t(cx.hexCapacity()), touched.empty() ? size_t(0) : size_t(touched.back()) + 1);
    growHuge(sc.hexPos, reach, -1);
    if (!ids.empty()) growHuge(sc.idPos, size_t(ids.back()) + 1, -1);
    for (size_t i = 0; i < touched.size(); ++i) sc.hexPos[size_t(touched[i])] = int32_t(i);
    for (size_t k = 0; k < ids.size(); ++k) sc.idPos[size_t(ids[k])] = int32_t(k);
  }
  ~ChordRejoin() {
    for (int32_t id : taken) takenMark[size_t(id)] = 0;
    for (HexId h : touched) sc.hexPos[size_t(h)] = -1;
    for (int32_t id : ids) sc.idPos[size_t(id)] = -1;
  }
  ChordRejoin(const ChordRejoin&) = delete;
  ChordRejoin& operator=(const ChordRejoin&) = delete;
  // Small helpers of the hot walks, defined here (inline).
  // The place of chord c in ids, or ids.size() when it is not one of them.
  size_t idIndex(int32_t c) const {
    const int32_t k = c >= 0 && size_t(c) < sc.idPos.size() ? sc.idPos[size_t(c)] : -1;
    return k < 0 ? ids.size() : size_t(k);
  }
  bool inIds(int32_t c) const { return idIndex(c) < ids.size(); }
  // The index in ts of touched slot s, or -1.
  int32_t indexOf(Slot s) const {
    const int32_t i = s.hex >= 0 && size_t(s.hex) < sc.hexPos.size() ? sc.hexPos[size_t(s.hex)] : -1;
    return i < 0 ? -1 : int32_t(3 * size_t(i) + size_t(s.axis));
  }
  // The one face of s's hex along its axis glued to slot t, else -1.
  int faceTo(Slot s, Slot t) const {
    int found = -1, count = 0;
    for (int f = 2 * s.axis; f < 2 * s.axis + 2; ++f) {
      Gluing g = cx.gluing(s.hex, f);
      if (!g.boundary() && Slot{g.hex, tables::axisOfFace(g.face)} == t) {
        found = f;
        ++count;
      }
    }
    return count == 1 ? found : -1;
  }
  void listTouched();
  bool cutStretches();
  bool cutStretchesOf(size_t k);
  bool addStretch(int32_t id, int32_t a, int32_t b, int32_t len, bool closed);
  // The stretch end (2 * stretch + side) at slot s leaving through face, else -1.
  int32_t endAt(Slot s, int face) const {
    return endIndex.get(endKey(s, face), -1);
  }
  bool walkFromStretchEnds();
  bool walkFrom(size_t r, int side);
  void walkItems(int32_t w, bool forward, std::vector<Item>& out) const;
  bool chainStretches();
  bool chainFrom(size_t r0);
  bool walkLoneChords();
  bool walkLoneChord(size_t k);
  bool listAsRewalk();
  void chooseIds();
  void markSelfIntersections();
  bool splice(size_t ci) const;
  void findSplices();
  void commit(DualChange& change);
  void piecesOf(const Comp& c);
};

bool DualTracker::rejoinChords(const Complex& cx, const std::vector<HexId>& touched, const std::vector<int32_t>& ids,
                               DualChange& change) {
  ChordRejoin rj(*this, cx, touched, ids);
  rj.listTouched();
  if (!rj.cutStretches() || !rj.walkFromStretchEnds() || !rj.chainStretches() || !rj.walkLoneChords() ||
      !rj.listAsRewalk())
    return false;
  rj.chooseIds();
  rj.markSelfIntersections();
  rj.findSplices();
  rj.commit(change);
  return true;
}

// ---- the touched slots, by slot (touched is sorted) ----

void DualTracker::ChordRejoin::listTouched() {
  ts.reserve(3 * touched.size());
  for (HexId h : touched)
    for (int a = 0; a < 3; ++a) ts.push_back({{h, a}, tr.dual_.chordAt(h, a), cx.isHex(h)});
}

// ---- stretches: the untouched places of each old chord between touched ones ----

bool DualTracker::ChordRejoin::cutStretches() {
  lengths.assign(ids.size(), 0);
  liveOld.assign(ids.size(), 0);
  contiguous.assign(ids.size(), 0);
  // byOld by counting: each changed chord's touched slots in ts order (as sorting the pairs gave);
  // afterwards byOldEnd[k] is where chord ids[k]'s range ends (and ids[k + 1]'s begins).
  std::vector<int32_t>& end = sc.byOldEnd;
  end.assign(ids.size(), 0);
  for (const Touched& t : ts)
    if (const size_t k = idIndex(t.old); k < ids.size()) ++end[k];
  int32_t total = 0;
  for (int32_t& e : end) total += std::exchange(e, total);  // each range's start
  byOld.resize(size_t(total));
  for (size_t i = 0; i < ts.size(); ++i)
    if (const size_t k = idIndex(ts[i].old); k < ids.size()) byOld[size_t(end[k]++)] = {ts[i].old, int32_t(i)};
  for (size_t k = 0; k < ids.size(); ++k)
    if (!cutStretchesOf(k)) return false;
  tr.slotsTouched_ += 2 * stretches.size();
  for (size_t r = 0; r < stretches.size(); ++r)
    for (int side = 0; side < 2; ++side)
      if (stretches[r].face[side] >= 0)
        endIndex.emplace(endKey(stretches[r].end[side], stretches[r].face[side]), int32_t(2 * r + size_t(side)));
  return true;
}

// The stretch a..b of chord id, with the faces its ends leave through to the touched places beside them.
bool DualTracker::ChordRejoin::addStretch(int32_t id, int32_t a, int32_t b, int32_t len, bool closed) {
  Stretch st{id, a, b, {tr.chordSlotAt(id, a % len), tr.chordSlotAt(id, b % len)}};
  for (int side = 0; side < 2; ++side) {
    if (!closed && (side == 0 ? a == 0 : b == len - 1)) continue;  // the chord's boundary end
    const Slot n = tr.chordSlotAt(id, side == 0 ? (a - 1 + len) % len : (b + 1) % len);
    st.face[side] = faceTo(st.end[side], n);
    if (st.face[side] < 0) return false;
  }
  stretches.push_back(st);
  return true;
}

bool DualTracker::ChordRejoin::cutStretchesOf(size_t k) {
  const int32_t id = ids[k], len = tr.chordLength(id);
  const bool closed = tr.dual_.chords[size_t(id)].closed;
  lengths[k] = len;
  std::vector<int32_t>& at = sc.at;
  at.clear();
  for (int32_t q = k ? sc.byOldEnd[k - 1] : 0; q < sc.byOldEnd[k]; ++q) {
    const Touched& t = ts[size_t(byOld[size_t(q)].second)];
    const int32_t p = tr.placeInChord(id, t.slot);
    if (p < 0) return false;
    at.push_back(p);
    liveOld[k] += t.live;
  }
  if (at.empty()) return false;
  std::sort(at.begin(), at.end());
  contiguous[k] = !closed && at.front() > 0 && at.back() + 1 < len && at.back() - at.front() + 1 == int32_t(at.size());
  bool ok = true;
  if (!closed) {
    if (at.front() > 0) ok = ok && addStretch(id, 0, at.front() - 1, len, closed);
    if (at.back() + 1 < len) ok = ok && addStretch(id, at.back() + 1, len - 1, len, closed);
  }
  for (size_t j = 0; ok && j < at.size(); ++j) {
    if (j + 1 == at.size() && !closed) break;
    const int32_t next = j + 1 < at.size() ? at[j + 1] : at[0] + len;
    if (next > at[j] + 1) ok = addStretch(id, at[j] + 1, next - 1, len, closed);
  }
  return ok;
}

// ---- walks through the touched slots from every stretch end ----

bool DualTracker::ChordRejoin::walkFromStretchEnds() {
  for (size_t r = 0; r < stretches.size(); ++r)
    for (int side = 0; side < 2; ++side) {
      if (stretches[r].face[side] < 0 || stretches[r].link[side] >= 0) continue;
      if (!walkFrom(r, side)) return false;
    }
  return true;
}

// Walks from an end of stretch r through touched slots to the boundary or another stretch end.
bool DualTracker::ChordRejoin::walkFrom(size_t r, int side) {
  const int32_t w = int32_t(walks.size());
  const int32_t begin = int32_t(walkSlots.size());
  walks.push_back({begin, begin, int32_t(2 * r + size_t(side)), -1});
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
    if (!t.live || t.run >= 0 || (t.old >= 0 && !inIds(t.old)) || walkSlots.size() - size_t(begin) >= ts.size())
      return false;
    t.run = w;
    t.entry = g.face;
    walkSlots.push_back(k);
    walks[size_t(w)].end = int32_t(walkSlots.size());
    cur = n;
    exit = tables::oppositeFace(g.face);
  }
  tr.slotsTouched_ += size_t(walks[size_t(w)].end - begin);
  return true;
}

// ---- new chords: chains of stretches and walks, and chords of touched slots alone ----

void DualTracker::ChordRejoin::walkItems(int32_t w, bool forward, std::vector<Item>& out) const {
  const Walk& wk = walks[size_t(w)];
  if (forward)
    for (int32_t i = wk.begin; i < wk.end; ++i) out.push_back({-1, walkSlots[size_t(i)], true});
  else
    for (int32_t i = wk.end; i-- > wk.begin;) out.push_back({-1, walkSlots[size_t(i)], false});
}

bool DualTracker::ChordRejoin::chainStretches() {
  sc.inChain.assign(stretches.size(), 0);
  for (size_t r0 = 0; r0 < stretches.size(); ++r0) {
    if (sc.inChain[r0]) continue;
    if (!chainFrom(r0)) return false;
  }
  return true;
}

// The chain through stretch r0: rightwards from side 1, then leftwards from side 0 (listed reversed).
bool DualTracker::ChordRejoin::chainFrom(size_t r0) {
  std::vector<uint8_t>& inChain = sc.inChain;
  inChain[r0] = 1;
  Comp c;
  std::vector<Item>&right = sc.right, &left = sc.left;
  right.clear();
  left.clear();
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
    const size_t from = left.size();
    walkItems(w, fwd, left);
    for (size_t i = from; i < left.size(); ++i) left[i].forward = !left[i].forward;  // listed right to left
    const int32_t other = fwd ? walks[size_t(w)].to : walks[size_t(w)].from;
    if (other < 0) break;
    if (inChain[size_t(other / 2)]) return false;
    inChain[size_t(other / 2)] = 1;
    left.push_back({other / 2, -1, other % 2 == 1});
    end = other ^ 1;
  }
  c.begin = int32_t(items.size());
  items.insert(items.end(), left.rbegin(), left.rend());
  items.push_back({int32_t(r0), -1, true});
  items.insert(items.end(), right.begin(), right.end());
  c.end = int32_t(items.size());
  comps.push_back(c);
  return true;
}

// Touched slots no walk met (old chords rebuilt here, or new slots) form chords of their own.
bool DualTracker::ChordRejoin::walkLoneChords() {
  for (size_t k = 0; k < ts.size(); ++k) {
    const Touched& t0 = ts[k];
    if (!t0.live || t0.run >= 0 || t0.comp >= 0 || (t0.old >= 0 && !inIds(t0.old))) continue;
    if (!walkLoneChord(k)) return false;
  }
  return true;
}

// The chord of touched slot k, walked as walkChord would from the smallest: back through its low
// face to an end (or once round), then forward; every slot on it must be touched.
bool DualTracker::ChordRejoin::walkLoneChord(size_t k) {
  const Slot start = ts[k].slot;
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
  c.begin = int32_t(items.size());
  int exit = closed ? 2 * start.axis + 1 : tables::oppositeFace(back);
  const int32_t ci = int32_t(comps.size());
  bool returned = false;
  for (;;) {
    const int32_t i = indexOf(cur);
    Touched& t = ts[size_t(i)];
    if (!t.live || t.run >= 0 || t.comp >= 0 || (t.old >= 0 && !inIds(t.old))) return false;
    t.comp = ci;
    items.push_back({-1, i, true});
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
  c.end = int32_t(items.size());
  tr.slotsTouched_ += size_t(c.end - c.begin);
  comps.push_back(c);
  return true;
}

// Each chain is listed as a re-walk from its smallest touched slot lists it: from the end its low
// face leads to, or (closed) starting there and leaving through its high face.
bool DualTracker::ChordRejoin::listAsRewalk() {
  for (size_t ci = 0; ci < comps.size(); ++ci) {
    Comp& c = comps[ci];
    if (c.first >= 0) continue;  // a chord of touched slots alone: walked in order
    const std::span<Item> cs = itemsOf(c);
    size_t at = cs.size();
    for (size_t i = 0; i < cs.size(); ++i)
      if (cs[i].slot >= 0 && (at == cs.size() || cs[i].slot < cs[at].slot)) at = i;
    if (at == cs.size()) return false;
    for (const Item& it : cs)
      if (it.slot >= 0) ts[size_t(it.slot)].comp = int32_t(ci);
    // The slot before it in this listing is across its low face when the listing runs along the
    // walk that met it and it entered through its low face, or against it and through the high one.
    const Touched& t = ts[size_t(cs[at].slot)];
    const bool lowBefore = ((t.entry & 1) == 0) == cs[at].forward;
    if (!lowBefore) {
      std::reverse(cs.begin(), cs.end());
      for (Item& it : cs) it.forward = !it.forward;
      at = cs.size() - 1 - at;
    }
    if (c.closed) std::rotate(cs.begin(), cs.begin() + std::ptrdiff_t(at), cs.end());
    c.first = cs[c.closed ? 0 : at].slot;
  }
  return true;
}

// ---- ids: in the order of each new chord's smallest touched slot, the smallest old id it holds
// that no earlier one took, else a fresh one (relabel's rule) ----
void DualTracker::ChordRejoin::chooseIds() {
  order.resize(comps.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::sort(order.begin(), order.end(), [&](size_t x, size_t y) { return comps[x].first < comps[y].first; });
  auto oldOf = [&](const Item& it) {
    return it.stretch >= 0 ? stretches[size_t(it.stretch)].chord : ts[size_t(it.slot)].old;
  };
  compId.assign(comps.size(), -1);
  fresh = int32_t(tr.dual_.chords.size());
  for (size_t ci : order) {
    int32_t best = -1;
    for (const Item& it : itemsOf(comps[ci])) {
      const int32_t o = oldOf(it);
      if (o >= 0 && (best < 0 || o < best) && !isTaken(o)) best = o;
    }
    if (best >= 0) {
      if (takenMark.size() <= size_t(best)) takenMark.resize(std::max(size_t(best) + 1, tr.dual_.chords.size()), 0);
      takenMark[size_t(best)] = 1;
      taken.push_back(best);
    }
    compId[ci] = best >= 0 ? best : fresh++;
  }
}

// ---- self-intersection: a touched hex with two slots in one new chord; untouched hexes only
// matter when a chord joins stretches of several old chords (or of one that self-intersected):
// then it is left for the reader (settleChords) ----
void DualTracker::ChordRejoin::markSelfIntersections() {
  self.assign(comps.size(), 0);
  for (size_t i = 0; i + 2 < ts.size(); i += 3)
    for (size_t a = 0; a < 3; ++a)
      for (size_t b = a + 1; b < 3; ++b)
        if (ts[i + a].comp >= 0 && ts[i + a].comp == ts[i + b].comp) self[size_t(ts[i + a].comp)] = 1;
  for (size_t ci = 0; ci < comps.size(); ++ci) {
    int32_t one = -1;
    bool several = false;
    for (const Item& it : itemsOf(comps[ci]))
      if (it.stretch >= 0) {
        const int32_t o = stretches[size_t(it.stretch)].chord;
        several = several || (one >= 0 && o != one);
        one = o;
      }
    if (!self[ci] && (several || (one >= 0 && tr.chordSelf_[size_t(one)] != 0))) self[ci] = 2;
  }
}

// ---- which of them an in-place splice of one old chord would have given (listed first among the
// changed, as before) ----
bool DualTracker::ChordRejoin::splice(size_t ci) const {
  const Comp& c = comps[ci];
  const int32_t id = compId[ci];
  const size_t k = idIndex(id);
  const std::span<const Item> cs = itemsOf(c);
  if (c.closed || k == ids.size() || !contiguous[k] || cs.size() < 3) return false;
  const Item &head = cs.front(), &tail = cs.back();
  if (head.stretch < 0 || tail.stretch < 0 || !head.forward || !tail.forward ||
      stretches[size_t(head.stretch)].chord != id || stretches[size_t(head.stretch)].a != 0 ||
      stretches[size_t(tail.stretch)].chord != id || stretches[size_t(tail.stretch)].b != lengths[k] - 1)
    return false;
  int32_t kept = 0;
  for (size_t i = 1; i + 1 < cs.size(); ++i) {
    const Item& it = cs[i];
    if (it.slot < 0 || (ts[size_t(it.slot)].old != id && ts[size_t(it.slot)].old != -1)) return false;
    kept += ts[size_t(it.slot)].old == id;
  }
  if (kept != liveOld[k] || cs.size() - 2 >= 3 * touched.size()) return false;
  return tr.chordSelf_[size_t(id)] == 0 || (tr.chordSelf_[size_t(id)] == 2 && !tr.chordSelfIntersects(id));
}

void DualTracker::ChordRejoin::findSplices() {
  spliced.assign(comps.size(), 0);
  for (size_t ci = 0; ci < comps.size(); ++ci) spliced[ci] = splice(ci);
}

// ---- commit: stretches keep their pieces, consecutive touched slots get new labels ----

// A new chord's pieces (into sc.pieces): its stretches' pieces (reversed when listed backwards),
// and a new label for every run of consecutive touched slots.
void DualTracker::ChordRejoin::piecesOf(const Comp& c) {
  std::vector<Piece>& pieces = sc.pieces;
  pieces.clear();
  std::vector<Slot>& run = sc.run;
  run.clear();
  auto flush = [&] {
    if (run.empty()) return;
    const int32_t len = int32_t(run.size());
    tr.slotsTouched_ += run.size();
    pieces.push_back({tr.newChordLabel(run), 0, len, false});
    run.clear();
  };
  for (const Item& it : itemsOf(c)) {
    if (it.slot >= 0) {
      run.push_back(ts[size_t(it.slot)].slot);
      continue;
    }
    flush();
    const Piece* b = sc.stretchPieces.data() + sc.stretchPieceAt[size_t(it.stretch)];
    const Piece* e = sc.stretchPieces.data() + sc.stretchPieceAt[size_t(it.stretch) + 1];
    if (it.forward) {
      pieces.insert(pieces.end(), b, e);
    } else {
      for (const Piece* p = e; p-- > b;) pieces.push_back({p->label, p->lo, p->hi, !p->reversed});
    }
  }
  flush();
}

void DualTracker::ChordRejoin::commit(DualChange& change) {
  Dual& d = tr.dual_;
  // Each stretch's pieces: [stretchPieceAt[r], stretchPieceAt[r + 1]) of stretchPieces.
  sc.stretchPieces.clear();
  sc.stretchPieceAt.assign(1, 0);
  for (size_t r = 0; r < stretches.size(); ++r) {
    const Stretch& st = stretches[r];
    const int32_t len = lengths[idIndex(st.chord)];
    tr.sliceChord(st.chord, st.a, std::min(st.b, len - 1), sc.stretchPieces);
    if (st.b >= len) tr.sliceChord(st.chord, 0, st.b - len, sc.stretchPieces);
    sc.stretchPieceAt.push_back(int32_t(sc.stretchPieces.size()));
  }
  tr.dropPieces(ids);
  for (const Touched& t : ts)
    if (!t.live) d.chordLabel[size_t(t.slot.hex)][size_t(t.slot.axis)] = -1;
  tr.growChordIds(size_t(fresh));
  std::vector<int32_t>& splicedIds = sc.splicedIds;
  splicedIds.clear();
  for (size_t ci : order) {
    piecesOf(comps[ci]);
    const int32_t id = compId[ci];
    Chord& ch = d.chords[size_t(id)];
    ch.id = id;
    ch.alive = true;
    ch.closed = comps[ci].closed;
    tr.chordSelf_[size_t(id)] = self[ci];
    if (self[ci] != 2) ch.selfIntersecting = self[ci] != 0;
    tr.setChordPieces(id, sc.pieces);
    if (!inIds(id))
      report(change.chordsCreated, id);
    else if (spliced[ci])
      splicedIds.push_back(id);
    else
      report(change.chordsChanged, id);
  }
  std::sort(splicedIds.begin(), splicedIds.end());
  change.chordsChanged.insert(change.chordsChanged.begin(), splicedIds.begin(), splicedIds.end());
  for (int32_t id : ids)
    if (!isTaken(id)) {
      Chord& ch = d.chords[size_t(id)];
      ch.alive = false;
      ch.slots.clear();
      tr.chordSelf_[size_t(id)] = 0;
      report(change.chordsRemoved, id);
    }
  tr.releaseLabels();
}

}  // namespace hexdual
