// From a placed mid-surface to a sheet diagram: crossings at quad centres, chords as polylines
// edge midpoint -> quad centre -> edge midpoint (so two chords meet exactly at their hex's
// crossing, TK03 §1.1), boundary points, boundary loops.
#pragma once
#include "dual/dual.hpp"
#include "layout/circle_placement.hpp"
#include "layout/diagram.hpp"
#include "layout/mid_surface.hpp"

namespace hexdual {

// A chord crossing a cut of the surface is split into pieces there.
SheetDiagram assembleDiagram(const Dual& dual, int sheet, const MidSurface& s, const Placement& pl, bool local);

}  // namespace hexdual
