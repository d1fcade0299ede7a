// The shape term of one hex corner that the untangling and smoothing minimise (smoothing.hpp): the
// squared condition number of the corner's frame S = [p1-p0, p2-p0, p3-p0] (Knupp 2000),
//   kappa^2 = |S|^2 |adj S|^2 / (9 h(sigma)^2),  sigma = det S,
// with the modified determinant of Escobar et al. (2003), h = (sigma + sqrt(sigma^2 + 4 delta^2)) / 2.
// With delta > 0, h > 0 for every sigma: a tangled corner has a finite value that falls smoothly as
// it untangles. With delta = 0 it is a barrier: infinite when sigma <= 0, so a valid corner stays
// valid. 1 for a cube's corner, >= 1 otherwise (delta = 0). Only +, -, *, / and sqrt, in a fixed
// order: the same bits natively and in wasm.
#pragma once
#include <array>

#include "complex/complex.hpp"
#include "geometry/scaled_jacobian.hpp"

namespace hexdual {

// kappa^2 of the frame at p[0] with edges to p[1], p[2], p[3] (see above); delta2 = delta^2.
// Returns +infinity when delta2 == 0 and sigma <= 0. With `grad`, also writes the gradient with
// respect to p[k] (left untouched when the value is infinite).
double cornerEnergy(const std::array<Vec3, 4>& p, double delta2, int k = 0, Vec3* grad = nullptr);

}  // namespace hexdual
