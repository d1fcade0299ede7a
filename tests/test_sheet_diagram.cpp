#include <doctest/doctest.h>

#include <cstdio>
#include <map>
#include <random>

#include "complex/builders.hpp"
#include "complex/hex_tables.hpp"
#include "flips/flip.hpp"
#include "flips/fourcube.hpp"
#include "helpers.hpp"
#include "layout/diagram_spread.hpp"
#include "layout/sheet_diagram.hpp"
#include "ops/oplog.hpp"

using namespace hexdual;
using namespace hexdual::test;

namespace {
// Lays out and checks every sheet; returns how many used each method.
std::map<std::string, int> checkAllSheets(const Complex& cx) {
  Dual d = extractDual(cx);
  std::map<std::string, int> methods;
  for (const Sheet& s : d.sheets) {
    CAPTURE(s.id);
    CAPTURE(s.topology);
    SheetDiagram dg = layoutSheet(cx, d, s.id);
    ++methods[dg.method];
    checkDiagram(dg, dg.local ? dg.crossings.size() : s.slots.size());
    CHECK(diagramJson(dg).find("\"crossings\":[") != std::string::npos);
    CHECK(diagramSvg(dg).rfind("<svg", 0) == 0);
  }
  return methods;
}
}  // namespace

TEST_CASE("sheet diagrams of grids: disks, every slot once, chords meet only at crossings") {
  for (auto dims : {std::array<int, 3>{2, 2, 2}, {3, 3, 3}, {4, 3, 2}, {1, 1, 1}}) {
    auto m = checkAllSheets(makeGrid(dims[0], dims[1], dims[2]));
    CHECK(m["disk"] == dims[0] + dims[1] + dims[2]);
  }
  // The x=0 layer of a 3x3x3 grid: 9 crossings, 6 chords (3 each way), 12 boundary points.
  Complex g = makeGrid(3, 3, 3);
  Dual d = extractDual(g);
  SheetDiagram dg = layoutSheet(g, d, d.sheetAt(0, 0));
  CHECK(dg.crossings.size() == 9);
  CHECK(dg.chords.size() == 6);
  CHECK(dg.boundary.size() == 12);
  CHECK(dg.loops.size() == 1);
  for (const auto& c : dg.chords) CHECK_FALSE(c.closed);
}

// The extent of a diagram's outer loop: (width, height).
static std::pair<double, double> loopBox(const SheetDiagram& dg) {
  double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
  for (Point2 p : dg.loops.at(0)) x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  return {x1 - x0, y1 - y0};
}

TEST_CASE("a disk is drawn in the shape its quads give: a 20 x 3 layer as a long rectangle, not squeezed onto a circle") {
  Complex g = makeGrid(20, 3, 2);
  Dual d = extractDual(g);
  SheetDiagram dg = layoutSheet(g, d, d.sheetAt(0, 2));  // a z-layer: 20 x 3 hexes
  REQUIRE(dg.crossings.size() == 60);
  CHECK(dg.method == "disk");
  auto [w, h] = loopBox(dg);
  const double aspect = std::max(w, h) / std::min(w, h);
  CAPTURE(aspect);
  CHECK(aspect > 5.5);  // 20 : 3 (the loop's corners are the boundary quads' sides: 6.7 for a rectangle)
  CHECK(aspect < 7.5);
  for (Point2 p : dg.loops[0]) CHECK(std::hypot(p.x, p.y) <= 1 + 1e-9);  // inside the unit circle (radius)
  // Evenly spread like a grid: on the circle the same sheet crowds its ends.
  CHECK(diagramSpread(dg) > 0.3);
  // A square layer is a square: its four corners, where one quad meets the boundary, are corners.
  Complex c = makeGrid(6, 6, 2);
  Dual dc = extractDual(c);
  SheetDiagram sq = layoutSheet(c, dc, dc.sheetAt(0, 2));
  auto [sw, sh] = loopBox(sq);
  CHECK(sw == doctest::Approx(sh).epsilon(0.05));
  CHECK(sw == doctest::Approx(std::sqrt(2.0)).epsilon(0.05));  // the square inscribed in the unit circle

  // The CLI's SVG frames the rectangle by its box and labels every crossing: crossings spread over
  // its own area (not the circle's) are far enough apart for their ids.
  const std::string svg = diagramSvg(dg);
  double width = 0, height = 0;
  REQUIRE(std::sscanf(svg.c_str(), "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%lf\" height=\"%lf\"", &width, &height) == 2);
  CAPTURE(width);
  CAPTURE(height);
  CHECK(width > 3 * height);
  size_t labels = 0;
  for (size_t at = svg.find("<text x="); at != std::string::npos; at = svg.find("<text x=", at + 1)) ++labels;
  CHECK(labels == 60 + 1);  // every crossing, and the title
  // The right-most column's labels go under-left of their crossings, off the boundary marks.
  CHECK(contains(svg, " text-anchor=\"end\">0</text>"));
  CHECK_FALSE(contains(svg, " text-anchor=\"end\">19</text>"));  // the left-most column keeps up-right
}

TEST_CASE("an L-shaped layer is drawn convex, and its note says which corner was straightened") {
  // Three hexes in an L, one thick: the layer's boundary has a reflex corner where three quads meet it.
  std::vector<Vec3> p;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) p.push_back({double(i), double(j), double(k)});
  auto v = [](int i, int j, int k) { return VertexId(9 * k + 3 * j + i); };
  std::vector<std::array<VertexId, 8>> hexes;
  for (auto [i, j] : {std::pair{0, 0}, {1, 0}, {0, 1}}) {
    std::array<VertexId, 8> h;
    for (int c = 0; c < 8; ++c) h[size_t(c)] = v(i + tables::cornerBit(c, 0), j + tables::cornerBit(c, 1), tables::cornerBit(c, 2));
    hexes.push_back(h);
  }
  Complex l = fromConnectivity(p, hexes);
  Dual d = extractDual(l);
  SheetDiagram dg = layoutSheet(l, d, d.sheetAt(0, 2));
  CHECK(dg.crossings.size() == 3);
  CHECK(dg.method == "disk");
  CHECK(dg.note == "drawn convex: 1 reflex corner of its boundary (three quads meeting it) drawn straight");
  checkDiagram(dg, 3);
  // The SVG prints the note under its title (a PNG or a printed figure keeps it), in lines that fit.
  const std::string svg = diagramSvg(dg);
  CHECK(contains(svg, "<text x=\"8\" y="));
  CHECK(contains(svg, " fill=\"#555\">drawn convex: 1 reflex corner"));
  CHECK(contains(svg, "drawn straight</text>"));
  // A grid's layer has none: no note.
  Complex g = makeGrid(3, 3, 1);
  Dual dg3 = extractDual(g);
  CHECK(layoutSheet(g, dg3, dg3.sheetAt(0, 2)).note.empty());
}

TEST_CASE("sheet diagrams of the ring mesh: annuli drawn between two circles, closed chords") {
  for (auto dims : {std::array<int, 3>{8, 2, 2}, {8, 3, 3}, {6, 1, 4}}) {
    Complex r = makeRing(dims[0], dims[1], dims[2]);
    auto m = checkAllSheets(r);
    CHECK(m["annulus"] == dims[1] + dims[2]);
    CHECK(m["disk"] == dims[0]);
  }
  Complex r = makeRing(8, 3, 3);
  Dual d = extractDual(r);
  SheetDiagram dg = layoutSheet(r, d, 0);
  CHECK(dg.loops.size() == 2);
  int closed = 0;
  for (const auto& c : dg.chords) closed += c.closed;
  CHECK(closed == 3);
}

TEST_CASE("sheet diagram of a pillow: a sphere opened at one face, drawn outside the circle") {
  Complex g = makeGrid(3, 3, 3);
  pillow(g, {13, 5});
  Dual d = extractDual(g);
  int sphere = -1;
  for (const Sheet& s : d.sheets)
    if (s.topology == "sphere") sphere = s.id;
  REQUIRE(sphere >= 0);
  SheetDiagram dg = layoutSheet(g, d, sphere);
  CHECK(dg.method == "sphere");
  CHECK(dg.openedHex == 27);
  CHECK(dg.crossings.size() == 2);
  CHECK(dg.chords.size() == 2);
  for (const auto& c : dg.chords) CHECK(c.closed);
  checkDiagram(dg, 2);
  CHECK(contains(dg.note, "the face of hex 27"));
  checkAllSheets(g);
}

TEST_CASE("sheet diagrams after chord push, hex push, the 1-7 flip, and in every flip configuration") {
  Complex a = makeGrid(3, 3, 3);
  chordPush(a, {13, 11}, {13, 1}, {16, 1});
  checkAllSheets(a);
  Complex b = makeGrid(3, 3, 3);
  hexPush(b, {13, 5});
  checkAllSheets(b);
  Complex c = makeGrid(3, 3, 3);
  flip(c, "1-7", {13});
  checkAllSheets(c);
  for (const FlipClass& fc : enumerateFlipClasses()) {
    CAPTURE(fc.name);
    Complex f = makeFourCubeBoundary();
    checkAllSheets(f);
    flip(f, fc.name, facetsOf(fc.before));
    checkAllSheets(f);
  }
}

// A face collapse joins two 4x4 layer disks crosswise at one quad each: an annulus with a neck of
// 4 sides between two 16-sided loops. Drawn between two circles, the inner disk has to fit inside
// the neck and came out squeezed round a dot (crossings 0.063 of an even spread apart); cut open
// along one seam it spreads about 4.6x better, so that drawing is chosen (TK03 §4.4, the
// tutorial's face collapse).
TEST_CASE("a face collapse's merged annulus is drawn cut open: its crossings spread, not crowded round the hole") {
  Complex g = makeGrid(4, 4, 4);
  applyStep(g, "facecollapse h21e11 h21f1 h26f0");
  Dual d = extractDual(g);
  int merged = -1;
  for (const Sheet& s : d.sheets)
    if (s.topology == "annulus") merged = s.id;
  REQUIRE(merged >= 0);
  CHECK(d.sheets[size_t(merged)].slots.size() == 32);
  SheetDiagram dg = layoutSheet(g, d, merged);
  CHECK(dg.method == "polygon");
  CHECK(dg.crossings.size() == 32);
  CHECK(diagramSpread(dg) > 0.25);
  CHECK(contains(dg.note, "cut open along 1 seam"));
  checkAllSheets(g);
  // The annuli of a ring mesh stay drawn between two circles (spread well above the threshold).
  Complex r = makeRing(8, 3, 3);
  Dual rd = extractDual(r);
  SheetDiagram ring = layoutSheet(r, rd, 0);
  CHECK(ring.method == "annulus");
  CHECK(diagramSpread(ring) >= kReadableSpread);
}

TEST_CASE("local diagrams: k rings of chosen hexes inside a dotted circle") {
  Complex g = makeGrid(5, 5, 5);
  Dual d = extractDual(g);
  int sheet = d.sheetAt(62, 2);
  SheetDiagram one = layoutLocal(g, d, sheet, {62}, 1);
  CHECK(one.local);
  CHECK(one.method == "local");
  CHECK(one.crossings.size() == 9);  // 3x3 around hex 62 in its z-layer
  checkDiagram(one, 9);
  SheetDiagram two = layoutLocal(g, d, sheet, {62}, 2);
  CHECK(two.crossings.size() == 25);
  checkDiagram(two, 25);
  CHECK(contains(diagramSvg(two), "stroke-dasharray"));
  CHECK(errorOf([&] { layoutLocal(g, d, sheet, {0}, 1); }) ==
        "sheet diagram: none of the given hexes lies on sheet " + std::to_string(sheet));
  CHECK(errorOf([&] { layoutSheet(g, d, 999); }) == "sheet diagram: sheet 999 does not exist");
}

TEST_CASE("sheet diagrams after random operation sequences (fixed seeds)") {
  const uint32_t firstSeed = 77;
  int diagrams = 0;
  for (uint32_t seed = firstSeed; seed < firstSeed + 40; ++seed) {
    CAPTURE(seed);
    std::mt19937 rng(seed);
    Complex cx = seed % 2 ? makeGrid(4, 4, 4) : makeRing(8, 3, 3);
    for (int step = 0; step < 6; ++step) {
      HexId h = HexId(rng() % uint32_t(cx.hexCapacity()));
      if (!cx.isHex(h)) continue;
      const char* ops[] = {"pillow", "hexpush"};
      try {
        applyStep(cx, std::string(ops[rng() % 2]) + " h" + std::to_string(h) + "f" + std::to_string(rng() % 6));
      } catch (const Error&) {
      }
    }
    auto m = checkAllSheets(cx);
    for (auto& [k, n] : m) diagrams += n;
  }
  MESSAGE("sheet diagrams after random sequences: seeds " << firstSeed << ".." << firstSeed + 39 << ", " << diagrams
                                                          << " diagrams checked");
  CHECK(diagrams > 400);
}

TEST_CASE("a self-intersecting sheet (a quarter-twisted ring): a hex on it twice appears as two crossings") {
  Complex t = makeTwistedRing(8);
  t.validate();
  Dual d = extractDual(t);
  REQUIRE(d.sheets[0].selfIntersecting);
  CHECK(d.sheets[0].slots.size() == 16);   // 8 hexes, each twice
  CHECK(d.sheets[0].topology == "other");  // a Moebius band: Euler characteristic 0, one boundary loop
  CHECK_FALSE(d.sheets[0].orientable);
  SheetDiagram dg = layoutSheet(t, d, 0);
  MESSAGE(dg.note << " euler " << dg.euler << " arcs " << dg.arcs.size() << " sheet euler " << d.sheets[0].euler
                  << " loops " << d.sheets[0].boundaryLoops);
  CHECK(dg.method == "polygon");
  checkDiagram(dg, 16);
  std::map<HexId, int> times;
  for (const auto& c : dg.crossings) ++times[c.hex];
  for (auto [h, n] : times) CHECK(n == 2);
  checkAllSheets(t);
}
