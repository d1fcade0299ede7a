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

DualChange DualTracker::update(const Complex& cx, const OpResult& result) {
  return update(cx, touchedHexes(cx, result.edits));
}

DualChange DualTracker::update(const Complex& cx, std::vector<HexId> touched) {
  const size_t cap = size_t(cx.hexCapacity());
  const size_t oldCap = dual_.sheetOf.size();
  dual_.sheetOf.resize(std::max(cap, oldCap), {-1, -1, -1});
  dual_.chordOf.resize(std::max(cap, oldCap), {-1, -1, -1});
  sign_.resize(3 * dual_.sheetOf.size(), 0);
  int32_t* sheetOf = dual_.sheetOf.empty() ? nullptr : dual_.sheetOf[0].data();
  int32_t* chordOf = dual_.chordOf.empty() ? nullptr : dual_.chordOf[0].data();

  // Old sheets and chords through touched hexes, and the slots they held.
  std::vector<int> oldSheets, oldChords;
  for (HexId h : touched) {
    if (size_t(h) >= oldCap) continue;
    for (int a = 0; a < 3; ++a) {
      if (dual_.sheetOf[size_t(h)][size_t(a)] >= 0) oldSheets.push_back(dual_.sheetOf[size_t(h)][size_t(a)]);
      if (dual_.chordOf[size_t(h)][size_t(a)] >= 0) oldChords.push_back(dual_.chordOf[size_t(h)][size_t(a)]);
    }
  }
  for (auto* v : {&oldSheets, &oldChords}) {
    std::sort(v->begin(), v->end());
    v->erase(std::unique(v->begin(), v->end()), v->end());
  }
  std::map<std::pair<HexId, int>, int> oldSheetOfSlot, oldChordOfSlot;
  std::vector<Slot> seeds;
  for (int id : oldSheets) {
    for (Slot s : dual_.sheets[size_t(id)].slots) {
      oldSheetOfSlot[{s.hex, s.axis}] = id;
      dual_.sheetOf[size_t(s.hex)][size_t(s.axis)] = -1;
      seeds.push_back(s);
    }
    dual_.sheets[size_t(id)].alive = false;
    dual_.sheets[size_t(id)].slots.clear();
  }
  for (int id : oldChords) {
    for (Slot s : dual_.chords[size_t(id)].slots) {
      oldChordOfSlot[{s.hex, s.axis}] = id;
      dual_.chordOf[size_t(s.hex)][size_t(s.axis)] = -1;
    }
    dual_.chords[size_t(id)].alive = false;
    dual_.chords[size_t(id)].slots.clear();
  }
  for (HexId h : touched)
    if (cx.isHex(h))
      for (int a = 0; a < 3; ++a) {
        if (dual_.sheetOf[size_t(h)][size_t(a)] >= 0 || dual_.chordOf[size_t(h)][size_t(a)] >= 0) continue;
        seeds.push_back({h, a});
      }
  // Dead hexes keep no slots.
  for (HexId h : touched)
    if (!cx.isHex(h) && size_t(h) < dual_.sheetOf.size()) {
      dual_.sheetOf[size_t(h)] = {-1, -1, -1};
      dual_.chordOf[size_t(h)] = {-1, -1, -1};
    }
  std::sort(seeds.begin(), seeds.end());
  seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());

  DualChange change;
  std::vector<int> takenSheets, takenChords;
  auto chooseId = [](std::vector<int> candidates, std::vector<int>& taken, size_t freshId) {
    std::sort(candidates.begin(), candidates.end());
    for (int c : candidates)
      if (std::find(taken.begin(), taken.end(), c) == taken.end()) {
        taken.push_back(c);
        return c;
      }
    return int(freshId);
  };
  // Sheets: flood each unlabelled seed with a temporary id, then give the component its id.
  const int32_t kTemp = INT32_MAX - 1;
  for (Slot s : seeds) {
    if (!cx.isHex(s.hex) || dual_.sheetOf[size_t(s.hex)][size_t(s.axis)] >= 0) continue;
    Sheet sh;
    sh.orientable = floodSheet(cx, s, kTemp, sheetOf, sign_.data(), stack_, &sh.slots);
    std::vector<int> cand;
    for (Slot t : sh.slots) {
      auto it = oldSheetOfSlot.find({t.hex, t.axis});
      if (it != oldSheetOfSlot.end()) cand.push_back(it->second);
    }
    int id = chooseId(cand, takenSheets, dual_.sheets.size());
    for (Slot t : sh.slots) {
      dual_.sheetOf[size_t(t.hex)][size_t(t.axis)] = id;
      sign_[3 * size_t(t.hex) + size_t(t.axis)] = 0;
    }
    sh.id = id;
    classifySheet(cx, sh);
    if (id == int(dual_.sheets.size())) {
      dual_.sheets.push_back(std::move(sh));
      change.sheetsCreated.push_back(id);
    } else {
      dual_.sheets[size_t(id)] = std::move(sh);
      change.sheetsChanged.push_back(id);
    }
  }
  for (int id : oldSheets)
    if (!dual_.sheets[size_t(id)].alive) change.sheetsRemoved.push_back(id);
  // Chords: walk each unlabelled seed.
  for (Slot s : seeds) {
    if (!cx.isHex(s.hex) || dual_.chordOf[size_t(s.hex)][size_t(s.axis)] >= 0) continue;
    Chord ch;
    ch.id = kTemp;
    walkChord(cx, s, ch, chordOf);
    std::vector<int> cand;
    for (Slot t : ch.slots) {
      auto it = oldChordOfSlot.find({t.hex, t.axis});
      if (it != oldChordOfSlot.end()) cand.push_back(it->second);
    }
    int id = chooseId(cand, takenChords, dual_.chords.size());
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
  for (int id : oldChords)
    if (!dual_.chords[size_t(id)].alive) change.chordsRemoved.push_back(id);
  return change;
}

}  // namespace hexdual
