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
