// A simplicial triangulation of a mid-surface, the ground a sheet diagram is drawn on. Each quad
// is fanned from its centre: over its 4 corners (4 triangles), or over its corners and mid-edges
// (8 triangles) where the corners alone are not simplicial (two mid-edges on the same two corners,
// as around a chord push's blind chord, or a boundary loop of two corners). A chord runs centre ->
// mid-edge -> centre, inside the triangles of its quads, so a planar drawing of the triangulation
// is a planar sheet diagram: two chords can meet only at a centre, their hex's crossing.
// Holes (inner boundary loops) are closed by virtual rings of triangles, so that every genus-0
// sheet is drawn as a disk (Tutte/Floater: tutte_embedding.hpp).
#pragma once
#include <array>
#include <string>
#include <vector>

#include "layout/boundary_loops.hpp"
#include "layout/diagram.hpp"
#include "layout/mid_surface.hpp"

namespace hexdual {

struct Triangulation {
  bool withMids = false;  // 8 triangles per quad (corners and mid-edges), else 4 (corners)
  int vertices = 0;       // the refined surface's ids (corners, mids, centres), then virtual vertices
  int firstVirtual = 0;   // = s.total(): hole fillings
  std::vector<std::array<int, 3>> tris;  // oriented consistently with the quads' signs
  // Per triangle: its ideal shape (counter-clockwise), from each quad drawn as a unit square and
  // each hole as a regular polygon: what arap_relax pulls the drawing towards.
  std::vector<std::array<Point2, 3>> ref;
  // Boundary loops as vertex cycles, in the direction of the boundary edges (boundary_loops.hpp).
  std::vector<std::vector<int>> loops;
  // Per loop: its boundary edges (indices into `edges`), and the edges themselves.
  std::vector<std::vector<int>> loopEdges;
  std::vector<BoundaryEdge> edges;
  size_t outer = 0;  // the loop drawn on the circle, the longest (the others are holes)
  std::vector<bool> centre;  // per vertex: a quad's centre (adjacent to no other centre)
};

// Why a surface cannot be fanned into a simplicial triangulation, or empty when it can. With
// `withMids`, the 8-triangle fan; the 4-triangle one is simplicial only when no two mid-edges join
// the same two corners and every boundary loop has 3 or more corners.
std::string fanObstacle(const MidSurface& s, int skipSlot, bool withMids);

// The fan triangulation of s without slot `skipSlot` (a sphere's opened face): the 4-triangle fan
// when it is simplicial, else the 8-triangle one; throws Error when neither is (a quad with a
// repeated corner). The boundary loops are chained from boundaryEdges(s, skipSlot).
Triangulation triangulate(const MidSurface& s, int skipSlot = -1);

// Closes the hole bounded by loop `k` (an inner loop) with `rings` rings of virtual vertices and a
// virtual centre, oriented consistently with the surface.
void fillHole(Triangulation& t, size_t k, int rings);

}  // namespace hexdual
