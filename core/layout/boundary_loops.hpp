// The boundary of a mid-surface as directed loops of corners (TK03 §1.1: a sheet's boundary loops,
// where it meets the mesh boundary), following each quad's orientation.
#pragma once
#include <vector>

#include "layout/mid_surface.hpp"

namespace hexdual {

struct BoundaryEdge {
  int from, to;    // corners, in the direction of the surface's orientation
  int slot, face;  // the side of the quad it bounds
};

// Sides with no joined neighbour (mesh boundary, edge of the slot set, or a cut), skipping the
// sides of slot `skipSlot` and treating its neighbours' sides towards it as boundary (a sphere
// opened at one face).
std::vector<BoundaryEdge> boundaryEdges(const MidSurface& s, int skipSlot = -1);

// Chains directed boundary edges into loops of edge indices. False when a corner has two outgoing
// edges or a loop does not close (the surface is not oriented consistently).
bool chainLoops(const std::vector<BoundaryEdge>& edges, std::vector<std::vector<int>>& loops);

// The corners of a loop of edge indices.
std::vector<int> loopCorners(const std::vector<BoundaryEdge>& edges, const std::vector<int>& loop);

}  // namespace hexdual
