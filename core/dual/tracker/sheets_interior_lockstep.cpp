// Sheet update for an edit that may cut, merge or re-shape sheets, away from the boundary and on
// orientable sheets: the lockstep flood (TK03 §4.4: a collapse cuts and re-glues sheets in one
// place). update() runs it for every operation that does not keep sheet topology (and for a merge
// the topology-kept update refused); it refuses, changing nothing, near the boundary, on a
// non-orientable sheet, or when the edit is not one it can follow, and the reflood runs instead.
// Owns nothing between updates; marks front_ while it runs (cleared before it returns).
#include "dual/dual_tracker.hpp"

#include <algorithm>

#include "dual/tracker/slots.hpp"

namespace hexdual {
using namespace tracker;

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

}  // namespace hexdual
