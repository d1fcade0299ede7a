#include <doctest/doctest.h>

#include <algorithm>
#include <random>

#include "complex/builders.hpp"
#include "complex/canonical.hpp"
#include "helpers.hpp"
#include "io/io.hpp"
#include "ops/oplog.hpp"
#include "ops/ops.hpp"

using namespace hexdual;
using namespace hexdual::test;

namespace {
int closedChordsOfLength(const Dual& d, size_t n) {
  int k = 0;
  for (const Chord& c : d.chords) k += c.closed && c.slots.size() == n;
  return k;
}
}  // namespace

TEST_CASE("pillow at the centre of a 3x3x3 grid: counts, dual, inverse") {
  Complex cx = makeGrid(3, 3, 3);
  Complex orig = cx;
  Counts before = cx.counts();
  Dual d0 = extractDual(cx);
  OpResult r = pillow(cx, {13, 5});  // centre hex, top face
  cx.validate();
  Counts after = cx.counts();
  CHECK(after.vertices - before.vertices == 4);
  CHECK(after.edges - before.edges == 8);
  CHECK(after.quads - before.quads == 6);
  CHECK(after.hexes - before.hexes == 2);
  CHECK(r.dV == 4);
  CHECK(r.dE == 8);
  CHECK(r.dF == 6);
  CHECK(r.dH == 2);
  CHECK(r.createdHexes == std::vector<HexId>{27, 28});
  CHECK(r.createdVertices == std::vector<VertexId>{64, 65, 66, 67});
  CHECK(after.boundaryQuads == before.boundaryQuads);
  Dual d1 = extractDual(cx);
  CHECK(d1.sheets.size() == d0.sheets.size() + 1);
  CHECK(countTopology(d1, "sphere") == 1);
  CHECK(d1.chords.size() == d0.chords.size() + 2);
  CHECK(closedChordsOfLength(d1, 2) == 2);
  // The z chord through the centre gains X and Y.
  CHECK(d1.chords[size_t(d1.chordAt(13, 2))].slots.size() == 5);
  CHECK(formatOpStep(r.inverse.value()) == "unpillow h27");
  OpResult u = unpillow(cx, 27);
  cx.validate();
  CHECK(u.dV == -4);
  CHECK(u.dE == -8);
  CHECK(cx.counts() == before);
  CHECK(isomorphic(cx, orig));
  CHECK(canonicalHash(cx) == canonicalHash(orig));
}

TEST_CASE("pillow next to the boundary and next to an earlier pillow; unpillow from either half") {
  Complex cx = makeGrid(3, 3, 3);
  Complex orig = cx;
  pillow(cx, {0, 1});  // corner hex, interior face toward hex 1
  cx.validate();
  OpResult second = pillow(cx, {27, 5});  // a face of the degenerate pillow hex itself
  cx.validate();
  CHECK(second.dH == 2);
  Dual d = extractDual(cx);
  CHECK(countTopology(d, "sphere") == 2);
  unpillow(cx, 30);  // the second pair, named by its other half
  cx.validate();
  unpillow(cx, 28);
  CHECK(isomorphic(cx, orig));
}

TEST_CASE("pillow and unpillow reject bad input and leave the complex untouched") {
  Complex cx = makeGrid(2, 2, 2);
  std::string before = stateDump(cx);
  CHECK(errorOf([&] { pillow(cx, {0, 0}); }) == "pillow: quad h0f0 is on the boundary; a pillow needs an interior quad");
  CHECK(errorOf([&] { pillow(cx, {99, 1}); }) == "pillow: hex 99 does not exist");
  CHECK(errorOf([&] { pillow(cx, {0, 7}); }) == "pillow: local face 7 is not 0..5");
  CHECK(errorOf([&] { unpillow(cx, 0); }) == "unpillow: hex 0 is not half of a pillow (no hex shares exactly 5 quads with it)");
  CHECK(stateDump(cx) == before);
}

TEST_CASE("canonical form: isomorphic under renumbering, different after a change") {
  Complex a = makeGrid(2, 3, 2);
  // The same grid with its hexes listed in reverse order and each hex's corners rotated.
  std::vector<std::array<VertexId, 8>> hexes;
  for (HexId h = a.hexCapacity() - 1; h >= 0; --h) {
    auto v = a.hexVertices(h);
    hexes.push_back({v[1], v[2], v[3], v[0], v[5], v[6], v[7], v[4]});
  }
  Complex b = fromConnectivity(std::vector<Vec3>(a.positions().begin(), a.positions().end()), hexes);
  CHECK(b.vertex(0, 0) != a.vertex(0, 0));
  CHECK(isomorphic(a, b));
  Complex c = a;
  pillow(c, {0, 1});
  CHECK_FALSE(isomorphic(a, c));
  CHECK(canonicalHash(a) != canonicalHash(c));
  // Closed complexes: every start flag is tried.
  CHECK(isomorphic(makeGrid(2, 1, 1), makeGrid(1, 2, 1), false));
  CHECK_FALSE(isomorphic(makeGrid(2, 1, 1), makeGrid(1, 2, 1), true));  // boundary vertex ids differ
}

TEST_CASE("canonical form with the boundary free: any renumbering of vertices and hexes, and nothing else") {
  const Complex a = makeGrid(3, 4, 2);
  // Every vertex id moved (boundary ones too) and the hexes listed backwards, corners rotated.
  const unsigned seed = 20261204;
  MESSAGE("seed " << seed);
  std::vector<VertexId> perm;
  const Complex b = test::renumbered(a, seed, &perm);
  CHECK_FALSE(isomorphic(a, b));  // boundary kept: the boundary vertex ids moved
  CHECK(isomorphic(a, b, false));
  CHECK(canonicalHash(a, false) == canonicalHash(b, false));
  CHECK(isomorphic(a, makeGrid(4, 3, 2), false));  // the same grid turned
  CHECK(isomorphic(a, makeGrid(2, 3, 4), false));
  CHECK_FALSE(isomorphic(a, makeGrid(3, 4, 3), false));  // another grid
  // A pillow on the same quad in both numberings keeps them isomorphic; on another quad, not.
  // Hex 5 of a is hex 24 - 1 - 5 of b, corners rotated: find b's face on the same vertices.
  const HexId ha = 5, hb = HexId(a.hexCapacity() - 1 - 5);
  auto faceInB = [&](int fa) {
    std::array<VertexId, 4> want{};
    for (int p = 0; p < 4; ++p) want[size_t(p)] = perm[size_t(a.vertex(ha, tables::kFaceCorners[size_t(fa)][size_t(p)]))];
    std::sort(want.begin(), want.end());
    for (int f = 0; f < 6; ++f) {
      std::array<VertexId, 4> got{};
      for (int p = 0; p < 4; ++p) got[size_t(p)] = b.vertex(hb, tables::kFaceCorners[size_t(f)][size_t(p)]);
      std::sort(got.begin(), got.end());
      if (got == want) return f;
    }
    return -1;
  };
  REQUIRE(faceInB(0) >= 0);
  REQUIRE(faceInB(5) >= 0);
  Complex pa = a, pb = b, other = b;
  pillow(pa, {ha, 0});               // hex 5 is (2, 1, 0): its -x quad is interior
  pillow(pb, {hb, faceInB(0)});      // the same quad in b
  pillow(other, {hb, faceInB(5)});   // its +z quad (k = 0 of 2): interior too, elsewhere
  CHECK(isomorphic(pa, pb, false));
  CHECK_FALSE(isomorphic(pa, b, false));
  CHECK_FALSE(isomorphic(pa, other, false));
  CHECK(canonicalHash(pa, false) != canonicalHash(other, false));
}
