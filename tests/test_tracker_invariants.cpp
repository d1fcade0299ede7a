// DualTracker::checkInvariants: it holds after every kind of update (each sheet strategy, the local
// and the re-walked chord update, undos), and it fails, naming the invariant, when the tracker's
// state is broken on purpose through DualTrackerTestAccess (the friend the tracker declares for this).
#include <doctest/doctest.h>

#include <cstdio>
#include <functional>
#include <memory>
#include <random>
#include <thread>

#include "complex/builders.hpp"
#include "dual/dual_tracker.hpp"
#include "helpers.hpp"
#include "ops/candidates.hpp"
#include "ops/op_table.hpp"
#include "ops/oplog.hpp"

namespace hexdual {
// Reaches into the tracker's private state to break one invariant at a time.
struct DualTrackerTestAccess {
  static HugeVector<int8_t>& shares(DualTracker& t) { return t.share_; }
  static HugeVector<uint16_t>& edgeMarks(DualTracker& t) { return t.edgeMarks_; }
  static std::vector<int32_t>& labelSlots(DualTracker& t) { return t.labelSlots_; }
  static std::vector<int32_t>& freeLabels(DualTracker& t) { return t.freeLabels_; }
  static HugeVector<int8_t>& signs(DualTracker& t) { return t.flooder_.signs(); }
  static std::vector<int32_t>& selfPairs(DualTracker& t) { return t.selfPairs_; }
  static void addPair(DualTracker& t, int32_t a, int32_t b) { t.pairs_.add(a, b, 1); }
  static HugeVector<int32_t>& front(DualTracker& t) { return t.front_; }
  static std::vector<int64_t>& delta(DualTracker& t) { return t.delta_; }
  static int32_t& pieceHi(DualTracker& t, int32_t chord) { return t.pieces_[size_t(chord)][0].hi; }
  static HugeVector<int32_t>& labelChord(DualTracker& t) { return t.dual_.labelChord; }
  static int64_t& euler(DualTracker& t, int32_t sheet) { return t.dual_.sheets[size_t(sheet)].euler; }
  static std::vector<Slot>& chordSlots(DualTracker& t, int32_t chord) { return t.dual_.chords[size_t(chord)].slots.own(); }
};
}  // namespace hexdual

using namespace hexdual;
using namespace hexdual::test;

namespace {

// Applies step text, updates the tracker (and a re-walking one) and checks both trackers' invariants.
// reflood: the update is told the edit may re-shape sheets even when the operation keeps them.
void step(Complex& cx, DualTracker& local, DualTracker& walked, const std::string& text, std::vector<OpResult>& done,
          bool reflood = false) {
  CAPTURE(text);
  OpResult r = applyStep(cx, text);
  local.update(cx, r.edits, keepsSheetTopology(r) && !reflood);
  walked.update(cx, r.edits, keepsSheetTopology(r) && !reflood);
  CHECK(errorOf([&] { local.checkInvariants(cx); }) == "");
  CHECK(errorOf([&] { walked.checkInvariants(cx); }) == "");
  done.push_back(std::move(r));
}

void undoAll(Complex& cx, DualTracker& local, DualTracker& walked, std::vector<OpResult>& done) {
  for (auto it = done.rbegin(); it != done.rend(); ++it) {
    cx.undo(it->edits);
    local.update(cx, it->edits, keepsSheetTopology(*it));
    walked.update(cx, it->edits, keepsSheetTopology(*it));
    CHECK(errorOf([&] { local.checkInvariants(cx); }) == "");
    CHECK(errorOf([&] { walked.checkInvariants(cx); }) == "");
  }
  done.clear();
  local.releaseRetiredTail();
  CHECK(errorOf([&] { local.checkInvariants(cx); }) == "");
}

}  // namespace

TEST_CASE("dual tracker: checkInvariants holds after each sheet strategy, both chord updates and undos") {
  Complex cx = makeGrid(7, 7, 7);  // centre hex 171 = (3,3,3), 178 = (3,4,3), 114 = (2,2,2)
  DualTracker local(cx), walked(cx);
  walked.setLocalChords(false);
  CHECK(errorOf([&] { local.checkInvariants(cx); }) == "");
  std::vector<OpResult> done;
  // The lockstep flood (an interior face collapse merges two layer sheets), the topology-kept
  // update (pillow, hex push), then the lockstep at the boundary (an edit there that may re-shape
  // sheets: the sheets it touches near the boundary are flooded whole as pieces).
  step(cx, local, walked, "facecollapse h171e11 h171f1 h178f1", done);
  CHECK_FALSE(local.lastUpdateReflooded());
  CHECK(local.mergedLabels() == 1);
  CHECK_FALSE(local.lastChordsRewalked());
  CHECK(walked.lastChordsRewalked());
  step(cx, local, walked, "pillow h171f5", done);
  step(cx, local, walked, "hexpush h114f1", done);
  CHECK_FALSE(local.lastUpdateReflooded());
  step(cx, local, walked, "pillow h0f1", done, true);
  CHECK_FALSE(local.lastUpdateReflooded());
  undoAll(cx, local, walked, done);
  {
    // The fallback reflood: an edit that may re-shape a non-orientable sheet (a twisted ring's).
    Complex tw = makeTwistedRing(4);
    DualTracker twLocal(tw), twWalked(tw);
    twWalked.setLocalChords(false);
    std::vector<OpResult> twDone;
    step(tw, twLocal, twWalked, "pillow h0f3", twDone, true);
    CHECK(twLocal.lastUpdateReflooded());
    undoAll(tw, twLocal, twWalked, twDone);
    compareDuals(tw, twLocal.dual(), extractDual(tw));
  }
  // A ring collapse after a hex push (the lockstep again, chords joined crosswise).
  const HexId first = cx.hexCapacity();
  step(cx, local, walked, "hexpush h171f5", done);
  std::string ring = "ringcollapse h" + std::to_string(first + 2) + "e";
  const HexId ringHex = cx.hexCapacity() - 4;
  for (int a = 0; a < 3; ++a)
    if (local.dual().chords[size_t(local.dual().chordAt(ringHex, a))].closed) ring += std::to_string(4 * a);
  step(cx, local, walked, ring, done);
  CHECK_FALSE(local.lastUpdateReflooded());
  undoAll(cx, local, walked, done);
  compareDuals(cx, local.dual(), extractDual(cx));
}

// Random candidate steps (every one applies) on a grid and a ring; seeds fixed and printed.
TEST_CASE("dual tracker: checkInvariants holds along random candidate sequences") {
  const OpKind kinds[] = {OpKind::Pillow,       OpKind::HexPush,  OpKind::ChordPush, OpKind::FaceCollapse,
                          OpKind::RingCollapse, OpKind::Unpillow, OpKind::HexPull};
  int applied = 0;
  for (uint32_t seed = 1; seed <= 6; ++seed) {
    std::printf("tracker invariants: seed %u\n", seed);
    CAPTURE(seed);
    std::mt19937 rng(seed);
    Complex cx = seed % 2 ? makeGrid(4, 4, 3) : makeRing(8, 2, 2);
    DualTracker local(cx), walked(cx);
    walked.setLocalChords(false);
    std::vector<OpResult> done;
    for (int k = 0; k < 8; ++k) {
      const OpKind op = kinds[rng() % 7];
      const std::vector<OpStep> steps = candidates(cx, op);
      if (steps.empty()) continue;
      step(cx, local, walked, formatOpStep(steps[rng() % steps.size()]), done);
      ++applied;
    }
    undoAll(cx, local, walked, done);
  }
  CHECK(applied >= 30);
}

TEST_CASE("dual tracker: new sheets fit the room reserved at construction (the sheet arrays are not re-copied)") {
  // A pillow adds a sheet and two chords; the tracker reserves room for half as many new sheets as
  // the mesh has chords, so that an edit session does not re-copy every sheet (and page-fault fresh
  // memory) each time the list doubles. 40 pillows on a 6^3 grid (18 sheets, 108 chords): room for 136.
  Complex cx = makeGrid(6, 6, 6);
  DualTracker tracker(cx);
  const Sheet* before = tracker.dual().sheets.data();
  const size_t sheets0 = tracker.dual().sheets.size();
  REQUIRE(sheets0 == 18);
  int pillows = 0;
  for (HexId h = 0; h < cx.hexCapacity() && pillows < 40; h += 5) {
    if (!cx.isHex(h)) continue;
    std::optional<OpResult> r = tryApplyStep(cx, "pillow h" + std::to_string(h) + "f" + std::to_string(h % 6));
    if (!r) continue;
    tracker.update(cx, r->edits, keepsSheetTopology(*r));
    ++pillows;
  }
  REQUIRE(pillows == 40);
  CHECK(tracker.dual().sheets.size() == sheets0 + 40);  // a minimal pillow's sheet is a new sphere
  CHECK(tracker.dual().sheets.data() == before);        // fails when the list re-allocated on the way
  CHECK_NOTHROW(tracker.checkInvariants(cx));
}

TEST_CASE("dual tracker: checkInvariants names the invariant a broken state breaks") {
  using A = DualTrackerTestAccess;
  Complex cx = makeGrid(4, 4, 4);
  OpResult r = applyStep(cx, "facecollapse h21e11 h21f1 h25f1");  // an interior collapse: labels merged
  auto fresh = [&] {
    auto t = std::make_unique<DualTracker>(makeGrid(4, 4, 4));
    t->update(cx, r.edits, keepsSheetTopology(r));
    REQUIRE(errorOf([&] { t->checkInvariants(cx); }) == "");
    return t;
  };
  auto broken = [&](const std::function<void(DualTracker&)>& harm) {
    auto t = fresh();
    harm(*t);
    return errorOf([&] { t->checkInvariants(cx); });
  };
  const HexId h = 1;
  const size_t s = 3 * size_t(h) + 2;  // slot (h1, axis 2)
  CHECK(broken([&](DualTracker& t) { A::shares(t)[s] += 2; }) ==
        "dual tracker invariant: slot h1 axis 2 has share " + std::to_string(A::shares(*fresh())[s] + 2) +
            ", the complex gives " + std::to_string(A::shares(*fresh())[s]));
  CHECK(contains(broken([&](DualTracker& t) { A::edgeMarks(t)[size_t(h)] ^= 1; }), "hex 1 has edge marks"));
  CHECK(contains(broken([&](DualTracker& t) { ++A::labelSlots(t)[0]; }), "label 0 is carried by"));
  CHECK(contains(broken([&](DualTracker& t) { A::freeLabels(t).push_back(0); }),
                 "label 0 (free) is out of range or listed twice"));
  CHECK(contains(broken([&](DualTracker& t) { A::signs(t)[s] = int8_t(-A::signs(t)[s]); }),
                 "disagree in orientation across face"));
  CHECK(contains(broken([&](DualTracker& t) { ++A::selfPairs(t)[0]; }),
                 "sheet 0 has 0 self-intersecting pairs of slots, selfPairs_ says 1"));
  CHECK(contains(broken([&](DualTracker& t) { A::addPair(t, 0, 1); }), "pairs_ says"));
  CHECK(contains(broken([&](DualTracker& t) { A::euler(t, 0) += 1; }),
                 "sheet 0 has Euler characteristic 2, its slots' shares give 2/2"));
  CHECK(contains(broken([&](DualTracker& t) { --A::pieceHi(t, 0); }), "chord 0 has a piece [0, "));
  CHECK(contains(broken([&](DualTracker& t) { A::labelChord(t)[0] = -1; }), "label 0's chord is -1, its cuts give 0"));
  CHECK(contains(broken([&](DualTracker& t) { std::swap(A::chordSlots(t, 0)[0], A::chordSlots(t, 0)[1]); }),
                 "chord 0's settled slot list is not its pieces'"));
  CHECK(broken([&](DualTracker& t) { A::front(t)[s] = 1; }) ==
        "dual tracker invariant: front_ marks left after an update");
  CHECK(broken([&](DualTracker& t) { A::delta(t)[0] = 2; }) ==
        "dual tracker invariant: delta_ (Euler changes) left after an update");
}

// A random pillow, hex push or chord push at live hex h, as op-log text (the draws in this order).
static std::string randomStepAt(std::mt19937& rng, HexId h) {
  const char* ops[] = {"pillow", "hexpush", "chordpush"};
  const std::string op = ops[rng() % 3], hs = "h" + std::to_string(h);
  return op == "chordpush" ? "chordpush " + hs + "e" + std::to_string(rng() % 12) + " " + hs + "f" +
                                 std::to_string(rng() % 6) + " " + hs + "f" + std::to_string(rng() % 6)
                           : op + " " + hs + "f" + std::to_string(rng() % 6);
}

// refreshShares walks only the edges an edit log can have changed (edgesChangedBy); the same log
// read after its undo must re-walk a hex the undo brings back. Random pillows, hex pushes and chord
// pushes with undos interleaved (one in four), every edge mark and share recomputed after each.
TEST_CASE("dual tracker: edge marks and shares hold when only the edited edges are walked, undos interleaved") {
  int applied = 0, undone = 0;
  for (uint32_t seed = 1; seed <= 10; ++seed) {
    std::printf("tracker edge marks: seed %u\n", seed);
    CAPTURE(seed);
    const int n = 3 + int(seed % 5);
    Complex cx = makeGrid(n, n, n);
    DualTracker tracker(cx);
    std::mt19937 rng(seed);
    std::vector<OpResult> done;
    for (int s = 0; s < 200; ++s) {
      if (!done.empty() && rng() % 4 == 0) {
        cx.undo(done.back().edits);
        tracker.update(cx, done.back().edits, keepsSheetTopology(done.back()));
        tracker.releaseRetiredTail();
        done.pop_back();
        REQUIRE_NOTHROW(tracker.checkInvariants(cx));
        ++undone;
        continue;
      }
      const HexId h = HexId(rng() % uint32_t(cx.hexCapacity()));
      if (!cx.isHex(h)) continue;
      const std::string text = randomStepAt(rng, h);
      if (std::optional<OpResult> r = tryApplyStep(cx, text)) {
        tracker.update(cx, r->edits, keepsSheetTopology(*r));
        REQUIRE_NOTHROW(tracker.checkInvariants(cx));
        // update() reads a short log's hexes and edges in one sort: the same lists as the two passes.
        std::vector<HexId> touched;
        std::vector<uint16_t> edges;
        HugeVector<uint16_t> scratch;
        touchedHexesWithEdges(r->edits, touched, edges, scratch);
        REQUIRE(touched == touchedHexes(cx, r->edits));
        REQUIRE(edges == edgesChangedBy(r->edits, touched));
        REQUIRE(std::count(scratch.begin(), scratch.end(), 0) == std::ptrdiff_t(scratch.size()));
        ++applied;
        done.push_back(std::move(*r));
      }
    }
  }
  MESSAGE("tracker edge marks: seeds 1..10, " << applied << " steps applied, " << undone << " undone");
  CHECK(applied == 767);
  CHECK(undone == 469);
}

// The chord-axis bits (bits 12-14 of touchedHexesWithEdges' words) say which slots changedChords
// must check: a live touched hex whose bit a is clear was live before and its two faces across
// axis a are glued exactly as before, and a hex not touched kept all its gluings. Checked against
// a copy of the complex taken before each random step and before each undo.
TEST_CASE("dual tracker: a slot whose chord-axis bit is clear kept its neighbours across both faces") {
  int applied = 0, undone = 0, skipped = 0;
  auto sameGluing = [](Gluing x, Gluing y) { return x.hex == y.hex && (x.boundary() || (x.face == y.face && x.orient == y.orient)); };
  auto check = [&](const Complex& before, const Complex& after, const Complex::EditLog& log) {
    std::vector<HexId> touched;
    std::vector<uint16_t> edges;
    HugeVector<uint16_t> scratch;
    touchedHexesWithEdges(log, touched, edges, scratch);
    for (HexId h = 0; h < after.hexCapacity(); ++h) {
      if (!after.isHex(h)) continue;
      const auto at = std::lower_bound(touched.begin(), touched.end(), h);
      const bool isTouched = at != touched.end() && *at == h;
      const uint16_t word = isTouched ? edges[size_t(at - touched.begin())] : 0;
      for (int a = 0; a < 3; ++a) {
        if (word & chordAxisChanged(a)) continue;
        CAPTURE(h);
        CAPTURE(a);
        REQUIRE(h < before.hexCapacity());
        REQUIRE(before.isHex(h));
        for (int f = 2 * a; f < 2 * a + 2; ++f) REQUIRE(sameGluing(after.gluing(h, f), before.gluing(h, f)));
        skipped += isTouched;
      }
    }
  };
  for (uint32_t seed = 1; seed <= 6; ++seed) {
    std::printf("chord-axis bits: seed %u\n", seed);
    CAPTURE(seed);
    const int n = 3 + int(seed % 4);
    Complex cx = makeGrid(n, n, n);
    std::mt19937 rng(seed);
    std::vector<OpResult> done;
    for (int s = 0; s < 150; ++s) {
      const Complex before = cx;
      if (!done.empty() && rng() % 4 == 0) {
        cx.undo(done.back().edits);
        check(before, cx, done.back().edits);
        done.pop_back();
        ++undone;
        continue;
      }
      const HexId h = HexId(rng() % uint32_t(cx.hexCapacity()));
      if (!cx.isHex(h)) continue;
      const std::string text = randomStepAt(rng, h);
      if (std::optional<OpResult> r = tryApplyStep(cx, text)) {
        check(before, cx, r->edits);
        ++applied;
        done.push_back(std::move(*r));
      }
    }
  }
  MESSAGE("chord-axis bits: seeds 1..6, " << applied << " steps and " << undone << " undos, " << skipped
                                          << " touched slots left out");
  CHECK(applied == 345);
  CHECK(undone == 217);
  CHECK(skipped == 4507);  // the bits do leave slots out
}

// A sheet operation's long log (thousands of edits): the one-pass gathering gives the same lists as
// touchedHexes and edgesChangedBy there too (its sort switches to a bitmap for long lists), for
// the extraction and for its undo.
TEST_CASE("dual tracker: a sheet extraction's long log gives the same touched hexes and changed edges both ways") {
  Complex cx = makeGrid(40, 40, 40);
  std::optional<OpResult> r = tryApplyStep(cx, "sheet-extract h4210e0");
  REQUIRE(r.has_value());
  REQUIRE(r->edits.edits.size() > 4096);
  for (int pass = 0; pass < 2; ++pass) {
    CAPTURE(pass);
    std::vector<HexId> touched;
    std::vector<uint16_t> edges;
    HugeVector<uint16_t> scratch;
    touchedHexesWithEdges(r->edits, touched, edges, scratch);
    CHECK(touched.size() > 4096);
    CHECK(touched == touchedHexes(cx, r->edits));
    CHECK(edges == edgesChangedBy(r->edits, touched));
    CHECK(std::count(scratch.begin(), scratch.end(), 0) == std::ptrdiff_t(scratch.size()));
    if (pass == 0) cx.undo(r->edits);
  }
}

// An undo's log names the hexes the step added, which the complex no longer has (its capacity
// shrank back): the chord rejoin's per-hex scratch must reach them too. On a fresh thread, whose
// scratch starts empty, with the tracker built after the step. (Under the sanitizer build this
// was a heap overflow; the release build wrote past the scratch silently.)
TEST_CASE("dual tracker: an undo's update names hexes past the complex's capacity (a fresh thread)") {
  std::string failure = "did not run";
  std::thread worker([&] {
    try {
      Complex cx = makeGrid(3, 3, 3);
      const OpResult r = applyStep(cx, "pillow h13f5");
      const HexId grown = cx.hexCapacity();
      DualTracker tracker(cx);
      cx.undo(r.edits);
      tracker.update(cx, r.edits, keepsSheetTopology(r));
      compareDuals(cx, tracker.dual(), extractDual(cx));
      failure = grown == 29 && cx.hexCapacity() == 27 ? "" : "the capacities are not 29 then 27";
    } catch (const std::exception& e) {
      failure = e.what();
    }
  });
  worker.join();
  CHECK(failure == "");
}
