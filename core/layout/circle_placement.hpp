// Placing a mid-surface in the plane, planar by construction: the surface is triangulated
// (triangulation.hpp), its outer boundary loop goes on the unit circle, holes are closed by
// virtual rings, and everything else is placed by Tutte's barycentric embedding
// (tutte_embedding.hpp); a disk's loop may instead go on the convex polygon its quads give
// (DiskBoundary). Disks, annuli and disks with holes keep their holes; a sphere has one face opened
// as the outside; cut-open sheets (polygon_diagram) are disks.
#pragma once
#include <string>
#include <vector>

#include "layout/diagram.hpp"
#include "layout/mid_surface.hpp"
#include "layout/triangulation.hpp"

namespace hexdual {

struct Placement {
  std::vector<Point2> pos;  // per vertex of the refined surface (corners, mids, centres), then virtual ones
  int opened = -1;          // the opened slot (sphere)
  std::string method;       // "disk", "annulus", "holes", "sphere", "polygon"
  int straightened = 0;     // a disk in its own shape: reflex boundary corners drawn straight
  Triangulation tri;        // what was drawn: every triangle keeps its orientation
};

// V - E + F of the surface with its cuts open.
int64_t eulerCharacteristic(const MidSurface& s);

// How a disk's boundary is drawn: on the unit circle, or as the convex polygon its quads give it
// (boundary corners on one quad turn a quarter, cones' turns carried to the boundary by harmonic
// measure; circle_placement.cpp, shapedLoop), falling back to the circle when they give none.
enum class DiskBoundary { circle, shaped };

// Places a disk, an annulus, a disk with holes or a sphere; false (with the reason in *why) for
// other topologies or a non-orientable surface. Throws Error when the drawing is not an embedding
// (which Tutte's theorem rules out: a bug, not a property of the sheet).
bool placeSurface(const MidSurface& s, Placement& pl, std::string* why = nullptr,
                  DiskBoundary disk = DiskBoundary::circle);

// Places a disk-shaped surface (one boundary loop) with its boundary corners on the unit circle at
// the given angles (radians, per corner id; increasing along the loop but for one wrap).
void placeDisk(const MidSurface& s, const std::vector<double>& cornerAngle, Placement& pl, const std::string& method);

}  // namespace hexdual
