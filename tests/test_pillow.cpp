#include <doctest/doctest.h>

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
  Complex b = fromConnectivity(a.positions(), hexes);
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
