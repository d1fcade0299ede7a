// Hex push (the 2-6 flip) and hex pull (6-2), TK03 §4.2.
#include <doctest/doctest.h>

#include "complex/builders.hpp"
#include "complex/canonical.hpp"
#include "dual/dual_tracker.hpp"
#include "helpers.hpp"
#include "ops/op_table.hpp"
#include "ops/oplog.hpp"
#include "ops/ops.hpp"

using namespace hexdual;
using namespace hexdual::test;

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

TEST_CASE("hex pull reports hex push as its inverse; the tracked dual stays equal to a fresh one") {
  Complex cx = makeGrid(4, 4, 4);
  const Complex orig = cx;
  DualTracker tracker(cx);
  OpResult push = applyStep(cx, "hexpush h21f5");
  DualChange ch = tracker.update(cx, push.edits, keepsSheetTopology(push));
  CHECK(ch.sheetsCreated.empty());
  CHECK(ch.chordsCreated.size() == 1);  // the closed chord of the 4 ring hexes
  compareDuals(cx, tracker.dual(), extractDual(cx));
  OpResult pull = applyStep(cx, push.inverse.value());
  CHECK(pull.op == OpKind::HexPull);
  CHECK(pull.dV == -4);
  CHECK(pull.dE == -12);
  CHECK(pull.dF == -12);
  CHECK(pull.dH == -4);
  tracker.update(cx, pull.edits, keepsSheetTopology(pull));
  compareDuals(cx, tracker.dual(), extractDual(cx));
  CHECK(isomorphic(cx, orig));
  REQUIRE(pull.inverse);
  CHECK(pull.inverse->op == OpKind::HexPush);
  OpResult again = applyStep(cx, *pull.inverse);
  CHECK(again.dH == 4);
  cx.validate();
}
