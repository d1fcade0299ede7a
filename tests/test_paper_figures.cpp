// The paper's sheet-diagram figures (TK03 Fig. 1, 2-3, 4-5, 6-7, 8, and the flips of the 4-cube),
// each drawn whole and checked for what the figure shows: the chords and crossings it draws, and
// that the features it is about (a blind chord, two chords crossing twice, a pillow's pair) are
// drawn apart. The SVGs are written to figures/ under the working directory (ctest: the build
// folder) to be looked at.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

#include "complex/builders.hpp"
#include "flips/flip.hpp"
#include "flips/fourcube.hpp"
#include "helpers.hpp"
#include "layout/diagram_spread.hpp"
#include "layout/sheet_diagram.hpp"
#include "ops/oplog.hpp"

using namespace hexdual;

namespace {

void save(const SheetDiagram& d, const std::string& name) {
  std::filesystem::create_directories("figures");
  std::ofstream("figures/" + name + ".svg") << diagramSvg(d);
}

Point2 crossingOf(const SheetDiagram& d, HexId h) {
  for (const auto& c : d.crossings)
    if (c.hex == h) return c.p;
  FAIL("hex " << h << " is not a crossing of sheet " << d.sheet);
  return {};
}

// Distance between two crossings in units of an even spread of the diagram's crossings.
double apart(const SheetDiagram& d, HexId a, HexId b) {
  Point2 p = crossingOf(d, a), q = crossingOf(d, b);
  return std::hypot(p.x - q.x, p.y - q.y) / std::sqrt(std::acos(-1.0) / double(d.crossings.size()));
}

// The chords of the diagram passing crossing h (ids, one per pass).
std::multiset<int> chordsAt(const SheetDiagram& d, HexId h) {
  std::multiset<int> out;
  for (const auto& c : d.chords)
    for (HexId x : c.hexes)
      if (x == h) out.insert(c.chord);
  return out;
}

// Every sheet through hex h, drawn whole and checked.
std::vector<SheetDiagram> sheetsThrough(const Complex& cx, HexId h, const std::string& name) {
  Dual dual = extractDual(cx);
  std::vector<SheetDiagram> out;
  for (int a = 0; a < 3; ++a) {
    SheetDiagram d = layoutSheet(cx, dual, dual.sheetAt(h, a));
    REQUIRE(d.method != "local");
    checkDiagram(d, dual.sheets[size_t(d.sheet)].slots.size());
    save(d, name + "-sheet" + std::to_string(d.sheet));
    out.push_back(std::move(d));
  }
  return out;
}

}  // namespace

TEST_CASE("paper Fig. 1: a sheet of a 3x3x3 grid is a disk of 9 crossings of 3 + 3 chords") {
  Complex cx = makeGrid(3, 3, 3);
  SheetDiagram d = layoutSheet(cx, extractDual(cx), 0);
  save(d, "fig1-grid-sheet");
  CHECK(d.method == "disk");
  CHECK(d.crossings.size() == 9);
  CHECK(d.chords.size() == 6);
  CHECK(d.boundary.size() == 12);
  CHECK(diagramSpread(d) > 0.5);
}

TEST_CASE("paper Fig. 2-3: chord push h13e3 h13f3 h16f5 on 3x3x3: a blind chord on each pushed sheet, two chords crossing twice on e's sheet") {
  Complex cx = makeGrid(3, 3, 3);
  OpResult r = applyStep(cx, "chordpush h13e3 h13f3 h16f5");
  REQUIRE(r.createdHexes == std::vector<HexId>{27, 28});
  int blind = 0, twice = 0;
  for (const SheetDiagram& d : sheetsThrough(cx, 27, "fig2-chordpush")) {
    CAPTURE(d.sheet);
    CHECK(d.method == "disk");
    CHECK(apart(d, 27, 28) > 0.25);  // X and Y drawn apart
    // A closed chord through exactly X and Y (the blind chord), or two chords both passing X and Y.
    for (const auto& c : d.chords)
      if (c.closed && c.hexes.size() == 2) ++blind;
    std::multiset<int> x = chordsAt(d, 27), y = chordsAt(d, 28);
    if (x == y && x.size() == 2 && *x.begin() != *x.rbegin()) ++twice;
    CHECK(diagramSpread(d) > 0.1);
  }
  CHECK(blind == 2);  // on sheets 2 and 3 of the figure
  CHECK(twice >= 1);  // the chords 12 and 34 of the figure, on e's sheet
}

TEST_CASE("paper Fig. 4-5: hex push h13f5 on 3x3x3: a closed chord of 4 surrounds the swapped crossings") {
  Complex cx = makeGrid(3, 3, 3);
  OpResult r = applyStep(cx, "hexpush h13f5");
  REQUIRE(r.createdHexes.size() == 6);
  Dual dual = extractDual(cx);
  int rings = 0;
  for (HexId h : r.createdHexes)
    for (const SheetDiagram& d : sheetsThrough(cx, h, "fig4-hexpush")) {
      CHECK(d.method == "disk");
      for (const auto& c : d.chords) rings += c.closed && c.hexes.size() == 4;
      CHECK(diagramSpread(d) > 0.1);
    }
  CHECK(rings > 0);
}

TEST_CASE("paper Fig. 6-7: pillow h13f5 on 3x3x3: a sphere of X, Y crossed by two closed chords of 2; the chord through q gains X, Y") {
  Complex cx = makeGrid(3, 3, 3);
  applyStep(cx, "pillow h13f5");
  Dual dual = extractDual(cx);
  bool sphere = false, crossed = false;
  for (const SheetDiagram& d : sheetsThrough(cx, 27, "fig6-pillow")) {
    CAPTURE(d.sheet);
    if (d.topology == "sphere") {
      sphere = true;
      CHECK(d.method == "sphere");
      CHECK(d.crossings.size() == 2);
      int closedTwo = 0;
      for (const auto& c : d.chords) closedTwo += c.closed && c.hexes.size() == 2;
      CHECK(closedTwo == 2);
    } else {
      CHECK(apart(d, 27, 28) > 0.25);  // the pillow's pair drawn apart on the sheets it crosses
      for (const auto& c : d.chords)
        if (std::count(c.hexes.begin(), c.hexes.end(), 27) && std::count(c.hexes.begin(), c.hexes.end(), 28))
          crossed = true;
    }
  }
  CHECK(sphere);
  CHECK(crossed);
}

TEST_CASE("paper Fig. 8: the 1-7 flip (pillow + hex push): a sphere of 6 crossed by three closed chords") {
  Complex cx = makeGrid(3, 3, 3);
  applyLog(cx, parseOpLog("v1;pillow h13f5;hexpush h13f5"));
  Dual dual = extractDual(cx);
  int spheres = 0;
  for (const Sheet& s : dual.sheets) {
    if (!s.alive || s.topology != "sphere") continue;
    SheetDiagram d = layoutSheet(cx, dual, s.id);
    save(d, "fig8-flip17-sphere");
    CHECK(d.method == "sphere");
    CHECK(d.crossings.size() == 6);
    std::set<int> chords;
    for (const auto& c : d.chords) {
      CHECK(c.closed);
      chords.insert(c.chord);
    }
    CHECK(chords.size() == 3);
    CHECK(diagramSpread(d) > 0.2);
    ++spheres;
  }
  CHECK(spheres == 1);
}

TEST_CASE("paper flips: every sheet of both sides of every flip of the 4-cube drawn whole") {
  for (const FlipClass& fc : enumerateFlipClasses()) {
    CAPTURE(fc.name);
    Complex f = makeFourCubeBoundary();
    for (int side = 0; side < 2; ++side) {
      Dual dual = extractDual(f);
      for (const Sheet& s : dual.sheets) {
        if (!s.alive) continue;
        SheetDiagram d = layoutSheet(f, dual, s.id);
        CHECK(d.method != "local");
        CHECK(diagramSpread(d) > 0.05);
        save(d, "flip-" + fc.name + (side ? "-after" : "-before") + "-sheet" + std::to_string(s.id));
      }
      if (side == 0) flip(f, fc.name, facetsOf(fc.before));
    }
  }
}
