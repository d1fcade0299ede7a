#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <map>

#include "complex/builders.hpp"
#include "helpers.hpp"
#include "io/io.hpp"
#include "layout/mid_surface.hpp"
#include "layout/polygon_diagram.hpp"
#include "layout/sheet_diagram.hpp"

using namespace hexdual;
using namespace hexdual::test;

namespace {
struct PolygonCounts {
  int pairs = 0, twisted = 0, boundarySides = 0;
};
PolygonCounts countSides(const SheetDiagram& dg) {
  PolygonCounts c;
  std::map<int, int> signs;
  for (const auto& a : dg.arcs) {
    if (a.pair < 0)
      ++c.boundarySides;
    else
      signs[a.pair] += a.sign;
  }
  c.pairs = int(signs.size());
  for (auto [p, s] : signs) c.twisted += s == 2;  // both sides +1: glued with a twist
  return c;
}
std::string word(const SheetDiagram& dg) {
  std::string w;
  for (const auto& a : dg.arcs) w += (w.empty() ? "" : " ") + a.label;
  return w;
}
// Lays out every sheet, checks it, and returns the diagrams of the sheets drawn as polygons.
std::vector<SheetDiagram> polygonSheets(const Complex& cx, const Dual& d) {
  std::vector<SheetDiagram> out;
  for (const Sheet& s : d.sheets) {
    CAPTURE(s.id);
    SheetDiagram dg = layoutSheet(cx, d, s.id);
    CHECK_FALSE(dg.local);
    checkDiagram(dg, s.slots.size());
    CHECK(dg.euler == s.euler);
    if (dg.method == "polygon") out.push_back(dg);
  }
  return out;
}
}  // namespace

TEST_CASE("torus shell builder: a thickened torus, and its Klein-bottle twin") {
  Complex t = makeTorusShell(6, 4, 2);
  t.validate();
  CHECK(t.counts().hexes == 48);
  CHECK(t.counts().vertices == 72);
  CHECK(t.counts().boundaryQuads == 48);
  Dual d = extractDual(t);
  CHECK(d.sheets.size() == 12);
  CHECK(countTopology(d, "torus") == 2);
  CHECK(countTopology(d, "annulus") == 10);
  Complex k = makeTorusShell(6, 4, 2, true);
  k.validate();
  Dual dk = extractDual(k);
  CHECK(dk.sheets.size() == 10);  // the tube's layers pair up under the reflection
  int klein = 0;
  for (const Sheet& s : dk.sheets) klein += !s.orientable && s.euler == 0 && s.boundaryLoops == 0;
  CHECK(klein == 2);
  CHECK(errorOf([] { makeTorusShell(2, 4, 1); }) ==
        "torus shell: needs at least 3 around and 3 along the tube, 1 layer, at most 10^7 hexes");
}

TEST_CASE("a torus sheet is cut open into the square a b a^-1 b^-1") {
  Complex t = makeTorusShell(6, 4, 2);
  Dual d = extractDual(t);
  auto polys = polygonSheets(t, d);
  REQUIRE(polys.size() == 2);
  for (const SheetDiagram& dg : polys) {
    CHECK(dg.topology == "torus");
    CHECK(word(dg) == "a b a\u207b\u00b9 b\u207b\u00b9");
    PolygonCounts c = countSides(dg);
    CHECK(dg.arcs.size() == 4);
    CHECK(c.pairs == 2);
    CHECK(c.twisted == 0);
    CHECK(c.boundarySides == 0);
    CHECK(dg.euler == 0);
    CHECK(dg.crossings.size() == 24);
    // 6 chords along the tube, 4 around, all closed, each drawn in one or more pieces.
    std::map<int, int> pieces;
    for (const auto& ch : dg.chords) {
      CHECK(ch.closed);
      ++pieces[ch.chord];
    }
    CHECK(pieces.size() == 10);
    CHECK(contains(dg.note, "cut open along 2 seams: dashed sides with the same letter are the same seam (sides in order: a b a"));
    CHECK(contains(diagramJson(dg), "\"arcs\":[{\"label\":\"a\",\"pair\":0,\"sign\":1,\"points\":[["));
    CHECK(contains(diagramSvg(dg), ">b\u207b\u00b9</text>"));
  }
}

TEST_CASE("a Klein-bottle sheet: three seams, two glued with a twist") {
  Complex k = makeTorusShell(6, 4, 2, true);
  Dual d = extractDual(k);
  auto polys = polygonSheets(k, d);
  REQUIRE(polys.size() == 2);
  for (const SheetDiagram& dg : polys) {
    CHECK(word(dg) == "a b a c b\u207b\u00b9 c");
    PolygonCounts c = countSides(dg);
    CHECK(dg.arcs.size() == 6);
    CHECK(c.pairs == 3);
    CHECK(c.twisted == 2);
    CHECK(dg.euler == 0);  // 1 + 2 branch corners - 3 seams
  }
}

TEST_CASE("a Moebius-band sheet (the quarter-twisted ring): one twisted seam between two boundary sides") {
  Complex t = makeTwistedRing(8);
  Dual d = extractDual(t);
  auto polys = polygonSheets(t, d);
  REQUIRE(polys.size() == 1);
  const SheetDiagram& dg = polys[0];
  CHECK(word(dg) == "a \u2202 a \u2202");
  PolygonCounts c = countSides(dg);
  CHECK(c.pairs == 1);
  CHECK(c.twisted == 1);
  CHECK(c.boundarySides == 2);
  CHECK(dg.euler == 0);
}

TEST_CASE("an annulus cut open: one seam drawn twice in opposite directions") {
  Complex r = makeRing(8, 2, 2);
  Dual d = extractDual(r);
  SheetDiagram dg = layoutPolygon(d, 0, buildMidSurface(r, {d.sheets[0].slots.begin(), d.sheets[0].slots.end()}));
  checkDiagram(dg, d.sheets[0].slots.size());
  PolygonCounts c = countSides(dg);
  CHECK(dg.arcs.size() == 4);
  CHECK(c.pairs == 1);
  CHECK(c.twisted == 0);
  CHECK(c.boundarySides == 2);
  CHECK(dg.euler == 0);
}

TEST_CASE("the example meshes of docs/examples are the builders' output") {
  const std::filesystem::path dir = std::filesystem::path(__FILE__).parent_path().parent_path() / "docs" / "examples";
  auto file = [&](const char* name) {
    std::ifstream in(dir / name, std::ios::binary);
    REQUIRE(in);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  CHECK(file("torus-shell.hxd") == io::writeNative(makeTorusShell(6, 4, 2)));
  CHECK(file("klein-shell.hxd") == io::writeNative(makeTorusShell(6, 4, 2, true)));
  CHECK(file("twisted-ring.hxd") == io::writeNative(makeTwistedRing(8)));
}
