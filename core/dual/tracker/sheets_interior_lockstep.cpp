// Sheet update for an edit that may cut, merge or re-shape sheets, on orientable sheets: the
// lockstep flood (TK03 §4.4: a collapse cuts and re-glues sheets in one place). update() runs it
// for every operation that does not keep sheet topology (and for a merge the topology-kept update
// refused); it refuses, changing nothing, on a non-orientable sheet, or when the edit is not one it
// can follow, and the reflood runs instead. Near the boundary an edit can re-join a sheet's
// boundary loops, which a remainder cannot count without walking them: the groups that meet a
// sheet the edit touched near the boundary (or hold a new slot there) never pause, so they become
// pieces, flooded and measured whole; the other sheets (e.g. the sheets a column collapse crosses,
// which each lose a quad in their interior) still settle where the edit left them.
// Owns nothing between updates; marks front_ while it runs (cleared before it returns).
#include <algorithm>

#include "dual/dual_tracker.hpp"
#include "dual/tracker/slots.hpp"

namespace hexdual {
using namespace tracker;

// One lockstep update: its exploration (fronts, groups), its plan (pieces, remainders, their
// orientations and ids) and the steps that commit it. Steps run in the order of
// updateSheetsLockstep below; each reads what the earlier ones left in these fields.
struct DualTracker::Lockstep {
  DualTracker& t;
  const Complex& cx;
  const std::vector<HexId>& touched;
  const std::vector<int32_t> old;  // the old sheets through the touched hexes, ascending

  Lockstep(DualTracker& tracker, const Complex& c, const std::vector<HexId>& hexes)
      : t(tracker), cx(c), touched(hexes), old(sheetIdsThrough(tracker.dual_, hexes)) {}
  int32_t label(Slot s) const { return t.dual_.sheetAt(s.hex, s.axis); }  // the slot's sheet id
  size_t oldIndex(int32_t id) const { return size_t(std::lower_bound(old.begin(), old.end(), id) - old.begin()); }

  // ---- explore: fronts grouped as they meet ----
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
  size_t unfinished = 0;
  bool foreign = false;  // reached a sheet not through the touched hexes: an edit not logged whole
  std::vector<uint8_t> paused;
  std::vector<uint8_t> nearOld;  // per old sheet: a slot of it in a touched hex near the boundary, before or after
  std::vector<uint8_t> nearNew;  // per front: its group holds a new slot of a touched hex near the boundary
  std::vector<int32_t> owner, sharers;  // per old sheet: the unfinished group meeting it, and how many do

  bool applies() const;
  void markNearBoundary();
  void startFronts();
  void floodUntilSettled();
  // The flood's hot steps, defined here (inline): a group's root; front f reaches slot s.
  int32_t find(int32_t x) {
    while (parent[size_t(x)] != x) x = parent[size_t(x)] = parent[size_t(parent[size_t(x)])];
    return x;
  }
  void reach(Slot s, int32_t f) {
    t.front_[slotIndex(s)] = f + 1;
    reached.push_back({s, label(s), f});
    queue[size_t(f)].push_back(s);
    const int32_t id = label(s);
    if (id >= 0 && !std::binary_search(old.begin(), old.end(), id)) foreign = true;  // an edit not logged whole
    auto& m = meets[size_t(find(f))];
    if (id >= 0 && std::find(m.begin(), m.end(), id) == m.end()) m.push_back(id);
  }
  void unite(int32_t a, int32_t b);
  void advance(size_t f);
  bool settled();
  void clearFronts();

  // ---- plan: pieces (finished groups), remainders (unfinished ones), orientations, ids ----
  std::vector<int64_t> remainder, loopsTaken;  // per old sheet: slots left in its remainder, loops pieces took
  std::vector<std::vector<Slot>> pieces;
  std::vector<std::vector<int32_t>> pieceLabels;
  std::vector<Slot> newInRest;  // new slots of unfinished groups
  std::vector<int32_t> up;      // orientation union-find over old sheets and new slots in remainders
  std::vector<uint8_t> par;
  std::vector<int32_t> keepOf;  // per group: the old sheet whose id its remainder keeps
  std::vector<uint8_t> flipOf;  // per old sheet and new slot: flipped relative to its kept sheet
  std::vector<int32_t> pieceId;
  std::vector<uint8_t> taken;  // per old sheet: a piece kept its id
  int32_t fresh = 0;

  bool splitPiecesFromRemainders();
  int32_t root(int32_t x, int& p) const;
  int32_t orientationVar(Slot s, int& sg) const;
  bool orientRemainders();
  void keepLargestOldSheet();
  bool flipsRelativeToKept();
  void numberPieces();
  void recordForUndo();

  // ---- commit ----
  std::vector<int32_t> affected, merged;
  std::vector<HexId> recount;              // hexes whose slots change labels: their pairs are counted again
  std::vector<std::vector<Slot>> leaving;  // per old sheet: slots leaving its list (dead, or in a piece)

  void uncountRelabelledHexes();
  void moveShares();
  void move(Slot s, int32_t toLabel);
  void dropDeadSlots();
  void labelPiece(size_t p, DualChange& change);
  bool orientPiece(const std::vector<Slot>& piece);
  void shrinkRemainders();
  void mergeIntoKept(DualChange& change);
  void joinNewSlots(DualChange& change);
  void retireSheetsLeft(DualChange& change);
  void finishSheets();
};

// The sheets through the touched hexes after an edit. Every touched slot starts a front; fronts that
// meet join one group; a group whose fronts all run dry is a whole new sheet (a piece). The flood
// stops once every old sheet meets at most one unfinished group: that group is the rest of those old
// sheets (a remainder), which keeps the id of its largest old sheet and takes the others by
// re-pointing their labels. Returns false, changing nothing, when the edit is not one it can follow.
bool DualTracker::updateSheetsLockstep(const Complex& cx, const std::vector<HexId>& touched, DualChange& change) {
  Lockstep ls(*this, cx, touched);
  if (!ls.applies()) return false;
  ls.startFronts();
  ls.markNearBoundary();
  ls.floodUntilSettled();
  if (ls.foreign || !ls.splitPiecesFromRemainders() || !ls.orientRemainders()) {
    ls.clearFronts();
    return false;
  }
  ls.keepLargestOldSheet();
  if (!ls.flipsRelativeToKept()) {
    ls.clearFronts();
    return false;
  }
  ls.numberPieces();
  if (recordUnmerge_) ls.recordForUndo();
  ls.uncountRelabelledHexes();
  ls.moveShares();
  ls.dropDeadSlots();
  for (size_t p = 0; p < ls.pieces.size(); ++p) ls.labelPiece(p, change);
  ls.shrinkRemainders();
  ls.mergeIntoKept(change);
  ls.joinNewSlots(change);
  ls.retireSheetsLeft(change);
  ls.finishSheets();
  sheetSlotsTouched_ += ls.reached.size();
  ls.clearFronts();
  return true;
}

// ---- explore ----

// Orientable sheets: the orientations it reads are exact there.
bool DualTracker::Lockstep::applies() const {
  for (int32_t id : old)
    if (!t.dual_.sheets[size_t(id)].orientable) return false;
  return true;
}

// A sheet's boundary loops run through its slots' boundary sides and boundary edges (the sheet
// crossing an edge has a slot in every hex round it), so the edit can re-join them only at an
// edge whose cycle it changed (the faces glued or unglued are the faces through such edges) and
// that reaches the boundary before or after it: in a removed hex, an axis with an edge near the
// boundary before (the edge marks still hold it); in a live touched hex, an axis with a changed
// edge, near the boundary before or now. Those slots' old sheets, and the fronts of such new
// slots, are marked: their groups are flooded until finished.
void DualTracker::Lockstep::markNearBoundary() {
  nearOld.assign(old.size(), 0);
  nearNew.assign(parent.size(), 0);
  const bool known = t.edgesToWalk_.size() == touched.size();
  size_t f = 0;  // fronts were started per live touched slot, in this order
  for (size_t i = 0; i < touched.size(); ++i) {
    const HexId h = touched[i];
    const uint16_t before = t.edgeMarks_[size_t(h)];
    const bool live = cx.isHex(h);
    for (int a = 0; a < 3; ++a, f += live) {
      const unsigned changed = live ? ((known ? t.edgesToWalk_[i] : 0xFFFu) >> (4 * a)) & 0xFu : 0xFu;
      if (!changed || !((before & kEdgeAxisNearBoundary(a)) || (live && edgesNear(cx, h, changed << (4 * a)))))
        continue;
      const int32_t id = label({h, a});
      if (id >= 0)
        nearOld[oldIndex(id)] = 1;
      else if (live)
        nearNew[f] = 1;
    }
  }
}

void DualTracker::Lockstep::unite(int32_t a, int32_t b) {
  a = find(a);
  b = find(b);
  if (a == b) return;
  if (b < a) std::swap(a, b);
  if (active[size_t(a)] && active[size_t(b)]) --unfinished;
  parent[size_t(b)] = a;
  nearNew[size_t(a)] |= nearNew[size_t(b)];
  if (size_t(a) < paused.size()) paused[size_t(a)] = 0;
  active[size_t(a)] += active[size_t(b)];
  for (int32_t id : meets[size_t(b)])
    if (std::find(meets[size_t(a)].begin(), meets[size_t(a)].end(), id) == meets[size_t(a)].end())
      meets[size_t(a)].push_back(id);
}

// One front per live touched slot, each its own group.
void DualTracker::Lockstep::startFronts() {
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
  owner.assign(old.size(), -1);
  sharers.assign(old.size(), 0);
  paused.assign(parent.size(), 0);
}

// Front f takes one slot from its queue and reaches its sheet neighbours, joining the fronts it meets.
void DualTracker::Lockstep::advance(size_t f) {
  if (head[f] == queue[f].size() || paused[size_t(find(int32_t(f)))]) return;
  const Slot cur = queue[f][head[f]++];
  for (int face : kParallelFaces[size_t(cur.axis)]) {
    Slot n;
    int flip;
    if (!sheetNeighbour(cx, cur, face, n, flip)) continue;
    const int32_t m = t.front_[slotIndex(n)];
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

// Every front advances one slot per round until all groups are finished or settled (or the flood
// reaches a foreign sheet).
void DualTracker::Lockstep::floodUntilSettled() {
  while (unfinished > 0 && !foreign) {
    for (size_t f = 0; f < queue.size(); ++f) advance(f);
    if (foreign || settled()) break;
  }
}

// A group pauses when every old sheet it has met meets no other unfinished group: it then is the
// rest of those sheets (a group joined to it later resumes it). Settled when all have paused. A
// group marked near the boundary (markNearBoundary) never pauses: it runs until it is a piece.
bool DualTracker::Lockstep::settled() {
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
    bool alone = !meets[f].empty() && !nearNew[f];
    for (int32_t id : meets[f]) alone = alone && sharers[oldIndex(id)] == 1 && !nearOld[oldIndex(id)];
    paused[f] = alone;
    all = all && alone;
  }
  return all;
}

void DualTracker::Lockstep::clearFronts() {
  for (const Reached& r : reached) t.front_[slotIndex(r.slot)] = 0;
}

// ---- plan ----

// Finished groups become pieces; what the old sheets keep outside them (less dead slots) is counted.
// False when an old sheet's remainder and owner disagree (cannot happen on a valid complex; be safe).
bool DualTracker::Lockstep::splitPiecesFromRemainders() {
  remainder.assign(old.size(), 0);
  loopsTaken.assign(old.size(), 0);
  for (size_t k = 0; k < old.size(); ++k) remainder[k] = int64_t(t.dual_.sheets[size_t(old[k])].slots.size());
  for (HexId h : touched)
    if (!cx.isHex(h))
      for (int32_t id : t.dual_.sheetsAt(h))
        if (id >= 0) --remainder[oldIndex(id)];
  std::vector<int32_t> pieceOf(parent.size(), -1);
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
    if ((owner[k] < 0) != (remainder[k] == 0) || sharers[k] > 1) return false;
  return true;
}

// The root of x in the orientation union-find, and x's parity relative to it.
int32_t DualTracker::Lockstep::root(int32_t x, int& p) const {
  p = 0;
  while (up[size_t(x)] != x) {
    p ^= par[size_t(x)];
    x = up[size_t(x)];
  }
  return x;
}

// The variable of a slot's orientation (its old sheet, or itself when new in a remainder; -1
// otherwise) and its stored sign (new slots: +1 until solved).
int32_t DualTracker::Lockstep::orientationVar(Slot s, int& sg) const {
  const int32_t id = label(s);
  if (id >= 0) {
    sg = t.signOf(s);
    return int32_t(oldIndex(id));
  }
  sg = 1;
  auto it = std::lower_bound(newInRest.begin(), newInRest.end(), s);
  return it != newInRest.end() && *it == s ? int32_t(old.size() + size_t(it - newInRest.begin())) : -1;
}

// Orientations of the remainders: each re-glued quad ties the orientation of the old sheets (or
// new slots) on its two sides; a contradiction is a twist, or a sheet re-glued to itself flipped:
// false (re-flood). Old sheets merged into a kept one are flipped as they are re-labelled.
bool DualTracker::Lockstep::orientRemainders() {
  std::sort(newInRest.begin(), newInRest.end());
  up.resize(old.size() + newInRest.size());
  par.assign(up.size(), 0);
  for (size_t v = 0; v < up.size(); ++v) up[v] = int32_t(v);
  for (const Reached& r : reached) {
    if (!active[size_t(find(r.front))] ||
        !(r.label < 0 || std::binary_search(touched.begin(), touched.end(), r.slot.hex)))
      continue;
    int ss = 0, ps = 0;
    const int32_t vs = orientationVar(r.slot, ss);
    for (int face : kParallelFaces[size_t(r.slot.axis)]) {
      Slot n;
      int flip, sn = 0, pn = 0;
      if (!sheetNeighbour(cx, r.slot, face, n, flip)) continue;
      const int32_t vn = orientationVar(n, sn);
      if (vs < 0 || vn < 0 || !ss || !sn) return false;
      const int need = sn != ss * flip;
      const int32_t rs = root(vs, ps), rn = root(vn, pn);
      if (rs == rn) {
        if ((ps ^ pn) != need) return false;
      } else {
        up[size_t(rn)] = rs;
        par[size_t(rn)] = uint8_t(ps ^ pn ^ need);
      }
    }
  }
  return true;
}

// The rest of each unfinished group keeps the id of its old sheet with most slots left.
void DualTracker::Lockstep::keepLargestOldSheet() {
  keepOf.assign(parent.size(), -1);
  for (size_t k = 0; k < old.size(); ++k) {
    const int32_t g = owner[k];
    if (g < 0) continue;
    const int32_t cur = keepOf[size_t(g)];
    if (cur < 0 || remainder[k] > remainder[oldIndex(cur)]) keepOf[size_t(g)] = old[k];
  }
}

// Flip of each old sheet and new slot relative to the sheet its group keeps; false when one is
// joined to it through no re-glued quad (cannot happen; be safe).
bool DualTracker::Lockstep::flipsRelativeToKept() {
  flipOf.assign(up.size(), 0);
  for (size_t k = 0; k < old.size(); ++k) {
    if (owner[k] < 0) continue;
    int pk = 0, pkeep = 0;
    if (root(int32_t(k), pk) != root(int32_t(oldIndex(keepOf[size_t(owner[k])])), pkeep)) return false;
    flipOf[k] = uint8_t(pk ^ pkeep);
  }
  for (size_t i = 0; i < newInRest.size(); ++i) {
    const int32_t keep = keepOf[size_t(find(t.front_[slotIndex(newInRest[i])] - 1))];
    int pv = 0, pkeep = 0;
    if (root(int32_t(old.size() + i), pv) != root(int32_t(oldIndex(keep)), pkeep)) return false;
    flipOf[old.size() + i] = uint8_t(pv ^ pkeep);
  }
  return true;
}

// Pieces in the order of their smallest slot; a piece keeps an old id only when it is all that is
// left of that sheet (the smallest such id), else it gets a fresh one.
void DualTracker::Lockstep::numberPieces() {
  std::vector<uint64_t> order(pieces.size());  // smallest slot << 32 | piece
  for (size_t p = 0; p < pieces.size(); ++p) {
    std::sort(pieces[p].begin(), pieces[p].end());
    order[p] = uint64_t(slotIndex(pieces[p][0])) << 32 | p;
  }
  std::sort(order.begin(), order.end());
  pieceId.assign(pieces.size(), -1);
  taken.assign(old.size(), 0);
  fresh = int32_t(t.dual_.sheets.size());
  for (uint64_t key : order) {
    const size_t p = size_t(key & 0xFFFFFFFFu);
    int32_t best = -1;
    for (int32_t id : pieceLabels[p])
      if (id >= 0 && owner[oldIndex(id)] < 0 && !taken[oldIndex(id)] && (best < 0 || id < best)) best = id;
    if (best >= 0) taken[oldIndex(best)] = 1;
    pieceId[p] = best >= 0 ? best : fresh++;
  }
}

// A plan that keeps every old sheet (merging some into others, adding new pieces made of touched
// hexes' slots only) is recorded for its exact undo (tracker/sheets_unmerge.cpp), before anything
// is written: a face or ring collapse joining two layers, a hex push's new sheet.
void DualTracker::Lockstep::recordForUndo() {
  std::vector<std::pair<int32_t, int32_t>> merges;  // in mergeIntoKept's order
  for (size_t k = 0; k < old.size(); ++k) {
    if (owner[k] < 0) return;
    if (keepOf[size_t(owner[k])] != old[k]) merges.push_back({old[k], keepOf[size_t(owner[k])]});
  }
  for (const auto& piece : pieces)
    for (Slot s : piece)
      if (!std::binary_search(touched.begin(), touched.end(), s.hex)) return;
  if (!merges.empty() || !pieces.empty()) t.recordUnmerge(touched, old, merges, pieces.size());
}

// ---- commit ----

// Room for the fresh ids; the sheets affected; and the hexes whose slot labels change (dead, in a
// piece, or new), whose pairs of slots are uncounted now and counted again at the end. The other
// hexes keep their labels, and a merge moves their pairs itself.
void DualTracker::Lockstep::uncountRelabelledHexes() {
  t.dual_.sheets.resize(size_t(fresh));
  t.selfPairs_.resize(size_t(fresh), 0);
  if (t.labels_.size() < size_t(fresh)) t.labels_.resize(size_t(fresh));
  if (t.delta_.size() < size_t(fresh)) t.delta_.resize(size_t(fresh), 0);
  affected.assign(old.begin(), old.end());
  for (size_t p = 0; p < pieces.size(); ++p) affected.push_back(pieceId[p]);
  std::sort(affected.begin(), affected.end());
  affected.erase(std::unique(affected.begin(), affected.end()), affected.end());
  for (HexId h : touched)
    if (!cx.isHex(h)) recount.push_back(h);
  for (const auto& piece : pieces)
    for (Slot s : piece) recount.push_back(s.hex);
  for (Slot s : newInRest) recount.push_back(s.hex);
  for (size_t k = 0; k < old.size(); ++k)
    if (owner[k] >= 0 && keepOf[size_t(owner[k])] != old[k]) merged.push_back(old[k]);
  std::sort(recount.begin(), recount.end());
  recount.erase(std::unique(recount.begin(), recount.end()), recount.end());
  t.countSelfHexes(recount, -1);
}

// The edit's change of each slot's share, charged to the slot's old sheet.
void DualTracker::Lockstep::moveShares() {
  std::vector<ShareChange> shareChanges;
  t.refreshShares(cx, touched, &shareChanges);
  for (const ShareChange& c : shareChanges) {
    const int32_t id = label(c.slot);
    if (id >= 0) t.delta_[size_t(id)] += c.after - c.before;
  }
}

// s gets a label of another sheet; its share follows.
void DualTracker::Lockstep::move(Slot s, int32_t toLabel) {
  const int32_t from = label(s), to = t.dual_.labelSheet[size_t(toLabel)];
  const int c = t.share_[slotIndex(s)];
  if (from >= 0) t.delta_[size_t(from)] -= c;
  t.delta_[size_t(to)] += c;
  t.setLabel(s, toLabel);
}

// Slots leaving the old sheets' lists (dead, or in a piece), by old sheet: dropped when next read.
// Dead slots lose their label and orientation here.
void DualTracker::Lockstep::dropDeadSlots() {
  HugeVector<int8_t>& signs = t.flooder_.signs();
  leaving.resize(old.size());
  for (HexId h : touched)
    if (!cx.isHex(h)) {
      for (int a = 0; a < 3; ++a) {
        const int32_t id = label({h, a});
        if (id >= 0) leaving[oldIndex(id)].push_back({h, a});
        t.setLabel({h, a}, -1);
        signs[3 * size_t(h) + size_t(a)] = 0;
      }
    }
  // (By each slot's own label: pieces are sorted by now, their pieceLabels are not.)
  for (const auto& piece : pieces)
    for (Slot s : piece)
      if (label(s) >= 0) leaving[oldIndex(label(s))].push_back(s);
}

// Piece p becomes sheet pieceId[p]: labelled, oriented by a flood of its own slots, its boundary
// loops walked and charged to the old sheets they came from.
void DualTracker::Lockstep::labelPiece(size_t p, DualChange& change) {
  const int32_t id = pieceId[p];
  Sheet& sh = t.dual_.sheets[size_t(id)];
  const bool reused = std::binary_search(old.begin(), old.end(), id);
  int loops = 0;
  for (size_t i = 0; i < pieces[p].size(); ++i) {
    const Slot s = pieces[p][i];
    const int l = t.flooder_.walkNewLoops(cx, s.hex, s.axis);
    loops += l;
    const int32_t from = label(s);
    if (l && from >= 0) loopsTaken[oldIndex(from)] += l;
  }
  t.flooder_.clear(pieces[p]);
  const int32_t pieceLabel = t.newLabel(id);
  for (Slot s : pieces[p]) {
    move(s, pieceLabel);
    t.flooder_.signs()[slotIndex(s)] = 0;
  }
  const bool orientable = orientPiece(pieces[p]);
  if (!reused) sh.euler = 0;
  sh.id = id;
  sh.alive = true;
  sh.slots = pieces[p];
  sh.boundaryLoops = loops;
  sh.orientable = orientable;
  (reused ? change.sheetsChanged : change.sheetsCreated).push_back(id);
}

// Orients a piece from its first slot (its own label is not flipped); false when it is twisted.
bool DualTracker::Lockstep::orientPiece(const std::vector<Slot>& piece) {
  HugeVector<int8_t>& signs = t.flooder_.signs();
  bool orientable = true;
  std::vector<Slot> stack{piece[0]};
  signs[slotIndex(piece[0])] = 1;
  while (!stack.empty()) {
    const Slot s = stack.back();
    stack.pop_back();
    for (int face : kParallelFaces[size_t(s.axis)]) {
      Slot n;
      int flip;
      if (!sheetNeighbour(cx, s, face, n, flip)) continue;
      const int want = signs[slotIndex(s)] * flip;
      if (!signs[slotIndex(n)]) {
        signs[slotIndex(n)] = int8_t(want);
        stack.push_back(n);
      } else if (signs[slotIndex(n)] != want) {
        orientable = false;
      }
    }
  }
  return orientable;
}

// Remainders: the old sheets drop the slots they lost.
void DualTracker::Lockstep::shrinkRemainders() {
  for (size_t k = 0; k < old.size(); ++k)
    if (owner[k] >= 0) {
      std::sort(leaving[k].begin(), leaving[k].end());
      t.dual_.sheets[size_t(old[k])].slots.remove(leaving[k]);
    }
}

// Merged old sheets join their kept sheet whole (labels re-pointed, lists handed over: no slot written).
void DualTracker::Lockstep::mergeIntoKept(DualChange& change) {
  for (int32_t x : merged) {
    const size_t g = size_t(owner[oldIndex(x)]);
    t.mergeSheet(x, keepOf[g], flipOf[oldIndex(x)] != 0);
    t.dual_.sheets[size_t(x)].slots.clear();
    t.dual_.sheets[size_t(x)].alive = false;
    change.sheetsRemoved.push_back(x);
  }
}

// New slots of a remainder join it with its kept label, oriented as solved; the kept sheet's loops
// are its old sheets' loops less those the pieces took.
void DualTracker::Lockstep::joinNewSlots(DualChange& change) {
  std::vector<std::vector<Slot>> joining(parent.size());
  for (size_t i = 0; i < newInRest.size(); ++i) {
    const Slot s = newInRest[i];
    const int32_t g = find(t.front_[slotIndex(s)] - 1);
    move(s, t.labels_[size_t(keepOf[size_t(g)])].front());
    t.setSign(s, flipOf[old.size() + i] ? -1 : 1);
    joining[size_t(g)].push_back(s);  // sorted: newInRest is
  }
  for (size_t g = 0; g < parent.size(); ++g) {
    const int32_t keep = keepOf[g];
    if (keep < 0) continue;
    int64_t loops = 0;
    for (size_t k = 0; k < old.size(); ++k)
      if (owner[k] == int32_t(g)) loops += t.dual_.sheets[size_t(old[k])].boundaryLoops - loopsTaken[k];
    t.dual_.sheets[size_t(keep)].slots.add(joining[g]);
    t.dual_.sheets[size_t(keep)].boundaryLoops = int(loops);
    change.sheetsChanged.push_back(keep);
  }
}

// Old sheets with no remainder whose id no piece kept are retired.
void DualTracker::Lockstep::retireSheetsLeft(DualChange& change) {
  for (size_t k = 0; k < old.size(); ++k)
    if (owner[k] < 0 && !taken[k]) {
      t.dual_.sheets[size_t(old[k])].slots.clear();
      t.dual_.sheets[size_t(old[k])].alive = false;
      change.sheetsRemoved.push_back(old[k]);
    }
}

// Pairs counted again; each affected sheet's Euler characteristic from its share delta, its labels
// pruned, its self-intersection and topology named.
void DualTracker::Lockstep::finishSheets() {
  t.countSelfHexes(recount, +1);
  for (int32_t id : affected) {
    Sheet& sh = t.dual_.sheets[size_t(id)];
    sh.euler += t.delta_[size_t(id)] / 2;
    t.delta_[size_t(id)] = 0;
    t.pruneLabels(id);
    if (!sh.alive) continue;
    sh.selfIntersecting = t.selfPairs_[size_t(id)] > 0;
    sh.topology = classifySurface(sh.euler, sh.boundaryLoops, sh.orientable);
  }
}

}  // namespace hexdual
