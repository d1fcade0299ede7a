#include <doctest/doctest.h>

#include <algorithm>

#include "complex/builders.hpp"
#include "complex/canonical.hpp"
#include "helpers.hpp"
#include "ops/oplog.hpp"
#include "ops/ops.hpp"
#include "ops/support.hpp"

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
      if (dp.chords[size_t(dp.chordAt(rh, a))].closed) axis = a;
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

TEST_CASE("ring collapse reports a ring-split inverse only when it applies; otherwise none, with the reason") {
  // After this collapse two of the recorded side quads are the same quad (h3f3): the step
  // `ringsplit h4f1/h3f3 h6f0/h3f3` would be rejected, so none is reported.
  Complex cx = makeRing(3, 1, 1);
  ApplyReport setup = applyLog(cx, "v1;hexpush h2f3;pillow h8f2;chordpush h6e8 h4f2 h6f0;pillow h11f3");
  REQUIRE(setup.failedStep == 0);
  Complex before = cx;
  OpResult r = applyStep(cx, "ringcollapse h12e3");
  cx.validate();
  CHECK_FALSE(r.inverse);
  CHECK(r.noInverse ==
        "the ring split of the collapsed loop does not apply (ringsplit: the quads do not separate vertex 15 consistently)");
  CHECK(errorOf([&] { applyStep(cx, "ringsplit h4f1/h3f3 h6f0/h3f3"); }) ==
        "ringsplit: the quads do not separate vertex 15 consistently");
  // The report leaves the result exactly as the collapse made it: undo restores the start.
  cx.undo(r.edits);
  CHECK(stateDump(cx) == stateDump(before));
}

TEST_CASE("ring collapse next to the boundary: interior vertices merge into boundary ones, the boundary stays") {
  // The 4-ring of a hex push in the bottom layer of a 3x3x4 grid: its collapse merges interior
  // vertices into bottom-face vertices, which keep their ids.
  Complex cx = makeGrid(3, 3, 4);
  std::vector<std::array<VertexId, 4>> boundary;
  auto boundaryQuads = [](const Complex& c) {
    std::vector<std::array<VertexId, 4>> out;
    for (QuadSide q : c.quads())
      if (c.isBoundary(q)) out.push_back(ops::faceVertexSet(c, q.hex, q.face));
    std::sort(out.begin(), out.end());
    return out;
  };
  boundary = boundaryQuads(cx);
  REQUIRE(applyLog(cx, "v1;hexpush h4f5").failedStep == 0);
  const Complex pushed = cx;
  OpResult r = applyStep(cx, "ringcollapse h38e4");
  cx.validate();
  CHECK(r.dV == -4);
  CHECK(r.dE == -12);
  CHECK(r.dF == -12);
  CHECK(r.dH == -4);
  CHECK(boundaryQuads(cx) == boundary);
  // The ring split puts the new vertices inside, off the boundary: the inverse applies.
  REQUIRE(r.inverse);
  Complex back = cx;
  applyStep(back, *r.inverse);
  back.validate();
  CHECK(isomorphic(back, pushed));
  CHECK(boundaryQuads(back) == boundary);
}
