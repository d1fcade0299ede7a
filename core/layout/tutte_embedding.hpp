// Tutte's barycentric embedding (1963) with positive weights (Floater 2003): when the outer loop of
// a triangulated disk is fixed on a strictly convex polygon and every other vertex is a positive
// weighted average of its neighbours, the straight-line drawing is planar: no triangle flips, so
// no two edges cross. The sheet diagram is planar by construction; `flippedTriangle` checks it.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "layout/diagram.hpp"
#include "layout/triangulation.hpp"

namespace hexdual {

// The Laplacian of a triangulation with its fixed vertices removed, factorised once: solves
// sum_j w_ij (x_i - x_j) = b_i for the free vertices (every triangle edge weighs 1 per triangle it
// bounds). Quad centres, which touch no other centre, are eliminated before the factorisation and
// placed after each solve from their neighbours.
class DiskSolver {
 public:
  DiskSolver(const Triangulation& t, const std::vector<bool>& fixed);
  ~DiskSolver();
  bool ok() const;
  // Writes the free vertices of pos (fixed ones are read); rhs: per vertex b_i, or null for 0.
  void solve(std::vector<Point2>& pos, const std::vector<Point2>* rhs) const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

// The first triangle that is flipped (negative orientation) or flat, or -1: the certificate that the
// drawing of a disk whose outer loop is fixed on a convex polygon is an embedding.
int flippedTriangle(const Triangulation& t, const std::vector<Point2>& pos);

// Signed area (twice) of triangle k.
double signedArea2(const Triangulation& t, const std::vector<Point2>& pos, size_t k);

}  // namespace hexdual
