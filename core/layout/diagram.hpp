// The result of a sheet layout (TK03 §1.1): plain arrays of points, polylines and labels, so that
// writers (JSON, SVG) and bindings can copy them out without knowing how they were made.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "complex/complex.hpp"

namespace hexdual {

struct Point2 {
  double x = 0, y = 0;
};

struct SheetDiagram {
  int sheet = -1;
  std::string topology;  // of the whole sheet
  std::string method;    // "disk", "annulus", "holes", "sphere" (one face opened), "polygon" (cut open), "local" (asked for)
  std::string note;      // which face was opened, the polygon's word, the rings of a local diagram
  HexId openedHex = -1;  // sphere: the slot whose face became the outside
  int openedAxis = -1;
  bool local = false;   // a neighbourhood of chosen hexes inside a dotted circle
  double radius = 1.0;  // the outer circle, centred at the origin
  int64_t euler = 0;    // Euler characteristic of the drawn mid-surface

  struct Crossing {
    HexId hex;
    int axis;  // the slot (hex, axis) of the sheet
    Point2 p;
    int chords[2];         // the chords crossing here
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
    bool closed;     // the chord (not this piece) is closed
    std::vector<Point2> points;
    std::vector<HexId> hexes;  // crossings passed, in order
    int piece = 0;             // a chord crossing seams of a cut-open sheet is drawn in pieces 0, 1, ...
  };
  struct Cell {  // a mid-surface vertex = a primal edge crossing the sheet
    EdgeRef edge;
    Point2 p;
  };
  // A side of the fundamental polygon of a cut-open sheet: a seam (drawn twice, once per side, with
  // the labels x and x⁻¹ when the sides are glued with opposite directions, x and x when glued
  // with a twist) or a piece of the sheet's boundary (pair -1, label "∂").
  struct Arc {
    std::string label;
    int pair = -1;  // the seam: both sides of a seam have the same pair
    int sign = 1;   // +1 on the first side of a seam, -1 on a side glued in the opposite direction
    std::vector<Point2> points;
  };
  std::vector<Crossing> crossings;
  std::vector<BoundaryPoint> boundary;
  std::vector<std::vector<Point2>> loops;  // boundary loops (outer first), or the local circle
  std::vector<ChordLine> chords;
  std::vector<Cell> cells;
  std::vector<std::array<int, 4>> quads;  // mid-quads (indices into cells), one per crossing
  std::vector<Arc> arcs;                  // method "polygon": the sides of the polygon, in order
};

}  // namespace hexdual
