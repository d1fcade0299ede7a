#include <doctest/doctest.h>

#include "complex/builders.hpp"
#include "complex/canonical.hpp"
#include "helpers.hpp"
#include "ops/oplog.hpp"
#include "ops/ops.hpp"

using namespace hexdual;
using namespace hexdual::test;

namespace {
// In makeRing(8,3,3) hexes are numbered ((k*8 + t)*3 + s): the middle ring is s=1, k=1.
HexId ringHex(int t, int s, int k) { return HexId((k * 8 + t) * 3 + s); }
int closedChords(const Dual& d) {
  int k = 0;
  for (const Chord& c : d.chords) k += c.closed;
  return k;
}
}  // namespace

TEST_CASE("ring collapse of the middle ring of an 8x3x3 O-grid, and ring split back") {
  Complex cx = makeRing(8, 3, 3);
  Complex orig = cx;
  Counts before = cx.counts();
  Dual d0 = extractDual(cx);
  HexId h = ringHex(0, 1, 1);
  // Local y runs around the ring; edge 4*1 + 0 + 2*0 = 4 is the y-edge at (z=0, x=0).
  OpResult r = ringCollapse(cx, {h, 4});
  cx.validate();
  Counts after = cx.counts();
  CHECK(after.vertices - before.vertices == -8);
  CHECK(after.edges - before.edges == -24);
  CHECK(after.quads - before.quads == -24);
  CHECK(after.hexes - before.hexes == -8);
  CHECK(r.dE == -24);
  CHECK(after.boundaryQuads == before.boundaryQuads);
  Dual d1 = extractDual(cx);
  CHECK(closedChords(d1) == closedChords(d0) - 1);
  // The radial and axial annuli through the ring are cut along it and rejoined crosswise. The ring
  // separates both annuli, so the pieces swap: still two sheets, both annuli (no merge here).
  CHECK(d1.sheets.size() == d0.sheets.size());
  CHECK(countTopology(d1, "annulus") == countTopology(d0, "annulus"));
  REQUIRE(r.inverse);
  CHECK(r.inverse->op == OpKind::RingSplit);
  OpResult back = applyStep(cx, *r.inverse);
  cx.validate();
  CHECK(back.createdHexes.size() == 8);
  CHECK(cx.counts() == before);
  CHECK(isomorphic(cx, orig));
}

TEST_CASE("ring collapse rejects open chords, boundary rings and bad edges, untouched") {
  Complex cx = makeRing(8, 2, 2);
  std::string before = stateDump(cx);
  CHECK(errorOf([&] { ringCollapse(cx, {0, 0}); }) ==
        "ringcollapse: the chord through h0e0 reaches the boundary; ring collapse needs a closed chord");
  CHECK(errorOf([&] { ringCollapse(cx, {0, 4}); }) == "ringcollapse: side quad h0f0 of the ring is on the boundary");
  CHECK(errorOf([&] { ringCollapse(cx, {0, 12}); }) == "ringcollapse: local edge 12 is not 0..11");
  CHECK(stateDump(cx) == before);
}

TEST_CASE("hex push then ring collapse of its 4-ring: one diagonal undoes it, the other keeps counts") {
  Complex g = makeGrid(3, 3, 4);  // hexes 13 and 22 and all their far vertices are interior
  Counts base = g.counts();
  Dual d0 = extractDual(g);
  int undone = 0, twoNewChords = 0;
  for (int diag = 0; diag < 2; ++diag) {
    Complex cx = g;
    OpResult p = hexPush(cx, {13, 5});
    // A ring hex: created[2..5]; the new chord runs through them. Find its axis from the dual.
    Dual dp = extractDual(cx);
    HexId rh = p.createdHexes[2];
    int axis = -1;
    for (int a = 0; a < 3; ++a)
      if (dp.chords[size_t(dp.chordOf[rh][a])].closed) axis = a;
    REQUIRE(axis >= 0);
    OpResult c = ringCollapse(cx, {rh, 4 * axis + (diag ? 1 : 0)});
    cx.validate();
    CHECK(cx.counts() == base);
    Dual d1 = extractDual(cx);
    CHECK(d1.sheets.size() == d0.sheets.size());
    if (isomorphic(cx, g)) ++undone;
    else if (closedChords(d1) == 2) ++twoNewChords;
  }
  CHECK(undone == 1);
  CHECK(twoNewChords == 1);
}
