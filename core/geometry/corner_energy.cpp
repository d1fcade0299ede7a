#include "geometry/corner_energy.hpp"

#include <cmath>
#include <limits>

namespace hexdual {

namespace {
double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

// d|adj S|^2 / da for the column a, the others b and c: 2 ((|b|^2 + |c|^2) a - (a.b) b - (a.c) c).
inline Vec3 adjugateGrad(Vec3 a, Vec3 b, Vec3 c) {
  return 2.0 * ((dot(b, b) + dot(c, c)) * a - dot(a, b) * b - dot(a, c) * c);
}
}  // namespace

double cornerEnergy(const std::array<Vec3, 4>& p, double delta2, int k, Vec3* grad) {
  const Vec3 a = p[1] - p[0], b = p[2] - p[0], c = p[3] - p[0];
  const double sigma = det3(a, b, c);  // the same bits as the scaled Jacobian's sign
  if (delta2 == 0 && sigma <= 0) return std::numeric_limits<double>::infinity();
  // h and r = sqrt(sigma^2 + 4 delta^2) (h'/h = 1/r); for sigma < 0 the cancellation-free form of h.
  double h = sigma, r = sigma;
  if (delta2 > 0) {
    r = std::sqrt(sigma * sigma + 4 * delta2);
    h = sigma >= 0 ? 0.5 * (sigma + r) : 2 * delta2 / (r - sigma);
  }
  const Vec3 u = cross(b, c), v = cross(c, a), w = cross(a, b);
  const double frob = dot(a, a) + dot(b, b) + dot(c, c);
  const double adj = dot(u, u) + dot(v, v) + dot(w, w);
  const double denom = 9 * h * h;
  const double e = frob * adj / denom;
  if (grad) {
    // d/d(column) of e: (2 adj col + frob d|adj S|^2/dcol) / denom - (2 e / r) dsigma/dcol
    const double s = 1 / denom, t = 2 * e / r;
    auto column = [&](Vec3 x, Vec3 y, Vec3 z, Vec3 dsigma) {
      return s * (2 * adj * x + frob * adjugateGrad(x, y, z)) - t * dsigma;
    };
    if (k == 1)
      *grad = column(a, b, c, u);
    else if (k == 2)
      *grad = column(b, c, a, v);
    else if (k == 3)
      *grad = column(c, a, b, w);
    else
      *grad = Vec3{} - (column(a, b, c, u) + column(b, c, a, v) + column(c, a, b, w));
  }
  return e;
}

}  // namespace hexdual
