// The pieces of the untangling and smoothing (core/geometry): the corner energy and its gradient,
// the max-min linear programme, the degenerate-by-construction and pinned-inversion certificates.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "complex/builders.hpp"
#include "geometry/corner_energy.hpp"
#include "geometry/degenerate.hpp"
#include "geometry/max_min.hpp"
#include "geometry/pinned.hpp"
#include "geometry/scaled_jacobian.hpp"
#include "ops/oplog.hpp"

using namespace hexdual;

namespace {
Vec3 random(std::mt19937& rng, double r) {
  std::uniform_real_distribution<double> u(-r, r);
  return {u(rng), u(rng), u(rng)};
}
double& coord(Vec3& p, int d) { return d == 0 ? p.x : d == 1 ? p.y : p.z; }
}  // namespace

TEST_CASE("corner energy: 1 at a cube's corner, a barrier without delta, finite with it, exact gradient") {
  const std::array<Vec3, 4> cube{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
  CHECK(cornerEnergy(cube, 0) == 1);
  CHECK(cornerEnergy({cube[0], Vec3{2, 0, 0}, Vec3{0, 2, 0}, Vec3{0, 0, 2}}, 0) == 1);  // scale-free
  const std::array<Vec3, 4> flipped{cube[0], cube[2], cube[1], cube[3]};                 // left-handed
  CHECK(std::isinf(cornerEnergy(flipped, 0)));
  CHECK(std::isfinite(cornerEnergy(flipped, 1e-6)));
  CHECK(cornerEnergy(flipped, 1e-6) > cornerEnergy(flipped, 1e-2));  // softer with a larger delta
  // The gradient against central differences, for each of the four vertices, tangled or not.
  const unsigned seed = 7;
  MESSAGE("seed " << seed);
  std::mt19937 rng(seed);
  for (int trial = 0; trial < 50; ++trial) {
    std::array<Vec3, 4> p = cube;
    for (Vec3& q : p) q = q + random(rng, 0.6);
    const double delta2 = trial % 2 ? 1e-3 : 0;
    if (std::isinf(cornerEnergy(p, delta2))) continue;
    for (int k = 0; k < 4; ++k) {
      Vec3 g;
      cornerEnergy(p, delta2, k, &g);
      for (int d = 0; d < 3; ++d) {
        std::array<Vec3, 4> a = p, b = p;
        const double h = 1e-6;
        coord(a[size_t(k)], d) += h;
        coord(b[size_t(k)], d) -= h;
        const double fd = (cornerEnergy(a, delta2) - cornerEnergy(b, delta2)) / (2 * h);
        CHECK(coord(g, d) == doctest::Approx(fd).epsilon(1e-4).scale(1 + std::fabs(fd)));
      }
    }
  }
}

TEST_CASE("max-min: the linear programme finds the best smallest value, inside its box") {
  // min(x, 2 - x, y + 5): best at x = 1 with value 1, whatever y and z (y kept >= -4).
  std::vector<AffineFunction> fs{{{1, 0, 0}, 0}, {{-1, 0, 0}, 2}, {{0, 1, 0}, 5}};
  Vec3 p = maximiseMinimum(fs, {0, 0, 0}, 10);
  CHECK(p.x == doctest::Approx(1));
  CHECK(std::min({p.x, 2 - p.x, p.y + 5}) == doctest::Approx(1));
  // The box binds: from x = -3 within 1, the best is x = -2.
  p = maximiseMinimum(fs, {-3, 0, 0}, 1);
  CHECK(p.x == doctest::Approx(-2));
  // A corner determinant is affine in each of its vertices.
  const std::array<Vec3, 4> c{Vec3{0.1, 0.2, 0}, Vec3{1, 0.1, 0.2}, Vec3{0, 1.2, 0.1}, Vec3{0.2, 0, 0.9}};
  for (int k = 0; k < 4; ++k) {
    const AffineFunction f = cornerDeterminantIn(c, k);
    std::array<Vec3, 4> moved = c;
    moved[size_t(k)] = moved[size_t(k)] + Vec3{0.3, -0.7, 0.45};
    const Vec3 q = moved[size_t(k)];
    CHECK(f.g.x * q.x + f.g.y * q.y + f.g.z * q.z + f.h ==
          doctest::Approx(det3(moved[1] - moved[0], moved[2] - moved[0], moved[3] - moved[0])));
  }
}

TEST_CASE("degenerate by construction: mirrored corner frames have opposite determinants in every embedding") {
  // After a face collapse at the centre of a 4x4x4 grid (L and R two hexes each), the four hexes
  // around the doubled edge have valence-2 edges and the four below and above them (the 2x2x3
  // column) share mirrored frames at its ends.
  Complex cx = makeGrid(4, 4, 4);
  OpResult r = applyStep(cx, "facecollapse h21e11 h21f1 h25f1");
  std::vector<HexId> degenerate;
  for (HexId h : cx.hexes())
    if (degenerateByConstruction(cx, h)) degenerate.push_back(h);
  CHECK(degenerate == std::vector<HexId>{5, 6, 9, 10, 21, 22, 25, 26, 37, 38, 41, 42});
  // For each corner of a degenerate hex whose frame another hex mirrors, the two determinants
  // have opposite signs for random positions of every vertex.
  const unsigned seed = 11;
  MESSAGE("seed " << seed);
  std::mt19937 rng(seed);
  int pairs = 0;
  for (int trial = 0; trial < 20; ++trial) {
    Complex moved = cx;
    for (VertexId v : moved.vertices()) moved.setPosition(v, moved.position(v) + random(rng, 0.4));
    for (HexId h : degenerate)
      for (int c = 0; c < 8; ++c)
        for (auto [h2, c2] : moved.cornersOfVertex(h, c)) {
          if (h2 == h) continue;
          std::array<VertexId, 3> a, b;
          for (int k = 0; k < 3; ++k) a[size_t(k)] = moved.vertex(h, kCornerFrame[c][k]), b[size_t(k)] = moved.vertex(h2, kCornerFrame[c2][k]);
          std::array<VertexId, 3> sa = a, sb = b;
          std::sort(sa.begin(), sa.end());
          std::sort(sb.begin(), sb.end());
          if (sa != sb) continue;
          auto det = [&](HexId x, int cc) {
            const std::array<Vec3, 8> p = hexPoints(moved, x);
            const int* f = kCornerFrame[cc];
            return det3(p[size_t(f[0])] - p[size_t(cc)], p[size_t(f[1])] - p[size_t(cc)], p[size_t(f[2])] - p[size_t(cc)]);
          };
          CHECK(det(h, c) * det(h2, c2) <= 0);
          ++pairs;
        }
  }
  CHECK(pairs > 0);
  Complex pillowed = makeGrid(3, 3, 3);
  OpResult p = applyStep(pillowed, "pillow h13f1");
  for (HexId h : p.createdHexes) CHECK(degenerateByConstruction(pillowed, h));
  CHECK(!degenerateByConstruction(pillowed, 13));
  CHECK(r.createdHexes.empty());
}

TEST_CASE("pinned inversions: a flat hex push on the boundary, and the certificates' rules") {
  // At the corner of a 3x3x3 grid the pushed quad h0f1 has an edge on the bottom face: the ring
  // hex there has a corner whose vertex and two neighbours lie on one boundary line.
  Complex cx = makeGrid(3, 3, 3);
  OpResult r = applyStep(cx, "hexpush h0f1", kSmoothStep);
  CHECK(!r.quality.inverted.empty());
  CHECK(r.quality.pinned == r.quality.inverted);
  for (HexId h : r.quality.pinned) CHECK(pinnedInversion(cx, h));
  // The rules, on one corner: all four fixed and flat; three fixed on a line; one free vertex.
  const Vec3 o{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  CHECK(cornerStuck({o, x, y, Vec3{1, 1, 0}}, 15));      // coplanar: determinant 0
  CHECK(!cornerStuck({o, x, y, z}, 15));                 // a cube's corner
  CHECK(cornerStuck({o, x, Vec3{-1, 0, 0}, z}, 0b0111));  // o, x, -x fixed on a line: z cannot help
  CHECK(!cornerStuck({o, x, y, Vec3{0, 0, -1}}, 0b0111)); // z free: it can go up
  CHECK(!cornerStuck({o, x, Vec3{-1, 0, 0}, z}, 0b1110)); // the corner itself free
  // One free vertex asked to be above and below the same plane: no common point.
  CHECK(!oneVertexFeasible({{{o, x, y, z}, 3}, {{o, y, x, z}, 3}}));
  CHECK(oneVertexFeasible({{{o, x, y, z}, 3}, {{o, x, y, Vec3{1, 1, 1}}, 3}}));
  CHECK(oneVertexFeasible({}));
}
