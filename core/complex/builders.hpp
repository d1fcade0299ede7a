// Ways to make a Complex: structured grids, ring (O-grid) meshes, and hex connectivity.
#pragma once
#include <array>
#include <vector>

#include "complex/complex.hpp"

namespace hexdual {

// An a x b x c block of unit hexes; hex (i,j,k) has id i + a*(j + b*k).
Complex makeGrid(int a, int b, int c);

// An O-grid: `around` hexes around the axis, `radial` layers outward, `axial` layers along the axis.
// Local axes of every hex: x radial, y around, z axial.
Complex makeRing(int around, int radial, int axial);

// A ring of `around` hexes (1x1 cross-section) whose cross-section turns a quarter turn before the
// ring closes: the radial and axial layers become one self-intersecting sheet through every hex.
Complex makeTwistedRing(int around);

// A thickened torus: `around` x `tube` hexes on a torus surface (both directions closed), `layers`
// thick. Its `layers` sheets parallel to the surface are tori. With `klein`, going once around
// reflects the tube, so those sheets are Klein bottles (the complex is not orientable).
Complex makeTorusShell(int around, int tube, int layers, bool klein = false);

// Glues hexes given as 8 vertex ids each (VTK order) wherever two hexes share a quad's 4 vertices
// in the same cycle. Throws Error when a quad would be shared by three or more hexes, when two
// hexes share 4 vertices in different cyclic orders, or when a hex repeats a vertex.
// The result is validated (manifold vertex links, Euler characteristic).
Complex fromConnectivity(const std::vector<Vec3>& points, const std::vector<std::array<VertexId, 8>>& hexes);

}  // namespace hexdual
