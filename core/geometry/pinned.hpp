// Inversions that no smoothing can remove while the boundary stays where it is: certificates that
// a corner's determinant is <= 0 for every placement of the vertices that may move (those not on
// the boundary and not non-manifold). Reports list such hexes as pinned, and the smoothing leaves
// stuck corners out of its energy.
#pragma once
#include <array>
#include <vector>

#include "complex/complex.hpp"
#include "geometry/degenerate.hpp"

namespace hexdual {

// Whether the vertex at corner c of hex h may never move: on the boundary or non-manifold.
bool pinnedVertex(const Complex& cx, HexId h, int c);
// The same, reading the vertex's corners from `stars` (built on cx, which has not changed since).
bool pinnedVertex(const Complex& cx, HexId h, int c, VertexStars& stars);

// Whether no placement of the free ones among a corner's four vertices (the corner, then its
// frame's three; bit k of `fixedMask` = vertex k is fixed) makes its determinant positive: all
// four fixed with determinant <= 0, or the corner and two of its neighbours fixed on one line.
// Both up to a relative tolerance of 1e-9 (points on a flat or straight boundary are not always
// exactly coplanar or collinear in floating point).
bool cornerStuck(const std::array<Vec3, 4>& p, unsigned fixedMask);

// A corner frame whose vertex k (0: the corner, 1..3: its frame's neighbours) is the only one
// that may move.
struct OneFreeCorner {
  std::array<Vec3, 4> p;
  int k;
};
// Whether one position of the free vertex makes all the corners' determinants positive: each asks
// for an open half-space; Fourier-Motzkin elimination decides whether they meet (relative
// tolerance 1e-9; true, undecided, when there are too many to eliminate).
bool oneVertexFeasible(const std::vector<OneFreeCorner>& corners);

// Whether hex h (not degenerate by construction) has a corner with determinant <= 0 that no
// smoothing keeping the pinned vertices can make positive while keeping every other regular hex
// valid: a stuck corner, or a corner whose only unpinned vertex v would have to lie in every
// half-space that the corners of regular hexes with v as their only unpinned vertex ask for, and
// those half-spaces have no common point (Fourier-Motzkin elimination, same tolerance).
bool pinnedInversion(const Complex& cx, HexId h);
// The same, reading vertex stars from `stars` (built on cx, which has not changed since).
bool pinnedInversion(const Complex& cx, HexId h, VertexStars& stars);

}  // namespace hexdual
