// A sheet of genus > 0 or a non-orientable sheet (torus, Möbius band, Klein bottle, projective
// plane, ...) drawn as a fundamental polygon: cut open along a cut graph into a disk, the disk
// laid out like a disk sheet, the seams drawn as labelled sides identified in pairs.
#pragma once
#include "dual/dual.hpp"
#include "layout/diagram.hpp"
#include "layout/mid_surface.hpp"

namespace hexdual {

// Throws Error when the cut surface does not lay out as a disk, or when the polygon's Euler
// characteristic (1 + corners - sides) is not the surface's.
SheetDiagram layoutPolygon(const Dual& dual, int sheet, const MidSurface& s);

}  // namespace hexdual
