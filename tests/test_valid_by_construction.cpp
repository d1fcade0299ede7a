// Pillow and hex push commit without walking vertex links (Transaction::commitValidByConstruction):
// their results are valid whenever the complex was and their prechecks passed, by the arguments in
// pillow.cpp and hex_push.cpp. This checks that claim the way the walk would have: after every
// applied step of random sequences (which reach the degenerate states: hexes sharing 5 quads,
// doublets, large vertex stars), the touched hexes are validated with every vertex link walked.
#include <doctest/doctest.h>

#include <random>

#include "complex/builders.hpp"
#include "dev_mesh.hpp"
#include "helpers.hpp"
#include "ops/ops.hpp"
#include "ops/oplog.hpp"
#include "ops/support.hpp"
#include "sheet_helpers.hpp"

using namespace hexdual;
using namespace hexdual::test;

namespace {
// Debug builds validate the whole complex in every commit already (and run far slower): fewer steps.
#ifdef HEXDUAL_CHECK_INVARIANTS
constexpr int kGridSteps = 800, kMeshSteps = 300, kScale = 8;
#else
constexpr int kGridSteps = 6000, kMeshSteps = 2000, kScale = 1;
#endif

struct ConstructionCounts {
  int pillows = 0, hexPushes = 0, others = 0;
};

// Random pillows, hex pushes, unpillows, hex pulls and chord pushes at random hexes (seed printed);
// after each applied pillow or hex push its hexes and their neighbours are validated outside any
// transaction, so every vertex of theirs has its link walked, and every `fullEvery` steps the whole
// complex is.
ConstructionCounts runConstructionChecked(Complex& cx, uint32_t seed, int steps, int fullEvery) {
  MESSAGE("seed " << seed);
  std::mt19937 rng(seed);
  const char* kinds[] = {"pillow", "hexpush", "pillow", "hexpush", "unpillow", "hexpull", "chordpush"};
  ConstructionCounts n;
  for (int s = 0; s < steps; ++s) {
    const HexId h = HexId(rng() % uint32_t(cx.hexCapacity()));
    const std::string kind = kinds[rng() % 7];
    const std::string hx = "h" + std::to_string(h);
    std::string text = kind + " " + hx + "f" + std::to_string(rng() % 6);
    if (kind == "unpillow") text = kind + " " + hx;
    if (kind == "chordpush")
      text = kind + " " + hx + "e" + std::to_string(rng() % 12) + " " + hx + "f" + std::to_string(rng() % 6) + " " + hx +
             "f" + std::to_string(rng() % 6);
    if (!cx.isHex(h)) continue;
    std::optional<OpResult> r = tryApplyStep(cx, text);
    if (!r) continue;
    if (kind == "pillow" || kind == "hexpush") {
      CAPTURE(text);
      CAPTURE(s);
      REQUIRE(errorOf([&] { cx.validateAround(ops::withNeighbours(cx, r->createdHexes)); }) == "");
      (kind == "pillow" ? n.pillows : n.hexPushes) += 1;
    } else {
      ++n.others;
    }
    if (s % fullEvery == 0) REQUIRE(errorOf([&] { cx.validate(); }) == "");
  }
  REQUIRE(errorOf([&] { cx.validate(); }) == "");
  return n;
}
}  // namespace

TEST_CASE("valid by construction: pillows and hex pushes in random sequences on grids (fixed seeds)") {
  for (uint32_t seed : {11u, 12u, 13u}) {
    Complex cx = makeGrid(4, 4, 4);
    ConstructionCounts n = runConstructionChecked(cx, seed, kGridSteps, 100);
    MESSAGE("pillows " << n.pillows << ", hex pushes " << n.hexPushes << ", other steps " << n.others);
    // Enough of each to reach degenerate states (a pillow next to a pillow, hex pushes into them).
    CHECK(n.pillows > 600 / kScale);
    CHECK(n.hexPushes > 300 / kScale);
    CHECK(n.others > 50 / kScale);
  }
}

TEST_CASE("valid by construction: a hex push into a pillow (the 1-7 flip) and on a 2x1x1 grid") {
  Complex cx = makeGrid(3, 3, 3);
  const HexId c = 13;  // the centre hex
  OpResult p = pillow(cx, {c, 5});
  OpResult h = hexPush(cx, {c, 5});
  CHECK(errorOf([&] { cx.validate(); }) == "");
  CHECK(p.dH + h.dH == 6);
  Complex two = makeGrid(2, 1, 1);
  OpResult t = hexPush(two, {0, 1});
  CHECK(t.dH == 4);
  CHECK(errorOf([&] { two.validate(); }) == "");
}

TEST_CASE("valid by construction: random pillows and hex pushes on development-set meshes (fixed seeds)") {
  if (!std::filesystem::is_directory(devMeshDir())) {
    MESSAGE("skipped: no development-set meshes at " << devMeshDir().string());
    return;
  }
  uint32_t seed = 21;
  for (std::string name : {"MOAB_125hex.vtk.gz", "G_cylinder_1.vtk.gz", "P_double-torus.vtk.gz"}) {
    CAPTURE(name);
    Complex cx = readDevMesh(devMeshDir() / name);
    ConstructionCounts n = runConstructionChecked(cx, seed++, kMeshSteps, 200);
    MESSAGE(name << ": pillows " << n.pillows << ", hex pushes " << n.hexPushes << ", other steps " << n.others);
    CHECK(n.pillows + n.hexPushes > 400 * kMeshSteps / 2000);
  }
}

// Hex push glues its six hexes from a plan (ops::replaceHexesByPlan, hexPushGluings) instead of
// matching their faces by vertices: the same steps, re-done with replaceHexes on a copy of the
// complex before each, give the same ids and every gluing of the new hexes and their neighbours
// the same, pillows in between making the neighbourhoods degenerate.
TEST_CASE("valid by construction: hex push's planned gluings are the ones matching faces by vertices finds") {
  auto compare = [](Complex cx, uint32_t seed, int steps) {
    MESSAGE("seed " << seed);
    std::mt19937 rng(seed);
    int compared = 0;
    for (int s = 0; s < steps; ++s) {
      const HexId h = HexId(rng() % uint32_t(cx.hexCapacity()));
      const int f = int(rng() % 6);
      const bool push = rng() % 3 != 0;
      if (!cx.isHex(h)) continue;
      const std::string text = std::string(push ? "hexpush" : "pillow") + " h" + std::to_string(h) + "f" + std::to_string(f);
      Complex generic = cx;
      std::optional<OpResult> r = tryApplyStep(cx, text);
      if (!r || !push) continue;
      CAPTURE(text);
      ops::Transaction tx(generic);  // rolled back: only compared
      for (VertexId v : r->createdVertices) REQUIRE(generic.addVertex(cx.position(v)) == v);
      std::vector<std::array<VertexId, 8>> added;
      for (HexId c : r->createdHexes) added.push_back(cx.hexVertices(c));
      REQUIRE(ops::replaceHexes(generic, "hexpush", r->removedHexes, added) == r->createdHexes);
      for (HexId c : ops::withNeighbours(cx, r->createdHexes))
        for (int g = 0; g < 6; ++g) {
          const Gluing a = cx.gluing(c, g), b = generic.gluing(c, g);
          CAPTURE(c);
          CAPTURE(g);
          REQUIRE(a.hex == b.hex);
          if (!a.boundary()) {
            REQUIRE(a.face == b.face);
            REQUIRE(a.orient == b.orient);
          }
        }
      ++compared;
    }
    return compared;
  };
  const int onGrid = compare(makeGrid(4, 4, 4), 2026120601, 900 / kScale);
  MESSAGE("hex pushes compared on a 4x4x4 grid: " << onGrid);
  CHECK(onGrid >= 100 / kScale);
  if (!std::filesystem::is_directory(devMeshDir())) {
    MESSAGE("skipped the development-set mesh: none at " << devMeshDir().string());
    return;
  }
  const int onMesh = compare(readDevMesh(devMeshDir() / "MOAB_125hex.vtk.gz"), 2026120602, 900 / kScale);
  MESSAGE("hex pushes compared on MOAB_125hex: " << onMesh);
  CHECK(onMesh >= 100 / kScale);
}

// Sheet extraction commits without walking vertex links when sheetExtractValidByConstruction holds
// (the argument in core/ops/sheet_extract.cpp). Every sheet of grids, an O-grid, 400 random atomic
// meshes (folds, pinches, doubled edges, sheets touching themselves and the boundary) and the
// development meshes is extracted on a copy; where it is certified, the whole result must validate
// with every link walked. Certified means applied, except where a touched hex keeps a vertex the
// input left non-manifold (P_rockarm: refused as before).
namespace {
struct CertifiedCounts {
  int applied = 0, certified = 0;
};
void extractEverySheetChecked(const Complex& cx, CertifiedCounts& n) {
  for (EdgeRef e : sheetEdges(cx)) {
    Complex c = cx;
    const bool certified = sheetExtractValidByConstruction(c, e);
    std::string refusal;
    try {
      sheetExtract(c, e);
    } catch (const Error& err) {
      refusal = err.what();
    }
    CAPTURE(e.hex);
    CAPTURE(e.edge);
    if (certified) CHECK((refusal.empty() || refusal.find("touches non-manifold vertex") != std::string::npos));
    if (!refusal.empty()) continue;
    ++n.applied;
    if (!certified) continue;
    ++n.certified;
    REQUIRE(errorOf([&] { c.validate(); }) == "");
  }
}
}  // namespace

TEST_CASE("valid by construction: every sheet extraction it certifies leaves every vertex link valid") {
  CertifiedCounts grids, atomic, dev;
  for (const Complex& g : {makeGrid(3, 3, 3), makeGrid(5, 4, 3), makeGrid(2, 2, 1), makeRing(6, 2, 2), makeRing(8, 3, 2)})
    extractEverySheetChecked(g, grids);
  MESSAGE("grids and O-grids: " << grids.applied << " applied, " << grids.certified << " certified");
  CHECK(grids.certified > 10);
  // (Debug builds validate the whole complex in every commit already: fewer seeds there.)
  const uint32_t first = 20261207, seeds = 400 / kScale;
  MESSAGE("random atomic meshes, seeds " << first << ".." << first + seeds - 1);
  for (uint32_t seed = first; seed < first + seeds; ++seed) {
    CAPTURE(seed);
    extractEverySheetChecked(randomAtomicMesh(seed), atomic);
  }
  MESSAGE("random atomic meshes: " << atomic.applied << " applied, " << atomic.certified << " certified");
  CHECK(atomic.certified > 700 / kScale);
  CHECK(atomic.applied > atomic.certified + 100 / kScale);  // the check still decides the others
  if (!std::filesystem::is_directory(devMeshDir())) {
    MESSAGE("skipped: no development-set meshes at " << devMeshDir().string());
    return;
  }
  for (const auto& f : std::filesystem::directory_iterator(devMeshDir())) {
    const std::string name = f.path().filename().string();
    if (f.path().extension() != ".gz" || name == "P_big_buddy.mesh.gz") continue;  // (the largest: 15k hexes, 325 sheets)
    Complex cx;
    try {
      cx = readDevMesh(f.path());
    } catch (const Error&) {
      continue;  // refused by the readers (MANIFEST.md)
    }
    CAPTURE(name);
    extractEverySheetChecked(cx, dev);
  }
  MESSAGE("development meshes: " << dev.applied << " applied, " << dev.certified << " certified");
  CHECK(dev.certified > 100);
}
