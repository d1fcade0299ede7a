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
    const Chord& blind = d1.chords[size_t(d1.chordOf[r.createdHexes[0]][0])];
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

TEST_CASE("hex push at the centre of a 3x3x3 grid: the 2-6 flip") {
  Complex cx = makeGrid(3, 3, 3);
  Complex orig = cx;
  Counts before = cx.counts();
  Dual d0 = extractDual(cx);
  OpResult r = hexPush(cx, {13, 5});
  cx.validate();
  Counts after = cx.counts();
  CHECK(after.vertices - before.vertices == 4);
  CHECK(after.edges - before.edges == 12);
  CHECK(after.quads - before.quads == 12);
  CHECK(after.hexes - before.hexes == 4);
  CHECK(r.dE == 12);
  CHECK(r.removedHexes == std::vector<HexId>{13, 22});
  CHECK(r.createdHexes.size() == 6);
  Dual d1 = extractDual(cx);
  CHECK(d1.sheets.size() == d0.sheets.size());
  CHECK(d1.chords.size() == d0.chords.size() + 1);
  int ring4 = 0;
  for (const Chord& c : d1.chords) ring4 += c.closed && c.slots.size() == 4;
  CHECK(ring4 == 1);
  CHECK(formatOpStep(r.inverse.value()) == "hexpull h27f5");
  OpResult u = hexPull(cx, {27, 5});
  cx.validate();
  CHECK(u.dV == -4);
  CHECK(u.dE == -12);
  CHECK(cx.counts() == before);
  CHECK(isomorphic(cx, orig));
}

TEST_CASE("hex push next to the boundary, and 1-7 counts: pillow then hex push") {
  Complex cx = makeGrid(3, 3, 3);
  Counts before = cx.counts();
  Complex orig = cx;
  pillow(cx, {13, 5});  // X = 27 touches hex 13 across q
  OpResult h = hexPush(cx, {13, 5});  // between C = 13 and the adjacent new hex X
  cx.validate();
  Counts after = cx.counts();
  CHECK(after.vertices - before.vertices == 8);
  CHECK(after.edges - before.edges == 20);
  CHECK(after.quads - before.quads == 18);
  CHECK(after.hexes - before.hexes == 6);
  Dual d = extractDual(cx);
  CHECK(countTopology(d, "sphere") == 1);
  // Undo in reverse order.
  OpResult back = hexPull(cx, {h.createdHexes[0], 5});
  CHECK(back.createdHexes.size() == 2);  // C and X again, with fresh ids
  unpillow(cx, back.createdHexes[1]);
  CHECK(isomorphic(cx, orig));
  // Next to the boundary: corner hex 0 and its neighbour 1.
  Complex g = makeGrid(3, 3, 3);
  hexPush(g, {0, 1});
  g.validate();
  CHECK(g.counts().hexes == 31);
}

TEST_CASE("hex push rejects hexes sharing more than one quad, untouched") {
  Complex cx = makeGrid(3, 3, 3);
  pillow(cx, {13, 5});
  std::string before = stateDump(cx);
  CHECK(errorOf([&] { hexPush(cx, {27, 5}); }) == "hexpush: hexes 27 and 28 share 5 quads; hex push needs exactly one");
  CHECK(errorOf([&] { hexPush(cx, {0, 0}); }) == "hexpush: quad h0f0 is on the boundary; hex push needs an interior quad");
  CHECK(errorOf([&] { hexPull(cx, {13, 5}); }).rfind("hexpull: ", 0) == 0);
  CHECK(stateDump(cx) == before);
}
