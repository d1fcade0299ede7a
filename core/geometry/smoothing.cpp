#include "geometry/smoothing.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "geometry/degenerate.hpp"
#include "geometry/scaled_jacobian.hpp"

namespace hexdual {

namespace {

// The hexes around the free vertices, with each corner either a free vertex (its index) or a
// fixed one (-1), and working positions of the free vertices.
struct Region {
  std::vector<VertexId> free;                     // ascending
  std::vector<Vec3> pos;                          // working positions, per free vertex
  std::vector<HexId> hexes;                       // ascending
  std::vector<std::array<int, 8>> src;            // per region hex, per corner
  std::vector<std::vector<int>> around;           // per free vertex: its region hexes that count
  std::vector<std::vector<int>> neighbours;       // per free vertex: edge neighbours (free index, or -1 - vertex id)
  std::vector<double> scale;                      // per free vertex: mean edge length
  int64_t evaluations = 0;
};

int freeIndex(const Region& r, VertexId v) {
  auto it = std::lower_bound(r.free.begin(), r.free.end(), v);
  return it != r.free.end() && *it == v ? int(it - r.free.begin()) : -1;
}

Vec3 at(const Complex& cx, const Region& r, int n) { return n >= 0 ? r.pos[size_t(n)] : cx.position(VertexId(-1 - n)); }

double length(Vec3 a) { return std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z); }

void collectNeighbours(const Complex& cx, Region& r, size_t i, const std::vector<std::pair<HexId, int>>& corners) {
  // The three neighbours of each VTK corner (the frame of scaled_jacobian.cpp, order irrelevant here).
  static constexpr int kAdjacent[8][3] = {{1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7}, {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}};
  std::vector<VertexId> ids;
  for (auto [h, c] : corners)
    for (int k : kAdjacent[c]) ids.push_back(cx.vertex(h, k));
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  double sum = 0;
  for (VertexId v : ids) {
    const int f = freeIndex(r, v);
    r.neighbours[i].push_back(f >= 0 ? f : -1 - v);
    sum += length(cx.position(v) - r.pos[i]);
  }
  r.scale[i] = ids.empty() ? 0 : sum / double(ids.size());
}

Region buildRegion(const Complex& cx, const std::vector<FreeVertex>& free) {
  Region r;
  for (const FreeVertex& f : free) r.free.push_back(f.vertex), r.pos.push_back(cx.position(f.vertex));
  r.around.resize(free.size());
  r.neighbours.resize(free.size());
  r.scale.resize(free.size());
  std::vector<std::vector<std::pair<HexId, int>>> stars;
  for (const FreeVertex& f : free) {
    stars.push_back(cx.cornersOfVertex(f.hex, f.corner));
    for (auto [h, c] : stars.back()) r.hexes.push_back(h);
  }
  std::sort(r.hexes.begin(), r.hexes.end());
  r.hexes.erase(std::unique(r.hexes.begin(), r.hexes.end()), r.hexes.end());
  for (HexId h : r.hexes) {
    std::array<int, 8> s;
    for (int c = 0; c < 8; ++c) {
      const int f = freeIndex(r, cx.vertex(h, c));
      s[size_t(c)] = f >= 0 ? f : -1 - cx.vertex(h, c);
    }
    r.src.push_back(s);
  }
  for (size_t i = 0; i < free.size(); ++i) {
    for (auto [h, c] : stars[i]) {
      const int k = int(std::lower_bound(r.hexes.begin(), r.hexes.end(), h) - r.hexes.begin());
      if (!degenerateByConstruction(cx, h) && std::find(r.around[i].begin(), r.around[i].end(), k) == r.around[i].end())
        r.around[i].push_back(k);
    }
    std::sort(r.around[i].begin(), r.around[i].end());
    collectNeighbours(cx, r, i, stars[i]);
  }
  return r;
}

struct Score {
  double min = 1, sum = 0;  // minimum over the hexes, sum over their corners
  bool betterThan(const Score& o) const { return min > o.min + 1e-12 || (min >= o.min && sum > o.sum + 1e-9); }
};

// The hexes around free vertex i with it placed at p.
Score evaluate(const Complex& cx, Region& r, size_t i, Vec3 p) {
  Score s;
  for (int k : r.around[i]) {
    std::array<Vec3, 8> pts;
    for (size_t c = 0; c < 8; ++c) {
      const int n = r.src[size_t(k)][c];
      pts[c] = n == int(i) ? p : at(cx, r, n);
    }
    s.min = std::min(s.min, scaledJacobian(pts, &s.sum));
    ++r.evaluations;
  }
  return s;
}

Vec3 average(const Complex& cx, const Region& r, size_t i) {
  Vec3 sum;
  for (int n : r.neighbours[i]) sum = sum + at(cx, r, n);
  return (1.0 / double(r.neighbours[i].size())) * sum;
}

// Gauss-Seidel Laplacian steps, each kept only when it improves the vertex's score.
void laplacian(const Complex& cx, Region& r, int iterations) {
  for (int it = 0; it < iterations; ++it)
    for (size_t i = 0; i < r.free.size(); ++i) {
      if (r.around[i].empty() || r.neighbours[i].empty()) continue;
      const Vec3 p = average(cx, r, i);
      if (evaluate(cx, r, i, p).betterThan(evaluate(cx, r, i, r.pos[i]))) r.pos[i] = p;
    }
}

// Compass search on each vertex's score: 14 directions (axes and diagonals), the step halved
// when none improves; sweeps until a sweep moves nothing.
bool compassVertex(const Complex& cx, Region& r, size_t i) {
  static constexpr double d = 0.5773502691896258;  // 1/sqrt(3), a literal so every platform has the same bits
  static constexpr double kDirs[14][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {d, d, d},
                                          {-d, d, d}, {d, -d, d}, {-d, -d, d}, {d, d, -d}, {-d, d, -d}, {d, -d, -d}, {-d, -d, -d}};
  if (r.around[i].empty() || r.scale[i] <= 0) return false;
  Score best = evaluate(cx, r, i, r.pos[i]);
  bool moved = false;
  int accepted = 0;
  for (double step = 0.25 * r.scale[i]; step > 0.01 * r.scale[i] && accepted < 8;) {
    bool found = false;
    for (const auto& dir : kDirs) {
      const Vec3 p = r.pos[i] + step * Vec3{dir[0], dir[1], dir[2]};
      const Score s = evaluate(cx, r, i, p);
      if (s.betterThan(best)) {
        best = s, r.pos[i] = p, found = moved = true;
        ++accepted;
        break;
      }
    }
    if (!found) step *= 0.5;
  }
  return moved;
}

}  // namespace

SmoothingStats smoothVertices(Complex& cx, std::vector<FreeVertex> free) {
  std::sort(free.begin(), free.end(), [](const FreeVertex& a, const FreeVertex& b) { return a.vertex < b.vertex; });
  Region r = buildRegion(cx, free);
  laplacian(cx, r, 8);
  for (int sweep = 0; sweep < 6; ++sweep) {
    bool any = false;
    for (size_t i = 0; i < r.free.size(); ++i) any = compassVertex(cx, r, i) || any;
    if (!any) break;
  }
  SmoothingStats st;
  st.evaluations = r.evaluations;
  for (size_t i = 0; i < r.free.size(); ++i) {
    const Vec3 old = cx.position(r.free[i]);
    if (old.x == r.pos[i].x && old.y == r.pos[i].y && old.z == r.pos[i].z) continue;
    cx.setPosition(r.free[i], r.pos[i]);
    st.moved.push_back(r.free[i]);
  }
  return st;
}

}  // namespace hexdual
