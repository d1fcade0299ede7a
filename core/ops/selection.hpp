// Picking the way Cubit users pick: the sheet through an edge (the layer its edge class crosses),
// the chord through a quad (the column through it), and the sheet-operation steps that act on them.
#pragma once
#include <string>
#include <vector>

#include "complex/complex.hpp"
#include "dual/dual.hpp"

namespace hexdual {

// The sheet id crossed by edge e (slot of e's hex along e's axis); the chord id through quad q
// (slot of q's hex normal to q). Throws Error "select: ..." for an entity that does not exist.
int32_t sheetThroughEdge(const Complex& cx, const Dual& dual, EdgeRef e);
int32_t chordThroughQuad(const Complex& cx, const Dual& dual, QuadSide q);

struct Selection {
  bool sheet = true;            // a sheet (picked by an edge) or a chord (picked by a quad)
  int32_t id = -1;
  std::string through;          // the pick, "h13e8" or "h13f5"
  std::string topology;         // sheets: disk, annulus, sphere, torus, other
  int boundaryLoops = 0;        // sheets
  bool closed = false, selfIntersecting = false;
  std::vector<HexId> hexes;     // one per slot (a self-intersecting one lists a hex twice); chords in order
  std::vector<std::string> steps;  // operation-log steps acting on it: sheet-extract/-dice, column-collapse
};
// The selection through a picked edge or quad ("h13e8", "h13f5").
Selection selectSheet(const Complex& cx, const Dual& dual, EdgeRef e);
Selection selectChord(const Complex& cx, const Dual& dual, QuadSide q);

}  // namespace hexdual
