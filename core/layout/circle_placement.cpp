#include "layout/circle_placement.hpp"

#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>

#include "layout/boundary_loops.hpp"

namespace hexdual {
using namespace tables;

namespace {

const double kPi = std::acos(-1.0);
Point2 mid2(Point2 a, Point2 b) { return {0.5 * (a.x + b.x), 0.5 * (a.y + b.y)}; }

// Mids and centres of a non-degenerate surface: averages of their corners.
void averageRefinement(const MidSurface& s, Placement& pl) {
  for (int m = 0; m < s.nMid; ++m)
    if (!pl.fixed[size_t(s.nCorner + m)])
      pl.pos[size_t(s.nCorner + m)] = mid2(pl.pos[size_t(s.midEnds[size_t(m)].first)], pl.pos[size_t(s.midEnds[size_t(m)].second)]);
  for (size_t i = 0; i < s.quad.size(); ++i) {
    Point2 c;
    for (int v : s.quad[i]) c = {c.x + 0.25 * pl.pos[size_t(v)].x, c.y + 0.25 * pl.pos[size_t(v)].y};
    pl.pos[size_t(s.centre(int(i)))] = c;
  }
}

void onCircle(const std::vector<int>& loop, double r, double phase, double dir, Placement& pl) {
  for (size_t k = 0; k < loop.size(); ++k) {
    double t = phase + dir * 2 * kPi * double(k) / double(loop.size());
    pl.pos[size_t(loop[k])] = {r * std::cos(t), r * std::sin(t)};
    pl.fixed[size_t(loop[k])] = true;
  }
}

// Annulus: angles from the planar harmonic map; radii from a scalar harmonic function (1 on the
// outer loop, 0 on the inner), so every vertex lies between the two loops (maximum principle): on
// coarse rings the planar map alone pulls rows inside the inner circle.
bool placeAnnulus(const MidSurface& s, std::vector<std::vector<int>> loops, Placement& pl) {
  const int n = s.total();
  std::sort(loops.begin(), loops.end(), [](const auto& a, const auto& b) { return a.size() > b.size(); });
  onCircle(loops[0], 1.0, 0, 1, pl);
  // Align the inner loop with the outer one along a shortest path of mid-surface edges.
  std::vector<std::vector<int>> adj(static_cast<size_t>(n));
  for (const auto& q : s.quad)
    for (int k = 0; k < 4; ++k) {
      adj[size_t(q[size_t(k)])].push_back(q[size_t((k + 1) & 3)]);
      adj[size_t(q[size_t((k + 1) & 3)])].push_back(q[size_t(k)]);
    }
  std::vector<bool> onInner(size_t(n), false);
  for (int v : loops[1]) onInner[size_t(v)] = true;
  std::vector<int> dist(size_t(n), -1);
  std::vector<int> queue{loops[0][0]};
  dist[size_t(loops[0][0])] = 0;
  int hit = -1;
  for (size_t i = 0; i < queue.size() && hit < 0; ++i)
    for (int w : adj[size_t(queue[i])]) {
      if (dist[size_t(w)] >= 0) continue;
      dist[size_t(w)] = dist[size_t(queue[i])] + 1;
      queue.push_back(w);
      if (onInner[size_t(w)]) {
        hit = w;
        break;
      }
    }
  auto it = std::find(loops[1].begin(), loops[1].end(), hit);
  std::rotate(loops[1].begin(), it == loops[1].end() ? loops[1].begin() : it, loops[1].end());
  onCircle(loops[1], 0.45, 0, -1, pl);  // the inner loop runs the other way
  fixBoundaryMids(s, pl);
  pl.method = "annulus";
  Placement rho = pl;
  for (int v : loops[0]) rho.pos[size_t(v)] = {1, 0};
  for (int v : loops[1]) rho.pos[size_t(v)] = {0, 0};
  for (int m = 0; m < s.nMid; ++m)
    if (rho.fixed[size_t(s.nCorner + m)])
      rho.pos[size_t(s.nCorner + m)] = {0.5 * (rho.pos[size_t(s.midEnds[size_t(m)].first)].x + rho.pos[size_t(s.midEnds[size_t(m)].second)].x), 0};
  if (!harmonicSolve(s, pl) || !harmonicSolve(s, rho)) return false;
  // Radius along each ray: between the inner and the outer loop polygons.
  auto polygonRadius = [&](const std::vector<int>& loop, double t) {
    double dx = std::cos(t), dy = std::sin(t), best = 1.0;
    for (size_t k = 0; k < loop.size(); ++k) {
      Point2 a = pl.pos[size_t(loop[k])], b = pl.pos[size_t(loop[(k + 1) % loop.size()])];
      double ex = b.x - a.x, ey = b.y - a.y, den = dx * ey - dy * ex;
      if (std::fabs(den) < 1e-15) continue;
      double r = (a.x * ey - a.y * ex) / den, u = (a.x * dy - a.y * dx) / den;
      if (r > 0 && u >= -1e-12 && u <= 1 + 1e-12) best = r;
    }
    return best;
  };
  for (int v = 0; v < n; ++v) {
    if (pl.fixed[size_t(v)]) continue;
    double t = std::atan2(pl.pos[size_t(v)].y, pl.pos[size_t(v)].x);
    double rin = polygonRadius(loops[1], t), rout = polygonRadius(loops[0], t);
    double r = rin + (rout - rin) * rho.pos[size_t(v)].x;
    pl.pos[size_t(v)] = {r * std::cos(t), r * std::sin(t)};
  }
  return true;
}

}  // namespace

// Fixes the mid vertices of boundary sides (and of the opened face) halfway between their corners.
void fixBoundaryMids(const MidSurface& s, Placement& pl) {
  for (int m = 0; m < s.nMid; ++m) {
    bool onOpened = false;
    if (pl.opened >= 0)
      for (int f = 0; f < 6; ++f) onOpened = onOpened || s.mid[size_t(pl.opened)][size_t(f)] == s.nCorner + m;
    if (!s.midBoundary[size_t(m)] && !onOpened) continue;
    auto [a, b] = s.midEnds[size_t(m)];
    pl.pos[size_t(s.nCorner + m)] = mid2(pl.pos[size_t(a)], pl.pos[size_t(b)]);
    pl.fixed[size_t(s.nCorner + m)] = true;
  }
}

int64_t eulerCharacteristic(const MidSurface& s) {
  int64_t interiorSides = 0, boundarySides = 0;
  for (size_t i = 0; i < s.slots.size(); ++i)
    for (int f = 0; f < 6; ++f)
      if (axisOfFace(f) != s.slots[i].axis) (s.joined(int(i), f) >= 0 ? interiorSides : boundarySides)++;
  return int64_t(s.nCorner) - (interiorSides / 2 + boundarySides) + int64_t(s.slots.size());
}

bool harmonicSolve(const MidSurface& s, Placement& pl) {
  // Degenerate surfaces are solved on the refined mesh (corners, mids, centres) so that coincident
  // quads come apart; others on the corners alone, 4x fewer unknowns.
  const bool refined = s.degenerate;
  const int n = refined ? s.total() : s.nCorner;
  std::vector<int> unk(size_t(n), -1);
  int m = 0;
  for (int v = 0; v < n; ++v)
    if (!pl.fixed[size_t(v)]) unk[size_t(v)] = m++;
  if (m == 0) {
    if (!refined) averageRefinement(s, pl);
    return true;
  }
  std::vector<std::pair<int, int>> edges;  // corner - mid, mid - centre (refined) or quad edges
  auto add = [&](int a, int b) { edges.push_back({std::min(a, b), std::max(a, b)}); };
  if (!refined)
    for (const auto& q : s.quad)
      for (int k = 0; k < 4; ++k) add(q[size_t(k)], q[size_t((k + 1) & 3)]);
  for (int k = 0; refined && k < s.nMid; ++k) {
    add(s.midEnds[size_t(k)].first, s.nCorner + k);
    add(s.midEnds[size_t(k)].second, s.nCorner + k);
  }
  for (size_t i = 0; refined && i < s.slots.size(); ++i)
    for (int f = 0; f < 6; ++f)
      if (s.mid[i][size_t(f)] >= 0) add(s.mid[i][size_t(f)], s.centre(int(i)));
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::vector<Eigen::Triplet<double>> trip;
  Eigen::VectorXd bx = Eigen::VectorXd::Zero(m), by = Eigen::VectorXd::Zero(m);
  std::vector<double> diag(size_t(m), 0);
  for (auto [a, b] : edges)
    for (auto [p, q] : {std::pair{a, b}, std::pair{b, a}}) {
      if (unk[size_t(p)] < 0) continue;
      diag[size_t(unk[size_t(p)])] += 1;
      if (unk[size_t(q)] >= 0) trip.push_back({unk[size_t(p)], unk[size_t(q)], -1});
      else {
        bx[unk[size_t(p)]] += pl.pos[size_t(q)].x;
        by[unk[size_t(p)]] += pl.pos[size_t(q)].y;
      }
    }
  for (int i = 0; i < m; ++i) trip.push_back({i, i, diag[size_t(i)]});
  Eigen::SparseMatrix<double> L(m, m);
  L.setFromTriplets(trip.begin(), trip.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(L);
  if (solver.info() != Eigen::Success) return false;
  Eigen::VectorXd x = solver.solve(bx), y = solver.solve(by);
  for (int v = 0; v < n; ++v)
    if (unk[size_t(v)] >= 0) pl.pos[size_t(v)] = {x[unk[size_t(v)]], y[unk[size_t(v)]]};
  if (!refined) averageRefinement(s, pl);
  return true;
}

bool placeSurface(const MidSurface& s, Placement& pl) {
  const int n = s.total();
  pl.pos.assign(size_t(n), {});
  pl.fixed.assign(size_t(n), false);
  if (!s.orientable) return false;
  std::vector<BoundaryEdge> edges = boundaryEdges(s);
  std::vector<std::vector<int>> loopEdges;
  if (!chainLoops(edges, loopEdges)) return false;
  std::vector<std::vector<int>> loops;
  for (const auto& l : loopEdges) loops.push_back(loopCorners(edges, l));
  const int64_t chi = eulerCharacteristic(s);
  for (const auto& l : loops)
    if (l.size() < 3) return false;  // a digon boundary cannot be drawn on a circle
  if (loops.size() == 1 && chi == 1) {
    onCircle(loops[0], 1.0, 0, 1, pl);
    fixBoundaryMids(s, pl);
    pl.method = "disk";
  } else if (loops.size() == 2 && chi == 0) {
    return placeAnnulus(s, loops, pl);
  } else if (loops.empty() && chi == 2) {
    pl.opened = 0;
    std::vector<BoundaryEdge> e2 = boundaryEdges(s, 0);
    std::vector<std::vector<int>> l2;
    if (!chainLoops(e2, l2) || l2.size() != 1) return false;
    onCircle(loopCorners(e2, l2[0]), 1.0, kPi / 4, 1, pl);
    fixBoundaryMids(s, pl);
    pl.method = "sphere";
  } else {
    return false;
  }
  return harmonicSolve(s, pl);
}

}  // namespace hexdual
