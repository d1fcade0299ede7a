#include <doctest/doctest.h>

#include "complex/builders.hpp"
#include "complex/canonical.hpp"
#include "flips/flip.hpp"
#include "flips/fourcube.hpp"
#include "helpers.hpp"

using namespace hexdual;
using namespace hexdual::test;

namespace {
Counts delta(const Counts& a, const Counts& b) {
  return {b.vertices - a.vertices, b.edges - a.edges, b.quads - a.quads, b.hexes - a.hexes, 0, 0, 0};
}
Counts interiorDelta(const FlipClass& f) { return delta(f.interiorBefore, f.interiorAfter); }
Counts meshDelta(const Complex& a, const Complex& b) { return delta(a.counts(), b.counts()); }
}  // namespace

TEST_CASE("the 4-cube boundary: 8 cubes, closed, valid") {
  Complex c = makeFourCubeBoundary();
  c.validate();
  Counts k = c.counts();
  CHECK(k.vertices == 16);
  CHECK(k.edges == 32);
  CHECK(k.quads == 24);
  CHECK(k.hexes == 8);
  CHECK(k.boundaryQuads == 0);
  CHECK(extractDual(c).sheets.size() == 4);  // one per axis of [0,1]^4
}

TEST_CASE("enumerating splits of the 4-cube finds exactly six flip classes plus inverses") {
  auto all = enumerateFlipClasses();
  std::vector<std::string> names;
  for (const auto& f : all) names.push_back(f.name);
  CHECK(names == std::vector<std::string>{"1-7", "2-6", "3-5c", "3-5e", "4-4m", "4-4v", "5-3c", "5-3e", "6-2", "7-1"});
  auto counts = [](const Counts& c) { return std::array<int64_t, 4>{c.vertices, c.edges, c.quads, c.hexes}; };
  using A = std::array<int64_t, 4>;
  CHECK(counts(flipClass("1-7").interiorBefore) == A{0, 0, 0, 1});
  CHECK(counts(flipClass("1-7").interiorAfter) == A{8, 20, 18, 7});
  CHECK(counts(flipClass("2-6").interiorBefore) == A{0, 0, 1, 2});
  CHECK(counts(flipClass("2-6").interiorAfter) == A{4, 12, 13, 6});
  CHECK(counts(flipClass("3-5e").interiorBefore) == A{0, 1, 3, 3});
  CHECK(counts(flipClass("3-5e").interiorAfter) == A{2, 7, 9, 5});
  CHECK(counts(flipClass("3-5c").interiorBefore) == A{0, 0, 2, 3});
  CHECK(counts(flipClass("3-5c").interiorAfter) == A{0, 4, 8, 5});
  CHECK(counts(flipClass("4-4v").interiorBefore) == A{1, 4, 6, 4});
  CHECK(counts(flipClass("4-4v").interiorAfter) == A{1, 4, 6, 4});
  CHECK(counts(flipClass("4-4m").interiorBefore) == A{0, 2, 5, 4});
  CHECK(counts(flipClass("4-4m").interiorAfter) == A{0, 2, 5, 4});
  CHECK(flipClass("4-4v").inverse == "4-4v");
  CHECK(flipClass("3-5c").inverse == "5-3c");
  CHECK(contains(errorOf([] { flipClass("9-9"); }), "flip: unknown flip '9-9' (known: 1-7, 2-6, 3-5c"));
}

TEST_CASE("every flip and its inverse inside the 4-cube boundary: counts, validity, identity up to isomorphism") {
  for (const FlipClass& fc : enumerateFlipClasses()) {
    CAPTURE(fc.name);
    Complex c = makeFourCubeBoundary();
    Complex orig = c;
    OpResult r = flip(c, fc.name, facetsOf(fc.before));
    c.validate();
    Counts d = meshDelta(orig, c), want = interiorDelta(fc);
    CHECK(d.vertices == want.vertices);
    CHECK(d.edges == want.edges);
    CHECK(d.quads == want.quads);
    CHECK(d.hexes == want.hexes);
    OpResult back = flip(c, fc.inverse, r.createdHexes);
    c.validate();
    CHECK(isomorphic(c, orig, false));
  }
}

TEST_CASE("flips inside grids: 1-7, 2-6 and 3-5 column; rejected when the hexes do not match") {
  Complex g = makeGrid(3, 3, 3);
  Complex a = g;
  flip(a, "1-7", {13});
  a.validate();
  CHECK(meshDelta(g, a).hexes == 6);
  Complex b = g;
  flip(b, "2-6", {13, 22});
  b.validate();
  CHECK(meshDelta(g, b).edges == 12);
  Complex c = g;
  OpResult col = flip(c, "3-5c", {4, 13, 22});
  c.validate();
  Counts d = meshDelta(g, c);
  CHECK(d.vertices == 0);
  CHECK(d.edges == 4);
  CHECK(d.quads == 6);
  CHECK(d.hexes == 2);
  flip(c, "5-3c", col.createdHexes);
  CHECK(isomorphic(c, g));
  std::string before = stateDump(g);
  CHECK(errorOf([&] { flip(g, "2-6", {0, 13}); }) == "flip 2-6: the hexes do not form the 2-6 flip's before side");
  CHECK(errorOf([&] { flip(g, "3-5e", {0, 1, 3}); }) == "flip 3-5e: the hexes do not form the 3-5e flip's before side");
  CHECK(errorOf([&] { flip(g, "1-7", {0, 1}); }) == "flip 1-7: the 1-7 flip replaces 1 hexes, not 2");
  CHECK(stateDump(g) == before);
}

TEST_CASE("traditional pillow (pillow + hex push, TK03 Fig. 8) is the 1-7 flip; so is pillowRegion of one hex") {
  Complex g = makeGrid(3, 3, 3);
  Complex viaFlip = g, viaOps = g, viaRegion = g;
  flip(viaFlip, "1-7", {13});
  auto steps = traditionalPillow(viaOps, 13, 5);
  CHECK(steps.size() == 2);
  viaOps.validate();
  CHECK(isomorphic(viaOps, viaFlip));
  OpResult pr = pillowRegion(viaRegion, {13});
  viaRegion.validate();
  CHECK(isomorphic(viaRegion, viaFlip));
  CHECK(pr.dV == 8);
  CHECK(pr.dE == 20);
  CHECK(pr.dF == 18);
  CHECK(pr.dH == 6);
  // In the closed 4-cube boundary too (the paper's claim, all 16 original vertices fixed).
  Complex c1 = makeFourCubeBoundary(), c2 = makeFourCubeBoundary();
  flip(c1, "1-7", {0});
  traditionalPillow(c2, 0, 1);
  CHECK(isomorphic(c1, c2, false));
}

TEST_CASE("pillowRegion of two hexes: delta (+V, +V+E, +F+E, +F) of the outer surface") {
  Complex g = makeGrid(4, 3, 3);
  Complex before = g;
  OpResult r = pillowRegion(g, {17, 18});  // (1,1,1) and (2,1,1): an interior 2x1x1 block
  g.validate();
  // Outer surface of a 2x1x1 block: V=12, E=20, F=10.
  CHECK(r.dV == 12);
  CHECK(r.dE == 32);
  CHECK(r.dF == 30);
  CHECK(r.dH == 10);
  CHECK(meshDelta(before, g).edges == 32);
  CHECK(errorOf([&] { pillowRegion(g, {0}); }) == "pillowRegion: quad h0f0 of the set is on the mesh boundary");
}

TEST_CASE("triple-chord push at a hex corner: (+2,+6,+6,+2), valid, no new sheet or chord") {
  Complex g = makeGrid(3, 3, 3);
  Dual d0 = extractDual(g);
  Counts c0 = g.counts();
  OpResult r = tripleChordPush(g, 13, 0, {13, 0}, {13, 2}, {13, 4});
  g.validate();
  Counts c1 = g.counts();
  CHECK(c1.vertices - c0.vertices == 2);
  CHECK(c1.edges - c0.edges == 6);
  CHECK(c1.quads - c0.quads == 6);
  CHECK(c1.hexes - c0.hexes == 2);
  Dual d1 = extractDual(g);
  CHECK(d1.sheets.size() == d0.sheets.size());
  CHECK(d1.chords.size() == d0.chords.size());
  g.undo(r.edits);
  CHECK(errorOf([&] { tripleChordPush(g, 0, 0, {0, 0}, {0, 2}, {0, 4}); }) == "tripleChordPush: quad h0f0 is on the boundary");
}

#include "flips/decompositions.hpp"
#include "flips/search.hpp"
#include "ops/op_table.hpp"
#include "ops/oplog.hpp"

TEST_CASE("every stored decomposition is verified at three or more places") {
  int found = 0;
  for (const StoredDecomposition& d : storedDecompositions()) {
    CAPTURE(d.problem);
    if (!d.found) continue;
    ++found;
    SearchProblem pb = problemFor(d.problem);
    verifyDecomposition(pb, d.steps);
    int places = 1;
    for (const Embedding& e : flipEmbeddings(d.problem)) {
      CAPTURE(e.name);
      verifyInEmbedding(pb, d.steps, e);
      ++places;
    }
    CHECK(places >= 3);
  }
  CHECK(found == 11);  // the ten flips (six classes and inverses; 4-4v, 4-4m their own) and the triple-chord push
}

TEST_CASE("the triple-chord push is 8 atomic steps: two hex pushes, collapses and splits, a chord pull") {
  // TK03 §4.5.1 left its decomposition open; verified here in the 3x3x3 grid and in four more places.
  const StoredDecomposition* d = storedFor("tripleChordPush");
  REQUIRE(d != nullptr);
  REQUIRE(d->found);
  REQUIRE(d->steps.size() == 8);
  std::vector<std::string> kinds;
  for (const OpStep& st : d->steps) kinds.push_back(opName(st.op));
  CHECK(kinds == std::vector<std::string>{"hexpush", "hexpush", "facecollapse", "ringcollapse", "facesplit", "facecollapse",
                                          "facesplit", "chordpull"});
  SearchProblem pb = problemFor("tripleChordPush");
  Complex cx = pb.start;
  std::vector<int64_t> hexes{cx.numHexes()};
  for (const OpStep& st : d->steps) {
    applyStep(cx, st);
    cx.validate();
    hexes.push_back(cx.numHexes());
  }
  CHECK(hexes == std::vector<int64_t>{27, 31, 35, 35, 31, 31, 31, 31, 29});
  verifyDecomposition(pb, d->steps);
  std::vector<std::string> places;
  for (const Embedding& e : flipEmbeddings("tripleChordPush")) {
    CAPTURE(e.name);
    verifyInEmbedding(pb, d->steps, e);
    places.push_back(e.name);
  }
  CHECK(places == std::vector<std::string>{"3x3x3 grid, host pillowed at h26f0", "4x4x4 grid at vertex (2,2,2)",
                                           "5x5x5 grid at vertex (2,3,2)", "8x3x3 O-grid at h6"});
  // A sequence that does something else is refused: without its last step (the chord pull) the
  // result has two more hexes than any triple-chord push.
  std::vector<OpStep> shorter(d->steps.begin(), d->steps.end() - 1);
  CHECK_THROWS_WITH(verifyInEmbedding(pb, shorter, flipEmbeddings("tripleChordPush")[1]),
                    "verify tripleChordPush in 4x4x4 grid at vertex (2,2,2): the result is not isomorphic to the operation applied directly");
}

TEST_CASE("the 4-4 vertex flip (triple-hex push) is 8 atomic steps: hex pushes and pulls, ring splits and collapses") {
  // TK03 §4.5.2 left it open ("most likely involving hex push and some form of ring collapse").
  const StoredDecomposition* d = storedFor("4-4v");
  REQUIRE(d != nullptr);
  REQUIRE(d->found);
  REQUIRE(d->steps.size() == 8);
  std::vector<std::string> kinds;
  for (const OpStep& st : d->steps) kinds.push_back(opName(st.op));
  CHECK(kinds == std::vector<std::string>{"hexpush", "ringsplit", "ringsplit", "ringsplit", "ringcollapse", "hexpull",
                                          "ringcollapse", "hexpull"});
  // Hex counts along the way (host: 4 facets; the region peaks at 22 hexes), and every step
  // reports an inverse step that gives back the complex before it.
  SearchProblem pb = problemFor("4-4v");
  Complex cx = pb.start;
  std::vector<int64_t> hexes{cx.numHexes()};
  for (const OpStep& st : d->steps) {
    CAPTURE(formatOpStep(st));
    Complex before = cx;
    OpResult r = applyStep(cx, st);
    cx.validate();
    hexes.push_back(cx.numHexes());
    REQUIRE(r.inverse);
    Complex back = cx;
    applyStep(back, *r.inverse);
    CHECK(isomorphic(back, before, true));
  }
  CHECK(hexes == std::vector<int64_t>{8, 12, 16, 20, 26, 20, 16, 12, 8});
  verifyDecomposition(pb, d->steps);  // local steps, and the goal with the region boundary fixed
}

TEST_CASE("search finds the paper's decompositions: 2-6 is one hex push, 1-7 is pillow + hex push") {
  SearchOptions o;
  o.maxDepth = 3;
  SearchResult r26 = searchDecomposition(flipProblem("2-6"), o);
  CHECK(r26.found);
  CHECK(formatOpLog({1, r26.steps}) == "v1;hexpush h0f0");
  SearchResult r17 = searchDecomposition(flipProblem("1-7"), o);
  CHECK(r17.found);
  REQUIRE(r17.steps.size() == 2);
  CHECK(r17.steps[0].op == OpKind::Pillow);
  CHECK(r17.steps[1].op == OpKind::HexPush);
  // A search that cannot succeed stops at its depth and says so.
  o.maxDepth = 2;
  o.ops = {OpKind::ChordPush, OpKind::ChordPull};
  SearchResult none = searchDecomposition(flipProblem("2-6"), o);
  CHECK_FALSE(none.found);
  CHECK(none.depthSearched == 2);
  CHECK(none.stoppedBy == "depth");
  CHECK(none.statesExplored > 0);
}

TEST_CASE("a wrong decomposition is caught by verification") {
  SearchProblem pb = flipProblem("1-7");
  CHECK(contains(errorOf([&] { verifyDecomposition(pb, {parseOpStep("pillow h0f1")}); }),
                 "verify 1-7: the result is not isomorphic to the flip's after side"));
  CHECK(contains(errorOf([&] { verifyDecomposition(pb, {parseOpStep("hexpush h0f1")}); }), "verify 1-7: step 1 is not local: host hex"));
}

TEST_CASE("the (2,1)-(1,2) flip by the paper's recipe: two hex pushes, a ring collapse; 5 region sheets become 4") {
  Complex g = makeGrid(5, 5, 5);
  Complex c = g;
  // The column of hexes 37, 62, 87 (x=2, y=2, z=1..3).
  ApplyReport r = applyLog(c, "v1;hexpush h62f5;hexpush h37f5;ringcollapse h127e4");
  REQUIRE(r.failedStep == 0);
  c.validate();
  std::vector<HexId> before, after;
  for (HexId h = 0; h < g.hexCapacity(); ++h)
    if (!c.isHex(h)) before.push_back(h);
  for (HexId h = g.hexCapacity(); h < c.hexCapacity(); ++h)
    if (c.isHex(h)) after.push_back(h);
  CHECK(before == std::vector<HexId>{37, 62, 87});
  CHECK(after.size() == 7);
  CHECK(extractDual(subcomplex(g, before)).sheets.size() == 5);
  CHECK(extractDual(subcomplex(c, after)).sheets.size() == 4);
  CHECK(c.counts().boundaryQuads == g.counts().boundaryQuads);
}

TEST_CASE("flips change sheets and chords as their duals say") {
  // In the 4-cube boundary (4 sheets, 12 chords): the sheet and chord counts after each flip.
  for (const FlipClass& fc : enumerateFlipClasses()) {
    CAPTURE(fc.name);
    Complex c = makeFourCubeBoundary();
    Dual d0 = extractDual(c);
    CHECK(d0.sheets.size() == 4);
    CHECK(d0.chords.size() == 6);
    OpResult r = flip(c, fc.name, facetsOf(fc.before));
    Dual d1 = extractDual(c);
    if (fc.name == "1-7") {
      CHECK(d1.sheets.size() == 5);  // the pillow sheet
      CHECK(d1.chords.size() == 9);  // and three new closed chords
    }
    if (fc.name == "2-6") {
      CHECK(d1.sheets.size() == 4);
      CHECK(d1.chords.size() == 7);  // one new closed chord of 4
    }
    flip(c, fc.inverse, r.createdHexes);
    Dual d2 = extractDual(c);
    CHECK(d2.sheets.size() == 4);
    CHECK(d2.chords.size() == 6);
  }
}
