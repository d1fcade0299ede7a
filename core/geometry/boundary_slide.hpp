// Boundary vertices that may slide: a manifold boundary vertex all of whose boundary quads lie in
// one plane (inside a flat patch of the boundary, not on a curve or corner of it) can move within
// that plane without changing the boundary's shape, as long as the hexes at it stay valid (a
// valid hex corner at a boundary vertex orders its two boundary edges like the boundary quad, so
// the quads around it still tile the same piece of plane). The smoothing uses this only when
// keeping the boundary fixed leaves a step with hexes newly inverted (step_geometry.hpp).
#pragma once
#include <array>
#include <optional>

#include "complex/complex.hpp"

namespace hexdual {

// Two orthonormal directions spanning the plane of the flat patch around the vertex at corner c
// of hex h (the coordinate axes when the plane is perpendicular to one, so a move keeps that
// coordinate exactly); nullopt when the vertex is interior, non-manifold, or its boundary quads
// are not coplanar (relative tolerance 1e-9).
std::optional<std::array<Vec3, 2>> flatPatchTangents(const Complex& cx, HexId h, int c);

}  // namespace hexdual
