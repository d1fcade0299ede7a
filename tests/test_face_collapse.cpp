#include <doctest/doctest.h>

#include <algorithm>

#include "complex/builders.hpp"
#include "complex/canonical.hpp"
#include "helpers.hpp"
#include "ops/candidates.hpp"
#include "ops/oplog.hpp"
#include "ops/ops.hpp"
#include "ops/support.hpp"

using namespace hexdual;
using namespace hexdual::test;

namespace {
// 4x4x4 grid: the z-edge at x=2, y=2, z in [1,2] (hex 21 = (1,1,1), corners 2-6) has hexes 21, 22, 26, 25
// around it; f = 21|22 and g = 25|26 are opposite quads whose far vertices are all interior.
const EdgeRef kEdge{21, tables::edgeBetween(2, 6)};
const QuadSide kF{21, 1}, kG{25, 1};
}  // namespace

TEST_CASE("face collapse in a 4x4x4 grid: counts, two sheets merge, face split restores") {
  Complex cx = makeGrid(4, 4, 4);
  Complex orig = cx;
  Counts before = cx.counts();
  Dual d0 = extractDual(cx);
  OpResult r = faceCollapse(cx, kEdge, kF, kG);
  cx.validate();
  Counts after = cx.counts();
  CHECK(after.vertices - before.vertices == -2);
  CHECK(after.edges - before.edges == -2);
  CHECK(after.quads - before.quads == 0);
  CHECK(after.hexes - before.hexes == 0);
  CHECK(r.dE == -2);
  Dual d1 = extractDual(cx);
  CHECK(d1.sheets.size() == d0.sheets.size() - 1);
  CHECK(d1.chords.size() == d0.chords.size());  // the chords through f and g are cut and rejoined crosswise
  OpResult back = applyStep(cx, r.inverse.value());
  cx.validate();
  CHECK(back.dV == 2);
  CHECK(back.dE == 2);
  CHECK(cx.counts() == before);
  CHECK(isomorphic(cx, orig));
}

TEST_CASE("chord push then ring collapse of the blind chord (far diagonal) equals face collapse") {
  Complex a = makeGrid(4, 4, 4), b = makeGrid(4, 4, 4), c = makeGrid(4, 4, 4);
  Counts base = a.counts();
  OpResult p = chordPush(a, kEdge, kF, kG);
  // In X's frame x runs along e; edge 1 (y=1,z=0) is g's far edge, its diagonal edge 2 is f's far edge.
  OpResult rc = ringCollapse(a, {p.createdHexes[0], 1});
  a.validate();
  faceCollapse(b, kEdge, kF, kG);
  CHECK(a.counts() == b.counts());
  CHECK(isomorphic(a, b));
  CHECK_FALSE(rc.inverse);  // a ring glued to itself has no ring-split inverse
  // The other diagonal merges e with the blind chord's inner edge: that undoes the chord push.
  OpResult p2 = chordPush(c, kEdge, kF, kG);
  ringCollapse(c, {p2.createdHexes[0], 0});
  c.validate();
  CHECK(c.counts() == base);
  CHECK(isomorphic(c, makeGrid(4, 4, 4)));
}

TEST_CASE("face collapse rejections leave the complex untouched") {
  Complex cx = makeGrid(3, 3, 3);
  std::string before = stateDump(cx);
  // Around the centre z-edge of a 3x3x3 grid, f = h14f3 and g = h17f0 both have their far
  // vertices on the boundary: two boundary vertices would merge.
  CHECK(errorOf([&] { faceCollapse(cx, {13, 11}, {14, 3}, {17, 0}); }) ==
        "facecollapse: vertices 27 and 30 would merge but both are on the boundary");
  // Consecutive quads leave arc R = {13} glued to itself: not a valid complex.
  CHECK(errorOf([&] { faceCollapse(cx, {13, 11}, {13, 1}, {13, 3}); }).rfind("facecollapse: the result would not be a valid complex", 0) == 0);
  CHECK(errorOf([&] { faceSplit(cx, {13, 1}, {13, 3}); }) == "facesplit: quads h13f1 and h13f3 are not on the same 4 vertices");
  CHECK(stateDump(cx) == before);
}

namespace {
// The boundary quad mesh as vertex sets, sorted: what a collapse next to the boundary must keep.
std::vector<std::array<VertexId, 4>> boundaryQuads(const Complex& cx) {
  std::vector<std::array<VertexId, 4>> out;
  for (QuadSide q : cx.quads())
    if (cx.isBoundary(q)) out.push_back(ops::faceVertexSet(cx, q.hex, q.face));
  std::sort(out.begin(), out.end());
  return out;
}
}  // namespace

TEST_CASE("face collapse merging an interior vertex into a boundary vertex keeps the boundary quad mesh") {
  Complex cx = makeGrid(3, 3, 3);
  const Complex orig = cx;
  const auto boundary = boundaryQuads(cx);
  // Edge h1e3 runs from the bottom face to the centre; f's far vertices are interior, g's on the boundary.
  OpResult r = applyStep(cx, "facecollapse h1e3 h4f5 h10f4");
  cx.validate();
  CHECK(r.dV == -2);
  CHECK(r.dE == -2);
  CHECK(r.dF == 0);
  CHECK(r.dH == 0);
  CHECK(r.removedVertices == std::vector<VertexId>{25, 26});  // the interior ones; the boundary ids stay
  CHECK(boundaryQuads(cx) == boundary);
  for (VertexId v : r.removedVertices) CHECK_FALSE(cx.isVertex(v));
  // Its inverse splits the boundary vertices again, the new vertices on the interior side.
  REQUIRE(r.inverse);
  CHECK(formatOpStep(*r.inverse) == "facesplit h13f4 h4f5");
  Complex back = cx;
  applyStep(back, *r.inverse);
  back.validate();
  CHECK(isomorphic(back, orig));
  CHECK(boundaryQuads(back) == boundary);
  // The grid's face collapses are now listed: 24 of them (none merges two boundary vertices).
  auto steps = candidates(orig, OpKind::FaceCollapse);
  CHECK(steps.size() == 24);
  CHECK(std::find(steps.begin(), steps.end(), parseOpStep("facecollapse h1e3 h4f5 h10f4")) != steps.end());
}
