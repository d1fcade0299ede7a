#include <doctest/doctest.h>

#include "complex/builders.hpp"
#include "complex/canonical.hpp"
#include "helpers.hpp"
#include "ops/oplog.hpp"
#include "ops/ops.hpp"

using namespace hexdual;
using namespace hexdual::test;

namespace {
// Edge along z at corners 2-6 of hex 13 (3x3x3 centre): interior, 4 hexes around it: 13, 14, 17, 16.
const EdgeRef kCentreEdge{13, tables::edgeBetween(2, 6)};
int closedChords(const Dual& d) {
  int k = 0;
  for (const Chord& c : d.chords) k += c.closed;
  return k;
}
}  // namespace

TEST_CASE("chord push at the centre of a 3x3x3 grid: counts, a new blind chord, inverse") {
  for (auto [f, g] : {std::pair<QuadSide, QuadSide>{{13, 1}, {16, 1}}, {{13, 1}, {13, 3}}}) {
    CAPTURE(f.face);
    CAPTURE(g.hex);
    Complex cx = makeGrid(3, 3, 3);
    Complex orig = cx;
    Counts before = cx.counts();
    Dual d0 = extractDual(cx);
    OpResult r = chordPush(cx, kCentreEdge, f, g);
    cx.validate();
    Counts after = cx.counts();
    CHECK(after.vertices - before.vertices == 2);
    CHECK(after.edges - before.edges == 6);
    CHECK(after.quads - before.quads == 6);
    CHECK(after.hexes - before.hexes == 2);
    CHECK(r.dE == 6);
    Dual d1 = extractDual(cx);
    CHECK(d1.sheets.size() == d0.sheets.size());  // no new sheet
    CHECK(d1.chords.size() == d0.chords.size() + 1);
    CHECK(closedChords(d1) == 1);
    const Chord& blind = d1.chords[size_t(d1.chordAt(r.createdHexes[0], 0))];
    CHECK(blind.closed);
    CHECK(blind.slots.size() == 2);
    OpResult u = chordPull(cx, r.createdHexes[1]);
    cx.validate();
    CHECK(u.dV == -2);
    CHECK(cx.counts() == before);
    CHECK(isomorphic(cx, orig));
  }
}

TEST_CASE("chord push on opposite quads of the cycle (f, g not consecutive)") {
  Complex cx = makeGrid(3, 3, 3);
  Complex orig = cx;
  // Around the centre z-edge: quads 13|14 (h13f1) and 16|17 (h16f1) are opposite.
  OpResult r = chordPush(cx, kCentreEdge, {13, 1}, {16, 1});
  cx.validate();
  CHECK(r.createdHexes.size() == 2);
  // The inverse text replays.
  CHECK(formatOpStep(r.inverse.value()) == "chordpull h27");
}

TEST_CASE("chord push rejects boundary edges, quads off the cycle and equal quads, untouched") {
  Complex cx = makeGrid(3, 3, 3);
  std::string before = stateDump(cx);
  CHECK(errorOf([&] { chordPush(cx, {0, 0}, {0, 1}, {0, 3}); }) ==
        "chordpush: edge h0e0 is on the boundary; it needs a closed cycle of hexes");
  CHECK(errorOf([&] { chordPush(cx, kCentreEdge, {13, 1}, {0, 1}); }) ==
        "chordpush: quad h0f1 is not in the cycle around edge h13e11");
  CHECK(errorOf([&] { chordPush(cx, kCentreEdge, {13, 1}, {14, 0}); }) ==
        "chordpush: f and g are the same quad; chord push needs two distinct quads");
  CHECK(errorOf([&] { chordPull(cx, 13); }) == "chordpull: hex 13 is not half of a blind chord (no hex shares exactly 4 quads with it)");
  CHECK(stateDump(cx) == before);
}
