// How readable a sheet diagram is: how far apart its crossings are, relative to an even spread of
// the same number of crossings over the unit disk. 1 or more: as even as a grid; well below 0.1:
// some crossings crowd (a large sphere squeezed behind its opened face, a long tube drawn as an
// annulus); near 0: crossings a reader cannot tell apart.
#pragma once
#include "layout/diagram.hpp"

namespace hexdual {

// min over crossings of the distance to the nearest other crossing, times sqrt(crossings / pi).
double diagramSpread(const SheetDiagram& d);

// Below this, layoutSheet tries another way of drawing the sheet (cut open into a polygon) and
// keeps the one that spreads better. 0.1 (was 0.05): a face collapse's necked annulus drew at 0.063.
constexpr double kReadableSpread = 0.1;

}  // namespace hexdual
