// The tracker's frame: construction from a full extraction, update() choosing the sheet-update
// strategy (topology kept, interior lockstep, fallback reflood: tracker/sheets_*.cpp) before the
// chord update (tracker/chord_update.cpp), and the release of retired ids after an undo.
// Owns: the growth of every per-hex and per-slot array (all grow here together) and the cost
// counters (slotsTouched_, sheetSlotsTouched_, mergedLabels_, reflooded_).
// Keeps: every per-hex array holds at least the complex's hex capacity; an id is retired, never
// reused, except that releaseRetiredTail drops retired ids at the end of the id ranges.
#include "dual/dual_tracker.hpp"

#include <algorithm>
#include <atomic>

#include "complex/huge_pages.hpp"
#include "complex/id_map.hpp"
#include "complex/sorted_ids.hpp"
#include "dual/tracker/slots.hpp"

namespace hexdual {
using namespace tracker;

namespace {

// The hexes an edit touches, each with what it marks (see edgesChangedBy): mark(hex, bits) once
// per hex, the same rule for touchedHexes, edgesChangedBy and touchedHexesWithEdges.
template <class Mark>
void marksOf(const Complex::Edit& e, Mark mark) {
  auto faceBits = [](int f) {
    unsigned m = chordAxisChanged(tables::axisOfFace(f));
    for (int edge : tables::kFaceEdges[size_t(f)]) m |= 1u << edge;
    return uint16_t(m);
  };
  switch (e.kind) {
    case Complex::Edit::AddHex:
    case Complex::Edit::RemoveHex:
      mark(e.hex, uint16_t(0xFFFu | kChordAxesChanged));
      break;
    case Complex::Edit::SetCorner:
      mark(e.hex, uint16_t(0));
      break;
    case Complex::Edit::Glue:  // value: the partner, as glued
    case Complex::Edit::Unglue:
      mark(e.hex, faceBits(e.face));
      mark(Complex::wordHex(e.value), faceBits(Complex::wordFace(e.value)));
      break;
    default:
      break;
  }
}

}  // namespace

std::vector<HexId> touchedHexes(const Complex&, const Complex::EditLog& log) {
  std::vector<HexId> out;
  out.reserve(2 * log.edits.size());  // at most two hexes per edit: one allocation
  for (const Complex::Edit& e : log.edits) marksOf(e, [&](HexId h, uint16_t) { out.push_back(h); });
  sortUniqueIds(out);
  return out;
}

// The edges whose cycles an edit can have changed: stepAroundEdge crosses only the faces through
// an edge, so a cycle changes only where one of those faces is glued or unglued (both sides are
// logged), or where a hex is added or removed (either way: the log may have been undone; a
// removal is preceded by the ungluing of its faces, so the neighbours' edges are marked too).
std::vector<uint16_t> edgesChangedBy(const Complex::EditLog& log, const std::vector<HexId>& touched) {
  std::vector<uint16_t> out(touched.size(), 0);
  // Where each touched hex sits in `touched`: a binary search for a short list; for a long one
  // (a sheet operation's hundreds of thousands of edits) an IdMap, built once.
  const bool table = touched.size() >= 4096;
  IdMap<int32_t> indexOf;
  if (table) {
    indexOf.reserve(touched.size());
    for (size_t i = 0; i < touched.size(); ++i) indexOf.emplace(touched[i], int32_t(i));
  }
  auto mark = [&](HexId h, uint16_t edges) {
    if (table) {
      if (const int32_t* i = indexOf.find(h)) out[size_t(*i)] |= edges;
      return;
    }
    const auto at = std::lower_bound(touched.begin(), touched.end(), h);
    if (at != touched.end() && *at == h) out[size_t(at - touched.begin())] |= edges;
  };
  for (const Complex::Edit& e : log.edits) marksOf(e, mark);
  return out;
}

void DualTracker::newSheetState() {
  static std::atomic<uint64_t> last{0};
  sheetState_ = ++last;
}

DualTracker::DualTracker(const Complex& cx) {
  newSheetState();
  DualExtras extras;
  dual_ = extractDual(cx, &extras);
  flooder_.signs() = std::move(extras.slotSigns);
  edgeMarks_ = std::move(extras.edgeMarks);
  const size_t sheets = dual_.sheets.size();
  // Room for new sheets and labels, as for chords below: a pillow adds a sheet and two chords, so
  // the per-sheet and per-label arrays get room for half as many new entries as there are chords.
  // Without it a 1M-hex mesh's edit session re-copied its 300 sheets, then thousands, into fresh
  // memory every time they doubled (hundreds of page faults at ~10 µs each on a VM).
  const size_t sheetRoom = sheets + dual_.chords.size() / 2 + 64;
  reserveHuge(dual_.sheets, sheetRoom);
  reserveHuge(dual_.labelSheet, sheetRoom);
  reserveHuge(labels_, sheetRoom);
  reserveHuge(labelSlots_, sheetRoom);
  reserveHuge(labelFlip_, sheetRoom);
  reserveHuge(selfPairs_, sheetRoom);
  labels_.resize(sheets);
  labelSlots_.resize(sheets);
  labelFlip_.assign(sheets, 0);
  for (size_t s = 0; s < sheets; ++s) {
    labels_[s].assign(1, int32_t(s));
    labelSlots_[s] = int32_t(dual_.sheets[s].slots.size());
  }
  // A hex's two slots on axes a and b share their sheets with every hex along the chord through its
  // third axis (TK03 §1.1: two sheets cross in chords), so the pairs are counted per chord.
  selfPairs_.assign(sheets, 0);
  for (const Chord& ch : dual_.chords) {
    const Slot t = ch.slots[0];
    const auto& l = dual_.sheetLabel[size_t(t.hex)];
    countPair(l[size_t((t.axis + 1) % 3)], l[size_t((t.axis + 2) % 3)], int32_t(ch.slots.size()));
  }
  share_ = std::move(extras.slotShares);
  // Every chord is one piece: its label's run (extraction numbers labels as chords).
  dual_.chordPlace = std::move(extras.chordPlaces);
  const size_t chords = dual_.chords.size();
  reserveRoom(runs_, chords);  // room for new chords and labels without re-copying (huge_pages.hpp)
  reserveRoom(pieces_, chords);
  reserveRoom(chordSelf_, chords);
  reserveRoom(unsettledMark_, chords);
  reserveRoom(dual_.labelCuts, chords);
  runs_.resize(chords);
  pieces_.resize(chords);
  chordSelf_.resize(chords);
  unsettledMark_.assign(chords, 0);
  dual_.labelCuts.resize(chords);
  for (size_t c = 0; c < chords; ++c) {
    const Chord& ch = dual_.chords[c];
    const int32_t len = int32_t(ch.slots.size());
    runs_[c] = LabelRun(ch.slots);  // the extraction's pool, shared: no copy
    pieces_[c].assign(1, Piece{int32_t(c), 0, len, false});
    dual_.labelCuts[c].assign(1, Dual::ChordCut{0, len, int32_t(c)});
    chordSelf_[c] = ch.selfIntersecting;
  }
  reserveHuge(delta_, sheetRoom);
  delta_.assign(dual_.sheets.size(), 0);
  growPerHexArrays(size_t(cx.hexCapacity()));
}

// The per-hex and per-slot arrays, grown to `cap` hexes with headroom (see growHuge): the first
// steps after a build neither copy nor page-fault a 1M-hex mesh's arrays.
void DualTracker::growPerHexArrays(size_t cap) {
  growHuge(dual_.sheetLabel, cap, {-1, -1, -1});
  growHuge(dual_.chordLabel, cap, {-1, -1, -1});
  growHuge(dual_.chordPlace, 3 * cap, int32_t(0));
  flooder_.reserve(cap);
  growHuge(edgeMarks_, cap, uint16_t(0));
  growHuge(walked_, cap, uint16_t(0));
  growHuge(share_, 3 * cap, int8_t(0));
  growHuge(front_, 3 * cap, int32_t(0));
}

void DualTracker::releaseRetiredTail() { dropRetiredAbove(0, 0); }

// Drops the retired ids at the end of the id ranges, keeping at least `sheets` and `chords` ids.
void DualTracker::dropRetiredAbove(size_t sheets, size_t chords) {
  while (dual_.sheets.size() > sheets && !dual_.sheets.back().alive) {
    newSheetState();
    dual_.sheets.pop_back();
    selfPairs_.pop_back();
    if (labels_.size() > dual_.sheets.size()) {
      for (int32_t l : labels_.back()) freeLabels_.push_back(l);  // carried by no slot: the sheet is retired
      labels_.pop_back();
    }
  }
  while (dual_.chords.size() > chords && !dual_.chords.back().alive) dual_.chords.pop_back();
  pieces_.resize(dual_.chords.size());
  chordSelf_.resize(dual_.chords.size());
  unsettledMark_.resize(dual_.chords.size());
  unsettled_.erase(std::remove_if(unsettled_.begin(), unsettled_.end(),
                                  [&](int32_t id) { return size_t(id) >= dual_.chords.size(); }),
                   unsettled_.end());
}

// Each edit's hexes with the edges it marks, gathered per hex in `scratch` (bit 15: listed), then
// the distinct hexes sorted: no search per edit and no sort of the edits.
void touchedHexesWithEdges(const Complex::EditLog& log, std::vector<HexId>& touched, std::vector<uint16_t>& edges,
                           HugeVector<uint16_t>& scratch) {
  constexpr uint16_t kListed = 0x8000;
  touched.clear();
  auto add = [&](HexId h, unsigned mask) {
    if (size_t(h) >= scratch.size()) scratch.resize(size_t(h) + 1, 0);
    uint16_t& m = scratch[size_t(h)];
    if (!m) touched.push_back(h);
    m = uint16_t(m | kListed | mask);
  };
  for (const Complex::Edit& e : log.edits) marksOf(e, add);
  sortUniqueIds(touched);  // distinct already; a long list (a sheet operation's) by bitmap, in linear time
  edges.resize(touched.size());
  for (size_t i = 0; i < touched.size(); ++i) {
    uint16_t& m = scratch[size_t(touched[i])];
    edges[i] = uint16_t(m & ~kListed);
    m = 0;
  }
}

DualChange DualTracker::update(const Complex& cx, const Complex::EditLog& edits, bool sheetsKeepTopology) {
  return updateFromLog(cx, edits, sheetsKeepTopology, nullptr);
}

DualChange DualTracker::updateUndone(const Complex& cx, const Complex::EditLog& edits, bool sheetsKeepTopology,
                                     const DualIdMemo& memo) {
  return updateFromLog(cx, edits, sheetsKeepTopology, memo.unmerge.get());
}

DualChange DualTracker::updateFromLog(const Complex& cx, const Complex::EditLog& edits, bool sheetsKeepTopology,
                                      const DualUnmergeMemo* unmerge) {
  std::vector<HexId> touched;
  touched.reserve(2 * edits.edits.size());  // at most two hexes per edit: one allocation
  touchedHexesWithEdges(edits, touched, edgesToWalk_, walked_);  // walked_ is 0 outside refreshShares
  DualChange change = updateSorted(cx, touched, sheetsKeepTopology, unmerge);
  edgesToWalk_.clear();
  return change;
}

DualChange DualTracker::update(const Complex& cx, std::vector<HexId> touched, bool sheetsKeepTopology) {
  sortUniqueIds(touched);
  edgesToWalk_.clear();  // not known: every edge of a live touched hex is walked
  return updateSorted(cx, touched, sheetsKeepTopology);
}

// touched: sorted, without repeats.
DualChange DualTracker::updateSorted(const Complex& cx, const std::vector<HexId>& touched, bool sheetsKeepTopology,
                                     const DualUnmergeMemo* unmerge) {
  const size_t cap = std::max(size_t(cx.hexCapacity()), dual_.sheetLabel.size());
  growPerHexArrays(cap);
  slotsTouched_ = 0;
  sheetSlotsTouched_ = 0;
  mergedLabels_ = 0;
  reflooded_ = false;
  unmerged_ = false;
  DualChange change;
  if (unmerge && unmergeSheets(cx, touched, *unmerge, change)) {
    // sheetState_ is the merge's memo's again
  } else {
    if (!(sheetsKeepTopology && updateSheetsLocally(cx, touched, change)) && !updateSheetsLockstep(cx, touched, change)) {
      reflooded_ = true;
      updateSheetsByFlood(cx, touched, change);
    }
    newSheetState();
  }
  slotsTouched_ = sheetSlotsTouched_;
  updateChords(cx, touched, change);
  // Reported ascending, whichever way each list was found.
  for (std::vector<int>* list : {&change.sheetsCreated, &change.sheetsRemoved, &change.sheetsChanged, &change.chordsCreated,
                                 &change.chordsRemoved, &change.chordsChanged})
    std::sort(list->begin(), list->end());
#ifdef HEXDUAL_CHECK_INVARIANTS
  checkInvariants(cx);
#endif
  return change;
}

// Each unit's invariants (their first lines state them), then the scratch state every update
// leaves cleared. Linear in the mesh: the debug build's check after every update.
void DualTracker::checkInvariants(const Complex& cx) const {
  if (dual_.sheetLabel.size() < size_t(cx.hexCapacity()) || dual_.chordLabel.size() != dual_.sheetLabel.size() ||
      edgeMarks_.size() != dual_.sheetLabel.size() || share_.size() != 3 * dual_.sheetLabel.size())
    invariantBroken("the per-hex arrays do not hold the complex's " + std::to_string(cx.hexCapacity()) + " hexes");
  checkSheetLabels(cx);
  checkShares(cx);
  checkChordRuns(cx);
  checkScratchCleared();
}

// Scratch marks are cleared by the update that set them.
void DualTracker::checkScratchCleared() const {
  auto zero = [](const auto& v) { return std::all_of(v.begin(), v.end(), [](auto x) { return x == 0; }); };
  if (!zero(front_)) invariantBroken("front_ marks left after an update");
  if (!zero(walked_)) invariantBroken("walked_ marks left after an update");
  if (!zero(delta_)) invariantBroken("delta_ (Euler changes) left after an update");
  if (!dropped_.empty()) invariantBroken("dropped chord labels left after an update");
}

}  // namespace hexdual
