#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "complex/builders.hpp"
#include "dual/dual.hpp"
#include "layout/dual_points.hpp"
#include "layout/render_buffers.hpp"
#include "ops/oplog.hpp"

using namespace hexdual;

namespace {
double dist(Vec3 a, Vec3 b) { return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z)); }
Vec3 at(const std::vector<float>& p, size_t vertex) { return {p[3 * vertex], p[3 * vertex + 1], p[3 * vertex + 2]}; }
// Mean of the 24 face-vertex positions a hex contributes to the render buffers.
Vec3 drawnCentre(const RenderBuffers& rb, HexId h) {
  Vec3 s;
  int n = 0;
  for (size_t t = 0; t < rb.triangleHex.size(); t += 2)
    if (rb.triangleHex[t] == h)
      for (size_t q = 0; q < 4; ++q, ++n) s = s + at(rb.positions, 2 * t + q);
  return (1.0 / n) * s;
}
}  // namespace

TEST_CASE("render buffers: 12 triangles per hex with hex and local face; 12 edge segments per hex") {
  Complex cx = makeGrid(2, 1, 1);
  RenderBuffers rb = buildRenderBuffers(cx, 0.2, true);
  CHECK(rb.triangleHex.size() == 24);
  CHECK(rb.triangleFace.size() == 24);
  CHECK(rb.positions.size() == 2 * 24 * 3);
  CHECK(rb.indices.size() == 72);
  for (size_t t = 0; t < 24; ++t) {
    CHECK(rb.triangleHex[t] == int(t / 12));
    CHECK(rb.triangleFace[t] == (t % 12) / 2);
  }
  CHECK(rb.edgeHex.size() == 24);
  CHECK(rb.edgeLocal[13] == 1);
  CHECK(rb.edgePositions.size() == 24 * 2 * 3);
  CHECK(buildRenderBuffers(cx, 0.2).edgePositions.empty());
  // Face 1 of hex 0 is x = 1 side: shrunk 20% about x = 0.5 gives x = 0.9.
  for (size_t q = 0; q < 4; ++q) CHECK(at(rb.positions, 4 * 1 + q).x == doctest::Approx(0.9));
}

TEST_CASE("dual points: the centroid in a regular grid; a pillow pair's two hexes get different points") {
  Complex cx = makeGrid(3, 3, 3);
  std::vector<Vec3> dp = dualPoints(cx);
  for (HexId h : cx.hexes()) CHECK(dist(dp[size_t(h)], cx.hexCentroid(h)) == doctest::Approx(0).epsilon(1e-12));
  CHECK_FALSE(isDegenerateHex(cx, 13));

  OpResult r = applyStep(cx, "pillow h13f5");
  REQUIRE(r.createdHexes.size() == 2);
  const HexId X = r.createdHexes[0], Y = r.createdHexes[1];
  CHECK(dist(cx.hexCentroid(X), cx.hexCentroid(Y)) == doctest::Approx(0));
  CHECK(isDegenerateHex(cx, X));
  CHECK(isDegenerateHex(cx, Y));
  dp = dualPoints(cx);
  // X lies on hex 13's side of the quad, Y on the other: X's point is below Y's along z.
  CHECK(dp[size_t(Y)].z - dp[size_t(X)].z > 0.2);

  RenderBuffers rb = buildRenderBuffers(cx, 0.15);
  CHECK(rb.triangleHex.size() == 12 * 29);
  CHECK(dist(drawnCentre(rb, X), drawnCentre(rb, Y)) > 0.2);
  // The two drawn slabs do not overlap along z: X's top is below Y's bottom.
  double xTop = -1e9, yBottom = 1e9;
  for (size_t t = 0; t < rb.triangleHex.size(); t += 2)
    for (size_t q = 0; q < 4; ++q) {
      double z = at(rb.positions, 2 * t + q).z;
      if (rb.triangleHex[t] == X) xTop = std::max(xTop, z);
      if (rb.triangleHex[t] == Y) yBottom = std::min(yBottom, z);
    }
  CHECK(xTop < yBottom);
}

TEST_CASE("dual overlay: one mid-surface quad per sheet slot, chords through dual points, one dot per hex") {
  Complex cx = makeGrid(2, 2, 1);
  Dual d = extractDual(cx);
  DualOverlay o = buildDualOverlay(cx, d);
  // 4 hexes x 3 axes = 12 slots, 2 triangles each.
  CHECK(o.sheetTriangle.size() == 24);
  CHECK(o.sheetPositions.size() == 12 * 4 * 3);
  CHECK(std::set<int>(o.sheetTriangle.begin(), o.sheetTriangle.end()).size() == d.sheets.size());
  // Every chord is open: its slots plus two boundary ends, so slots + 1 segments.
  size_t segments = 0;
  for (const Chord& c : d.chords) segments += c.slots.size() + 1;
  CHECK(o.chordSegment.size() == segments);
  CHECK(o.dualVertexHex == std::vector<int32_t>{0, 1, 2, 3});
  // A z-chord through hex 0 runs from z=0 to z=1 at the hex's centre (0.5, 0.5).
  bool found = false;
  for (size_t s = 0; s < o.chordSegment.size(); ++s) {
    Vec3 a = at(o.chordPositions, 2 * s), b = at(o.chordPositions, 2 * s + 1);
    if (a.x == doctest::Approx(0.5) && a.y == doctest::Approx(0.5) && b.x == doctest::Approx(0.5) && a.z == doctest::Approx(0) &&
        b.z == doctest::Approx(0.5))
      found = true;
  }
  CHECK(found);

  // Only hexes 0 and 1 (the row y = 0): their 6 slots; the x-chord through both (3 segments), one
  // end segment of each y-chord, both segments of their z-chords.
  const std::vector<HexId> only{0, 1};
  DualOverlay part = buildDualOverlay(cx, d, &only);
  CHECK(part.sheetTriangle.size() == 12);
  CHECK(part.chordSegment.size() == 3 + 1 + 1 + 2 + 2);
  CHECK(part.dualVertexHex == std::vector<int32_t>{0, 1});
}

TEST_CASE("render buffers: a shell draws only the hexes seen from outside or from a cut; `always` adds hidden ones") {
  Complex cx = makeGrid(3, 3, 3);
  auto has = [](const std::vector<HexId>& v, HexId h) { return std::find(v.begin(), v.end(), h) != v.end(); };
  DrawnHexes shell;
  shell.shell = true;
  std::vector<HexId> drawn = drawnHexes(cx, shell);
  CHECK(drawn.size() == 26);
  CHECK_FALSE(has(drawn, 13));
  CHECK(buildRenderBuffers(cx, 0.15, false, shell).triangleHex.size() == 12 * 26);

  // Cutting away the top layer (z = 2: hexes 18..26) exposes the centre hex 13 below it.
  DrawnHexes cut = shell;
  cut.hidden.assign(27, 0);
  for (HexId h = 18; h < 27; ++h) cut.hidden[size_t(h)] = 1;
  drawn = drawnHexes(cx, cut);
  CHECK(drawn.size() == 18);
  CHECK(has(drawn, 13));
  CHECK_FALSE(has(drawn, 22));

  // A pillow at the centre creates two interior hexes: drawn only when asked for.
  OpResult r = applyStep(cx, "pillow h13f5");
  CHECK(drawnHexes(cx, shell).size() == 26);
  DrawnHexes withCreated = shell;
  withCreated.always = r.createdHexes;
  drawn = drawnHexes(cx, withCreated);
  CHECK(drawn.size() == 28);
  CHECK(has(drawn, r.createdHexes[0]));
  CHECK(has(drawn, r.createdHexes[1]));
  CHECK(drawnHexes(cx, {}).size() == 29);
}
