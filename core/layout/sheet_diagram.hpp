// Sheet diagrams (TK03 §1.1): one dual sheet drawn flat. Its mid-surface is a quad mesh (one quad
// per (hex, axis) slot of the sheet, one vertex per primal edge crossing it); the boundary loop
// goes on a circle, interior vertices by a harmonic (Tutte) solve; every hex appears as the
// crossing of two chords; chords are polylines through the quads' centres.
#pragma once
#include <string>
#include <vector>

#include "complex/complex.hpp"
#include "dual/dual.hpp"

namespace hexdual {

struct Point2 {
  double x = 0, y = 0;
};

struct SheetDiagram {
  int sheet = -1;
  std::string topology;  // of the whole sheet
  std::string method;    // "disk", "annulus", "sphere" (one face opened), "local"
  std::string note;      // why a fallback was used, which face was opened, ...
  HexId openedHex = -1;  // sphere: the slot whose face became the outside
  int openedAxis = -1;
  bool local = false;    // a neighbourhood of chosen hexes inside a dotted circle
  double radius = 1.0;   // the outer circle, centred at the origin

  struct Crossing {
    HexId hex;
    int axis;          // the slot (hex, axis) of the sheet
    Point2 p;
    int chords[2];     // the chords crossing here
    bool outside = false;  // the opened face of a sphere, drawn outside the circle
  };
  struct BoundaryPoint {  // where a chord meets the boundary loop: a boundary quad
    HexId hex;
    int face;
    Point2 p;
  };
  struct ChordLine {
    int chord;
    int otherSheet;  // the chord is this sheet's intersection with otherSheet
    bool closed;
    std::vector<Point2> points;
    std::vector<HexId> hexes;  // crossings passed, in order
  };
  struct Cell {  // a mid-surface vertex = a primal edge crossing the sheet
    EdgeRef edge;
    Point2 p;
  };
  std::vector<Crossing> crossings;
  std::vector<BoundaryPoint> boundary;
  std::vector<std::vector<Point2>> loops;  // boundary loops (outer first), or the local circle
  std::vector<ChordLine> chords;
  std::vector<Cell> cells;
  std::vector<std::array<int, 4>> quads;  // mid-quads (indices into cells), one per crossing
};

// The whole sheet. Disks, annuli and spheres are laid out directly; any other sheet falls back to
// the largest disk-shaped neighbourhood of its first hex (method "local", with a note).
SheetDiagram layoutSheet(const Complex& cx, const Dual& dual, int sheet);
// The part of a sheet within `rings` rings of the given hexes, inside a dotted circle.
SheetDiagram layoutLocal(const Complex& cx, const Dual& dual, int sheet, const std::vector<HexId>& hexes, int rings);

std::string diagramJson(const SheetDiagram& d);
std::string diagramSvg(const SheetDiagram& d);

// The correctness checks of issue 5; throws Error naming the first violation.
void checkDiagram(const SheetDiagram& d, size_t expectedSlots);

}  // namespace hexdual
