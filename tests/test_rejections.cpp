// Every rejection rule of every operation: the exact message, and the complex unchanged.
#include <doctest/doctest.h>

#include <optional>
#include <random>

#include "complex/builders.hpp"
#include "flips/flip.hpp"
#include "helpers.hpp"
#include "ops/oplog.hpp"

using namespace hexdual;
using namespace hexdual::test;

namespace {
struct Case {
  const char* setup;  // an op log applied to a 3x3x3 grid first ("" for none)
  const char* step;
  const char* message;
};
}  // namespace

// Of the cases below, those the operation table's precheck rejects (pillow, hex push, chord push and
// face collapse have one).
constexpr int kPrechecked = 13;

TEST_CASE("every rejection rule names the rule and leaves the complex exactly as it was") {
  const Case cases[] = {
      {"", "pillow h13f9", "pillow: local face 9 is not 0..5"},
      {"", "pillow h99f1", "pillow: hex 99 does not exist"},
      {"", "pillow h0f0", "pillow: quad h0f0 is on the boundary; a pillow needs an interior quad"},
      {"", "unpillow h5", "unpillow: hex 5 is not half of a pillow (no hex shares exactly 5 quads with it)"},
      {"", "unpillow h77", "unpillow: hex 77 does not exist"},
      {"v1;pillow h1f3", "unpillow h2", "unpillow: hex 2 is not half of a pillow (no hex shares exactly 5 quads with it)"},
      {"", "chordpush h0e0 h0f1 h0f3", "chordpush: edge h0e0 is on the boundary; it needs a closed cycle of hexes"},
      {"", "chordpush h13e11 h0f1 h13f1", "chordpush: quad h0f1 is not in the cycle around edge h13e11"},
      {"", "chordpush h13e11 h13f1 h0f1", "chordpush: quad h0f1 is not in the cycle around edge h13e11"},
      {"", "chordpush h13e11 h13f1 h14f0", "chordpush: f and g are the same quad; chord push needs two distinct quads"},
      {"", "chordpush h13e12 h13f1 h14f0", "chordpush: local edge 12 is not 0..11"},
      {"", "chordpull h13", "chordpull: hex 13 is not half of a blind chord (no hex shares exactly 4 quads with it)"},
      {"", "hexpush h13f7", "hexpush: local face 7 is not 0..5"},
      {"", "hexpush h0f2", "hexpush: quad h0f2 is on the boundary; hex push needs an interior quad"},
      {"v1;pillow h13f5", "hexpush h27f5", "hexpush: hexes 27 and 28 share 5 quads; hex push needs exactly one"},
      {"v1;chordpush h13e11 h13f1 h16f1", "hexpush h27f0", "hexpush: hexes 27 and 28 share 4 quads; hex push needs exactly one"},
      {"", "hexpull h13f5", "hexpull: ring hex 12 must share one quad with each of hex 13 and hex 22"},
      {"", "hexpull h0f1", "hexpull: the 4 side quads of hex 0 must be glued to 4 distinct ring hexes"},
      {"", "hexpull h0f0", "hexpull: quad h0f0 is on the boundary; hex pull needs an interior quad"},
      {"", "ringcollapse h13e0", "ringcollapse: the chord through h13e0 reaches the boundary; ring collapse needs a closed chord"},
      {"", "ringcollapse h13e13", "ringcollapse: local edge 13 is not 0..11"},
      {"", "ringsplit h13f1/h13f3", "ringsplit: needs at least 2 quad pairs around a loop"},
      {"", "ringsplit h13f1/h13f3 h0f0/h0f2", "ringsplit: quad h0f0 is on the boundary"},
      {"", "ringsplit h13f1/h13f0 h13f2/h13f3", "ringsplit: quads h13f1 and h13f0 must share exactly one edge"},
      {"", "facecollapse h13e11 h14f3 h17f0", "facecollapse: vertices 27 and 30 would merge but both are on the boundary"},
      {"", "facecollapse h13e11 h13f1 h14f0", "facecollapse: f and g are the same quad; face collapse needs two distinct quads"},
      {"", "facesplit h13f1 h13f1", "facesplit: the two sides belong to the same quad"},
      {"", "facesplit h13f1 h0f0", "facesplit: quad h0f0 is on the boundary"},
      {"", "facesplit h13f1 h13f3", "facesplit: quads h13f1 and h13f3 are not on the same 4 vertices"},
      {"v1;pillow h13f5", "facesplit h13f5 h28f5", "facesplit: quads h13f5 and h28f5 are not a collapsed face pair"},
  };
  int prechecked = 0;
  for (const Case& c : cases) {
    std::string step = c.step;
    CAPTURE(step);
    Complex cx = makeGrid(3, 3, 3);
    if (*c.setup) REQUIRE(applyLog(cx, c.setup).failedStep == 0);
    std::string before = stateDump(cx);
    CHECK(errorOf([&] { applyStep(cx, c.step); }) == c.message);
    CHECK(stateDump(cx) == before);
    // The non-throwing form rejects with the same message (by the precheck or the operation).
    std::string why;
    CHECK_FALSE(tryApplyStep(cx, c.step, &why).has_value());
    CHECK(why == c.message);
    CHECK(stateDump(cx) == before);
    // The precheck (the package's apply rejects by it without an exception) gives the same message
    // or none (the operation's later checks then reject).
    std::string pre;
    const std::string preThrown = errorOf([&] { pre = precheckStep(cx, parseOpStep(c.step)); });
    CHECK((preThrown == c.message || pre.empty() || pre == c.message));
    prechecked += !pre.empty();
  }
  MESSAGE(prechecked << " of " << std::size(cases) << " rejected by the precheck");
  CHECK(prechecked == kPrechecked);
}

TEST_CASE("tryApplyStep applies and rejects exactly the steps applyStep does, with the same messages and ids") {
  // Random pillow, hex push and chord push steps on two copies of a 4^3 grid, one through each form.
  const uint32_t seed = 20261202;
  MESSAGE("seed " << seed);
  std::mt19937 rng(seed);
  Complex a = makeGrid(4, 4, 4), b = makeGrid(4, 4, 4);
  int applied = 0, rejected = 0;
  const char* ops[] = {"pillow", "hexpush", "chordpush"};
  for (int s = 0; s < 600; ++s) {
    const std::string h = "h" + std::to_string(rng() % uint32_t(a.hexCapacity()));
    const std::string op = ops[rng() % 3];
    const std::string step = op == "chordpush" ? op + " " + h + "e" + std::to_string(rng() % 12) + " " + h + "f" +
                                                     std::to_string(rng() % 6) + " " + h + "f" + std::to_string(rng() % 6)
                                               : op + " " + h + "f" + std::to_string(rng() % 6);
    CAPTURE(step);
    const std::string thrown = errorOf([&] { applyStep(a, step); });
    std::string why;
    const std::string before = stateDump(b);
    std::optional<OpResult> r = tryApplyStep(b, step, &why);
    CHECK(r.has_value() == thrown.empty());
    if (r) {
      ++applied;
    } else {
      ++rejected;
      CHECK(why == thrown);
      CHECK(stateDump(b) == before);
    }
    REQUIRE(stateDump(a) == stateDump(b));
  }
  MESSAGE(applied << " applied, " << rejected << " rejected");
  CHECK(applied > 100);
  CHECK(rejected > 100);
}

TEST_CASE("composite and flip rejections leave the complex unchanged") {
  Complex cx = makeGrid(3, 3, 3);
  std::string before = stateDump(cx);
  CHECK(errorOf([&] { pillowRegion(cx, {}); }) == "pillowRegion: needs at least one hex");
  CHECK(errorOf([&] { pillowRegion(cx, {0}); }) == "pillowRegion: quad h0f0 of the set is on the mesh boundary");
  CHECK(errorOf([&] { tripleChordPush(cx, 13, 9, {13, 0}, {13, 2}, {13, 4}); }) == "tripleChordPush: corner 9 is not 0..7");
  CHECK(errorOf([&] { tripleChordPush(cx, 13, 0, {13, 0}, {13, 0}, {13, 4}); }) == "tripleChordPush: the three quads must be distinct");
  CHECK(errorOf([&] { tripleChordPush(cx, 13, 0, {13, 1}, {13, 2}, {13, 4}); }) == "tripleChordPush: quad h13f1 does not contain vertex 21");
  CHECK(errorOf([&] { flip(cx, "2-6", {13, 99}); }) == "flip 2-6: hex 99 does not exist");
  CHECK(errorOf([&] { traditionalPillow(cx, 0, 0); }) == "pillow: quad h0f0 is on the boundary; a pillow needs an interior quad");
  CHECK(stateDump(cx) == before);
}
