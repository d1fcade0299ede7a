#include "geometry/boundary_slide.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace hexdual {

namespace {

constexpr double kTolerance = 1e-9;

double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
Vec3 unit(Vec3 a) { return (1 / std::sqrt(dot(a, a))) * a; }

// The corners of the boundary quads at the vertex (each quad's four, in its face's order).
std::vector<std::array<Vec3, 4>> boundaryQuadsAt(const Complex& cx, HexId h, int c) {
  std::vector<std::array<Vec3, 4>> out;
  for (auto [hh, cc] : cx.cornersOfVertex(h, c))
    for (int f : tables::facesOfCorner(cc)) {
      if (!cx.isBoundary({hh, f})) continue;
      std::array<Vec3, 4> q;
      for (size_t k = 0; k < 4; ++k) q[k] = cx.position(cx.vertex(hh, tables::kFaceCorners[size_t(f)][k]));
      out.push_back(q);
    }
  return out;
}

// Orthonormal tangents of the plane with unit normal n: coordinate axes when n is one.
std::array<Vec3, 2> tangentsOf(Vec3 n) {
  if (n.x == 0 && n.y == 0) return {Vec3{1, 0, 0}, Vec3{0, 1, 0}};
  if (n.y == 0 && n.z == 0) return {Vec3{0, 1, 0}, Vec3{0, 0, 1}};
  if (n.x == 0 && n.z == 0) return {Vec3{1, 0, 0}, Vec3{0, 0, 1}};
  const double ax = std::fabs(n.x), ay = std::fabs(n.y), az = std::fabs(n.z);
  const Vec3 e = ax <= ay && ax <= az ? Vec3{1, 0, 0} : ay <= az ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
  const Vec3 t1 = unit(cross(n, e));
  return {t1, cross(n, t1)};
}

}  // namespace

std::optional<std::array<Vec3, 2>> flatPatchTangents(const Complex& cx, HexId h, int c) {
  const auto& nm = cx.nonManifoldVertices();
  if (std::binary_search(nm.begin(), nm.end(), cx.vertex(h, c))) return std::nullopt;
  const std::vector<std::array<Vec3, 4>> quads = boundaryQuadsAt(cx, h, c);
  if (quads.empty()) return std::nullopt;
  const Vec3 p = cx.position(cx.vertex(h, c));
  const Vec3 first = cross(quads[0][2] - quads[0][0], quads[0][3] - quads[0][1]);
  if (!(dot(first, first) > 0)) return std::nullopt;
  const Vec3 n = unit(first);
  for (const auto& q : quads) {
    if (!(dot(cross(q[2] - q[0], q[3] - q[1]), n) > 0)) return std::nullopt;  // folded or facing away
    for (const Vec3& x : q) {
      const Vec3 d = x - p;
      if (std::fabs(dot(d, n)) > kTolerance * std::sqrt(dot(d, d))) return std::nullopt;
    }
  }
  return tangentsOf(n);
}

}  // namespace hexdual
