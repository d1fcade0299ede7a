// Sheet insertion and pillowing (core/ops/sheet_insert.cpp): exact Δ and dual effects, surfaces
// that end on the boundary and boundary padding, agreement with pillowRegion and the 1-7 flip,
// refusals with their rules, the inverse extraction, random runs.
#include "sheet_helpers.hpp"

#include "complex/builders.hpp"
#include "flips/flip.hpp"
#include "geometry/scaled_jacobian.hpp"

using namespace hexdual;
using namespace hexdual::test;

namespace {
OpStep quadsStep(OpKind op, const std::vector<QuadSide>& quads) {
  OpStep st{op, {}, 0};
  for (QuadSide q : quads) st.args.push_back(OpArg::of(q));
  return st;
}
}  // namespace

TEST_CASE("sheet-pillow of one interior hex is pillowRegion and the 1-7 flip: same canonical form, one sphere sheet") {
  Complex cx = makeGrid(3, 3, 3), viaRegion = cx, viaFlip = cx;
  DualTracker tracker(cx);
  Checked c = checkSheetStep(cx, tracker, parseOpStep("sheet-pillow h13"), false);
  REQUIRE(c.applied);
  const OpResult& r = c.report.result;
  checkDelta(r, 8, 20, 18, 6);
  CHECK(r.createdHexes.size() == 6);
  CHECK(cx.isHex(13));  // the pillowed hex keeps its id: it moved onto the 8 new vertices
  pillowRegion(viaRegion, {13});
  flip(viaFlip, "1-7", {13});
  CHECK(canonicalHash(cx) == canonicalHash(viaRegion));
  CHECK(canonicalHash(cx) == canonicalHash(viaFlip));
  REQUIRE(c.report.dual.sheetsCreated.size() == 1);
  const Sheet& s = tracker.dual().sheets[size_t(c.report.dual.sheetsCreated[0])];
  CHECK(s.topology == "sphere");
  CHECK(s.slots.size() == 6);
  CHECK(c.report.dual.chordsCreated.size() == 3);  // three closed chords of 4 run round inside the new sheet
  REQUIRE(r.inverse);
  CHECK(formatOpStep(*r.inverse) == "sheet-extract h27e8");
}

TEST_CASE("sheet-pillow of an interior 2x1x1 block equals pillowRegion; Δ (+V, +V+E, +F+E, +F) of its surface") {
  Complex cx = makeGrid(4, 4, 4), viaRegion = cx;
  OpResult r = applyStep(cx, "sheet-pillow h21 h22");  // (1,1,1) and (2,1,1)
  pillowRegion(viaRegion, {21, 22});
  CHECK(canonicalHash(cx) == canonicalHash(viaRegion));
  // The block's surface: 12 vertices, 20 edges, 10 quads.
  checkDelta(r, 12, 32, 30, 10);
}

TEST_CASE("sheet-pillow of a corner hex: the new sheet is a disk ending on the boundary, which gains its side quads") {
  Complex cx = makeGrid(3, 3, 3);
  DualTracker tracker(cx);
  Checked c = checkSheetStep(cx, tracker, parseOpStep("sheet-pillow h0"), false);
  REQUIRE(c.applied);
  const OpResult& r = c.report.result;
  // The surface: 3 quads (toward h1, h3, h9), 7 vertices, 9 edges (6 of them on the boundary).
  checkDelta(r, 7, 16, 12, 3);
  CHECK(cx.numBoundaryQuads() == 54 + 6);
  REQUIRE(c.report.dual.sheetsCreated.size() == 1);
  const Sheet& s = tracker.dual().sheets[size_t(c.report.dual.sheetsCreated[0])];
  CHECK(s.topology == "disk");
  CHECK(s.boundaryLoops == 1);
  // pillowRegion refuses such a set.
  Complex g = makeGrid(3, 3, 3);
  CHECK(errorOf([&] { pillowRegion(g, {0}); }) == "pillowRegion: quad h0f0 of the set is on the mesh boundary");
}

TEST_CASE("sheet-insert along the 9 quads between two layers gives a 3x3x4 grid, however the sides are named") {
  std::vector<QuadSide> below, mixed;
  for (HexId h = 0; h < 9; ++h) {
    below.push_back({h, 5});
    mixed.push_back(h % 2 ? QuadSide{h + 9, 4} : QuadSide{h, 5});  // the other side of every other quad
  }
  Complex a = makeGrid(3, 3, 3), b = a;
  DualTracker tracker(a);
  Checked c = checkSheetStep(a, tracker, quadsStep(OpKind::SheetInsert, below), false);
  REQUIRE(c.applied);
  checkDelta(c.report.result, 16, 40, 33, 9);
  CHECK(isomorphic(a, makeGrid(3, 3, 4), false));
  CHECK(tracker.dual().sheets[size_t(c.report.dual.sheetsCreated.at(0))].topology == "disk");
  // The first quad names the moving side; the others follow it across the surface.
  applyStep(b, quadsStep(OpKind::SheetInsert, mixed));
  CHECK(stateDump(a) == stateDump(b));
}

TEST_CASE("sheet-insert along boundary quads pads the boundary: the boundary quad mesh keeps its count") {
  std::vector<QuadSide> top;
  for (HexId h = 18; h < 27; ++h) top.push_back({h, 5});
  Complex cx = makeGrid(3, 3, 3);
  DualTracker tracker(cx);
  Checked c = checkSheetStep(cx, tracker, quadsStep(OpKind::SheetInsert, top), true);
  REQUIRE(c.applied);
  applyStep(cx, quadsStep(OpKind::SheetInsert, top));
  CHECK(isomorphic(cx, makeGrid(3, 3, 4), false));
  CHECK(cx.numBoundaryQuads() == 54 + 12);  // the 12 side quads of the new layer
}

TEST_CASE("sheet-insert and sheet-pillow: refusals name their rule and leave the complex unchanged") {
  Complex grid = makeGrid(3, 3, 3);
  auto refusal = [&](const OpStep& step) {
    Complex cx = grid;
    const std::string why = errorOf([&] { applyStep(cx, step); });
    CHECK(stateDump(cx) == stateDump(grid));
    return why;
  };
  CHECK(errorOf([&] { sheetInsert(grid, {}); }) == "sheet-insert: empty: needs at least one quad");
  CHECK(refusal(parseOpStep("sheet-insert h40f1")) == "sheet-insert: no-such-entity: hex 40 does not exist");
  CHECK(refusal(parseOpStep("sheet-insert h13f1 h14f0")) == "sheet-insert: duplicate: quad h13f1 is named twice");
  CHECK(refusal(parseOpStep("sheet-insert h13f5")) ==
        "sheet-insert: open-surface: the surface ends inside the mesh at edge h10e3 (only quad h13f5 of it is there)");
  // Three of the four quads around the y-edge from (2,1,1) to (2,2,1): h4f5, h5f5 and h13f1.
  CHECK(refusal(parseOpStep("sheet-insert h13f1 h13f3 h14f3 h4f5 h5f5 h7f5 h8f5")) ==
        "sheet-insert: non-manifold-surface: edge h4e7 lies on 3 quads of the surface");
  // A corner hex and the centre hex share one vertex: their surfaces touch there.
  CHECK(refusal(parseOpStep("sheet-pillow h0 h13")) ==
        "sheet-pillow: non-manifold-surface: the surface passes vertex 21 (quad h13f0) more than once: it is pinched there");
  CHECK(refusal(parseOpStep("sheet-pillow h27")) == "sheet-pillow: no-such-entity: hex 27 does not exist");
  CHECK(refusal(parseOpStep("sheet-pillow h0 h0")) == "sheet-pillow: duplicate: hex 0 is named twice");
  CHECK(refusal(parseOpStep("sheet-pillow h13 h4 h13")) == "sheet-pillow: duplicate: hex 13 is named twice");
  Complex one = makeGrid(1, 1, 1);
  CHECK(errorOf([&] { applyStep(one, "sheet-pillow h0"); }) ==
        "sheet-pillow: no-surface: no quad lies between the set and the rest of the mesh");
}

TEST_CASE("sheet-insert: the cost of the dual update follows the new sheet (20^3 and 40^3)") {
  auto visited = [](int n) {  // the n^2 quads between layers n/2 - 1 and n/2 along z
    std::string step = "sheet-insert";
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) step += " h" + std::to_string(i + n * (j + n * (n / 2 - 1))) + "f5";
    const UpdateCost cost = costAtCentre(n, [&](const std::string&) { return step; });
    CHECK_FALSE(cost.reflooded);
    return std::pair<size_t, size_t>{cost.sheetSlots, cost.chordSlots};
  };
  const auto small = visited(20), big = visited(40);
  MESSAGE("sheet slots 20^3 / 40^3: " << small.first << " / " << big.first << ", chord slots " << small.second << " / " << big.second);
  CHECK(small.first == 3 * 400);  // the new sheet's slots, and the strips the crossing sheets gain
  CHECK(big.first == 3 * 1600);
  CHECK(small.second == 16 * 400);  // chords: 16 slots per new hex (20 before re-glued faces were told apart)
  CHECK(big.second == 16 * 1600);
}

TEST_CASE("sheet-pillow of the centre hex: the dual update visits the same slots at 20^3 and 40^3") {
  auto visited = [](int n) {
    const UpdateCost cost = costAtCentre(n, [](const std::string& centre) { return "sheet-pillow h" + centre; });
    CHECK_FALSE(cost.reflooded);
    return cost.sheetSlots + cost.chordSlots;
  };
  const size_t small = visited(20), big = visited(40);
  CHECK(small == 93);  // 105 before changedChords skipped slots whose faces across their axis kept their gluings
  CHECK(big == small);
}

TEST_CASE("sheet-pillow: random runs on grids and an O-grid (fixed seeds)") {
  auto a = randomSheetRuns(makeGrid(4, 4, 4), 20261403, 40, OpKind::SheetPillow);
  auto b = randomSheetRuns(makeRing(6, 2, 2), 20261503, 20, OpKind::SheetPillow);
  CHECK(a["applied"] > 40);
  CHECK(b["applied"] > 20);
}

TEST_CASE("sheet-insert and sheet-pillow: the new hexes are right-handed with the operation's own placement, from either side") {
  // The smallest scaled Jacobian of the created hexes, the operation's placement kept as it is.
  auto newHexesMinSJ = [](Complex& cx, const OpStep& step) {
    const OpResult r = applyStep(cx, step);
    REQUIRE_FALSE(r.createdHexes.empty());
    double lo = 2;
    for (HexId h : r.createdHexes) lo = std::min(lo, scaledJacobian(cx, h));
    return lo;
  };
  std::vector<QuadSide> fromBelow, fromAbove;  // the 25 quads between layers 2 and 3 of a 5^3 grid
  for (HexId h = 50; h < 75; ++h) {
    fromBelow.push_back({h, 5});       // odd faces: the moving hexes lie below
    fromAbove.push_back({h + 25, 4});  // even faces: the moving hexes lie above
  }
  Complex a = makeGrid(5, 5, 5), b = a;
  CHECK(newHexesMinSJ(a, quadsStep(OpKind::SheetInsert, fromBelow)) > 0.5);
  CHECK(newHexesMinSJ(b, quadsStep(OpKind::SheetInsert, fromAbove)) > 0.5);
  CHECK(isomorphic(a, makeGrid(5, 5, 6), false));
  // A pillowed hex's six sides are three even and three odd faces; an interior 2x2x1 block, a
  // corner hex (the sheet ends on the boundary) and a boundary column.
  for (const char* step : {"sheet-pillow h62", "sheet-pillow h31 h32 h36 h37", "sheet-pillow h0", "sheet-pillow h2 h27 h52 h77 h102"}) {
    CAPTURE(step);
    Complex cx = makeGrid(5, 5, 5);
    CHECK(newHexesMinSJ(cx, parseOpStep(step)) > 0.3);
    for (HexId h : cx.hexes()) CHECK(scaledJacobian(cx, h) > 0);  // the moved hexes too
  }
}
