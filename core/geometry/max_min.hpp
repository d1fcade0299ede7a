// The untangling step of Freitag & Plassmann (2000): the position of one vertex that maximises the
// smallest of a few affine functions of it (a corner determinant is affine in each of its four
// vertices), within a box around its current position. A linear programme in (p, t), solved
// exactly by the simplex method with Bland's rule (deterministic, no tolerance on the pivots but
// the sign tests).
#pragma once
#include <array>
#include <vector>

#include "complex/complex.hpp"

namespace hexdual {

struct AffineFunction {  // g . p + h
  Vec3 g;
  double h = 0;
};

// A corner determinant as an affine function of the corner's vertex k (0: the corner, 1..3: its
// frame's neighbours), the other three at p.
AffineFunction cornerDeterminantIn(const std::array<Vec3, 4>& p, int k);

// The argmax over |p - p0|_inf <= radius of min_j f_j(p) (p0 when `fs` is empty or the simplex
// gives up after its pivot limit).
Vec3 maximiseMinimum(const std::vector<AffineFunction>& fs, Vec3 p0, double radius);

}  // namespace hexdual
