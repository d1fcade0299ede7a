// Column collapse (core/ops/column_collapse.cpp): exact Δ and dual effects of an open chord, a
// closed chord's column collapse is its ring collapse, refusals with their rules, the cost of the
// dual update, random runs.
#include "sheet_helpers.hpp"

#include <cmath>

#include "complex/builders.hpp"

using namespace hexdual;
using namespace hexdual::test;

namespace {
// Four wedges in a ring that starts at the east face of a hex H (id 4) and comes back into its
// south face: the chord through H along x runs round the ring and through H again along y.
Complex loopedChord() {
  std::vector<Vec3> p;
  auto at = [&](double angle, double r, double z) {
    p.push_back({(2 + r) * std::cos(angle), (2 + r) * std::sin(angle), z});
    return VertexId(p.size() - 1);
  };
  const double quarter = 1.5707963267948966;
  VertexId a[4][2][2];
  for (int k = 0; k < 4; ++k)
    for (int r = 0; r < 2; ++r)
      for (int z = 0; z < 2; ++z) a[k][r][z] = at(quarter * 0.7 * k, r, z);
  VertexId n[2], m[2];
  for (int z = 0; z < 2; ++z) n[z] = at(-0.4, 0.5, z), m[z] = at(-0.2, 1.5, z);
  std::vector<std::array<VertexId, 8>> hexes;
  auto hexOf = [](auto corner) {  // corner(x, y, z) -> vertex, in VTK order
    std::array<VertexId, 8> v;
    for (int c = 0; c < 8; ++c) v[size_t(c)] = corner(tables::cornerBit(c, 0), tables::cornerBit(c, 1), tables::cornerBit(c, 2));
    return v;
  };
  for (int k = 0; k < 4; ++k)  // wedge k from angle k to angle k+1; angle 4 is H's south face
    hexes.push_back(hexOf([&](int x, int y, int z) {
      if (k + x < 4) return a[k + x][y][z];
      return y == 0 ? a[0][0][z] : n[z];
    }));
  hexes.push_back(hexOf([&](int x, int y, int z) {  // H: east face = angle 0, south face = angle 4
    if (x == 1) return a[0][y][z];
    return y == 0 ? n[z] : m[z];
  }));
  return fromConnectivity(p, hexes);
}
}  // namespace

TEST_CASE("column-collapse of the middle x-chord of a 3x3x3 grid: Δ (-4,-11,-10,-3), the chord gone, its end quads collapsed") {
  Complex cx = makeGrid(3, 3, 3);
  DualTracker tracker(cx);
  const int32_t chord = tracker.dual().chordAt(13, 0);
  Checked c = checkSheetStep(cx, tracker, parseOpStep("column-collapse h13e0"), false);
  REQUIRE(c.applied);
  const OpResult& r = c.report.result;
  // Per cross-section plane (4): a quad collapses to an edge (V -1, E -2, F -1); per hex (3): two
  // pairs of side quads become two quads and two edges along the chord one.
  checkDelta(r, -4, -11, -10, -3);
  CHECK(r.removedHexes == std::vector<HexId>{12, 13, 14});
  CHECK(cx.numBoundaryQuads() == 54 - 2);  // the chord's two end quads collapsed on the boundary
  CHECK(std::find(c.report.dual.chordsRemoved.begin(), c.report.dual.chordsRemoved.end(), chord) !=
        c.report.dual.chordsRemoved.end());
  CHECK(c.report.dual.chordsCreated.empty());
  CHECK_FALSE(r.inverse);
  CHECK(r.noInverse == "a column collapse has no inverse step in the operation log");
  // The two sheets through the chord were cut along it and re-joined crosswise: still 9 sheets.
  CHECK(extractDual(cx).sheets.size() == 9);
}

TEST_CASE("column-collapse of a closed chord is its ring collapse (same canonical form)") {
  // The middle ring of an 8x3x3 O-grid, both diagonals; and the 4-ring of a hex push.
  for (const char* e : {"h25e4", "h25e5"}) {
    CAPTURE(e);
    Complex a = makeRing(8, 3, 3), b = a;
    DualTracker tracker(a);
    Checked c = checkSheetStep(a, tracker, parseOpStep(std::string("column-collapse ") + e), true);
    REQUIRE(c.applied);
    applyStep(a, std::string("column-collapse ") + e);
    applyStep(b, std::string("ringcollapse ") + e);
    CHECK(canonicalHash(a) == canonicalHash(b));
    CHECK(b.hexCapacity() == a.hexCapacity());
  }
  Complex g = makeGrid(5, 5, 5);
  applyStep(g, "hexpush h62f5");
  Complex a = g, b = g;
  const std::string ring = "h" + std::to_string(g.hexCapacity() - 4) + "e";
  for (int axis = 0; axis < 3; ++axis) {
    Complex x = g, y = g;
    const std::string e = ring + std::to_string(4 * axis);
    std::string why;
    if (!tryApplyStep(y, "ringcollapse " + e, &why)) continue;
    applyStep(x, "column-collapse " + e);
    CHECK(canonicalHash(x) == canonicalHash(y));
  }
}

TEST_CASE("column-collapse: refusals name their rule and leave the complex unchanged") {
  auto refusal = [](Complex cx, const std::string& step) {
    const std::string dump = stateDump(cx);
    const std::string why = errorOf([&] { applyStep(cx, step); });
    CHECK(stateDump(cx) == dump);
    return why;
  };
  CHECK(refusal(makeGrid(2, 2, 2), "column-collapse h8e0") == "column-collapse: no-such-entity: hex 8 does not exist");
  CHECK(refusal(makeTwistedRing(4), "column-collapse h0e4") ==
        "column-collapse: twisted: carried round the chord, the diagonal of h0e4 comes back as the other diagonal");
  CHECK(nonManifoldLink(refusal(makeGrid(3, 3, 1), "column-collapse h1e4"),
                        "column-collapse: non-manifold-result: the result would not be a valid complex (validate: vertex 1 "
                        "is non-manifold: "));
  Complex collapsed = makeGrid(3, 3, 3);
  applyStep(collapsed, "facecollapse h1e3 h1f3 h13f2");
  CHECK(refusal(collapsed, "column-collapse h0e1") ==
        "column-collapse: hex-vertices-merge: hex 9 would lose a corner: its vertices 17 and 5 would merge into 5");
  CHECK(refusal(loopedChord(), "column-collapse h4e0") == "column-collapse: self-intersecting: the chord through h4e0 passes hex 4 twice");
}

TEST_CASE("column-collapse: the dual update is proportional to the chord and the two sheets through it (10^3, 20^3, 40^3)") {
  auto collapse = [](const std::string& centre) { return "column-collapse h" + centre + "e0"; };
  const auto [small, big] = costsAtCentre(10, 20, collapse);
  const UpdateCost bigger = costAtCentre(40, collapse);
  MESSAGE("sheet slots 40^3: " << bigger.sheetSlots << ", chord slots " << bigger.chordSlots);
  // Chords: cut and re-joined where the chord was, a fixed number of slots per hex of the chord.
  // (Only slots whose faces across their axis were re-glued are checked against their chords:
  // 23 per hex of the chord since 2026-12-06, 34 before.)
  CHECK(small.chordSlots == 10 * 23);
  CHECK(big.chordSlots == 20 * 23);
  CHECK(bigger.chordSlots == 40 * 23);
  // Sheets: the lockstep flood, at the boundary too. The two sheets through the chord are cut
  // there and re-joined crosswise into two new sheets; the edit re-joins their boundary loops
  // where the chord ends, so their groups are flooded whole (2 n^2 - 2n slots), while each of the
  // n sheets the chord crosses loses one quad in its interior and settles at once: a fixed number
  // of slots per hex of the chord. 2 n^2 + 26 n in all (it was a re-flood of every crossed
  // sheet, O(n^3): 3,320 at 10^3 and 21,040 at 20^3).
  CHECK_FALSE(small.reflooded);
  CHECK_FALSE(big.reflooded);
  CHECK_FALSE(bigger.reflooded);
  CHECK(small.sheetSlots == 2 * 10 * 10 + 26 * 10);
  CHECK(big.sheetSlots == 2 * 20 * 20 + 26 * 20);
  CHECK(bigger.sheetSlots == 2 * 40 * 40 + 26 * 40);
}

TEST_CASE("column-collapse: its undo's dual update is proportional too (10^3, 20^3, 40^3)") {
  // The undo gives the chord back: the two new sheets are cut again and re-joined as they were,
  // the crossed sheets each regain their quad (topology kept: they settle at once).
  auto undoCost = [](int n) {
    Complex cx = makeGrid(n, n, n);
    DualTracker tracker(cx);
    const int c = n / 2;
    OpResult r = applyStep(cx, "column-collapse h" + std::to_string(c + n * (c + n * c)) + "e0");
    tracker.update(cx, r.edits, keepsSheetTopology(r));
    cx.undo(r.edits);
    tracker.update(cx, r.edits, keepsSheetTopology(r));
    compareDuals(cx, tracker.dual(), extractDual(cx));
    CHECK_FALSE(tracker.lastUpdateReflooded());
    MESSAGE("undo at " << n << "^3: sheet slots " << tracker.sheetSlotsTouched());
    return tracker.sheetSlotsTouched();
  };
  // 2 n^2 + 29 n: the two sheets through the chord flooded whole again, and a fixed number of
  // slots per hex of the chord.
  CHECK(undoCost(10) == 2 * 10 * 10 + 29 * 10);
  CHECK(undoCost(20) == 2 * 20 * 20 + 29 * 20);
  CHECK(undoCost(40) == 2 * 40 * 40 + 29 * 40);
}

TEST_CASE("column-collapse: random runs on grids and an O-grid (fixed seeds)") {
  auto a = randomSheetRuns(makeGrid(4, 4, 4), 20261603, 40, OpKind::ColumnCollapse);
  auto b = randomSheetRuns(makeRing(6, 2, 2), 20261703, 20, OpKind::ColumnCollapse);
  CHECK(a["applied"] > 30);
  CHECK(b["applied"] > 10);
}

TEST_CASE("column-collapse: every chord, both diagonals, after random collapses, pushes and pillows (fixed seeds)") {
  auto tally = everyStepAfterRandomAtomic(20261606, 12, [](const Complex& cx) {
    return stepsOn(chordEdges(cx), [](EdgeRef e) { return makeStep(OpKind::ColumnCollapse, e); });
  });
  CHECK(tally["column-collapse applied, no inverse"] > 300);
}
