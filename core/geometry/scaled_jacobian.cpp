#include "geometry/scaled_jacobian.hpp"

#include <algorithm>
#include <cmath>

namespace hexdual {

namespace {
double length(Vec3 a) { return std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z); }
}  // namespace

double det3(Vec3 a, Vec3 b, Vec3 c) {
  return a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) + a.z * (b.x * c.y - b.y * c.x);
}

double scaledJacobian(const std::array<Vec3, 8>& p) { return scaledJacobian(p, nullptr); }

double scaledJacobian(const std::array<Vec3, 8>& p, double* cornerSum) {
  double worst = 1;
  for (int k = 0; k < 8; ++k) {
    Vec3 e[3];
    double len = 1;
    for (int i = 0; i < 3; ++i) {
      e[i] = p[size_t(kCornerFrame[k][i])] - p[size_t(k)];
      len *= length(e[i]);
    }
    double sj = len > 0 ? det3(e[0], e[1], e[2]) / len : 0;
    worst = std::min(worst, sj);
    if (cornerSum) *cornerSum += sj;
  }
  return worst;
}

std::array<Vec3, 8> hexPoints(const Complex& cx, HexId h) {
  std::array<Vec3, 8> p;
  for (int k = 0; k < 8; ++k) p[size_t(k)] = cx.position(cx.vertex(h, k));
  return p;
}

double scaledJacobian(const Complex& cx, HexId h) { return scaledJacobian(hexPoints(cx, h)); }

}  // namespace hexdual
