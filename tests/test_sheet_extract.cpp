// Sheet extraction (core/ops/sheet_extract.cpp): exact Δ and dual effects, the refusals with their
// rules (the complex unchanged), undo and the inverse insertion, a sphere sheet as an unpillow, the
// cost of the dual update, random runs and every sheet of the development meshes.
#include <functional>

#include "sheet_helpers.hpp"

#include "complex/builders.hpp"
#include "complex/hex_tables.hpp"
#include "ops/sheet_support.hpp"

using namespace hexdual;
using namespace hexdual::test;

namespace {
std::vector<int32_t> sorted(std::vector<int32_t> v) {
  std::sort(v.begin(), v.end());
  return v;
}
// The distinct chord ids through these hexes along one axis.
std::vector<int32_t> chordsThrough(const Dual& d, const std::vector<HexId>& hexes, int axis) {
  std::vector<int32_t> ids;
  for (HexId h : hexes) ids.push_back(d.chordAt(h, axis));
  ids = sorted(ids);
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}
}  // namespace

TEST_CASE("sheet-extract: the x=1 layer of a 4x4x4 grid; a 3x4x4 grid is left, one sheet fewer, x-chords one shorter") {
  Complex cx = makeGrid(4, 4, 4);
  DualTracker tracker(cx);
  std::vector<HexId> layer;
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 4; ++j) layer.push_back(1 + 4 * (j + 4 * k));
  const Dual d0 = tracker.dual();
  const int32_t sheet = d0.sheetAt(21, 0);
  const auto crossing = chordsThrough(d0, layer, 0);  // 16 chords along x, 4 hexes each
  auto inLayer = chordsThrough(d0, layer, 1);          // 4 along y and 4 along z lie in the layer
  for (int32_t c : chordsThrough(d0, layer, 2)) inLayer.push_back(c);
  REQUIRE(crossing.size() == 16);
  REQUIRE(inLayer.size() == 8);

  Checked c = checkSheetStep(cx, tracker, parseOpStep("sheet-extract h21e0"), false);
  REQUIRE(c.applied);
  const OpResult& r = c.report.result;
  checkDelta(r, -25, -65, -56, -16);
  CHECK(r.removedHexes == layer);
  CHECK(r.removedVertices.size() == 25);
  CHECK(r.createdHexes.empty());
  CHECK(cx.numBoundaryQuads() == 96 - 16);  // the layer's 16 boundary quads are gone: the boundary changed
  CHECK(isomorphic(cx, makeGrid(3, 4, 4), false));
  // Dual: the sheet is gone, the chords lying in it are gone, every x-chord is one hex shorter.
  CHECK(c.report.dual.sheetsRemoved == std::vector<int>{sheet});
  CHECK(c.report.dual.sheetsCreated.empty());
  CHECK(sorted(c.report.dual.chordsRemoved) == sorted(inLayer));
  CHECK(sorted(c.report.dual.chordsChanged) == crossing);
  // Every list is reported ascending (the text and JSON reports print them as they are).
  CHECK(c.report.dual.chordsRemoved == sorted(c.report.dual.chordsRemoved));
  CHECK(c.report.dual.chordsChanged == crossing);
  CHECK(c.report.dual.sheetsChanged == sorted(c.report.dual.sheetsChanged));
  for (int32_t id : crossing) CHECK(tracker.dual().chords[size_t(id)].slots.size() == 3);
  CHECK(tracker.dual().sheets.size() - size_t(std::count_if(tracker.dual().sheets.begin(), tracker.dual().sheets.end(),
                                                            [](const Sheet& s) { return !s.alive; })) == 11);
  // The inverse inserts a sheet along the 16 glued quads.
  REQUIRE(r.inverse);
  CHECK(r.inverse->op == OpKind::SheetInsert);
  CHECK(r.inverse->args.size() == 16);
}

TEST_CASE("sheet-extract: undo restores the grid exactly; the inverse insertion gives back an isomorphic grid") {
  Complex cx = makeGrid(4, 4, 4);
  const Complex grid = cx;
  DualTracker tracker(cx);
  for (const char* step : {"sheet-extract h21e0", "sheet-extract h0e8", "sheet-extract h63e4", "sheet-extract h5e4"}) {
    CAPTURE(step);
    Checked c = checkSheetStep(cx, tracker, parseOpStep(step), true);  // undo: exact state, hash and dual
    REQUIRE(c.applied);
    Complex back = cx;
    applyStep(back, step);
    applyStep(back, *c.report.result.inverse);
    CHECK(isomorphic(back, grid, false));
  }
}

TEST_CASE("sheet-extract: a boundary layer; its inverse pads the new boundary") {
  Complex cx = makeGrid(4, 4, 4);
  OpResult r = applyStep(cx, "sheet-extract h48e8");  // the top layer z=3
  CHECK(r.dH == -16);
  CHECK(isomorphic(cx, makeGrid(4, 4, 3), false));
  CHECK(cx.numBoundaryQuads() == 80);
  // The glued quads are the tops of the layer below, now boundary: the insertion pads them.
  REQUIRE(r.inverse);
  for (const OpArg& a : r.inverse->args) CHECK(cx.isBoundary(a.quad()));
  Complex back = cx;
  applyStep(back, *r.inverse);
  CHECK(isomorphic(back, makeGrid(4, 4, 4), false));
}

TEST_CASE("sheet-extract: a sphere sheet of two hexes is an unpillow (same canonical form); its inverse is a pillow") {
  Complex a = makeGrid(3, 3, 3);
  applyStep(a, "pillow h13f5");  // X = h27, Y = h28 on the same 8 vertices
  Complex b = a;
  DualTracker tracker(a);
  Checked c = checkSheetStep(a, tracker, parseOpStep("sheet-extract h27e8"), false);
  REQUIRE(c.applied);
  applyStep(b, "unpillow h27");
  CHECK(canonicalHash(a) == canonicalHash(b));
  CHECK(c.report.result.dV == -4);
  CHECK(c.report.result.dH == -2);
  CHECK(c.report.dual.sheetsRemoved.size() == 1);
  CHECK(c.report.dual.chordsRemoved.size() == 2);  // the two closed chords of length 2 inside the pillow
  REQUIRE(c.report.result.inverse);
  CHECK(formatOpStep(*c.report.result.inverse) == "pillow h13f5");
}

TEST_CASE("sheet-extract: refusals name their rule and leave the complex unchanged") {
  auto refusal = [](Complex cx, const std::string& step) {
    const std::string dump = stateDump(cx);
    const std::string why = errorOf([&] { applyStep(cx, step); });
    CHECK(stateDump(cx) == dump);
    return why;
  };
  Complex grid = makeGrid(3, 3, 3);
  CHECK(refusal(grid, "sheet-extract h27e0") == "sheet-extract: no-such-entity: hex 27 does not exist");
  CHECK(refusal(grid, "sheet-extract h0e12") == "sheet-extract: no-such-entity: local edge 12 is not 0..11");
  CHECK(refusal(makeTwistedRing(4), "sheet-extract h0e0") ==
        "sheet-extract: self-intersecting: the sheet through h0e0 passes hex 3 twice (along its local axes 2 and 0)");
  CHECK(refusal(makeGrid(3, 3, 1), "sheet-extract h4e8") ==
        "sheet-extract: no-sides: the chord through hex 0 runs from boundary to boundary inside the sheet (hexes 0); no "
        "hex would be left there");
  Complex pillowed = grid;
  applyStep(pillowed, "pillow h13f5");
  CHECK(refusal(pillowed, "sheet-extract h27e0") ==
        "sheet-extract: no-sides: the chord through hex 27 is closed and lies in the sheet; nothing is on either side of it");
  Complex collapsed = grid;
  applyStep(collapsed, "facecollapse h1e3 h1f3 h13f2");
  CHECK(refusal(collapsed, "sheet-extract h0e0") ==
        "sheet-extract: self-touching: the sheet touches itself at vertex 5: its edges to 4 and to 36 would merge three "
        "vertices into one");
  CHECK(nonManifoldLink(refusal(collapsed, "sheet-extract h1e0"),
                        "sheet-extract: non-manifold-result: the result would not be a valid complex (validate: vertex 5 "
                        "is non-manifold: "));
  // After a face collapse has merged a centre vertex into the boundary, extracting the x=0 layer
  // would merge it with another boundary vertex: a valid complex, but with a tunnel.
  Complex tunnel = grid;
  applyLog(tunnel, "v1;hexpush h20f3;facecollapse h13e11 h14f3 h16f2");
  CHECK(refusal(tunnel, "sheet-extract h0e0") ==
        "sheet-extract: topology-change: the result would have Euler characteristic V-E+F-H -1 from the mesh's: merging "
        "these vertices would open a handle (a tunnel)");
  // An O-grid of 3 around, one sheet extracted: the other two hexes share both ends of every edge
  // across the next sheet, so its collapse would merge two vertices of the hex that remains.
  Complex ring = makeRing(3, 1, 1);
  applyStep(ring, "sheet-extract h0e4");
  CHECK(refusal(ring, "sheet-extract h1e4") ==
        "sheet-extract: hex-vertices-merge: hex 2 would lose a corner: its vertices 5 and 3 would merge into 3");
}

// planMerges' split: a merged vertex whose corners off the sheet are not connected across faces
// (they touch only at the vertex). The extraction is valid, but no insertion gives it back.
TEST_CASE("sheet-extract: where the hexes off the sheet touch only at a merged vertex, it applies with no inverse, named") {
  Complex cx = makeGrid(3, 3, 3);
  applyLog(cx, "v1;chordpush h9e3 h12f5 h21f2;hexpush h4f1;hexpush h3f3");
  DualTracker tracker(cx);
  Checked c = checkSheetStep(cx, tracker, parseOpStep("sheet-extract h0e8"), true);
  REQUIRE(c.applied);
  CHECK_FALSE(c.report.result.inverse);
  CHECK(c.report.result.noInverse ==
        "around vertex 5 the hexes off the sheet touch only at the vertex: no sheet insertion gives it back");
  // Another sheet through hex 0 has no such vertex: it has an inverse.
  Checked other = checkSheetStep(cx, tracker, parseOpStep("sheet-extract h0e4"), true);
  REQUIRE(other.applied);
  REQUIRE(other.report.result.inverse);
  CHECK(formatOpStep(*other.report.result.inverse) == "sheet-insert h35f2 h31f2 h31f1 h12f2 h13f2 h14f2 h28f4 h22f2 h23f2");
}

TEST_CASE("sheet-extract: a vertex the input left non-manifold is refused with its rule") {
  // Two cubes touching at one vertex (accepted from a file, recorded as non-manifold).
  std::vector<Vec3> p;
  for (int i = 0; i < 15; ++i) p.push_back({double(i % 3), double((i / 3) % 3), double(i / 9)});
  Complex cx = fromConnectivity(
      {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}, {2, 1, 1}, {2, 2, 1},
       {1, 2, 1}, {1, 1, 2}, {2, 1, 2}, {2, 2, 2}, {1, 2, 2}},
      {{0, 1, 2, 3, 4, 5, 6, 7}, {6, 8, 9, 10, 11, 12, 13, 14}}, true);
  REQUIRE(cx.nonManifoldVertices() == std::vector<VertexId>{6});
  CHECK(contains(errorOf([&] { applyStep(cx, "sheet-extract h0e0"); }), "sheet-extract: non-manifold-vertex: touches non-manifold vertex 6"));
}

TEST_CASE("sheet-extract: the dual update visits slots in proportion to the sheet, not the mesh (20^3 and 40^3)") {
  // The middle x-layer: n^2 hexes. The update visits a fixed number of slots per hex of the sheet.
  auto extract = [](const std::string& centre) { return "sheet-extract h" + centre + "e0"; };
  const auto [small, big] = costsAtCentre(20, 40, extract);
  CHECK_FALSE(small.reflooded);
  CHECK_FALSE(big.reflooded);
  CHECK(small.sheetSlots == 0);  // the sheets keep their topology: dead slots leave their lists, nothing is flooded
  CHECK(big.sheetSlots == 0);
  CHECK(small.chordSlots == 13 * 400);  // chords: 13 slots per hex of the sheet (17 before re-glued faces were told apart)
  CHECK(big.chordSlots == 13 * 1600);
}

TEST_CASE("sheet-extract: a 16^3 grid's middle layers along x, y and z (the paths taken for large sheets), undone exactly") {
  // 256 hexes per layer: over 512 edits (the validity check lists each edited vertex once, by
  // stamps), over 1,024 renamed corners (their hexes listed through a bitmap), over 256 dead slots
  // (grouped per sheet by counting). Each is checked like every step: Δ, validate, the tracked dual
  // against a fresh extraction, then undone (exact state, canonical hash and dual) and given back
  // by its inverse.
  const Complex grid = makeGrid(16, 16, 16);
  const HexId centre = 8 + 16 * (8 + 16 * 8);
  for (int axis = 0; axis < 3; ++axis) {
    CAPTURE(axis);
    Complex cx = grid;
    DualTracker tracker(cx);
    const std::string step = "sheet-extract h" + std::to_string(centre) + "e" + std::to_string(4 * axis);
    Checked c = checkSheetStep(cx, tracker, parseOpStep(step), true);
    REQUIRE(c.applied);
    CHECK(c.report.result.dH == -256);
    CHECK(c.report.result.removedVertices.size() == 289);
    CHECK(c.report.result.edits.edits.size() > 512);
    Complex back = cx;
    applyStep(back, step);
    CHECK(isomorphic(back, makeGrid(axis == 0 ? 15 : 16, axis == 1 ? 15 : 16, axis == 2 ? 15 : 16), false));
    applyStep(back, *c.report.result.inverse);
    CHECK(isomorphic(back, grid, false));
  }
}

TEST_CASE("planMerges: the renamed hexes are the renamed corners' hexes, ascending, once each (small and large sheets)") {
  for (int n : {4, 24}) {
    CAPTURE(n);
    const Complex grid = makeGrid(n, n, n);
    // The x-edges of the layer x = n/2: one merge class per edge, as a sheet extraction plans them.
    ops::MergeClasses classes;
    std::vector<uint8_t> inLayer(size_t(grid.hexCapacity()), 0), seen(size_t(grid.vertexCapacity()), 0);
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j) {
        const HexId h = n / 2 + n * (j + n * k);
        inLayer[size_t(h)] = 1;
        for (int e = 0; e < 4; ++e) {
          const int c0 = tables::kEdgeCorners[size_t(e)][0], c1 = tables::kEdgeCorners[size_t(e)][1];
          if (seen[size_t(grid.vertex(h, c0))]) continue;
          seen[size_t(grid.vertex(h, c0))] = 1;
          const std::pair<HexId, int> ends[2] = {{h, c0}, {h, c1}};
          classes.add(ends);
        }
      }
    REQUIRE(classes.size() == size_t((n + 1) * (n + 1)));
    const ops::VertexMerges m = ops::planMerges(grid, classes, [&](HexId h) { return inLayer[size_t(h)] != 0; });
    std::vector<HexId> want;
    for (auto [h, c] : m.renamed) want.push_back(h);
    std::sort(want.begin(), want.end());
    want.erase(std::unique(want.begin(), want.end()), want.end());
    CHECK(m.renamedHexes == want);
    CHECK(m.renamedHexes.size() == size_t(n * n));  // the layer x = n/2 + 1 keeps the renamed corners
    CHECK((n == 24 ? m.renamed.size() >= 1024 : m.renamed.size() < 1024));  // the bitmap at 24^3 (2,304 corners), the sort at 4^3
  }
}

TEST_CASE("sheet-extract: random runs on grids and an O-grid (fixed seeds)") {
  auto a = randomSheetRuns(makeGrid(4, 4, 4), 20261203, 40, OpKind::SheetExtract);
  auto b = randomSheetRuns(makeRing(6, 2, 2), 20261303, 30, OpKind::SheetExtract);
  CHECK(a["applied"] > 20);
  CHECK(b["applied"] > 10);
}

TEST_CASE("sheet-extract: every sheet after random atomic steps (collapses, pushes, pillows; fixed seeds)") {
  auto tally = everyStepAfterRandomAtomic(20261206, 24, [](const Complex& cx) {
    return stepsOn(sheetEdges(cx), [](EdgeRef e) { return makeStep(OpKind::SheetExtract, e); });
  });
  CHECK(tally["sheet-extract applied"] > 100);
  CHECK(tally["sheet-extract self-touching"] > 0);
}

namespace {
// Every sheet of the development meshes `pick` accepts, extracted or refused by rule, undone to the
// exact state (checkSheetStep); returns the tally over every mesh and how many meshes opened.
std::pair<std::map<std::string, int>, int> extractEverySheet(const std::function<bool(const std::string&)>& pick) {
  std::vector<std::filesystem::path> files;
  for (const auto& f : std::filesystem::directory_iterator(devMeshDir()))
    if (f.path().extension() == ".gz" && pick(f.path().filename().string())) files.push_back(f.path());
  std::sort(files.begin(), files.end());
  int meshes = 0;
  std::map<std::string, int> total;
  for (const auto& f : files) {
    Complex cx;
    try {
      cx = readDevMesh(f);
    } catch (const Error&) {
      continue;  // refused by the readers (MANIFEST.md)
    }
    ++meshes;
    CAPTURE(f.filename().string());
    DualTracker tracker(cx);
    const int64_t hexes = cx.numHexes();
    std::map<std::string, int> tally;
    const Dual d = extractDual(cx);
    for (const Sheet& s : d.sheets) {
      const EdgeRef e{s.slots[0].hex, 4 * s.slots[0].axis};
      Checked c = checkSheetStep(cx, tracker, makeStep(OpKind::SheetExtract, e), true);
      ++tally[c.applied ? "applied" : c.rule];
      if (!c.applied) CHECK_FALSE(c.rule.empty());
      if (c.applied) CHECK(c.report.result.dH == -int64_t(s.slots.size()));
      if (c.applied) CHECK(c.report.dual.sheetsRemoved == std::vector<int>{s.id});
    }
    CHECK(cx.numHexes() == hexes);
    MESSAGE(f.filename().string() << ": " << d.sheets.size() << " sheets:" << tallyLine(tally));
    for (const auto& [k, v] : tally) total[k] += v;
  }
  return {total, meshes};
}
const char* kBigBuddy = "P_big_buddy.mesh.gz";
}  // namespace

// The figures of bench/README.md ("Every sheet of every development mesh"): 821 sheets in the 13
// meshes the readers open, 21 refused (P_kitten, P_rockarm, MOAB_hexes_mixed). Two cases, so that
// ctest runs the largest mesh (325 sheets of 15,232 hexes) beside the other twelve.
TEST_CASE("sheet-extract: every sheet of every development mesh, P_big_buddy apart (applied or refused by rule, undone exactly)") {
  if (!std::filesystem::is_directory(devMeshDir())) {
    MESSAGE("skipped: no development-set meshes at " << devMeshDir().string());
    return;
  }
  const auto [total, meshes] = extractEverySheet([](const std::string& name) { return name != kBigBuddy; });
  CHECK(meshes >= 8);
  if (meshes == 12)
    CHECK(tallyLine(total) == " applied=475 no-sides=1 non-manifold-result=5 non-manifold-vertex=11 self-touching=4");
}

TEST_CASE("sheet-extract: every sheet of every development mesh, P_big_buddy (applied or refused by rule, undone exactly)") {
  if (!std::filesystem::exists(devMeshDir() / kBigBuddy)) {
    MESSAGE("skipped: no " << kBigBuddy << " at " << devMeshDir().string());
    return;
  }
  const auto [total, meshes] = extractEverySheet([](const std::string& name) { return name == kBigBuddy; });
  CHECK(meshes == 1);
  CHECK(tallyLine(total) == " applied=325");
}
