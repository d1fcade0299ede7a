// Placing a mid-surface in the plane: boundary loops on circles, everything else by a harmonic
// (Tutte) solve. Disks and cut-open sheets on the unit circle; annuli between two circles;
// spheres with one face opened as the outside.
#pragma once
#include <string>
#include <vector>

#include "layout/diagram.hpp"
#include "layout/mid_surface.hpp"

namespace hexdual {

struct Placement {
  std::vector<Point2> pos;  // per vertex of the refined surface (corners, mids, centres)
  std::vector<bool> fixed;
  int opened = -1;          // the opened slot (sphere)
  std::string method;       // "disk", "annulus", "sphere"
};

// V - E + F of the surface with its cuts open.
int64_t eulerCharacteristic(const MidSurface& s);

// Places a disk, an annulus or a sphere; false for other topologies, a non-orientable surface,
// or a boundary loop too short to draw on a circle.
bool placeSurface(const MidSurface& s, Placement& pl);

// Fixes the mid vertices of boundary sides (and of the opened face) halfway between their corners.
void fixBoundaryMids(const MidSurface& s, Placement& pl);

// Solves for the unfixed vertices as averages of their neighbours (Tutte). Degenerate surfaces are
// solved on the refined mesh; others on the corners, then mids and centres are averaged.
bool harmonicSolve(const MidSurface& s, Placement& pl);

}  // namespace hexdual
