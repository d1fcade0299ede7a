// The chord update as a whole: chords through the touched hexes whose touched slots keep their
// neighbours along the chord are unchanged; the others are rebuilt locally (chord_rejoin.cpp) or,
// when the rejoin is not sure (or setLocalChords(false)), re-walked whole from the touched slots
// (relabel): the reference the local update must equal (same ids, same slot order).
// Owns chordsRewalked_; the re-walk gives every chord it walks one label run.
#include <algorithm>

#include "dual/dual_tracker.hpp"
#include "dual/tracker/relabel.hpp"
#include "dual/tracker/slots.hpp"

namespace hexdual {
using namespace tracker;

// The chords the edit changed are rebuilt locally, or re-walked when the rejoin gives up.
void DualTracker::updateChords(const Complex& cx, const std::vector<HexId>& touched, DualChange& change) {
  const std::vector<int32_t> ids = changedChords(cx, touched);
  const size_t before = slotsTouched_;
  chordsRewalked_ = !localChords_ || !rejoinChords(cx, touched, ids, change);
  if (chordsRewalked_) {
    slotsTouched_ = before;  // a rejoin that gave up counts nothing: the re-walk is the work done
    rewalkChords(cx, touched, ids, change);
  }
}

// The chords through the touched slots that the edit changed, ascending. The touched slots are
// grouped by chord, so each chord reads only its own. When the update knows its edits, a slot of
// a live hex none of whose two faces across its axis was glued or unglued is left out: its
// neighbours along the chord are the hexes across those faces, as before the edit (the tracker
// held them), so it cannot have changed its chord.
std::vector<int32_t> DualTracker::changedChords(const Complex& cx, const std::vector<HexId>& touched) {
  thread_local std::vector<std::pair<int32_t, Slot>> through;  // scratch kept between updates
  thread_local std::vector<Slot> own;
  through.clear();
  const bool known = edgesToWalk_.size() == touched.size();
  for (size_t i = 0; i < touched.size(); ++i) {
    const HexId h = touched[i];
    const unsigned axes = known ? edgesToWalk_[i] : kChordAxesChanged;
    for (int a = 0; a < 3; ++a) {
      if (!(axes & chordAxisChanged(a))) continue;
      const int32_t c = dual_.chordAt(h, a);
      if (c >= 0) through.push_back({c, Slot{h, a}});
    }
  }
  // Grouped by chord id (the order within a chord does not matter): counted into place when the
  // list is long against the id range (a sheet operation), else sorted.
  if (through.size() >= 4096 && dual_.chords.size() <= 4 * through.size()) {
    std::vector<uint32_t> start(dual_.chords.size() + 1, 0);
    for (const auto& x : through) ++start[size_t(x.first) + 1];
    for (size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
    std::vector<std::pair<int32_t, Slot>> grouped(through.size());
    for (const auto& x : through) grouped[start[size_t(x.first)]++] = x;
    through.swap(grouped);
  } else {
    std::sort(through.begin(), through.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  }
  std::vector<int32_t> ids;
  ids.reserve(16);  // a step changes a few chords: one allocation, not one per doubling
  for (size_t i = 0, j = 0; i < through.size(); i = j) {
    const int32_t id = through[i].first;
    own.clear();
    for (j = i; j < through.size() && through[j].first == id; ++j) own.push_back(through[j].second);
    slotsTouched_ += own.size();
    if (!chordUnchanged(cx, id, own)) ids.push_back(id);
  }
  return ids;
}

// A chord whose touched slots (`own`) still have the same neighbours along it is unchanged.
bool DualTracker::chordUnchanged(const Complex& cx, int32_t id, const std::vector<Slot>& own) const {
  for (Slot s : own) {
    if (!cx.isHex(s.hex)) return false;
    Slot prev, next;
    bool hasPrev = false, hasNext = false;
    if (chordNeighbours(id, s, &prev, &hasPrev, &next, &hasNext) < 0) return false;
    auto along = [&](int face, Slot& n) {
      Gluing g = cx.gluing(s.hex, face);
      if (g.boundary()) return false;
      n = {g.hex, tables::axisOfFace(g.face)};
      return true;
    };
    Slot lo, hi;
    const bool hasLo = along(2 * s.axis, lo), hasHi = along(2 * s.axis + 1, hi);
    auto same = [](bool x, Slot a, bool y, Slot b) { return x == y && (!x || a == b); };
    if (!(same(hasLo, lo, hasPrev, prev) && same(hasHi, hi, hasNext, next)) &&
        !(same(hasLo, lo, hasNext, next) && same(hasHi, hi, hasPrev, prev)))
      return false;
  }
  return true;
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
  growChordIds(n);
  for (auto [id, l] : made) {
    const Chord& ch = dual_.chords[size_t(id)];
    runs_[size_t(l)].assign(ch.slots.begin(), ch.slots.end());
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

}  // namespace hexdual
