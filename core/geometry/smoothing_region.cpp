#include "geometry/smoothing_region.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/corner_energy.hpp"
#include "geometry/degenerate.hpp"
#include "geometry/pinned.hpp"

namespace hexdual {

namespace {

double length(Vec3 a) { return std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z); }

int32_t refOf(const SmoothingRegion& r, VertexId v) {
  auto it = std::lower_bound(r.free.begin(), r.free.end(), v);
  return it != r.free.end() && *it == v ? int32_t(it - r.free.begin()) : -1 - v;
}

// Mean length of the edges at free vertex i over its star (all hexes, counted or not).
double vertexScale(const Complex& cx, VertexId v, const std::vector<std::pair<HexId, int>>& star) {
  std::vector<VertexId> ids;
  for (auto [h, c] : star)
    for (int k : kCornerFrame[c]) ids.push_back(cx.vertex(h, k));
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  double sum = 0;
  for (VertexId n : ids) sum += length(cx.position(n) - cx.position(v));
  return ids.empty() ? 0 : sum / double(ids.size());
}

double meanEdgeLength(const SmoothingRegion& r) {
  double sum = 0;
  for (const auto& hc : r.corners)
    for (int e = 0; e < 12; ++e)
      sum += length(r.at(hc[size_t(tables::kEdgeCorners[e][1])]) - r.at(hc[size_t(tables::kEdgeCorners[e][0])]));
  return r.corners.empty() ? 1 : sum / double(12 * r.corners.size());
}

std::array<Vec3, 4> framePoints(const SmoothingRegion& r, const std::array<int32_t, 8>& hc, int j) {
  const int* f = kCornerFrame[j];
  return {r.at(hc[size_t(j)]), r.at(hc[size_t(f[0])]), r.at(hc[size_t(f[1])]), r.at(hc[size_t(f[2])])};
}

// Bit j: corner j has a free vertex among its four and is not stuck.
uint8_t countedCorners(const SmoothingRegion& r, const std::array<int32_t, 8>& hc) {
  uint8_t mask = 0;
  for (int j = 0; j < 8; ++j) {
    const int* f = kCornerFrame[j];
    const unsigned fixed = unsigned(hc[size_t(j)] < 0) | unsigned(hc[size_t(f[0])] < 0) << 1 |
                           unsigned(hc[size_t(f[1])] < 0) << 2 | unsigned(hc[size_t(f[2])] < 0) << 3;
    if (fixed != 15 && !cornerStuck(framePoints(r, hc, j), fixed)) mask = uint8_t(mask | 1 << j);
  }
  return mask;
}

double cornerDeterminant(const SmoothingRegion& r, const std::array<int32_t, 8>& hc, int j) {
  const std::array<Vec3, 4> p = framePoints(r, hc, j);
  return det3(p[1] - p[0], p[2] - p[0], p[3] - p[0]);
}

uint8_t nonPositiveCorners(const SmoothingRegion& r, const std::array<int32_t, 8>& hc) {
  uint8_t mask = 0;
  for (int j = 0; j < 8; ++j)
    if (!(cornerDeterminant(r, hc, j) > 0)) mask = uint8_t(mask | 1 << j);
  return mask;
}

// Marks the counted corners whose only free vertex is i when they cannot all be positive at once.
void markDoomed(SmoothingRegion& r, size_t i) {
  std::vector<OneFreeCorner> corners;
  std::vector<std::pair<int32_t, int>> where;
  for (auto [k, c] : r.incidence[i]) {
    const auto& hc = r.corners[size_t(k)];
    const int moved[4] = {c, kCornerFrame[c][0], kCornerFrame[c][1], kCornerFrame[c][2]};
    for (int j : moved) {
      const int* f = kCornerFrame[j];
      const int32_t refs[4] = {hc[size_t(j)], hc[size_t(f[0])], hc[size_t(f[1])], hc[size_t(f[2])]};
      const int nFree = (refs[0] >= 0) + (refs[1] >= 0) + (refs[2] >= 0) + (refs[3] >= 0);
      if (nFree != 1 || !(r.counted[size_t(k)] >> j & 1)) continue;
      corners.push_back({framePoints(r, hc, j), int(std::find(refs, refs + 4, int32_t(i)) - refs)});
      where.push_back({k, j});
    }
  }
  if (oneVertexFeasible(corners)) return;
  for (auto [k, j] : where) r.doomed[size_t(k)] = uint8_t(r.doomed[size_t(k)] | 1 << j);
}

}  // namespace

SmoothingRegion buildSmoothingRegion(const Complex& cx, const std::vector<FreeVertex>& free,
                                     const std::vector<HexId>& near) {
  SmoothingRegion r;
  r.cx = &cx;
  for (const FreeVertex& f : free) r.free.push_back(f.vertex), r.pos.push_back(cx.position(f.vertex));
  std::vector<std::vector<std::pair<HexId, int>>> stars;
  std::vector<HexId> around;
  for (const FreeVertex& f : free) {
    stars.push_back(cx.cornersOfVertex(f.hex, f.corner));
    r.scale.push_back(vertexScale(cx, f.vertex, stars.back()));
    for (auto [h, c] : stars.back()) around.push_back(h);
  }
  std::sort(around.begin(), around.end());
  around.erase(std::unique(around.begin(), around.end()), around.end());
  for (HexId h : around) {
    if (degenerateByConstruction(cx, h)) continue;
    std::array<int32_t, 8> hc;
    for (int c = 0; c < 8; ++c) hc[size_t(c)] = refOf(r, cx.vertex(h, c));
    r.hexIds.push_back(h);
    r.corners.push_back(hc);
    r.counted.push_back(countedCorners(r, hc));
    r.doomed.push_back(0);
    r.frozen.push_back(
        std::binary_search(near.begin(), near.end(), h) ? 0 : uint8_t(nonPositiveCorners(r, hc) & r.counted.back()));
    r.floors.emplace_back();
    for (int j = 0; j < 8; ++j) r.floors.back()[size_t(j)] = cornerDeterminant(r, hc, j);
  }
  r.incidence.resize(free.size());
  for (size_t i = 0; i < free.size(); ++i)
    for (auto [h, c] : stars[i]) {
      auto it = std::lower_bound(r.hexIds.begin(), r.hexIds.end(), h);
      if (it != r.hexIds.end() && *it == h) r.incidence[i].push_back({int32_t(it - r.hexIds.begin()), int8_t(c)});
    }
  for (auto& inc : r.incidence) std::sort(inc.begin(), inc.end());
  for (size_t i = 0; i < r.free.size(); ++i) markDoomed(r, i);
  const double l = meanEdgeLength(r);
  r.volumeScale = l * l * l;
  return r;
}

double vertexEnergy(SmoothingRegion& r, size_t i, Vec3 p, double delta2, Vec3* grad) {
  double sum = 0;
  Vec3 g;
  for (auto [k, c] : r.incidence[i]) {
    const auto& hc = r.corners[size_t(k)];
    const uint8_t counted = r.counted[size_t(k)], doomed = r.doomed[size_t(k)];
    // The corner at i (its frame's vertex 0), then the three whose frames hold i.
    for (int m = 0; m < 4; ++m) {
      const int j = m == 0 ? c : kCornerFrame[c][m - 1];
      if (!(counted >> j & 1)) continue;
      const int* f = kCornerFrame[j];
      std::array<Vec3, 4> pts = framePoints(r, hc, j);
      const int at = m == 0 ? 0 : 1 + int(std::find(f, f + 3, c) - f);
      pts[size_t(at)] = p;
      if (r.frozen[size_t(k)] >> j & 1) {
        if (det3(pts[1] - pts[0], pts[2] - pts[0], pts[3] - pts[0]) < r.floors[size_t(k)][size_t(j)])
          return std::numeric_limits<double>::infinity();
        continue;
      }
      Vec3 cg;
      const double e =
          cornerEnergy(pts, doomed >> j & 1 ? std::max(delta2, r.doomedDelta2) : delta2, at, grad ? &cg : nullptr);
      ++r.evaluations;
      if (std::isinf(e)) return e;
      sum += e;
      if (grad) g = g + cg;
    }
  }
  if (grad) *grad = g;
  return sum;
}

bool keepsFloors(const SmoothingRegion& r, size_t i, Vec3 p) {
  for (auto [k, c] : r.incidence[i]) {
    const uint8_t frozen = r.frozen[size_t(k)];
    if (!frozen) continue;
    for (int m = 0; m < 4; ++m) {
      const int j = m == 0 ? c : kCornerFrame[c][m - 1];
      if (!(frozen >> j & 1)) continue;
      std::array<Vec3, 4> pts = framePoints(r, r.corners[size_t(k)], j);
      const int* f = kCornerFrame[j];
      pts[size_t(m == 0 ? 0 : 1 + int(std::find(f, f + 3, c) - f))] = p;
      if (det3(pts[1] - pts[0], pts[2] - pts[0], pts[3] - pts[0]) < r.floors[size_t(k)][size_t(j)]) return false;
    }
  }
  return true;
}

double minCornerDeterminant(const SmoothingRegion& r) {
  double m = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < r.corners.size(); ++k)
    for (int j = 0; j < 8; ++j)
      if ((r.counted[k] & ~r.doomed[k] & ~r.frozen[k]) >> j & 1) m = std::min(m, cornerDeterminant(r, r.corners[k], j));
  return m;
}

std::vector<AffineFunction> cornerFunctions(SmoothingRegion& r, size_t i) {
  std::vector<AffineFunction> out;
  for (auto [k, c] : r.incidence[i]) {
    const auto& hc = r.corners[size_t(k)];
    const int moved[4] = {c, kCornerFrame[c][0], kCornerFrame[c][1], kCornerFrame[c][2]};
    for (int j : moved) {
      if (!((r.counted[size_t(k)] & ~r.doomed[size_t(k)] & ~r.frozen[size_t(k)]) >> j & 1)) continue;
      const std::array<Vec3, 4> p = framePoints(r, hc, j);
      const int* f = kCornerFrame[j];
      const int at = j == c ? 0 : 1 + int(std::find(f, f + 3, c) - f);
      const double w = length(p[1] - p[0]) * length(p[2] - p[0]) * length(p[3] - p[0]);
      AffineFunction a = cornerDeterminantIn(p, at);
      ++r.evaluations;
      if (w > 0) a.g = (1 / w) * a.g, a.h /= w;
      out.push_back(a);
    }
  }
  return out;
}

double worstScaledCorner(const SmoothingRegion& r) {
  double m = 1;
  for (size_t k = 0; k < r.corners.size(); ++k)
    for (int j = 0; j < 8; ++j) {
      if (!((r.counted[k] & ~r.doomed[k] & ~r.frozen[k]) >> j & 1)) continue;
      const std::array<Vec3, 4> p = framePoints(r, r.corners[k], j);
      const Vec3 a = p[1] - p[0], b = p[2] - p[0], c = p[3] - p[0];
      const double len = length(a) * length(b) * length(c);
      m = std::min(m, len > 0 ? det3(a, b, c) / len : 0.0);
    }
  return m;
}

int invertedHexes(const SmoothingRegion& r) {
  int n = 0;
  for (const auto& hc : r.corners) {
    double m = std::numeric_limits<double>::infinity();
    for (int j = 0; j < 8; ++j) m = std::min(m, cornerDeterminant(r, hc, j));
    n += m <= 0;
  }
  return n;
}

}  // namespace hexdual
