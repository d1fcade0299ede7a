#include <doctest/doctest.h>

#include "complex/builders.hpp"
#include "dual/dual_tracker.hpp"
#include "helpers.hpp"
#include "io/io.hpp"
#include "ops/op_table.hpp"
#include "ops/oplog.hpp"
#include "ops/report.hpp"

using namespace hexdual;
using namespace hexdual::test;

TEST_CASE("grid sheets are a+b+c disks and chords ab+bc+ca open columns") {
  for (auto [a, b, c] : {std::array<int, 3>{1, 1, 1}, {2, 3, 4}, {3, 3, 3}, {6, 2, 1}}) {
    CAPTURE(a);
    CAPTURE(b);
    CAPTURE(c);
    Dual d = extractDual(makeGrid(a, b, c));
    CHECK(d.sheets.size() == size_t(a + b + c));
    CHECK(countTopology(d, "disk") == a + b + c);
    for (const Sheet& s : d.sheets) {
      CHECK(s.boundaryLoops == 1);
      CHECK(s.euler == 1);
      CHECK_FALSE(s.selfIntersecting);
    }
    CHECK(d.chords.size() == size_t(a * b + b * c + c * a));
    for (const Chord& ch : d.chords) {
      CHECK_FALSE(ch.closed);
      CHECK_FALSE(ch.selfIntersecting);
    }
    // Every hex lies on 3 sheets and 3 chords, consistently with the slot lists.
    Complex cx = makeGrid(a, b, c);
    for (HexId h : cx.hexes())
      for (int ax = 0; ax < 3; ++ax) {
        const Sheet& s = d.sheets[size_t(d.sheetAt(h, ax))];
        CHECK(std::binary_search(s.slots.begin(), s.slots.end(), Slot{h, ax}));
      }
  }
}

TEST_CASE("grid chord lengths and sheet sizes") {
  Dual d = extractDual(makeGrid(2, 3, 4));
  int len2 = 0, len3 = 0, len4 = 0;
  for (const Chord& ch : d.chords) {
    len2 += ch.slots.size() == 2;
    len3 += ch.slots.size() == 3;
    len4 += ch.slots.size() == 4;
  }
  CHECK(len2 == 3 * 4);  // columns along x
  CHECK(len3 == 2 * 4);  // along y
  CHECK(len4 == 2 * 3);  // along z
  // Chords are ordered from one boundary end to the other: consecutive hexes are glued.
  Complex cx = makeGrid(2, 3, 4);
  for (const Chord& ch : d.chords)
    for (size_t i = 0; i + 1 < ch.slots.size(); ++i) {
      Gluing g = cx.gluing(ch.slots[i].hex, 2 * ch.slots[i].axis + 1);
      bool adjacent = g.hex == ch.slots[i + 1].hex || cx.gluing(ch.slots[i].hex, 2 * ch.slots[i].axis).hex == ch.slots[i + 1].hex;
      CHECK(adjacent);
    }
}

TEST_CASE("ring mesh 8x2x2: circumferential chords closed, radial and axial sheets annuli") {
  Complex cx = makeRing(8, 2, 2);
  Dual d = extractDual(cx);
  CHECK(d.sheets.size() == 12);
  CHECK(countTopology(d, "annulus") == 4);  // 2 radial layers + 2 axial layers
  CHECK(countTopology(d, "disk") == 8);     // one per angular position
  int closed = 0;
  for (const Chord& ch : d.chords) {
    if (ch.closed) {
      ++closed;
      CHECK(ch.slots.size() == 8);
      CHECK(ch.slots[0].axis == 1);  // local y runs around
    } else {
      CHECK(ch.slots.size() == 2);
    }
  }
  CHECK(closed == 4);
  CHECK(d.chords.size() == 4 + 8 * 2 + 8 * 2);
}

TEST_CASE("the hand-made pillow has a sphere sheet of 2 hexes and two closed chords of length 2") {
  Complex cx = io::readNative(kPillowNative, "pillow.hxd");
  Dual d = extractDual(cx);
  Dual g = extractDual(makeGrid(1, 1, 2));
  CHECK(d.sheets.size() == g.sheets.size() + 1);
  CHECK(countTopology(d, "sphere") == 1);
  for (const Sheet& s : d.sheets)
    if (s.topology == "sphere") {
      CHECK(s.slots.size() == 2);
      CHECK(s.slots[0] == Slot{2, 2});
      CHECK(s.slots[1] == Slot{3, 2});
      CHECK(s.euler == 2);
      CHECK(s.boundaryLoops == 0);
    }
  int closedLen2 = 0;
  for (const Chord& ch : d.chords) closedLen2 += ch.closed && ch.slots.size() == 2;
  CHECK(closedLen2 == 2);
  // The chord through q gains X and Y: A, X, Y, B.
  const Chord& z = d.chords[size_t(d.chordAt(0, 2))];
  REQUIRE(z.slots.size() == 4);
  CHECK(z.slots[0].hex == 0);
  CHECK(z.slots[1].hex == 2);
  CHECK(z.slots[2].hex == 3);
  CHECK(z.slots[3].hex == 1);
  CHECK_FALSE(z.closed);
}

TEST_CASE("dual ids are deterministic") {
  Dual a = extractDual(makeRing(8, 2, 2)), b = extractDual(makeRing(8, 2, 2));
  CHECK(a.sheetLabel == b.sheetLabel);
  CHECK(a.labelSheet == b.labelSheet);
  CHECK(a.chordLabel == b.chordLabel);
}

TEST_CASE("validateDual accepts extracted duals and names a tampered slot") {
  for (Complex cx : {makeGrid(3, 2, 2), makeRing(8, 2, 2), io::readNative(kPillowNative, "p.hxd")}) {
    Dual d = extractDual(cx);
    validateDual(cx, d);
    Dual bad = d;
    bad.sheetLabel[1][0] = bad.sheetLabel[1][1];
    CHECK(contains(errorOf([&] { validateDual(cx, bad); }), "validateDual: slot (hex 1, axis 0)"));
  }
}

TEST_CASE("dual tracker: after an exact undo, releaseRetiredTail gives the redone step the same ids") {
  Complex cx = makeGrid(3, 3, 3);
  DualTracker tracker(cx);
  const Dual before = tracker.dual();
  StepReport first = applyStepTracked(cx, tracker, parseOpStep("pillow h13f5"));
  REQUIRE(first.dual.sheetsCreated == std::vector<int>{9});
  REQUIRE(first.dual.chordsCreated == std::vector<int>{27, 28});
  cx.undo(first.result.edits);
  tracker.update(cx, first.result.edits, keepsSheetTopology(first.result));
  CHECK(tracker.dual().sheets.size() == 10);  // sheet 9 retired, still holding its id
  tracker.releaseRetiredTail();
  CHECK(tracker.dual().sheets.size() == before.sheets.size());
  CHECK(tracker.dual().chords.size() == before.chords.size());
  StepReport again = applyStepTracked(cx, tracker, parseOpStep("pillow h13f5"));
  CHECK(again.dual.sheetsCreated == first.dual.sheetsCreated);
  CHECK(again.dual.chordsCreated == first.dual.chordsCreated);
  CHECK(again.dual.chordsChanged == first.dual.chordsChanged);
}

namespace {
struct CollapseCost {
  size_t explored = 0, merged = 0, chordSlots = 0, undoExplored = 0, pushChordSlots = 0, undoChordSlots = 0;
  size_t readUndoExplored = 0;  // the undo's sheet slots when the lists were read between step and undo
};
// Face collapse (or a hex push then ring collapse) at the centre of an n^3 grid, dual kept by the
// tracker, checked against a fresh extraction (on a copy of the tracker, so that no list is read),
// then undone (exactly: updateUndone with the step's memo); what each update touched. Then once
// more with the lists read between the step and its undo, which then re-floods the merged sheet.
CollapseCost collapseAtCentre(int n, bool ring) {
  Complex cx = makeGrid(n, n, n);
  DualTracker tracker(cx);
  auto id = [&](int i, int j, int k) { return std::to_string(i + n * (j + n * k)); };
  const int c = n / 2;
  size_t pushChordSlots = 0;
  std::string step = "facecollapse h" + id(c, c, c) + "e11 h" + id(c, c, c) + "f1 h" + id(c, c + 1, c) + "f1";
  if (ring) {
    const HexId first = cx.hexCapacity();
    applyStepTracked(cx, tracker, parseOpStep("hexpush h" + id(c, c, c) + "f5"));
    pushChordSlots = tracker.chordSlotsTouched();
    step = "ringcollapse h" + std::to_string(first + 2) + "e";
    const HexId ringHex = cx.hexCapacity() - 4;  // the ring chord's axis there names the edge
    for (int a = 0; a < 3; ++a)
      if (tracker.dual().chords[size_t(tracker.dual().chordAt(ringHex, a))].closed) step += std::to_string(4 * a);
  }
  const DualTracker before = tracker;
  DualIdMemo memo;
  StepReport r = applyStepTracked(cx, tracker, parseOpStep(step), {}, &memo);
  CHECK_FALSE(tracker.lastUpdateReflooded());
  CHECK(memo.unmerge != nullptr);  // every old sheet kept: recorded for the undo
  compareDuals(cx, DualTracker(tracker).dual(), extractDual(cx));
  CollapseCost cost{tracker.sheetSlotsTouched(), tracker.mergedLabels(), tracker.chordSlotsTouched(), 0,
                    pushChordSlots};
  undoStepTracked(cx, tracker, r, memo);
  CHECK(tracker.lastUpdateUnmerged());
  CHECK_FALSE(tracker.lastUpdateReflooded());
  cost.undoExplored = tracker.sheetSlotsTouched();
  cost.undoChordSlots = tracker.chordSlotsTouched();
  compareDuals(cx, DualTracker(tracker).dual(), extractDual(cx));
  for (HexId h : cx.hexes()) {  // the ids before the step
    REQUIRE(tracker.dual().sheetsAt(h) == before.dual().sheetsAt(h));
    REQUIRE(tracker.dual().chordsAt(h) == before.dual().chordsAt(h));
  }
  REQUIRE(tracker.dual().sheets.size() == before.dual().sheets.size());
  tracker.checkInvariants(cx);

  DualIdMemo memo2;
  StepReport r2 = applyStepTracked(cx, tracker, parseOpStep(step), {}, &memo2);
  compareDuals(cx, tracker.dual(), extractDual(cx));  // reads every list: the merge's runs are merged
  undoStepTracked(cx, tracker, r2, memo2);
  CHECK(tracker.lastUpdateUnmerged());  // the read lists split by label in one pass, no flood
  CHECK_FALSE(tracker.lastUpdateReflooded());
  cost.readUndoExplored = tracker.sheetSlotsTouched();
  compareDuals(cx, tracker.dual(), extractDual(cx));
  tracker.checkInvariants(cx);
  return cost;
}
}  // namespace

// TK03 §4.4: a collapse changes the dual in one place; the lockstep flood explores that place, not
// the sheets it cuts (which grow as n^2). Counted in slots, not timed.
TEST_CASE("dual tracker: ring and face collapse updates explore O(region) sheet slots (30^3 and 60^3)") {
  for (bool ring : {false, true}) {
    CAPTURE(ring);
    const CollapseCost small = collapseAtCentre(30, ring), big = collapseAtCentre(60, ring);
    MESSAGE((ring ? "ring" : "face") << " collapse, 30^3 / 60^3: sheet slots " << small.explored << " / " << big.explored
                                     << ", merged labels " << small.merged << " / " << big.merged << ", chord slots "
                                     << small.chordSlots << " / " << big.chordSlots << ", undo explored "
                                     << small.undoExplored << " / " << big.undoExplored << ", undo chord slots "
                                     << small.undoChordSlots << " / " << big.undoChordSlots << ", hex push chord slots "
                                     << small.pushChordSlots << " / " << big.pushChordSlots
                                     << ", undo explored with the lists read between " << small.readUndoExplored
                                     << " / " << big.readUndoExplored);
    // Every sheet slot the update visits, merge included, is in the same region whatever the grid size.
    CHECK(small.explored == (ring ? 165 : 114));
    CHECK(big.explored == small.explored);
    // Both collapses merge two parallel layer sheets of n^2 slots (TK03 §4.4): one label is
    // re-pointed, no slot is re-written.
    CHECK(small.merged == 1);
    CHECK(big.merged == 1);
    // The hex push before the ring collapse cuts and re-joins the chords through the pushed hex
    // next to it: spliced in place, the same slots at every size.
    if (ring) {
      CHECK(small.pushChordSlots == 92);  // 112 before slots with no re-glued face across their axis were skipped
      CHECK(big.pushChordSlots == small.pushChordSlots);
    }
    // Both collapses cut two chords and join them crosswise (TK03 §4.4): the untouched stretches
    // keep their labels and places, only the walks through the touched hexes are written, so the
    // chord slots touched are the same at every size.
    // (121 / 58 and 133 / 58 before changedChords skipped the slots whose two faces across their
    // axis the edit left glued as they were.)
    CHECK(small.chordSlots == (ring ? 64 : 20));
    CHECK(big.chordSlots == small.chordSlots);
    CHECK(small.undoChordSlots == (ring ? 76 : 20));
    CHECK(big.undoChordSlots == small.undoChordSlots);
    // The undo splits the merged layer again from the step's memo: the touched slots only, the
    // same at every size. With the lists read in between, each read list the step changed is split
    // by the labels given back in one pass: the merged layer (2n²) and, after a ring collapse, two
    // more layers whose lists the step edited (2n²), where a flood walked the same slots and their
    // neighbours (3.3 ms instead of 6 µs at 100³: bench/README.md, "Undo from the step's memo").
    CHECK(small.readUndoExplored == (ring ? 4 : 2) * 30 * 30 + (ring ? 79 : 42));
    CHECK(big.readUndoExplored == (ring ? 4 : 2) * 60 * 60 + (ring ? 79 : 42));
  }
}

// Steps undone in LIFO order, none of whose lists was read in between: each undo restores its
// step's sheets from the memo, the later undo's restore leaving the state the earlier memo names,
// also when the later step crossed a sheet the earlier one merged (whose list still holds the
// merge's pending run: a memo records the pending edits, it does not merge them).
TEST_CASE("dual tracker: collapses undone in LIFO order restore their sheets from the memo") {
  for (bool overlapping : {false, true}) {
    CAPTURE(overlapping);
    const int n = 14;
    Complex cx = makeGrid(n, n, n);
    DualTracker tracker(cx);
    const DualTracker before = tracker;
    auto id = [&](int i, int j, int k) { return std::to_string(i + n * (j + n * k)); };
    auto faceCollapse = [&](int i, int j, int k) {
      return "facecollapse h" + id(i, j, k) + "e11 h" + id(i, j, k) + "f1 h" + id(i, j + 1, k) + "f1";
    };
    // Apart, the three touch no sheet in common; overlapping, the second and third cross the first's.
    const std::vector<std::string> steps =
        overlapping ? std::vector<std::string>{faceCollapse(3, 3, 3), faceCollapse(7, 4, 6), faceCollapse(4, 8, 9)}
                    : std::vector<std::string>{faceCollapse(2, 2, 2), faceCollapse(6, 6, 6), faceCollapse(10, 10, 10)};
    std::vector<std::pair<StepReport, DualIdMemo>> done;
    for (const std::string& text : steps) {
      CAPTURE(text);
      DualIdMemo memo;
      StepReport r = applyStepTracked(cx, tracker, parseOpStep(text), {}, &memo);
      CHECK(memo.unmerge != nullptr);
      done.emplace_back(std::move(r), std::move(memo));
    }
    compareDuals(cx, DualTracker(tracker).dual(), extractDual(cx));
    while (!done.empty()) {
      CAPTURE(done.size());
      undoStepTracked(cx, tracker, done.back().first, done.back().second);
      CHECK(tracker.lastUpdateUnmerged());
      CHECK(tracker.sheetSlotsTouched() < 100);
      done.pop_back();
      compareDuals(cx, DualTracker(tracker).dual(), extractDual(cx));
    }
    for (HexId h : cx.hexes()) {
      REQUIRE(tracker.dual().sheetsAt(h) == before.dual().sheetsAt(h));
      REQUIRE(tracker.dual().chordsAt(h) == before.dual().chordsAt(h));
    }
    REQUIRE(tracker.dual().sheets.size() == before.dual().sheets.size());
    REQUIRE(tracker.dual().chords.size() == before.dual().chords.size());
    tracker.checkInvariants(cx);
    compareDuals(cx, tracker.dual(), before.dual());
  }
}

// A chord cut and re-joined in many places is listed as many pieces; past 16 it is given one run
// again, and it always reads as a re-walk lists it.
TEST_CASE("dual tracker: a chord cut in many places stays at most 16 pieces and reads as a re-walk") {
  const int nx = 60;  // 19 hex pushes along the chord: more than 16 pieces, so it is compacted once
  Complex cx = makeGrid(nx, 5, 5);
  DualTracker local(cx), walked(cx);
  walked.setLocalChords(false);
  auto hex = [&](int i, int j, int k) { return HexId(i + nx * (j + 5 * k)); };
  const int32_t chord = local.dual().chordAt(hex(0, 2, 3), 0);  // along x, above the pushed hexes
  size_t most = 0, previous = 0;
  bool compacted = false;
  for (int i = 2; i < nx - 2; i += 3) {
    CAPTURE(i);
    OpResult r = applyStep(cx, "hexpush h" + std::to_string(hex(i, 2, 2)) + "f5");
    local.update(cx, r.edits, keepsSheetTopology(r));
    walked.update(cx, r.edits, keepsSheetTopology(r));
    CHECK_FALSE(local.lastChordsRewalked());
    const int32_t id = local.dual().chordAt(hex(0, 2, 3), 0);
    CHECK(id == chord);
    const size_t pieces = local.chordPieces(id);
    compacted = compacted || (pieces < previous && previous > 8);  // given one run again
    previous = pieces;
    most = std::max(most, pieces);
    CHECK(pieces <= 16);
    CHECK(local.dual().chords[size_t(id)].slots == walked.dual().chords[size_t(id)].slots);
  }
  CHECK(most > 8);
  CHECK(compacted);
  validateDual(cx, local.dual());
  compareDuals(cx, local.dual(), extractDual(cx));
}

// A merged sheet's list is settled when read: runs join in order, removals drop one listed copy
// each (a slot removed and added back before the read stays listed once).
namespace {
// Slots from (hex, axis) pairs, for the SlotList tests.
std::vector<Slot> slots(std::initializer_list<std::pair<int, int>> xs) {
  std::vector<Slot> v;
  for (auto [h, a] : xs) v.push_back({h, a});
  return v;
}
}  // namespace

TEST_CASE("SlotList: pending runs and removals read as one sorted list") {
  SlotList a(slots({{1, 0}, {4, 2}, {9, 1}}));
  SlotList b(slots({{2, 1}, {4, 0}}));
  b.add(slots({{7, 2}}));
  b.remove(slots({{2, 1}}));
  a.absorb(std::move(b));
  CHECK(b.empty());
  CHECK(a.size() == 5);
  a.remove(slots({{9, 1}, {1, 0}}));
  a.add(slots({{1, 0}, {3, 1}}));
  CHECK(a.size() == 5);
  CHECK(a.get() == slots({{1, 0}, {3, 1}, {4, 0}, {4, 2}, {7, 2}}));
  CHECK(a.size() == a.get().size());
  SlotList many;
  for (int h = 40; h-- > 0;) many.add(slots({{h, 0}}));  // more runs than are kept pending
  CHECK(many.size() == 40);
  CHECK(std::is_sorted(many.begin(), many.end()));
  CHECK(many.front() == Slot{0, 0});
  CHECK(many.back() == Slot{39, 0});
  // Additions come in any order (sorted once, when merged), more of them than are kept pending.
  SlotList mixed(slots({{5, 0}}));
  mixed.add(slots({{9, 2}, {3, 1}, {7, 0}}));
  for (int h = 100; h < 140; ++h) mixed.add(slots({{h + 100, 0}, {h, 1}}));
  mixed.remove(slots({{5, 0}}));
  CHECK(mixed.size() == 83);
  CHECK(mixed.get().size() == 83);
  CHECK(std::is_sorted(mixed.begin(), mixed.end()));
  CHECK(mixed.front() == Slot{3, 1});
  CHECK(mixed.back() == Slot{239, 0});
}

// A mark counts a list's pending edits; the edits since (runs absorbed, additions, removals) roll
// back, and a list merged away is rebuilt from the runs it handed over and its recorded pending
// edits: both read as before, with the versions the marks recorded.
TEST_CASE("SlotList: a merge and the edits after a mark roll back exactly") {
  SlotList keep(slots({{2, 0}, {6, 0}, {10, 0}}));
  keep.add(slots({{8, 2}}));
  SlotList x(slots({{1, 1}, {5, 1}}));
  SlotList other(slots({{3, 1}}));
  x.absorb(std::move(other));  // x: a list and a pending run
  x.add(slots({{9, 1}, {4, 1}}));
  x.remove(slots({{5, 1}}));
  const SlotList keepCopy = keep, xCopy = x;
  const SlotList::Mark mk = keep.mark(), mx = x.mark();
  const size_t listed = x.listedSize();
  std::vector<size_t> runSizes;
  for (size_t r = 0; r < x.pendingRuns(); ++r) runSizes.push_back(x.runSize(r));
  const std::vector<Slot> adds = x.pendingAdds(), gone = x.pendingGone();
  REQUIRE(runSizes == std::vector<size_t>{1});
  // The step: a removal from x, the merge, an addition and a removal on keep.
  x.remove(slots({{1, 1}}));
  keep.absorb(std::move(x));
  keep.add(slots({{12, 0}}));
  keep.remove(slots({{6, 0}}));
  CHECK(keep.version() == mk.version);  // nothing merged: only appended
  REQUIRE(keep.pendingRuns() == mk.runs + 3);  // x's list, its run, its additions (sorted)
  std::vector<std::vector<Slot>> handed = keep.rollBack(mk);
  REQUIRE(handed.size() == 3);
  CHECK(handed[0].size() == listed);
  x.reset(std::move(handed[0]), {std::move(handed[1])}, adds, gone, mx);
  CHECK(keep.size() == keepCopy.size());
  CHECK(x.size() == xCopy.size());
  CHECK(keep.version() == mk.version);
  CHECK(x.version() == mx.version);
  CHECK(keep.get() == keepCopy.get());
  CHECK(x.get() == slots({{1, 1}, {3, 1}, {4, 1}, {9, 1}}));
  CHECK(x.get() == xCopy.get());
}

// A list handed over by a merge brings its pending additions, which wait in no order: they join
// as a sorted run (they once joined as they came, and the next read merged an unsorted run: a
// sheet then read with slots twice and out of order, found by the undo property test).
TEST_CASE("SlotList: a merged list's unsorted pending additions read sorted") {
  SlotList a(slots({{2, 0}, {6, 0}, {10, 0}}));
  SlotList b(slots({{1, 1}}));
  b.add(slots({{9, 1}, {3, 1}, {5, 1}}));
  b.add(slots({{4, 1}}));
  a.absorb(std::move(b));
  a.remove(slots({{3, 1}, {6, 0}}));
  CHECK(a.size() == 6);
  CHECK(a.get() == slots({{1, 1}, {2, 0}, {4, 1}, {5, 1}, {9, 1}, {10, 0}}));
  CHECK(a.size() == a.get().size());
}

// Extraction lists every sheet's slots in one pool and every chord's in another; a list copies
// its range out when written, and the pool and the other lists viewing it are left as they were.
TEST_CASE("PooledSlots: extraction's lists view two pools; a written list copies its range out") {
  const Complex cx = makeGrid(3, 3, 3);
  Dual d = extractDual(cx);
  REQUIRE(d.sheets.size() == 9);
  REQUIRE(d.chords.size() == 27);
  size_t sheetSlots = 0, chordSlots = 0;
  for (const Sheet& sh : d.sheets) {
    CHECK(sh.slots.get().pooled());
    CHECK(sh.slots.size() == 9);
    CHECK(std::is_sorted(sh.slots.begin(), sh.slots.end()));
    sheetSlots += sh.slots.size();
  }
  for (const Chord& ch : d.chords) {
    CHECK(ch.slots.pooled());
    CHECK(ch.slots.size() == 3);
    chordSlots += ch.slots.size();
  }
  CHECK(sheetSlots == 81);
  CHECK(chordSlots == 81);
  // Consecutive lists of one pool: the first chord's last slot sits just before the next chord's first.
  CHECK(d.chords[0].slots.end() == d.chords[1].slots.begin());
  // A copy shares the pool; writing one copy leaves the other (and the next list) reading the pool.
  const std::vector<Slot> before(d.chords[0].slots.begin(), d.chords[0].slots.end());
  PooledSlots copy = d.chords[0].slots;
  CHECK(copy.begin() == d.chords[0].slots.begin());
  copy.push_back({26, 0});
  CHECK(!copy.pooled());
  CHECK(copy.size() == 4);
  CHECK(copy.back() == Slot{26, 0});
  CHECK(d.chords[0].slots.pooled());
  CHECK(d.chords[0].slots == before);
  CHECK(d.chords[0].slots.end() == d.chords[1].slots.begin());
  // Assigning a list its own pooled range keeps the slots (the pool is let go after the copy).
  PooledSlots alone = d.chords[2].slots;
  const std::vector<Slot> third(alone.begin(), alone.end());
  d = Dual();  // every other view of the pools is gone
  alone.assign(alone.begin(), alone.end());
  CHECK(!alone.pooled());
  CHECK(alone == third);
  CHECK(copy.size() == 4);
}
