// Property test: random sequences of operations and inverses (fixed, printed seeds). After every
// step: validate(), the incremental dual equals a from-scratch extraction, the step's inverse
// operation gives back an isomorphic complex; rejected steps leave the complex exactly as it was;
// undoing the whole sequence restores the start exactly. HEXDUAL_PROPERTY_SEQUENCES sets the count.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <random>

#include "complex/builders.hpp"
#include "complex/canonical.hpp"
#include "dual/dual_tracker.hpp"
#include "helpers.hpp"
#include "ops/op_table.hpp"
#include "ops/report.hpp"
#include "ops/oplog.hpp"
#include "ops/support.hpp"

using namespace hexdual;
using namespace hexdual::test;

namespace {

struct Stats {
  int64_t applied = 0, rejected = 0, inverses = 0;
  int64_t lockstep = 0;  // updates of cut or re-glued sheets done by the local lockstep flood (no re-flood)
  std::map<std::string, int64_t> perOp;
};

// A random step: mostly ones likely to apply, with entities drawn from live hexes.
// collapses: mostly face collapses, hex pushes and ring collapses (the steps that cut and re-glue sheets).
std::string randomStep(const Complex& cx, std::mt19937& rng, const std::vector<HexId>& recent, bool collapses) {
  auto pick = [&](int n) { return int(rng() % uint32_t(n)); };
  std::vector<HexId> live;
  for (HexId h : cx.hexes()) live.push_back(h);
  HexId h = (!recent.empty() && pick(2)) ? recent[size_t(pick(int(recent.size())))] : live[size_t(pick(int(live.size())))];
  if (!cx.isHex(h)) h = live[size_t(pick(int(live.size())))];
  std::string H = "h" + std::to_string(h);
  static constexpr int kCollapseHeavy[] = {2, 3, 6, 8, 8, 0};
  switch (collapses ? kCollapseHeavy[pick(6)] : pick(9)) {
    case 0: return "pillow " + H + "f" + std::to_string(pick(6));
    case 1: return "unpillow " + H;
    case 2:
    case 3:
    case 4: {  // chord push or face collapse: two quads of a closed edge cycle
      EdgeRef e{h, pick(12)};
      try {
        auto st = ops::closedEdgeStar(cx, e, "test");
        int n = int(st.inc.size()), i = pick(n), j = pick(n);
        std::string f = "h" + std::to_string(st.inc[size_t(i)].hex) + "f" + std::to_string(st.exitFace[size_t(i)]);
        std::string g = "h" + std::to_string(st.inc[size_t(j)].hex) + "f" + std::to_string(st.exitFace[size_t(j)]);
        return std::string(pick(3) && !collapses ? "chordpush " : "facecollapse ") + H + "e" + std::to_string(e.edge) + " " + f + " " + g;
      } catch (const Error&) {
        return "chordpush " + H + "e" + std::to_string(e.edge) + " " + H + "f0 " + H + "f1";
      }
    }
    case 5: return "chordpull " + H;
    case 6: return "hexpush " + H + "f" + std::to_string(pick(6));
    case 7: return "hexpull " + H + "f" + std::to_string(pick(6));
    default: return "ringcollapse " + H + "e" + std::to_string(pick(12));
  }
}

void runSequence(const Complex& start, uint32_t seed, Stats& stats, bool collapses = false) {
  std::mt19937 rng(seed);
  Complex cx = start;
  DualTracker tracker(cx);
  std::vector<OpResult> done;
  std::vector<HexId> recent;
  int length = 1 + int(rng() % 12);
  for (int step = 0; step < length; ++step) {
    std::string text = randomStep(cx, rng, recent, collapses);
    CAPTURE(seed);
    CAPTURE(step);
    CAPTURE(text);
    Complex before = cx;
    std::string dump = stateDump(cx);
    OpResult r;
    try {
      r = applyStep(cx, text);
    } catch (const Error&) {
      ++stats.rejected;
      REQUIRE(stateDump(cx) == dump);  // a rejected step changes nothing
      continue;
    }
    ++stats.applied;
    ++stats.perOp[opName(r.op.value())];
    const std::string inverse = r.inverse ? formatOpStep(*r.inverse) : "(none: " + r.noInverse + ")";
    if (std::getenv("HEXDUAL_PROPERTY_TRACE")) std::fprintf(stderr, "seed %u step %d: %s -> %s\n", seed, step, text.c_str(), inverse.c_str());
    cx.validate();
    tracker.update(cx, r.edits, keepsSheetTopology(r));
    stats.lockstep += !keepsSheetTopology(r) && !tracker.lastUpdateReflooded();
    validateDual(cx, tracker.dual());
    compareDuals(cx, tracker.dual(), extractDual(cx));
    // The inverse operation, on a copy, gives back an isomorphic complex.
    // Every reported inverse applies; only ring collapse may have none (with the reason).
    REQUIRE((r.inverse || (r.op == OpKind::RingCollapse && !r.noInverse.empty())));
    if (r.inverse) {
      CAPTURE(inverse);
      Complex back = cx;
      applyStep(back, *r.inverse);
      back.validate();
      REQUIRE(isomorphic(back, before));
      ++stats.inverses;
    }
    recent = r.createdHexes;
    done.push_back(std::move(r));
  }
  std::string startDump = stateDump(start);
  for (auto it = done.rbegin(); it != done.rend(); ++it) {
    cx.undo(it->edits);
    tracker.update(cx, it->edits, keepsSheetTopology(*it));
    stats.lockstep += !keepsSheetTopology(*it) && !tracker.lastUpdateReflooded();
    validateDual(cx, tracker.dual());
  }
  CAPTURE(seed);
  REQUIRE(stateDump(cx) == startDump);
  compareDuals(cx, tracker.dual(), extractDual(cx));
}

}  // namespace

TEST_CASE("property: random operation sequences on grids and rings") {
  int sequences = 10000;
  if (const char* env = std::getenv("HEXDUAL_PROPERTY_SEQUENCES")) sequences = std::atoi(env);
  const uint32_t firstSeed = 20261122;
  std::vector<Complex> meshes{makeGrid(3, 3, 3), makeGrid(4, 4, 4), makeRing(8, 3, 3), makeGrid(2, 2, 2), makeGrid(4, 3, 3)};
  Stats stats;
  int from = 0;
  if (const char* env = std::getenv("HEXDUAL_PROPERTY_FROM")) from = std::atoi(env);  // replay one failing seed
  for (int k = from; k < from + sequences; ++k) runSequence(meshes[size_t(k) % meshes.size()], firstSeed + uint32_t(k), stats);
  std::string perOp;
  for (auto& [op, n] : stats.perOp) perOp += " " + op + "=" + std::to_string(n);
  MESSAGE("property: " << sequences << " sequences, seeds " << firstSeed << ".." << firstSeed + uint32_t(sequences) - 1
                       << ": " << stats.applied << " steps applied, " << stats.rejected << " rejected, " << stats.inverses
                       << " inverses checked; " << stats.lockstep << " local lockstep updates;" << perOp);
  CHECK(stats.applied > sequences);
  for (const char* op : {"pillow", "unpillow", "chordpush", "chordpull", "hexpush", "hexpull", "ringcollapse", "facecollapse"}) {
    CAPTURE(op);
    CHECK(stats.perOp[op] > 0);
  }
}

// The same on grids big enough that most steps are far from the boundary, so that cut and re-glued
// sheets are updated by the lockstep flood (not re-flooded) and still equal a fresh extraction.
TEST_CASE("property: lockstep sheet updates on 7x7x7 and 8x6x6 grids") {
  int sequences = 300;
  if (const char* env = std::getenv("HEXDUAL_PROPERTY_SEQUENCES")) sequences = std::min(sequences, std::atoi(env));
  const uint32_t firstSeed = 20261201;
  std::vector<Complex> meshes{makeGrid(7, 7, 7), makeGrid(8, 6, 6)};
  Stats stats;
  for (int k = 0; k < sequences; ++k) runSequence(meshes[size_t(k) % meshes.size()], firstSeed + uint32_t(k), stats, true);
  MESSAGE("property (lockstep): " << sequences << " sequences, seeds " << firstSeed << ".." << firstSeed + uint32_t(sequences) - 1
                                  << ": " << stats.applied << " steps applied, " << stats.lockstep << " local lockstep updates");
  CHECK(stats.lockstep >= sequences / 10);
  CHECK(stats.perOp["facecollapse"] > 0);
  CHECK(stats.perOp["ringcollapse"] > 0);
}

// The local chord update (stretches kept, walks through the touched hexes) against the re-walk of
// every changed chord: the same ids, slot lists in the same order, flags and per-slot chord ids
// after every step of longer sequences (pieces pile up and are joined again). Steps are undone at
// random right after they are applied (as the explorer's back button does), and the whole dual,
// sheets included, is validated after every step and every undo.
TEST_CASE("property: local chord updates equal a re-walk of the changed chords") {
  int sequences = 200;
  if (const char* env = std::getenv("HEXDUAL_PROPERTY_SEQUENCES")) sequences = std::min(sequences, std::atoi(env));
  const uint32_t firstSeed = 20261202;
  std::vector<Complex> meshes{makeGrid(6, 6, 6), makeRing(10, 3, 3), makeGrid(7, 5, 5)};
  int64_t steps = 0, rewalked = 0;
  for (int k = 0; k < sequences; ++k) {
    const uint32_t seed = firstSeed + uint32_t(k);
    CAPTURE(seed);
    std::mt19937 rng(seed);
    Complex cx = meshes[size_t(k) % meshes.size()];
    DualTracker local(cx), walked(cx);
    walked.setLocalChords(false);
    std::vector<HexId> recent;
    for (int step = 0; step < 40; ++step) {
      std::string text = randomStep(cx, rng, recent, k % 2 == 0);
      CAPTURE(text);
      OpResult r;
      try {
        r = applyStep(cx, text);
      } catch (const Error&) {
        continue;
      }
      ++steps;
      const DualChange a = local.update(cx, r.edits, keepsSheetTopology(r));
      const DualChange b = walked.update(cx, r.edits, keepsSheetTopology(r));
      rewalked += local.lastChordsRewalked();
      validateDual(cx, local.dual());
      auto sorted = [](std::vector<int> v) {
        std::sort(v.begin(), v.end());
        return v;
      };
      REQUIRE(a.chordsCreated == b.chordsCreated);
      REQUIRE(a.chordsRemoved == b.chordsRemoved);
      REQUIRE(sorted(a.chordsChanged) == sorted(b.chordsChanged));
      const Dual &da = local.dual(), &db = walked.dual();
      REQUIRE(da.chords.size() == db.chords.size());
      for (size_t c = 0; c < da.chords.size(); ++c) {
        CAPTURE(c);
        REQUIRE(da.chords[c].alive == db.chords[c].alive);
        REQUIRE(da.chords[c].closed == db.chords[c].closed);
        REQUIRE(da.chords[c].selfIntersecting == db.chords[c].selfIntersecting);
        if (da.chords[c].slots != db.chords[c].slots) {
          auto list = [](const PooledSlots& v) {
            std::string t;
            for (Slot x : v) t += " " + std::to_string(x.hex) + ":" + std::to_string(x.axis);
            return t;
          };
          FAIL_CHECK("chord " << c << " local" << list(da.chords[c].slots) << " / walked" << list(db.chords[c].slots));
        }
        REQUIRE(da.chords[c].slots == db.chords[c].slots);
      }
      for (HexId h : cx.hexes()) REQUIRE(da.chordsAt(h) == db.chordsAt(h));
      recent = r.createdHexes;
      if (rng() % 4 == 0) {  // undo, as the explorer does
        cx.undo(r.edits);
        local.update(cx, r.edits, keepsSheetTopology(r));
        walked.update(cx, r.edits, keepsSheetTopology(r));
        local.releaseRetiredTail();
        walked.releaseRetiredTail();
        validateDual(cx, local.dual());
        recent.clear();
      }
    }
    compareDuals(cx, local.dual(), extractDual(cx));
    // The chords equal a fresh extraction's up to renaming (flags and lengths too).
    const Dual fresh = extractDual(cx);
    std::map<int32_t, int32_t> toFresh, fromFresh;
    for (HexId h : cx.hexes())
      for (int a = 0; a < 3; ++a) {
        const int32_t x = local.dual().chordAt(h, a), y = fresh.chordAt(h, a);
        REQUIRE(toFresh.try_emplace(x, y).first->second == y);
        REQUIRE(fromFresh.try_emplace(y, x).first->second == x);
      }
    size_t alive = 0;
    for (const Chord& ch : local.dual().chords) alive += ch.alive;
    CHECK(alive == toFresh.size());
    for (auto [x, y] : toFresh) {
      const Chord &p = local.dual().chords[size_t(x)], &q = fresh.chords[size_t(y)];
      CHECK(p.slots.size() == q.slots.size());
      CHECK(p.closed == q.closed);
      CHECK(p.selfIntersecting == q.selfIntersecting);
    }
  }
  MESSAGE("property (local chords): " << sequences << " sequences, seeds " << firstSeed << ".." << firstSeed + uint32_t(sequences) - 1
                                      << ": " << steps << " steps compared, " << rewalked << " re-walked whole");
  CHECK(steps > sequences);
  CHECK(rewalked * 20 < steps);  // the local update follows nearly every step
}

namespace {
// The tracker's ids against a replay's: the same id ranges, the same retired ids, and every slot in
// the sheet and chord of the same id.
void requireSameIds(const Complex& cx, const DualTracker& live, const DualTracker& replay) {
  const Dual &a = live.dual(), &b = replay.dual();
  REQUIRE(a.sheets.size() == b.sheets.size());
  REQUIRE(a.chords.size() == b.chords.size());
  for (size_t s = 0; s < a.sheets.size(); ++s) REQUIRE(a.sheets[s].alive == b.sheets[s].alive);
  for (size_t c = 0; c < a.chords.size(); ++c) REQUIRE(a.chords[c].alive == b.chords[c].alive);
  for (HexId h : cx.hexes()) {
    REQUIRE(a.sheetsAt(h) == b.sheetsAt(h));
    REQUIRE(a.chordsAt(h) == b.chordsAt(h));
  }
}
}  // namespace

namespace {
struct UndoCounts {
  // unmerges: undos that restored the sheets from the memo; memoUndos: undos right after their
  // step, of a step whose memo kept its sheets; directRestored: those of them that restored
  int64_t undos = 0, sheetSteps = 0, unmerges = 0, memoUndos = 0, directRestored = 0;
};
// Random steps, undos and redos (30 actions per sequence, mesh k mod meshes), the ids after each
// against a replay's. readLists: the invariants are checked on the tracker itself (reading every
// sheet list), else on a copy (no list read between a step and its undo, which then splits merged
// sheets from the step's memo). collapses: in every sequence, else in the even ones. sheetOps:
// some steps are sheet extractions and dicings.
UndoCounts undoIdsSequences(const std::vector<Complex>& meshes, uint32_t firstSeed, int sequences, bool readLists,
                            bool collapses, bool sheetOps) {
  UndoCounts n;
  int64_t &undos = n.undos, &sheetSteps = n.sheetSteps, &unmerges = n.unmerges, &memoUndos = n.memoUndos,
          &directRestored = n.directRestored;
  for (int k = 0; k < sequences; ++k) {
    const uint32_t seed = firstSeed + uint32_t(k);
    CAPTURE(seed);
    std::mt19937 rng(seed);
    const Complex start = meshes[size_t(k) % meshes.size()];
    Complex cx = start;
    DualTracker tracker(cx);
    struct Done {
      StepReport report;
      DualIdMemo memo;
    };
    std::vector<Done> done;
    std::vector<OpStep> redo;
    std::vector<HexId> recent;
    bool followsItsStep = false;  // the last action applied the step on top of done
    auto apply = [&](const OpStep& step) {
      Done d;
      d.report = applyStepTracked(cx, tracker, step, {}, &d.memo);
      recent = d.report.result.createdHexes;
      done.push_back(std::move(d));
      followsItsStep = true;
    };
    for (int action = 0; action < 30; ++action) {
      const uint32_t r = rng() % 6;
      if (r == 0 && !done.empty()) {
        undoStepTracked(cx, tracker, done.back().report, done.back().memo);
        const bool direct = done.back().memo.unmerge != nullptr && followsItsStep;
        memoUndos += direct;
        directRestored += direct && tracker.lastUpdateUnmerged();
        followsItsStep = false;
        redo.push_back(done.back().report.step);
        done.pop_back();
        ++undos;
      } else if (r == 1 && !redo.empty()) {
        apply(redo.back());
        redo.pop_back();
      } else {
        // Sheet operations remove and re-create whole sheets: the case a fresh name is likeliest.
        std::string text = randomStep(cx, rng, recent, collapses || k % 2 == 0);
        if (r == 2 && sheetOps) {
          std::vector<HexId> live;
          for (HexId h : cx.hexes()) live.push_back(h);
          const std::string e = "h" + std::to_string(live[rng() % live.size()]) + "e" + std::to_string(rng() % 12);
          text = rng() % 2 ? "sheet-extract " + e : "sheet-dice " + e + " 2";
        }
        CAPTURE(text);
        try {
          apply(parseOpStep(text));
        } catch (const Error&) {
          continue;
        }
        sheetSteps += r == 2 && sheetOps;
        redo.clear();
      }
      CAPTURE(action);
      unmerges += tracker.lastUpdateUnmerged();
      if (readLists)
        tracker.checkInvariants(cx);
      else
        DualTracker(tracker).checkInvariants(cx);
      // Every sheet's pending list edits read as its slots: settled on a copy, so that the next
      // steps still meet the pending runs (a merged list's unsorted additions once read as
      // slots twice and out of order here, and only here: the next read was mostly a re-write).
      for (const Sheet& sh : tracker.dual().sheets)
        if (sh.alive) {
          SlotList copy = sh.slots;
          CAPTURE(sh.id);
          REQUIRE(copy.get().size() == sh.slots.size());
          REQUIRE(std::is_sorted(copy.begin(), copy.end()));
        }
      Complex fresh = start;
      DualTracker replay(fresh);
      for (const Done& d : done) applyStepTracked(fresh, replay, d.report.step);
      requireSameIds(cx, tracker, replay);
    }
  }
  return n;
}
}  // namespace

TEST_CASE("property: undo gives the dual its ids back, so after any mix of steps, undos and redos the ids are a replay's") {
  const uint32_t firstSeed = 20261205;
  int sequences = 60;
  if (const char* env = std::getenv("HEXDUAL_PROPERTY_SEQUENCES")) sequences = std::min(sequences, std::atoi(env));
  const UndoCounts n = undoIdsSequences({makeGrid(4, 4, 4), makeRing(8, 2, 3), makeGrid(5, 3, 3)}, firstSeed,
                                        sequences, true, false, true);
  MESSAGE("undo ids: " << sequences << " sequences from seed " << firstSeed << ", " << n.undos << " undos ("
                       << n.unmerges << " restored from the memo, the lists read in between), " << n.sheetSteps
                       << " sheet steps; every state's ids equal a replay's");
  CHECK(n.undos > 10);
  CHECK(n.sheetSteps > 5);
}

// The same with no list read between a step and its undo, on meshes with an interior: an undo of a
// step that kept every sheet (a collapse merging two, a ring collapse's new sheet) restores the
// sheets from the step's memo (DualTracker::updateUndone) instead of flooding them, and the ids,
// lists and invariants are a replay's all the same.
TEST_CASE("property: an undo that restores merged sheets from the step's memo gives a replay's dual") {
  const uint32_t firstSeed = 20261271;
  int sequences = 24;
  if (const char* env = std::getenv("HEXDUAL_PROPERTY_SEQUENCES")) sequences = std::min(sequences, std::atoi(env));
  // Without reads the lists are rolled back to their marks; with every list read after every
  // action (checkInvariants on the tracker itself) the read lists are split by label.
  for (bool readLists : {false, true}) {
    CAPTURE(readLists);
    const UndoCounts n =
        undoIdsSequences({makeGrid(9, 9, 9), makeRing(16, 4, 5)}, firstSeed, sequences, readLists, true, false);
    const std::string mode = readLists ? "undo from memo, lists read after every action" : "undo from memo";
    MESSAGE(mode << ": " << sequences
                             << " sequences from seed " << firstSeed << ", " << n.undos << " undos, " << n.memoUndos
                             << " right after a step that kept every sheet, " << n.unmerges
                             << " restored from the memo");
    CHECK(n.directRestored == n.memoUndos);  // every such undo restores, read or not
    if (sequences >= 24) CHECK(n.unmerges >= 4);
  }
}
