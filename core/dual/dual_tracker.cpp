#include "dual/dual_tracker.hpp"

#include <algorithm>
#include <climits>
#include <numeric>

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
// Inlined even where the tracker is built for size (the wasm module): the constructor calls it 3x per hex.
[[gnu::always_inline]] inline int slotsOnSheet(const std::array<int32_t, 3>& s, int32_t id) { return (s[0] == id) + (s[1] == id) + (s[2] == id); }
}  // namespace

namespace {

constexpr uint16_t kNearBoundary = kEdgeNearBoundary;

// Drops the slots no longer labelled `id`, keeping the order.
void keepLabelled(std::vector<Slot>& slots, const std::vector<std::array<int32_t, 3>>& of, int32_t id) {
  size_t k = 0;
  for (Slot t : slots)
    if (of[size_t(t.hex)][size_t(t.axis)] == id) slots[k++] = t;
  slots.resize(k);
}

// The sheet or chord ids on the slots of these hexes, ascending, once each.
std::vector<int32_t> idsThrough(const std::vector<std::array<int32_t, 3>>& of, const std::vector<HexId>& hexes) {
  std::vector<int32_t> ids;
  for (HexId h : hexes)
    for (int32_t id : of[size_t(h)])
      if (id >= 0) ids.push_back(id);
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
  selfHexes_.assign(dual_.sheets.size(), 0);
  for (HexId h : cx.hexes()) {
    const auto& s = dual_.sheetOf[size_t(h)];
    for (int a = 0; a < 3; ++a)
      if (slotsOnSheet(s, s[size_t(a)]) >= 2 && (a == 0 || s[size_t(a)] != s[0]) && (a < 2 || s[2] != s[1]))
        ++selfHexes_[size_t(s[size_t(a)])];
  }
  share_ = std::move(extras.slotShares);
  chordPos_ = std::move(extras.chordPlaces);
  delta_.assign(dual_.sheets.size(), 0);  // the scratch arrays are sized by the first update
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
      fan = !edgeIncidences(cx, {h, e}, inc) || fan;
      const EdgeRef least = *std::min_element(inc.begin(), inc.end());
      for (EdgeRef r : inc) {
        if (!walked_[size_t(r.hex)]) met.push_back(r.hex);
        walked_[size_t(r.hex)] |= uint16_t(1u << r.edge);
        const uint16_t bit = uint16_t(1u << r.edge);
        if (((edgeMarks_[size_t(r.hex)] & bit) != 0) != (r == least)) {
          edgeMarks_[size_t(r.hex)] ^= bit;
          dirty.push_back({r.hex, tables::axisOfEdge(r.edge)});
        }
      }
    }
  }
  for (HexId m : met) walked_[size_t(m)] = 0;
  // Only an edge through a touched hex can have reached or left the boundary.
  if (fan || nearBefore)
    for (HexId m : met)
      edgeMarks_[size_t(m)] = uint16_t((edgeMarks_[size_t(m)] & ~kNearBoundary) | (nearBoundary(cx, m) ? kNearBoundary : 0));
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
          sign[slotIndex(s)] = int8_t(sign[slotIndex(n)] * flip);
          progress = true;
          break;
        }
    }
  }
}

// Adds (sign +1) or removes (-1) these hexes' counts in selfHexes_ (a hex counts once per sheet it has two slots on).
void DualTracker::countSelfHexes(const std::vector<HexId>& hexes, int sign) {
  for (HexId h : hexes) countSelfHex(h, sign);
}

void DualTracker::countSelfHex(HexId h, int sign) {
  const auto& s = dual_.sheetOf[size_t(h)];
  for (int a = 0; a < 3; ++a) {
    const int32_t id = s[size_t(a)];
    if (id >= 0 && slotsOnSheet(s, id) >= 2 && (a == 0 || id != s[0]) && (a < 2 || s[2] != s[1])) selfHexes_[size_t(id)] += sign;
  }
}

void DualTracker::releaseRetiredTail() {
  while (!dual_.sheets.empty() && !dual_.sheets.back().alive) {
    dual_.sheets.pop_back();
    selfHexes_.pop_back();
  }
  while (!dual_.chords.empty() && !dual_.chords.back().alive) dual_.chords.pop_back();
}

DualChange DualTracker::update(const Complex& cx, const Complex::EditLog& edits, bool sheetsKeepTopology) {
  return update(cx, touchedHexes(cx, edits), sheetsKeepTopology);
}

bool DualTracker::updateSheetsLocally(const Complex& cx, const std::vector<HexId>& touched, DualChange& change) {
  const size_t cap = dual_.sheetOf.size();
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
      if (dual_.sheetOf[size_t(h)][size_t(a)] >= 0 || front_[slotIndex({h, a})]) continue;
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
          int32_t id = size_t(n.hex) < cap ? dual_.sheetOf[size_t(n.hex)][size_t(n.axis)] : -1;
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
  // Remove the slots of dead hexes.
  std::vector<int32_t> changed;
  for (HexId h : touched) {
    if (cx.isHex(h) || size_t(h) >= cap) continue;
    auto& s = dual_.sheetOf[size_t(h)];
    for (int a = 0; a < 3; ++a) {
      int32_t id = s[size_t(a)];
      if (id < 0) continue;
      if (slotsOnSheet(s, id) >= 2 && (a == 0 || id != s[0]) && (a < 2 || s[2] != s[1])) --selfHexes_[size_t(id)];
      auto& slots = dual_.sheets[size_t(id)].slots;
      auto it = std::lower_bound(slots.begin(), slots.end(), Slot{h, a});
      if (it != slots.end() && *it == Slot{h, a}) slots.erase(it);
      changed.push_back(id);
    }
    s = {-1, -1, -1};
    for (int a = 0; a < 3; ++a) flooder_.signs()[3 * size_t(h) + size_t(a)] = 0;
  }
  // Label the new components: join the one sheet they touch, or form a new sheet.
  for (size_t ci = 0; ci < comps.size(); ++ci) {
    int32_t id;
    if (joins[ci].empty()) {
      id = int32_t(dual_.sheets.size());
      Sheet sh;
      sh.id = id;
      SheetStats st = flooder_.flood(cx, comps[ci][0], id, dual_.sheetOf[0].data(), &sh.slots);
      flooder_.clear(sh.slots);
      std::sort(sh.slots.begin(), sh.slots.end());
      st.classify(sh);
      sheetSlotsTouched_ += sh.slots.size();
      dual_.sheets.push_back(std::move(sh));
      selfHexes_.push_back(0);
      change.sheetsCreated.push_back(id);
    } else {
      id = joins[ci][0];
      auto& slots = dual_.sheets[size_t(id)].slots;
      for (Slot t : comps[ci]) {
        dual_.sheetOf[size_t(t.hex)][size_t(t.axis)] = id;
        slots.insert(std::lower_bound(slots.begin(), slots.end(), t), t);
      }
      propagateSigns(cx, comps[ci]);
      sheetSlotsTouched_ += comps[ci].size();
      changed.push_back(id);
    }
  }
  // Self-intersection counts for the new hexes.
  for (const auto& comp : comps)
    for (Slot t : comp) {
      const auto& s = dual_.sheetOf[size_t(t.hex)];
      int32_t id = s[size_t(t.axis)];
      // Count each new hex once per sheet, at its first slot on that sheet.
      bool first = true;
      for (int a = 0; a < t.axis; ++a) first = first && s[size_t(a)] != id;
      if (first && slotsOnSheet(s, id) >= 2) ++selfHexes_[size_t(id)];
    }
  std::sort(changed.begin(), changed.end());
  changed.erase(std::unique(changed.begin(), changed.end()), changed.end());
  for (int32_t id : changed) {
    Sheet& sh = dual_.sheets[size_t(id)];
    sh.selfIntersecting = selfHexes_[size_t(id)] > 0;
    if (std::find(change.sheetsCreated.begin(), change.sheetsCreated.end(), id) != change.sheetsCreated.end()) continue;
    if (sh.slots.empty()) {
      sh.alive = false;
      change.sheetsRemoved.push_back(id);
    } else {
      change.sheetsChanged.push_back(id);
    }
  }
  return true;
}

// The sheets through the touched hexes after an edit, by a lockstep flood (TK03 §4.4: a collapse
// cuts and re-glues sheets in one place). Every touched slot starts a front; fronts that meet join
// one group; a group whose fronts all run dry is a whole new sheet (a piece). The flood stops once
// every old sheet meets at most one unfinished group: that group is the rest of those old sheets.
// Returns false, changing nothing, when the edit is not one it can follow (boundary, twisted sheets).
bool DualTracker::updateSheetsLockstep(const Complex& cx, const std::vector<HexId>& touched, DualChange& change) {
  auto& sheetOf = dual_.sheetOf;
  auto label = [&](Slot t) { return sheetOf[size_t(t.hex)][size_t(t.axis)]; };
  const std::vector<int32_t> old = idsThrough(sheetOf, touched);
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
      for (int32_t id : sheetOf[size_t(h)])
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
      sg = signs[slotIndex(t)];
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
  selfHexes_.resize(size_t(fresh), 0);
  if (delta_.size() < size_t(fresh)) delta_.resize(size_t(fresh), 0);
  std::vector<int32_t> affected(old.begin(), old.end());
  for (size_t p = 0; p < pieces.size(); ++p) affected.push_back(pieceId[p]);
  std::sort(affected.begin(), affected.end());
  affected.erase(std::unique(affected.begin(), affected.end()), affected.end());
  // Hexes whose slots may change sheet: their self-intersection counts are redone.
  std::vector<HexId> recount(touched.begin(), touched.end());
  for (const auto& piece : pieces)
    for (Slot t : piece) recount.push_back(t.hex);
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
  auto move = [&](Slot t, int32_t to) {
    int32_t& id = sheetOf[size_t(t.hex)][size_t(t.axis)];
    const int c = share_[slotIndex(t)];
    if (id >= 0) delta_[size_t(id)] -= c;
    delta_[size_t(to)] += c;
    id = to;
  };
  for (HexId h : touched)
    if (!cx.isHex(h)) {
      sheetOf[size_t(h)] = {-1, -1, -1};
      for (int a = 0; a < 3; ++a) signs[3 * size_t(h) + size_t(a)] = 0;
    }
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
    for (Slot t : pieces[p]) {
      move(t, id);
      signs[slotIndex(t)] = 0;
    }
    bool orientable = true;
    std::vector<Slot> stack{pieces[p][0]};
    signs[slotIndex(pieces[p][0])] = 1;
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
  // Remainders: merged old sheets and new slots join the kept id; loops are what the pieces did not take.
  // Merged sheets are re-labelled hex by hex (their slot lists are sorted by hex), each hex's
  // self-intersection count redone around it.
  std::vector<std::vector<Slot>> joining(parent.size());
  size_t relabelled = 0;
  auto join = [&](size_t g, const std::vector<Slot>& run) {  // run sorted
    auto& slots = dual_.sheets[size_t(keepOf[g])].slots;
    std::vector<Slot> both(slots.size() + run.size());
    std::merge(slots.begin(), slots.end(), run.begin(), run.end(), both.begin());
    slots = std::move(both);
  };
  for (size_t g = 0; g < parent.size(); ++g) {
    const int32_t keep = keepOf[g];
    if (keep < 0) continue;
    auto& slots = dual_.sheets[size_t(keep)].slots;
    keepLabelled(slots, sheetOf, keep);
  }
  for (int32_t x : merged) {
    const size_t g = size_t(owner[oldIndex(x)]);
    const int32_t keep = keepOf[g];
    const int8_t turn = flipOf[oldIndex(x)] ? -1 : 1;
    std::vector<Slot> run = std::move(dual_.sheets[size_t(x)].slots);
    keepLabelled(run, sheetOf, x);
    for (size_t i = 0; i < run.size();) {
      const HexId h = run[i].hex;
      const bool alone = !std::binary_search(recount.begin(), recount.end(), h);
      if (alone) countSelfHex(h, -1);
      for (; i < run.size() && run[i].hex == h; ++i) {
        signs[slotIndex(run[i])] = int8_t(signs[slotIndex(run[i])] * turn);
        move(run[i], keep);
      }
      if (alone) countSelfHex(h, +1);
    }
    relabelled += run.size();
    join(g, run);
    dual_.sheets[size_t(x)].slots.clear();
    dual_.sheets[size_t(x)].alive = false;
    change.sheetsRemoved.push_back(x);
  }
  for (size_t i = 0; i < newInRest.size(); ++i) {
    const Slot t = newInRest[i];
    signs[slotIndex(t)] = flipOf[old.size() + i] ? -1 : 1;
    const int32_t g = find(front_[slotIndex(t)] - 1);
    move(t, keepOf[size_t(g)]);
    joining[size_t(g)].push_back(t);  // sorted: newInRest is
  }
  for (size_t g = 0; g < parent.size(); ++g) {
    const int32_t keep = keepOf[g];
    if (keep < 0) continue;
    int64_t loops = 0;
    for (size_t k = 0; k < old.size(); ++k)
      if (owner[k] == int32_t(g)) loops += dual_.sheets[size_t(old[k])].boundaryLoops - loopsTaken[k];
    join(g, joining[g]);
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
    if (!sh.alive) continue;
    sh.selfIntersecting = selfHexes_[size_t(id)] > 0;
    sh.topology = classifySurface(sh.euler, sh.boundaryLoops, sh.orientable);
  }
  sheetSlotsTouched_ += reached.size() + relabelled;
  mergedSlots_ = relabelled;
  clearFronts();
  return true;
}

DualChange DualTracker::update(const Complex& cx, std::vector<HexId> touched, bool sheetsKeepTopology) {
  const size_t cap = std::max(size_t(cx.hexCapacity()), dual_.sheetOf.size());
  dual_.sheetOf.resize(cap, {-1, -1, -1});
  dual_.chordOf.resize(cap, {-1, -1, -1});
  flooder_.reserve(cap);
  edgeMarks_.resize(cap, 0);
  walked_.resize(cap, 0);
  share_.resize(3 * cap, 0);
  front_.resize(3 * cap, 0);
  slotsTouched_ = 0;
  sheetSlotsTouched_ = 0;
  mergedSlots_ = 0;
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
// old one touched is cleared and its slots re-walked from seeds (with `walk`, labelling kTemp),
// and each component found keeps the smallest old id it holds. Sheets and chords alike.
template <class Entity, class Walk, class Unchanged>
size_t relabel(const Complex& cx, const std::vector<HexId>& touched, std::vector<std::array<int32_t, 3>>& of,
               std::vector<Entity>& list, Walk walk, std::vector<int>& created, std::vector<int>& changed,
               std::vector<int>& removed, Unchanged unchanged) {
  size_t visited = 0;
  std::vector<int32_t> old = idsThrough(of, touched);
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
    for (Slot t : e.slots) of[size_t(t.hex)][size_t(t.axis)] = id;
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
  int32_t* sheetOf = dual_.sheetOf[0].data();
  auto walk = [&](Slot s, Sheet& sh, std::vector<int32_t>& previous) {
    SheetStats st = flooder_.flood(cx, s, kTemp, sheetOf, &sh.slots, &previous);
    flooder_.clear(sh.slots);
    std::sort(sh.slots.begin(), sh.slots.end());
    st.classify(sh);
  };
  refreshShares(cx, touched, nullptr);  // the floods measure each sheet whole
  sheetSlotsTouched_ += relabel(cx, touched, dual_.sheetOf, dual_.sheets, walk, change.sheetsCreated, change.sheetsChanged,
                                change.sheetsRemoved, [](int) { return false; });
  for (HexId h : touched)
    if (!cx.isHex(h))
      for (int a = 0; a < 3; ++a) flooder_.signs()[3 * size_t(h) + size_t(a)] = 0;
  selfHexes_.resize(dual_.sheets.size(), 0);
  auto recount = [&](int id) {
    Sheet& sh = dual_.sheets[size_t(id)];
    int32_t self = 0;
    for (size_t i = 1; i < sh.slots.size(); ++i)
      if (sh.slots[i].hex == sh.slots[i - 1].hex && (i < 2 || sh.slots[i - 2].hex != sh.slots[i].hex)) ++self;
    selfHexes_[size_t(id)] = self;
    sh.selfIntersecting = self > 0;
  };
  for (int id : change.sheetsCreated) recount(id);
  for (int id : change.sheetsChanged) recount(id);
}

void DualTracker::updateChords(const Complex& cx, const std::vector<HexId>& touched, DualChange& change) {
  int32_t* chordOf = dual_.chordOf[0].data();
  auto walk = [&](Slot s, Chord& ch, std::vector<int32_t>& previous) {
    ch.id = kTemp;
    walkChord(cx, s, ch, chordOf, &previous);
    for (Slot t : ch.slots) {  // a hex met twice (walked_ is free between refreshes)
      ch.selfIntersecting = ch.selfIntersecting || walked_[size_t(t.hex)];
      walked_[size_t(t.hex)] = 1;
    }
    for (Slot t : ch.slots) walked_[size_t(t.hex)] = 0;
  };
  // A chord whose touched slots still have the same neighbours along it (read from the slot's
  // place in its list) is unchanged: it is not re-walked.
  auto unchanged = [&](int id) {
    const Chord& ch = dual_.chords[size_t(id)];
    const size_t len = ch.slots.size();
    for (HexId h : touched)
      for (int a = 0; a < 3; ++a) {
        if (dual_.chordOf[size_t(h)][size_t(a)] != id) continue;
        const size_t p = size_t(chordPos_[3 * size_t(h) + size_t(a)]);
        if (!cx.isHex(h) || p >= len || !(ch.slots[p] == Slot{h, a})) return false;
        auto along = [&](int face, Slot& n) {
          Gluing g = cx.gluing(h, face);
          if (g.boundary()) return false;
          n = {g.hex, tables::axisOfFace(g.face)};
          return true;
        };
        Slot lo, hi, prev, next;
        const bool hasLo = along(2 * a, lo), hasHi = along(2 * a + 1, hi);
        const bool hasPrev = p > 0 || ch.closed, hasNext = p + 1 < len || ch.closed;
        if (hasPrev) prev = ch.slots[p > 0 ? p - 1 : len - 1];
        if (hasNext) next = ch.slots[p + 1 < len ? p + 1 : 0];
        auto same = [](bool x, Slot s, bool y, Slot t) { return x == y && (!x || s == t); };
        if (!(same(hasLo, lo, hasPrev, prev) && same(hasHi, hi, hasNext, next)) &&
            !(same(hasLo, lo, hasNext, next) && same(hasHi, hi, hasPrev, prev)))
          return false;
      }
    return true;
  };
  slotsTouched_ += relabel(cx, touched, dual_.chordOf, dual_.chords, walk, change.chordsCreated, change.chordsChanged,
                           change.chordsRemoved, unchanged);
  chordPos_.resize(3 * dual_.chordOf.size(), 0);
  auto place = [&](int id) {
    const auto& slots = dual_.chords[size_t(id)].slots;
    for (size_t i = 0; i < slots.size(); ++i) chordPos_[3 * size_t(slots[i].hex) + size_t(slots[i].axis)] = int32_t(i);
  };
  for (int id : change.chordsCreated) place(id);
  for (int id : change.chordsChanged) place(id);
}

}  // namespace hexdual
