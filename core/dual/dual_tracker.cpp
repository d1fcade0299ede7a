#include "dual/dual_tracker.hpp"

#include <algorithm>
#include <map>
#include <climits>

namespace hexdual {

std::vector<HexId> touchedHexes(const Complex& cx, const Complex::EditLog& log) {
  std::vector<HexId> out;
  for (const Complex::Edit& e : log.edits) {
    switch (e.kind) {
      case Complex::Edit::AddHex:
      case Complex::Edit::RemoveHex:
      case Complex::Edit::SetCorner:
        out.push_back(e.hex);
        break;
      case Complex::Edit::Glue:
        out.push_back(e.hex);
        if (cx.isHex(e.hex) && !cx.gluing(e.hex, e.face).boundary()) out.push_back(cx.gluing(e.hex, e.face).hex);
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
int slotsOnSheet(const std::array<int32_t, 3>& s, int32_t id) { return (s[0] == id) + (s[1] == id) + (s[2] == id); }
}  // namespace

DualTracker::DualTracker(const Complex& cx) : dual_(extractDual(cx)) {
  selfHexes_.assign(dual_.sheets.size(), 0);
  for (HexId h : cx.hexes()) {
    const auto& s = dual_.sheetOf[size_t(h)];
    for (int a = 0; a < 3; ++a)
      if (slotsOnSheet(s, s[size_t(a)]) >= 2 && (a == 0 || s[size_t(a)] != s[0]) && (a < 2 || s[2] != s[1]))
        ++selfHexes_[size_t(s[size_t(a)])];
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
  std::map<std::pair<HexId, int>, size_t> compOf;
  for (HexId h : touched) {
    if (!cx.isHex(h)) continue;
    for (int a = 0; a < 3; ++a) {
      if (dual_.sheetOf[size_t(h)][size_t(a)] >= 0 || compOf.count({h, a})) continue;
      size_t ci = comps.size();
      comps.push_back({{h, a}});
      joins.emplace_back();
      compOf[{h, a}] = ci;
      for (size_t i = 0; i < comps[ci].size(); ++i) {
        Slot cur = comps[ci][i];
        for (int f = 0; f < 6; ++f) {
          if (tables::axisOfFace(f) == cur.axis) continue;
          Gluing g = cx.gluing(cur.hex, f);
          if (g.boundary()) continue;
          Slot n{g.hex, mapAxisAcross(cx, cur.hex, f, cur.axis)};
          int32_t id = size_t(n.hex) < cap ? dual_.sheetOf[size_t(n.hex)][size_t(n.axis)] : -1;
          if (id >= 0) {
            if (std::find(joins[ci].begin(), joins[ci].end(), id) == joins[ci].end()) joins[ci].push_back(id);
          } else if (!compOf.count({n.hex, n.axis})) {
            compOf[{n.hex, n.axis}] = ci;
            comps[ci].push_back(n);
          }
        }
      }
      if (joins[ci].size() > 1) return false;  // two sheets would merge: not a local change
    }
  }
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
      slotsTouched_ += sh.slots.size();
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

DualChange DualTracker::update(const Complex& cx, std::vector<HexId> touched, bool sheetsKeepTopology) {
  const size_t cap = std::max(size_t(cx.hexCapacity()), dual_.sheetOf.size());
  dual_.sheetOf.resize(cap, {-1, -1, -1});
  dual_.chordOf.resize(cap, {-1, -1, -1});
  flooder_.reserve(cap);
  slotsTouched_ = 0;
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  DualChange change;
  if (!(sheetsKeepTopology && updateSheetsLocally(cx, touched, change))) updateSheetsByFlood(cx, touched, change);
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
template <class Entity, class Walk>
size_t relabel(const Complex& cx, const std::vector<HexId>& touched, std::vector<std::array<int32_t, 3>>& of,
               std::vector<Entity>& list, Walk walk, std::vector<int>& created, std::vector<int>& changed,
               std::vector<int>& removed) {
  size_t visited = 0;
  std::vector<int> old;
  for (HexId h : touched)
    for (int32_t id : of[size_t(h)])
      if (id >= 0) old.push_back(id);
  std::sort(old.begin(), old.end());
  old.erase(std::unique(old.begin(), old.end()), old.end());
  std::vector<Slot> seeds;
  for (int id : old) {
    for (Slot s : list[size_t(id)].slots) {
      of[size_t(s.hex)][size_t(s.axis)] = parked(id);
      seeds.push_back(s);
    }
    list[size_t(id)].alive = false;
    list[size_t(id)].slots.clear();
  }
  for (HexId h : touched) {
    if (!cx.isHex(h)) {
      of[size_t(h)] = {-1, -1, -1};
      continue;
    }
    for (int a = 0; a < 3; ++a)
      if (of[size_t(h)][size_t(a)] == -1) seeds.push_back({h, a});
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
  slotsTouched_ += relabel(cx, touched, dual_.sheetOf, dual_.sheets, walk, change.sheetsCreated, change.sheetsChanged,
                           change.sheetsRemoved);
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
    std::vector<Slot> sorted = ch.slots;
    std::sort(sorted.begin(), sorted.end());
    for (size_t i = 1; i < sorted.size(); ++i)
      if (sorted[i].hex == sorted[i - 1].hex) ch.selfIntersecting = true;
  };
  slotsTouched_ += relabel(cx, touched, dual_.chordOf, dual_.chords, walk, change.chordsCreated, change.chordsChanged,
                           change.chordsRemoved);
}

}  // namespace hexdual
