// Cutting a sheet's mid-surface open into a disk (a fundamental polygon) along a cut graph: the
// edges not crossed by a spanning tree of the dual graph (tree–cotree), with dangling paths
// pruned. The cut graph holds the boundary loops and one seam system of the handles and twists.
#pragma once
#include <string>
#include <vector>

#include "layout/boundary_loops.hpp"
#include "layout/mid_surface.hpp"

namespace hexdual {

struct CutGraph {
  std::vector<std::array<bool, 6>> cut;  // per slot, per side: cut open (both sides of each seam edge)
  std::vector<bool> edge;                // per mid vertex of the surface: its edge is on the cut graph
  std::vector<int> degree;               // per corner: cut-graph edges at it (a loop counts twice)
};

// The cut graph of a connected surface: the boundary alone for a disk; for a sphere, a tree of
// slits through corners far apart.
CutGraph cutGraph(const MidSurface& s);

// One side of the fundamental polygon: a run of the polygon's boundary edges between two branch
// corners of the cut graph (degree other than 2).
struct PolygonSide {
  std::vector<int> edges;  // indices into the open surface's boundary edges, in polygon order
  int pair = -1;           // seams: both sides of a seam share a pair; -1: the sheet's boundary
  int sign = 1;            // -1: glued to the pair's first side in the opposite direction
};

struct FundamentalPolygon {
  std::vector<PolygonSide> sides;
  int pairs = 0;          // seams
  int branchCorners = 0;  // distinct corners of the surface where sides meet
  int64_t euler = 0;      // 1 + branchCorners - (pairs + boundary sides): the surface's
};

// The sides of the polygon `loop` (indices into `edges`, the boundary of `open` = cutOpen(s, g.cut)).
FundamentalPolygon fundamentalPolygon(const MidSurface& s, const CutGraph& g, const MidSurface& open,
                                      const std::vector<BoundaryEdge>& edges, const std::vector<int>& loop);

// Seam labels: a, b, ..., z, a2, b2, ...; with "⁻¹" on sides glued in the opposite direction.
std::string seamLabel(int pair, int sign);

}  // namespace hexdual
