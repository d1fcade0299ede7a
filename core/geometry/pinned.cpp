#include "geometry/pinned.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <vector>

#include "geometry/degenerate.hpp"
#include "geometry/max_min.hpp"
#include "geometry/scaled_jacobian.hpp"

namespace hexdual {

namespace {

constexpr double kTolerance = 1e-9;

double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
double length(Vec3 a) { return std::sqrt(dot(a, a)); }
double coord(Vec3 p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }

struct HalfSpace {  // n . p > c, |n| = 1
  Vec3 n;
  double c;
};

// The open half-space of positions of vertex k where the corner's determinant is positive.
HalfSpace cornerHalfSpace(const std::array<Vec3, 4>& p, int k) {
  const AffineFunction f = cornerDeterminantIn(p, k);
  const double len = length(f.g);
  return len > 0 ? HalfSpace{(1 / len) * f.g, -f.h / len} : HalfSpace{Vec3{}, -f.h};
}

// One Fourier-Motzkin step: the constraints without `axis`; false when one of them reads 0 > c
// with c >= -tol (no common point).
bool eliminate(std::vector<HalfSpace>& hs, int axis, double tol) {
  std::vector<HalfSpace> next;
  for (const HalfSpace& h : hs)
    if (coord(h.n, axis) == 0) next.push_back(h);
  for (const HalfSpace& a : hs)
    for (const HalfSpace& b : hs) {
      const double ca = coord(a.n, axis), cb = coord(b.n, axis);
      if (!(ca > 0 && cb < 0)) continue;
      HalfSpace h{-cb * a.n + ca * b.n, -cb * a.c + ca * b.c};
      Vec3 n = h.n;
      if (axis == 0) n.x = 0;  // eliminated exactly
      if (axis == 1) n.y = 0;
      if (axis == 2) n.z = 0;
      const double len = length(n);
      if (len <= kTolerance) {
        if (h.c >= -tol * (ca - cb)) return false;
        continue;
      }
      next.push_back({(1 / len) * n, h.c / len});
    }
  hs = std::move(next);
  return true;
}

// Whether the half-spaces have a common point (true also when there are too many to decide).
bool haveCommonPoint(std::vector<HalfSpace> hs, double tol) {
  for (const HalfSpace& h : hs)
    if (length(h.n) == 0 && h.c >= -tol) return false;
  for (int axis = 0; axis < 3; ++axis) {
    if (hs.size() > 64) return true;
    if (!eliminate(hs, axis, tol)) return false;
  }
  return true;
}

std::array<Vec3, 4> framePoints(const Complex& cx, HexId h, int c) {
  const int* f = kCornerFrame[c];
  return {cx.position(cx.vertex(h, c)), cx.position(cx.vertex(h, f[0])), cx.position(cx.vertex(h, f[1])),
          cx.position(cx.vertex(h, f[2]))};
}

// pinnedVertex per vertex id, each walked once per query: a certificate asks about the same few
// vertices many times (4 per corner, over every corner of a star), and a star walk costs its size.
// In a valid complex a vertex's star is connected (or the vertex is a tolerated non-manifold one,
// pinned whatever the corner), so any corner of it gives the same answer.
class PinnedVertices {
 public:
  PinnedVertices(const Complex& cx, VertexStars& stars) : cx_(cx), stars_(stars) {}
  bool operator()(HexId h, int c) {
    const auto [at, added] = known_.try_emplace(cx_.vertex(h, c), false);
    if (added) at->second = pinnedVertex(cx_, h, c, stars_);
    return at->second;
  }

 private:
  const Complex& cx_;
  VertexStars& stars_;
  std::unordered_map<VertexId, bool> known_;
};

unsigned pinnedMask(PinnedVertices& pinned, HexId h, int c) {
  const int* f = kCornerFrame[c];
  return unsigned(pinned(h, c)) | unsigned(pinned(h, f[0])) << 1 | unsigned(pinned(h, f[1])) << 2 |
         unsigned(pinned(h, f[2])) << 3;
}

// Whether the corners of regular hexes whose only unpinned vertex is v (corner `corner` of hex h)
// can all be positive.
bool freeVertexFeasible(const Complex& cx, PinnedVertices& pinned, VertexStars& stars, HexId h, int corner) {
  const VertexId v = cx.vertex(h, corner);
  std::vector<OneFreeCorner> corners;
  for (auto [h2, c2] : cx.cornersOfVertex(h, corner)) {  // in walk order (the list's order is the walk's)
    if (degenerateByConstruction(cx, h2, stars)) continue;
    const int moved[4] = {c2, kCornerFrame[c2][0], kCornerFrame[c2][1], kCornerFrame[c2][2]};
    for (int j : moved) {
      const unsigned mask = pinnedMask(pinned, h2, j);
      if (__builtin_popcount(mask) != 3) continue;
      const int k = mask == 14 ? 0 : mask == 13 ? 1 : mask == 11 ? 2 : 3;
      if (cx.vertex(h2, k == 0 ? j : kCornerFrame[j][k - 1]) == v) corners.push_back({framePoints(cx, h2, j), k});
    }
  }
  return oneVertexFeasible(corners);
}

}  // namespace

bool oneVertexFeasible(const std::vector<OneFreeCorner>& corners) {
  std::vector<HalfSpace> hs;
  double scale = 0;
  for (const OneFreeCorner& c : corners) {
    hs.push_back(cornerHalfSpace(c.p, c.k));
    for (size_t i = 1; i < 4; ++i) scale = std::max(scale, length(c.p[i] - c.p[0]));
  }
  return haveCommonPoint(std::move(hs), kTolerance * scale);
}

namespace {
// Whether vertex v, whose corners `starOf()` lists, is non-manifold or on the boundary (the walk
// only when needed).
template <class StarOf>
bool pinnedAt(const Complex& cx, VertexId v, StarOf&& starOf) {
  const auto& nm = cx.nonManifoldVertices();
  if (std::binary_search(nm.begin(), nm.end(), v)) return true;
  for (auto [hh, cc] : starOf())
    for (int f : tables::facesOfCorner(cc))
      if (cx.isBoundary({hh, f})) return true;
  return false;
}
}  // namespace

bool pinnedVertex(const Complex& cx, HexId h, int c, VertexStars& stars) {
  return pinnedAt(cx, cx.vertex(h, c), [&]() -> const std::vector<std::pair<HexId, int>>& { return stars.of(h, c); });
}

bool pinnedVertex(const Complex& cx, HexId h, int c) {
  return pinnedAt(cx, cx.vertex(h, c), [&] { return cx.cornersOfVertex(h, c); });
}

bool cornerStuck(const std::array<Vec3, 4>& p, unsigned fixedMask) {
  const Vec3 e[3] = {p[1] - p[0], p[2] - p[0], p[3] - p[0]};
  if (fixedMask == 15) return det3(e[0], e[1], e[2]) <= kTolerance * length(e[0]) * length(e[1]) * length(e[2]);
  if (!(fixedMask & 1)) return false;
  for (int a = 0; a < 3; ++a)
    for (int b = a + 1; b < 3; ++b)
      if ((fixedMask >> (a + 1) & 1) && (fixedMask >> (b + 1) & 1) &&
          length(cross(e[a], e[b])) <= kTolerance * length(e[a]) * length(e[b]))
        return true;
  return false;
}

bool pinnedInversion(const Complex& cx, HexId h) {
  VertexStars stars(cx);
  return pinnedInversion(cx, h, stars);
}

bool pinnedInversion(const Complex& cx, HexId h, VertexStars& stars) {
  PinnedVertices pinned(cx, stars);
  for (int c = 0; c < 8; ++c) {
    const std::array<Vec3, 4> p = framePoints(cx, h, c);
    if (det3(p[1] - p[0], p[2] - p[0], p[3] - p[0]) > 0) continue;
    const unsigned mask = pinnedMask(pinned, h, c);
    if (cornerStuck(p, mask)) return true;
    if (__builtin_popcount(mask) != 3) continue;
    const int k = mask == 14 ? 0 : mask == 13 ? 1 : mask == 11 ? 2 : 3;
    if (!freeVertexFeasible(cx, pinned, stars, h, k == 0 ? c : kCornerFrame[c][k - 1])) return true;
  }
  return false;
}

}  // namespace hexdual
