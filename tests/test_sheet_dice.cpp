// Sheet dicing (core/ops/sheet_dice.cpp): exact Δ and dual effects, k layers, refusals with their
// rules, the inverse extraction, the cost of the dual update, random runs.
#include "sheet_helpers.hpp"

#include "complex/builders.hpp"

using namespace hexdual;
using namespace hexdual::test;

TEST_CASE("sheet-dice of the middle x-layer of a 3x3x3 grid into 2 and 3: a 4x3x3 and a 5x3x3 grid") {
  Complex cx = makeGrid(3, 3, 3);
  DualTracker tracker(cx);
  const Dual d0 = tracker.dual();
  const int32_t sheet = d0.sheetAt(13, 0);
  Checked c = checkSheetStep(cx, tracker, parseOpStep("sheet-dice h13e0 2"), false);
  REQUIRE(c.applied);
  const OpResult& r = c.report.result;
  // 16 edges cut in two (+16 vertices), 9 new hexes; the new mid-plane quads (9) and the halves of
  // the layer's 24 side quads; edges: 16 halves and the mid-plane's 24.
  checkDelta(r, 16, 40, 33, 9);
  CHECK(r.createdHexes.size() == 9);
  CHECK(r.removedHexes.empty());
  CHECK(isomorphic(cx, makeGrid(4, 3, 3), false));
  // The sheet keeps its id and its slots (the first layer: unchanged, so not reported); one new
  // sheet; the 9 x-chords crossing it gain a hex each; the 6 chords lying in it get a parallel copy.
  CHECK(c.report.dual.sheetsCreated.size() == 1);
  CHECK(c.report.dual.sheetsRemoved.empty());
  CHECK(tracker.dual().sheets[size_t(sheet)].slots.get() == d0.sheets[size_t(sheet)].slots.get());
  CHECK(c.report.dual.chordsCreated.size() == 6);
  for (HexId h : {4, 13, 22}) CHECK(tracker.dual().chords[size_t(tracker.dual().chordAt(h, 0))].slots.size() == 4);
  REQUIRE(r.inverse);
  CHECK(formatOpStep(*r.inverse) == "sheet-extract h27e0");

  Complex three = makeGrid(3, 3, 3);
  OpResult r3 = applyStep(three, "sheet-dice h13e0 3");
  CHECK(r3.dH == 18);
  CHECK(isomorphic(three, makeGrid(5, 3, 3), false));
  CHECK_FALSE(r3.inverse);
  CHECK(r3.noInverse == "the inverse is 2 sheet extractions, one per new layer (first: sheet-extract h27e0)");
}

TEST_CASE("sheet-dice of a boundary layer and of an O-grid annulus; undo is exact") {
  Complex cx = makeGrid(3, 3, 3);
  DualTracker tracker(cx);
  Checked top = checkSheetStep(cx, tracker, parseOpStep("sheet-dice h18e8 2"), true);
  REQUIRE(top.applied);
  CHECK(top.report.result.dH == 9);
  Complex ring = makeRing(8, 2, 2);
  DualTracker rt(ring);
  Checked annulus = checkSheetStep(ring, rt, parseOpStep("sheet-dice h0e0 2"), true);  // a radial layer: an annulus
  REQUIRE(annulus.applied);
  CHECK(annulus.report.result.dH == 16);
  CHECK(rt.dual().sheets[size_t(annulus.report.dual.sheetsCreated.at(0))].topology == "annulus");
}

TEST_CASE("sheet-dice: refusals name their rule and leave the complex unchanged") {
  auto refusal = [](Complex cx, const std::string& step) {
    const std::string dump = stateDump(cx);
    const std::string why = errorOf([&] { applyStep(cx, step); });
    CHECK(stateDump(cx) == dump);
    return why;
  };
  CHECK(refusal(makeGrid(2, 2, 2), "sheet-dice h0e0 1") == "sheet-dice: bad-count: a sheet is diced into 2 to 64 sheets, not 1");
  CHECK(refusal(makeGrid(2, 2, 2), "sheet-dice h0e0 65") == "sheet-dice: bad-count: a sheet is diced into 2 to 64 sheets, not 65");
  CHECK(refusal(makeGrid(2, 2, 2), "sheet-dice h9e0 2") == "sheet-dice: no-such-entity: hex 9 does not exist");
  CHECK(refusal(makeTwistedRing(4), "sheet-dice h0e0 2") ==
        "sheet-dice: self-intersecting: the sheet through h0e0 passes hex 3 twice (along its local axes 2 and 0)");
  CHECK(refusal(makeMobiusRing(6), "sheet-dice h0e8 2") ==
        "sheet-dice: one-sided: the sheet through h0e8 is one-sided: its layers would not stay apart");
}

TEST_CASE("sheet-dice: the dual update visits slots in proportion to the sheet (20^3 and 40^3)") {
  auto dice = [](const std::string& centre) { return "sheet-dice h" + centre + "e0 2"; };
  const auto [small, big] = costsAtCentre(20, 40, dice);
  CHECK_FALSE(small.reflooded);
  CHECK_FALSE(big.reflooded);
  CHECK(small.sheetSlots == 3 * 400);  // the new layer's slots: its own sheet and the strips of the crossing ones
  CHECK(big.sheetSlots == 3 * 1600);
  CHECK(small.chordSlots == 21 * 400);  // chords: 21 slots per hex of the sheet (25 before re-glued faces were told apart)
  CHECK(big.chordSlots == 21 * 1600);
}

TEST_CASE("sheet-dice: random runs on grids and an O-grid (fixed seeds)") {
  auto a = randomSheetRuns(makeGrid(4, 4, 4), 20261803, 30, OpKind::SheetDice);
  auto b = randomSheetRuns(makeRing(6, 2, 2), 20261903, 20, OpKind::SheetDice);
  CHECK(a["applied"] > 30);
  CHECK(b["applied"] > 10);
}

TEST_CASE("sheet-dice and sheet-pillow after random collapses, pushes and pillows (fixed seeds)") {
  auto tally = everyStepAfterRandomAtomic(20261806, 12, [](const Complex& cx) {
    auto steps = stepsOn(sheetEdges(cx), [](EdgeRef e) { return makeStep(OpKind::SheetDice, e, Count{2}); });
    for (HexId h : cx.hexes()) steps.push_back(makeStep(OpKind::SheetPillow, h));
    return steps;
  });
  CHECK(tally["sheet-dice applied"] > 60);
  CHECK(tally["sheet-pillow applied"] > 200);
}
