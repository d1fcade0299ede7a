// Exact undo, ids included. The complex's undo restores hexes and vertices with their ids, and the
// update that follows it finds the same sheets and chords as before the step, but it names a sheet
// or chord it re-creates afresh. Before the step, idMemo keeps one slot of every sheet and chord
// through the step's touched hexes (a step changes no other one); after the undo's update,
// restoreIds gives each of them its old id by exchanging ids, then drops the ids beyond the old
// ranges (all retired by then). Owns nothing between calls: it moves what the other units own.
#include <algorithm>
#include <cstdint>

#include "dual/dual_tracker.hpp"

namespace hexdual {

DualIdMemo DualTracker::idMemo(const Complex& cx, const Complex::EditLog& edits) const {
  DualIdMemo m;
  m.sheets = dual_.sheets.size();
  m.chords = dual_.chords.size();
  // One slot per id, the first in (hex, axis) order: touchedHexes lists hexes ascending. Marked per
  // id, so the memo costs one pass over the touched slots.
  std::vector<uint8_t> sheetSeen(m.sheets, 0), chordSeen(m.chords, 0);
  for (HexId h : touchedHexes(cx, edits)) {
    if (size_t(h) >= dual_.sheetLabel.size() || dual_.sheetLabel[size_t(h)][0] < 0) continue;  // new: no slots before
    for (int a = 0; a < 3; ++a) {
      const int32_t s = dual_.sheetAt(h, a), c = dual_.chordAt(h, a);
      if (s >= 0 && !sheetSeen[size_t(s)]) sheetSeen[size_t(s)] = 1, m.sheetSlots.push_back({Slot{h, a}, s});
      if (c >= 0 && !chordSeen[size_t(c)]) chordSeen[size_t(c)] = 1, m.chordSlots.push_back({Slot{h, a}, c});
    }
  }
  return m;
}

// Each memo slot's sheet (chord) is given the memo's id: the wanted ids are distinct and so are
// the sheets, so an exchange never moves an id an earlier one placed.
void DualTracker::restoreIds(const DualIdMemo& memo) {
  for (const auto& [slot, want] : memo.sheetSlots) {
    const int32_t cur = dual_.sheetAt(slot.hex, slot.axis);
    if (cur >= 0 && cur != want) swapSheetIds(cur, want);
  }
  for (const auto& [slot, want] : memo.chordSlots) {
    const int32_t cur = dual_.chordAt(slot.hex, slot.axis);
    if (cur >= 0 && cur != want) swapChordIds(cur, want);
  }
  dropRetiredAbove(memo.sheets, memo.chords);
}

void DualTracker::swapSheetIds(int32_t a, int32_t b) {
  newSheetState();
  const size_t n = size_t(std::max(a, b)) + 1;
  while (dual_.sheets.size() < n) {  // an id the undo's releases had dropped: back, retired
    Sheet s;
    s.id = int(dual_.sheets.size());
    s.alive = false;
    dual_.sheets.push_back(std::move(s));
  }
  if (labels_.size() < n) labels_.resize(n);
  if (selfPairs_.size() < n) selfPairs_.resize(n, 0);
  if (delta_.size() < n) delta_.resize(n, 0);
  for (int32_t l : labels_[size_t(a)]) dual_.labelSheet[size_t(l)] = b;
  for (int32_t l : labels_[size_t(b)]) dual_.labelSheet[size_t(l)] = a;
  std::swap(labels_[size_t(a)], labels_[size_t(b)]);
  std::swap(selfPairs_[size_t(a)], selfPairs_[size_t(b)]);
  std::swap(dual_.sheets[size_t(a)], dual_.sheets[size_t(b)]);
  dual_.sheets[size_t(a)].id = a;
  dual_.sheets[size_t(b)].id = b;
}

void DualTracker::swapChordIds(int32_t a, int32_t b) {
  const size_t n = size_t(std::max(a, b)) + 1;
  while (dual_.chords.size() < n) {
    Chord c;
    c.id = int(dual_.chords.size());
    c.alive = false;
    dual_.chords.push_back(std::move(c));
  }
  growChordIds(n);
  // The labels' cuts and one-chord names: a and b exchanged (a label may lie in both).
  auto rename = [&](int32_t c) { return c == a ? b : c == b ? a : c; };
  std::vector<int32_t> labels;
  for (int32_t id : {a, b})
    for (const Piece& p : pieces_[size_t(id)]) labels.push_back(p.label);
  std::sort(labels.begin(), labels.end());
  labels.erase(std::unique(labels.begin(), labels.end()), labels.end());
  for (int32_t l : labels) {
    for (Dual::ChordCut& k : dual_.labelCuts[size_t(l)]) k.chord = rename(k.chord);
    if (dual_.labelChord[size_t(l)] >= 0) dual_.labelChord[size_t(l)] = rename(dual_.labelChord[size_t(l)]);
  }
  std::swap(pieces_[size_t(a)], pieces_[size_t(b)]);
  std::swap(chordSelf_[size_t(a)], chordSelf_[size_t(b)]);
  std::swap(unsettledMark_[size_t(a)], unsettledMark_[size_t(b)]);
  for (int32_t& id : unsettled_) id = rename(id);
  std::swap(dual_.chords[size_t(a)], dual_.chords[size_t(b)]);
  dual_.chords[size_t(a)].id = a;
  dual_.chords[size_t(b)].id = b;
}

}  // namespace hexdual
