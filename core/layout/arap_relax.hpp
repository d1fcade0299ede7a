// Relaxing a planar drawing towards its triangles' ideal shapes (as-rigid-as-possible, Liu et al.
// 2008, local/global) without ever leaving the planar drawings: after each global step every free
// vertex moves towards its ARAP position only as far as its own triangles keep a positive area
// (a per-vertex form of the flip-preventing line search of Smith & Schaefer 2015). With the outer loop fixed on a convex
// polygon, a drawing with every triangle positive is an embedding, so the result is as planar as
// the Tutte drawing it starts from, and quads drawn as near-squares: a blind chord, a pillow's
// pair and two chords crossing twice open up instead of collapsing into a point.
#pragma once
#include <vector>

#include "layout/tutte_embedding.hpp"

namespace hexdual {

struct RelaxStats {
  int iterations = 0;
  double lastMove = 0;  // the largest vertex move of the last iteration
};

// pos: a drawing with every triangle positive (counter-clockwise), the fixed vertices in place.
// The reference shapes are scaled by `scale`, or (0) so that their total area is the drawing's.
RelaxStats arapRelax(const Triangulation& t, const DiskSolver& solver, const std::vector<bool>& fixed,
                     std::vector<Point2>& pos, int iterations, double scale = 0);

}  // namespace hexdual
