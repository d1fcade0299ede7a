// Local sheet diagrams (as in TK03's operation figures): the part of a sheet within k rings of
// chosen hexes, inside a dotted circle standing for the boundary of the region of interest.
#pragma once
#include <vector>

#include "dual/dual.hpp"
#include "layout/diagram.hpp"

namespace hexdual {

// The part of a sheet within `rings` rings of the given hexes, inside a dotted circle. A ring
// adds every slot sharing a mid-surface corner (a primal edge) with the piece, so one ring around
// a grid hex is 3x3. When that piece does not draw as a planar disk, fewer rings are drawn (the
// largest count found by bisection), and the note says so.
SheetDiagram layoutLocal(const Complex& cx, const Dual& dual, int sheet, const std::vector<HexId>& hexes, int rings);

// The same around sheet slots.
SheetDiagram layoutAround(const Complex& cx, const Dual& dual, int sheet, const std::vector<Slot>& seeds, int rings);

}  // namespace hexdual
