#include "geometry/scaled_jacobian.hpp"

#include <algorithm>
#include <cmath>

namespace hexdual {

namespace {
// The three neighbours of each VTK corner, ordered so a cube gives a right-handed frame.
constexpr int kCornerFrame[8][3] = {{1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7},
                                    {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}};

double length(Vec3 a) { return std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z); }
double det(Vec3 a, Vec3 b, Vec3 c) {
  return a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) + a.z * (b.x * c.y - b.y * c.x);
}
}  // namespace

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
    double sj = len > 0 ? det(e[0], e[1], e[2]) / len : 0;
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
