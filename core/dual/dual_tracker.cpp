#include "dual/dual_tracker.hpp"

#include <algorithm>
#include <map>

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
      std::vector<Slot> stack;
      sh.orientable = floodSheet(cx, comps[ci][0], id, dual_.sheetOf[0].data(), sign_.data(), stack, &sh.slots);
      for (Slot t : sh.slots) sign_[3 * size_t(t.hex) + size_t(t.axis)] = 0;
      classifySheet(cx, sh);
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
  sign_.resize(3 * cap, 0);
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  DualChange change;
  if (!(sheetsKeepTopology && updateSheetsLocally(cx, touched, change))) updateSheetsByFlood(cx, touched, change);
  updateChords(cx, touched, change);
  return change;
}

namespace {
// Picks the id for a recomputed component: the smallest old id it holds that no earlier
// component took, else a fresh id.
int chooseId(std::vector<int> candidates, std::vector<int>& taken, size_t freshId) {
  std::sort(candidates.begin(), candidates.end());
  for (int c : candidates)
    if (std::find(taken.begin(), taken.end(), c) == taken.end()) {
      taken.push_back(c);
      return c;
    }
  return int(freshId);
}
}  // namespace

void DualTracker::updateSheetsByFlood(const Complex& cx, const std::vector<HexId>& touched, DualChange& change) {
  int32_t* sheetOf = dual_.sheetOf[0].data();
  std::vector<int> old;
  for (HexId h : touched)
    for (int a = 0; a < 3; ++a)
      if (dual_.sheetOf[size_t(h)][size_t(a)] >= 0) old.push_back(dual_.sheetOf[size_t(h)][size_t(a)]);
  std::sort(old.begin(), old.end());
  old.erase(std::unique(old.begin(), old.end()), old.end());
  std::map<std::pair<HexId, int>, int> oldOf;
  std::vector<Slot> seeds;
  for (int id : old) {
    for (Slot s : dual_.sheets[size_t(id)].slots) {
      oldOf[{s.hex, s.axis}] = id;
      dual_.sheetOf[size_t(s.hex)][size_t(s.axis)] = -1;
      seeds.push_back(s);
    }
    dual_.sheets[size_t(id)].alive = false;
    dual_.sheets[size_t(id)].slots.clear();
  }
  for (HexId h : touched) {
    if (!cx.isHex(h)) {
      dual_.sheetOf[size_t(h)] = {-1, -1, -1};
      continue;
    }
    for (int a = 0; a < 3; ++a)
      if (dual_.sheetOf[size_t(h)][size_t(a)] < 0) seeds.push_back({h, a});
  }
  std::sort(seeds.begin(), seeds.end());
  seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
  std::vector<int> taken;
  const int32_t kTemp = INT32_MAX - 1;
  for (Slot s : seeds) {
    if (!cx.isHex(s.hex) || dual_.sheetOf[size_t(s.hex)][size_t(s.axis)] >= 0) continue;
    Sheet sh;
    sh.orientable = floodSheet(cx, s, kTemp, sheetOf, sign_.data(), stack_, &sh.slots);
    std::vector<int> cand;
    for (Slot t : sh.slots) {
      auto it = oldOf.find({t.hex, t.axis});
      if (it != oldOf.end()) cand.push_back(it->second);
    }
    int id = chooseId(cand, taken, dual_.sheets.size());
    for (Slot t : sh.slots) {
      dual_.sheetOf[size_t(t.hex)][size_t(t.axis)] = id;
      sign_[3 * size_t(t.hex) + size_t(t.axis)] = 0;
    }
    sh.id = id;
    classifySheet(cx, sh);
    int32_t self = 0;
    for (size_t i = 1; i < sh.slots.size(); ++i)
      if (sh.slots[i].hex == sh.slots[i - 1].hex && (i < 2 || sh.slots[i - 2].hex != sh.slots[i].hex)) ++self;
    if (id == int(dual_.sheets.size())) {
      dual_.sheets.push_back(std::move(sh));
      selfHexes_.push_back(self);
      change.sheetsCreated.push_back(id);
    } else {
      dual_.sheets[size_t(id)] = std::move(sh);
      selfHexes_[size_t(id)] = self;
      change.sheetsChanged.push_back(id);
    }
  }
  for (int id : old)
    if (!dual_.sheets[size_t(id)].alive) change.sheetsRemoved.push_back(id);
}

void DualTracker::updateChords(const Complex& cx, const std::vector<HexId>& touched, DualChange& change) {
  int32_t* chordOf = dual_.chordOf[0].data();
  std::vector<int> old;
  for (HexId h : touched)
    for (int a = 0; a < 3; ++a)
      if (dual_.chordOf[size_t(h)][size_t(a)] >= 0) old.push_back(dual_.chordOf[size_t(h)][size_t(a)]);
  std::sort(old.begin(), old.end());
  old.erase(std::unique(old.begin(), old.end()), old.end());
  std::map<std::pair<HexId, int>, int> oldOf;
  std::vector<Slot> seeds;
  for (int id : old) {
    for (Slot s : dual_.chords[size_t(id)].slots) {
      oldOf[{s.hex, s.axis}] = id;
      dual_.chordOf[size_t(s.hex)][size_t(s.axis)] = -1;
      seeds.push_back(s);
    }
    dual_.chords[size_t(id)].alive = false;
    dual_.chords[size_t(id)].slots.clear();
  }
  for (HexId h : touched) {
    if (!cx.isHex(h)) {
      dual_.chordOf[size_t(h)] = {-1, -1, -1};
      continue;
    }
    for (int a = 0; a < 3; ++a)
      if (dual_.chordOf[size_t(h)][size_t(a)] < 0) seeds.push_back({h, a});
  }
  std::sort(seeds.begin(), seeds.end());
  seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
  std::vector<int> taken;
  const int32_t kTemp = INT32_MAX - 1;
  for (Slot s : seeds) {
    if (!cx.isHex(s.hex) || dual_.chordOf[size_t(s.hex)][size_t(s.axis)] >= 0) continue;
    Chord ch;
    ch.id = kTemp;
    walkChord(cx, s, ch, chordOf);
    std::vector<int> cand;
    for (Slot t : ch.slots) {
      auto it = oldOf.find({t.hex, t.axis});
      if (it != oldOf.end()) cand.push_back(it->second);
    }
    int id = chooseId(cand, taken, dual_.chords.size());
    ch.id = id;
    std::vector<Slot> sorted = ch.slots;
    std::sort(sorted.begin(), sorted.end());
    for (size_t i = 1; i < sorted.size(); ++i)
      if (sorted[i].hex == sorted[i - 1].hex) ch.selfIntersecting = true;
    for (Slot t : ch.slots) dual_.chordOf[size_t(t.hex)][size_t(t.axis)] = id;
    if (id == int(dual_.chords.size())) {
      dual_.chords.push_back(std::move(ch));
      change.chordsCreated.push_back(id);
    } else {
      dual_.chords[size_t(id)] = std::move(ch);
      change.chordsChanged.push_back(id);
    }
  }
  for (int id : old)
    if (!dual_.chords[size_t(id)].alive) change.chordsRemoved.push_back(id);
}

}  // namespace hexdual
