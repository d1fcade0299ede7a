#include "layout/triangulation.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_set>

namespace hexdual {
using namespace tables;

namespace {

// The face of a slot with axis a on side k of its mid-quad cycle (between cycle corners k, k+1).
int sideFace(int axis, int k) {
  for (int f = 0; f < 6; ++f) {
    if (axisOfFace(f) == axis) continue;
    auto e = edgesOnFace(f, axis);
    int p = cyclePos(axis, e[0]), q = cyclePos(axis, e[1]);
    if ((p == k && q == ((k + 1) & 3)) || (q == k && p == ((k + 1) & 3))) return f;
  }
  return -1;
}

bool repeatedCorner(const std::array<int, 4>& q) {
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b)
      if (q[size_t(a)] == q[size_t(b)]) return true;
  return false;
}

uint64_t pairKey(int a, int b) { return uint64_t(uint32_t(std::min(a, b))) << 32 | uint32_t(std::max(a, b)); }

// The boundary loops of s without slot skip, as edge lists; false when they do not chain.
bool boundaryLoops(const MidSurface& s, int skip, std::vector<BoundaryEdge>& edges,
                   std::vector<std::vector<int>>& loops) {
  edges = boundaryEdges(s, skip);
  return chainLoops(edges, loops);
}

}  // namespace

std::string fanObstacle(const MidSurface& s, int skipSlot, bool withMids) {
  for (size_t i = 0; i < s.slots.size(); ++i)
    if (int(i) != skipSlot && repeatedCorner(s.quad[i]))
      return "the mid-quad of hex " + std::to_string(s.slots[i].hex) + " has a repeated corner";
  std::vector<BoundaryEdge> edges;
  std::vector<std::vector<int>> loops;
  if (!boundaryLoops(s, skipSlot, edges, loops)) return "the boundary does not chain into loops";
  if (withMids) return "";
  for (const auto& l : loops)
    if (l.size() < 3) return "a boundary loop of " + std::to_string(l.size()) + " corners";
  std::unordered_set<uint64_t> ends;
  std::vector<bool> seen(size_t(s.nMid), false);
  for (size_t i = 0; i < s.slots.size(); ++i) {
    if (int(i) == skipSlot) continue;
    for (int f = 0; f < 6; ++f) {
      int m = s.mid[i][size_t(f)] - s.nCorner;
      if (m < 0 || seen[size_t(m)]) continue;
      seen[size_t(m)] = true;
      auto [a, b] = s.midEnds[size_t(m)];
      if (!ends.insert(pairKey(a, b)).second) return "two mid-edges join the same two corners";
    }
  }
  return "";
}

namespace {

// The ideal shape of the fan triangle (c, u, v) of a quad side: the angles at the corners u and v
// are their share of the angle round them (2 pi over the quads there inside, pi on the boundary),
// clamped, so that a corner with two quads (a doublet) is drawn flat instead of as a cone; the
// angle at the centre takes the rest. Area 1/4, counter-clockwise, c at the origin.
std::array<Point2, 3> fanReference(double au, double av) {
  const double pi = std::acos(-1.0), lo = 0.25, hi = 0.5 * pi;
  if (au == 0.25 * pi && av == 0.25 * pi) return {Point2{0, 0}, Point2{-0.5, -0.5}, Point2{0.5, -0.5}};  // a square's
  au = std::clamp(au, lo, hi);
  av = std::clamp(av, lo, hi);
  if (au + av > pi - 0.5) {
    double f = (pi - 0.5) / (au + av);
    au *= f;
    av *= f;
  }
  double g = pi - au - av, cu = std::sin(av), cv = std::sin(au);  // sides opposite v and u
  double k = std::sqrt(0.25 / (0.5 * cu * cv * std::sin(g)));
  double tu = -0.5 * pi - 0.5 * g, tv = -0.5 * pi + 0.5 * g;
  return {Point2{0, 0}, Point2{k * cu * std::cos(tu), k * cu * std::sin(tu)},
          Point2{k * cv * std::cos(tv), k * cv * std::sin(tv)}};
}

// Per corner: the angle each of its quads should take there. Round an inner corner, 2 pi; on the
// outer loop (drawn as a convex polygon of n corners), pi - 2 pi / n; on a hole's loop (the
// outside of such a polygon), pi + 2 pi / n; shared by the corner's quads.
std::vector<double> cornerShares(const MidSurface& s, int skipSlot, const Triangulation& t) {
  const double pi = std::acos(-1.0);
  std::vector<int> quads(size_t(s.nCorner), 0);
  std::vector<double> around(size_t(s.nCorner), 2 * pi);
  for (size_t i = 0; i < s.slots.size(); ++i)
    if (int(i) != skipSlot)
      for (int v : s.quad[i]) ++quads[size_t(v)];
  for (size_t k = 0; k < t.loopEdges.size(); ++k) {
    const double n = double(t.loopEdges[k].size());
    for (int e : t.loopEdges[k]) around[size_t(t.edges[size_t(e)].from)] = k == t.outer ? pi - 2 * pi / n : pi + 2 * pi / n;
  }
  std::vector<double> share(size_t(s.nCorner), 0.5 * pi);
  for (int v = 0; v < s.nCorner; ++v)
    if (quads[size_t(v)] > 0 && !(quads[size_t(v)] == 4 && around[size_t(v)] == 2 * pi))  // a regular corner: exactly pi / 2
      share[size_t(v)] = around[size_t(v)] / quads[size_t(v)];
  return share;
}

}  // namespace

Triangulation triangulate(const MidSurface& s, int skipSlot) {
  Triangulation t;
  t.withMids = !fanObstacle(s, skipSlot, false).empty();
  if (t.withMids) {
    std::string why = fanObstacle(s, skipSlot, true);
    if (!why.empty()) throw Error("sheet diagram: the mid-surface cannot be triangulated: " + why);
  }
  if (!boundaryLoops(s, skipSlot, t.edges, t.loopEdges))
    throw Error("sheet diagram: the boundary does not chain into loops");
  for (size_t k = 1; k < t.loopEdges.size(); ++k)  // the longest loop goes outside
    if (t.loopEdges[k].size() > t.loopEdges[t.outer].size()) t.outer = k;
  const std::vector<double> share = cornerShares(s, skipSlot, t);
  t.vertices = t.firstVirtual = s.total();
  t.centre.assign(size_t(t.vertices), false);
  for (size_t i = 0; i < s.slots.size(); ++i) {
    if (int(i) == skipSlot) continue;
    const int a = s.slots[i].axis, c = s.centre(int(i));
    const auto& q = s.quad[i];
    t.centre[size_t(c)] = true;
    // The quad's corner angles, scaled to sum to 2 pi (a quad with two doublet corners would ask
    // for 3 pi: it is drawn as a quadrilateral that gives up some of the flatness at each).
    double sum = 0;
    for (int v : q) sum += share[size_t(v)];
    const double fit = 2 * std::acos(-1.0) / sum;
    for (int k = 0; k < 4; ++k) {
      int u = q[size_t(k)], v = q[size_t((k + 1) & 3)];
      if (s.sign[i] < 0) std::swap(u, v);
      // Each corner of a quad is in two of its fan triangles: half its share in each.
      std::array<Point2, 3> r = fanReference(0.5 * fit * share[size_t(u)], 0.5 * fit * share[size_t(v)]);
      if (!t.withMids) {
        t.tris.push_back({c, u, v});
        t.ref.push_back(r);
        continue;
      }
      int m = s.mid[i][size_t(sideFace(a, k))];
      Point2 pm{0.5 * (r[1].x + r[2].x), 0.5 * (r[1].y + r[2].y)};
      t.tris.push_back({c, u, m});
      t.tris.push_back({c, m, v});
      t.ref.push_back({r[0], r[1], pm});
      t.ref.push_back({r[0], pm, r[2]});
    }
  }
  for (const auto& l : t.loopEdges) {
    std::vector<int> loop;
    for (int k : l) {
      const BoundaryEdge& e = t.edges[size_t(k)];
      loop.push_back(e.from);
      if (t.withMids) loop.push_back(s.mid[size_t(e.slot)][size_t(e.face)]);
    }
    t.loops.push_back(std::move(loop));
  }
  return t;
}

void fillHole(Triangulation& t, size_t k, int rings) {
  std::vector<int> ring = t.loops[k];
  const size_t n = ring.size();
  // Ideal shape: concentric regular n-gons with the loop's edge length (a quad side, or half of
  // one when the fan has mid vertices), vertex j at angle -2 pi j / n so the triangles run
  // counter-clockwise.
  const double pi = std::acos(-1.0), edge = t.withMids ? 0.5 : 1.0, r0 = double(n) * edge / (2 * pi);
  auto at = [&](int r, size_t j) {
    double rad = r0 * (1 - double(r) / double(rings + 1)), a = -2 * pi * double(j) / double(n);
    return Point2{rad * std::cos(a), rad * std::sin(a)};
  };
  // The loop's edges run v_j -> v_j+1 in the surface's triangles: the filling runs them backwards.
  for (int r = 0; r < rings; ++r) {
    std::vector<int> next(n);
    for (size_t j = 0; j < n; ++j) next[j] = t.vertices++;
    for (size_t j = 0; j < n; ++j) {
      size_t j1 = (j + 1) % n;
      t.tris.push_back({ring[j1], ring[j], next[j]});
      t.tris.push_back({ring[j1], next[j], next[j1]});
      t.ref.push_back({at(r, j1), at(r, j), at(r + 1, j)});
      t.ref.push_back({at(r, j1), at(r + 1, j), at(r + 1, j1)});
    }
    ring = std::move(next);
  }
  int z = t.vertices++;
  for (size_t j = 0; j < n; ++j) {
    t.tris.push_back({ring[(j + 1) % n], ring[j], z});
    t.ref.push_back({at(rings, (j + 1) % n), at(rings, j), Point2{0, 0}});
  }
  t.centre.resize(size_t(t.vertices), false);
}

}  // namespace hexdual
