#include "layout/sheet_diagram.hpp"

#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <unordered_map>

#include "io/json.hpp"

namespace hexdual {
using namespace tables;

namespace {

const double kPi = std::acos(-1.0);
Point2 mid2(Point2 a, Point2 b) { return {0.5 * (a.x + b.x), 0.5 * (a.y + b.y)}; }

// The a-edges of slot (h, a) in the cycle of its mid-quad: (u,v) = 00, 10, 11, 01.
std::array<int, 4> midCycle(int a) { return {4 * a + 0, 4 * a + 1, 4 * a + 3, 4 * a + 2}; }
int cyclePos(int a, int edge) {
  auto c = midCycle(a);
  for (int i = 0; i < 4; ++i)
    if (c[size_t(i)] == edge) return i;
  return -1;
}
// The two a-edges on face f (parallel to a), in the face's order.
std::array<int, 2> edgesOnFace(int f, int a) {
  std::array<int, 2> r{-1, -1};
  int n = 0;
  for (int p = 0; p < 4; ++p) {
    int e = kFaceEdges[size_t(f)][size_t(p)];
    if (axisOfEdge(e) == a) r[size_t(n++)] = e;
  }
  return r;
}

struct Surface {
  std::vector<Slot> slots;
  std::map<std::pair<HexId, int>, int> index;  // slot -> face
  std::vector<EdgeRef> verts;                  // canonical primal edges
  std::vector<std::array<int, 4>> quad;        // vertex indices in mid-cycle order
  std::vector<int8_t> sign;                    // orientation per face (+1 keeps the cycle)
  bool orientable = true;
  // Refinement: one vertex per mid-edge and one per quad centre, after the corners, so that
  // doubled mid-edges and quads on the same corners (degenerate hexes) are drawn apart.
  std::vector<std::array<int, 6>> mid;       // per slot, per face parallel to its axis: mid vertex
  std::vector<std::pair<int, int>> midEnds;  // corners of each mid vertex
  std::vector<bool> midBoundary;             // on the boundary of the set (no neighbour inside)
  int nCorner = 0, nMid = 0;
  bool degenerate = false;  // two quads on the same corners, or two mid-edges on the same ends
  int centre(int i) const { return nCorner + nMid + i; }
  int total() const { return nCorner + nMid + int(slots.size()); }
  // Neighbour face across face f of slot i's hex (or -1 when outside the set or on the boundary).
  int neighbour(const Complex& cx, int i, int f) const {
    Gluing g = cx.gluing(slots[size_t(i)].hex, f);
    if (g.boundary()) return -1;
    int a2 = mapAxisAcross(cx, slots[size_t(i)].hex, f, slots[size_t(i)].axis);
    auto it = index.find({g.hex, a2});
    return it == index.end() ? -1 : it->second;
  }
};

Surface buildSurface(const Complex& cx, std::vector<Slot> slots) {
  Surface s;
  std::sort(slots.begin(), slots.end());
  s.slots = slots;
  for (size_t i = 0; i < slots.size(); ++i) s.index[{slots[i].hex, slots[i].axis}] = int(i);
  std::map<std::pair<HexId, int>, int> vid;
  for (Slot sl : slots) {
    std::array<int, 4> q;
    auto c = midCycle(sl.axis);
    for (int k = 0; k < 4; ++k) {
      EdgeRef e = cx.canonical(EdgeRef{sl.hex, c[size_t(k)]});
      auto [it, ins] = vid.try_emplace({e.hex, e.edge}, int(s.verts.size()));
      if (ins) s.verts.push_back(e);
      q[size_t(k)] = it->second;
    }
    s.quad.push_back(q);
  }
  s.nCorner = int(s.verts.size());
  s.mid.assign(slots.size(), {-1, -1, -1, -1, -1, -1});
  for (size_t i = 0; i < slots.size(); ++i)
    for (int f = 0; f < 6; ++f) {
      if (axisOfFace(f) == slots[i].axis || s.mid[i][size_t(f)] >= 0) continue;
      int id = int(s.midEnds.size());
      auto e = edgesOnFace(f, slots[i].axis);
      s.midEnds.push_back({s.quad[i][size_t(cyclePos(slots[i].axis, e[0]))], s.quad[i][size_t(cyclePos(slots[i].axis, e[1]))]});
      s.mid[i][size_t(f)] = s.nCorner + id;
      int j = s.neighbour(cx, int(i), f);
      s.midBoundary.push_back(j < 0);
      if (j >= 0) s.mid[size_t(j)][size_t(cx.gluing(slots[i].hex, f).face)] = s.nCorner + id;
    }
  s.nMid = int(s.midEnds.size());
  {
    std::set<std::array<int, 4>> quadSets;
    for (auto q : s.quad) {
      std::sort(q.begin(), q.end());
      if (!quadSets.insert(q).second) s.degenerate = true;
    }
    std::set<std::pair<int, int>> ends;
    for (auto [a, b] : s.midEnds)
      if (!ends.insert({std::min(a, b), std::max(a, b)}).second) s.degenerate = true;
  }
  // Orientation by propagation: neighbouring quads run over their shared edge in opposite directions.
  s.sign.assign(slots.size(), 0);
  for (size_t start = 0; start < slots.size(); ++start) {
    if (s.sign[start]) continue;
    s.sign[start] = 1;
    std::vector<int> stack{int(start)};
    while (!stack.empty()) {
      int i = stack.back();
      stack.pop_back();
      for (int f = 0; f < 6; ++f) {
        if (axisOfFace(f) == slots[size_t(i)].axis) continue;
        int j = s.neighbour(cx, i, f);
        if (j < 0) continue;
        auto e = edgesOnFace(f, slots[size_t(i)].axis);
        int u = s.quad[size_t(i)][size_t(cyclePos(slots[size_t(i)].axis, e[0]))];
        int v = s.quad[size_t(i)][size_t(cyclePos(slots[size_t(i)].axis, e[1]))];
        auto dirIn = [&](int q, int x, int y) {  // +1 when quad q's cycle runs x -> y
          for (int k = 0; k < 4; ++k)
            if (s.quad[size_t(q)][size_t(k)] == x) return s.quad[size_t(q)][size_t((k + 1) & 3)] == y ? 1 : -1;
          return 0;
        };
        int want = -s.sign[size_t(i)] * dirIn(i, u, v) * dirIn(j, u, v);
        if (!s.sign[size_t(j)]) {
          s.sign[size_t(j)] = int8_t(want);
          stack.push_back(j);
        } else if (s.sign[size_t(j)] != want) {
          s.orientable = false;
        }
      }
    }
  }
  return s;
}

// Boundary mid-edges as directed pairs (u -> v) following each quad's orientation.
std::vector<std::pair<int, int>> boundaryEdges(const Complex& cx, const Surface& s, int skipFace) {
  std::vector<std::pair<int, int>> out;
  for (size_t i = 0; i < s.slots.size(); ++i) {
    if (int(i) == skipFace) continue;
    for (int f = 0; f < 6; ++f) {
      if (axisOfFace(f) == s.slots[i].axis) continue;
      int j = s.neighbour(cx, int(i), f);
      if (j >= 0 && j != skipFace) continue;
      auto e = edgesOnFace(f, s.slots[i].axis);
      int u = s.quad[i][size_t(cyclePos(s.slots[i].axis, e[0]))], v = s.quad[i][size_t(cyclePos(s.slots[i].axis, e[1]))];
      bool forward = false;
      for (int k = 0; k < 4; ++k)
        if (s.quad[i][size_t(k)] == u) forward = s.quad[i][size_t((k + 1) & 3)] == v;
      if ((s.sign[i] > 0) != forward) std::swap(u, v);
      out.push_back({u, v});
    }
  }
  return out;
}

// Loops of directed boundary edges; empty when a vertex has two outgoing edges (a pinch).
bool chainLoops(std::vector<std::pair<int, int>> edges, std::vector<std::vector<int>>& loops) {
  std::map<int, int> next;
  for (auto [u, v] : edges)
    if (!next.emplace(u, v).second) return false;
  std::map<int, bool> used;
  for (auto [u, v] : edges) {
    if (used[u]) continue;
    std::vector<int> loop;
    int x = u;
    while (!used[x]) {
      used[x] = true;
      loop.push_back(x);
      auto it = next.find(x);
      if (it == next.end()) return false;
      x = it->second;
    }
    if (x != u) return false;
    loops.push_back(loop);
  }
  return true;
}

struct Placement {
  std::vector<Point2> pos;
  std::vector<bool> fixed;
  int opened = -1;  // opened face (sphere)
  std::string method;
};

// Mids and centres of a non-degenerate surface: averages of their corners.
void averageRefinement(const Surface& s, Placement& pl) {
  for (int m = 0; m < s.nMid; ++m)
    if (!pl.fixed[size_t(s.nCorner + m)])
      pl.pos[size_t(s.nCorner + m)] = mid2(pl.pos[size_t(s.midEnds[size_t(m)].first)], pl.pos[size_t(s.midEnds[size_t(m)].second)]);
  for (size_t i = 0; i < s.quad.size(); ++i) {
    Point2 c;
    for (int v : s.quad[i]) c = {c.x + 0.25 * pl.pos[size_t(v)].x, c.y + 0.25 * pl.pos[size_t(v)].y};
    pl.pos[size_t(s.centre(int(i)))] = c;
  }
}

bool harmonic(const Surface& s, Placement& pl) {
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
  std::set<std::pair<int, int>> edges;  // corner - mid, mid - centre (refined) or quad edges
  if (!refined)
    for (const auto& q : s.quad)
      for (int k = 0; k < 4; ++k) edges.insert({std::min(q[size_t(k)], q[size_t((k + 1) & 3)]), std::max(q[size_t(k)], q[size_t((k + 1) & 3)])});
  for (int m = 0; refined && m < s.nMid; ++m) {
    auto [a, b] = s.midEnds[size_t(m)];
    edges.insert({std::min(a, s.nCorner + m), std::max(a, s.nCorner + m)});
    edges.insert({std::min(b, s.nCorner + m), std::max(b, s.nCorner + m)});
  }
  for (size_t i = 0; refined && i < s.slots.size(); ++i)
    for (int f = 0; f < 6; ++f)
      if (s.mid[i][size_t(f)] >= 0) edges.insert({s.mid[i][size_t(f)], s.centre(int(i))});
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

void onCircle(const std::vector<int>& loop, double r, double phase, double dir, Placement& pl) {
  for (size_t k = 0; k < loop.size(); ++k) {
    double t = phase + dir * 2 * kPi * double(k) / double(loop.size());
    pl.pos[size_t(loop[k])] = {r * std::cos(t), r * std::sin(t)};
    pl.fixed[size_t(loop[k])] = true;
  }
}

// Places the surface: disk, annulus or opened sphere. Returns false for other topologies.
// Fixes the mid vertices of boundary mid-edges (and of the opened face) halfway between their corners.
void fixBoundaryMids(const Surface& s, Placement& pl) {
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

bool place(const Complex& cx, const Surface& s, Placement& pl) {
  const int n = s.total();
  pl.pos.assign(size_t(n), {});
  pl.fixed.assign(size_t(n), false);
  if (!s.orientable) return false;
  std::vector<std::vector<int>> loops;
  if (!chainLoops(boundaryEdges(cx, s, -1), loops)) return false;
  int64_t interiorSides = 0, boundarySides = 0;
  for (size_t i = 0; i < s.slots.size(); ++i)
    for (int f = 0; f < 6; ++f)
      if (axisOfFace(f) != s.slots[i].axis) (s.neighbour(cx, int(i), f) >= 0 ? interiorSides : boundarySides)++;
  int64_t chi = int64_t(s.nCorner) - (interiorSides / 2 + boundarySides) + int64_t(s.slots.size());
  for (const auto& l : loops)
    if (l.size() < 3) return false;  // a digon boundary cannot be drawn on a circle
  if (loops.size() == 1 && chi == 1) {
    onCircle(loops[0], 1.0, 0, 1, pl);
    fixBoundaryMids(s, pl);
    pl.method = "disk";
  } else if (loops.size() == 2 && chi == 0) {
    std::sort(loops.begin(), loops.end(), [](const auto& a, const auto& b) { return a.size() > b.size(); });
    onCircle(loops[0], 1.0, 0, 1, pl);
    // Align the inner loop with the outer one along a shortest path of mid-surface edges.
    std::vector<std::vector<int>> adj(static_cast<size_t>(n));
    for (const auto& q : s.quad)
      for (int k = 0; k < 4; ++k) {
        adj[size_t(q[size_t(k)])].push_back(q[size_t((k + 1) & 3)]);
        adj[size_t(q[size_t((k + 1) & 3)])].push_back(q[size_t(k)]);
      }
    std::vector<int> dist(size_t(n), -1);
    std::vector<int> queue{loops[0][0]};
    dist[size_t(loops[0][0])] = 0;
    int hit = -1;
    for (size_t i = 0; i < queue.size() && hit < 0; ++i)
      for (int w : adj[size_t(queue[i])]) {
        if (dist[size_t(w)] >= 0) continue;
        dist[size_t(w)] = dist[size_t(queue[i])] + 1;
        queue.push_back(w);
        if (std::find(loops[1].begin(), loops[1].end(), w) != loops[1].end()) {
          hit = w;
          break;
        }
      }
    auto it = std::find(loops[1].begin(), loops[1].end(), hit);
    std::rotate(loops[1].begin(), it == loops[1].end() ? loops[1].begin() : it, loops[1].end());
    onCircle(loops[1], 0.45, 0, -1, pl);  // the inner loop runs the other way
    fixBoundaryMids(s, pl);
    pl.method = "annulus";
    // Angles from the planar harmonic map; radii from a scalar harmonic function (1 on the outer
    // loop, 0 on the inner), so every vertex lies between the two circles (maximum principle):
    // on coarse rings the planar map alone pulls rows inside the inner circle.
    Placement rho = pl;
    for (int v : loops[0]) rho.pos[size_t(v)] = {1, 0};
    for (int v : loops[1]) rho.pos[size_t(v)] = {0, 0};
    for (int m = 0; m < s.nMid; ++m)
      if (rho.fixed[size_t(s.nCorner + m)])
        rho.pos[size_t(s.nCorner + m)] = {0.5 * (rho.pos[size_t(s.midEnds[size_t(m)].first)].x + rho.pos[size_t(s.midEnds[size_t(m)].second)].x), 0};
    if (!harmonic(s, pl) || !harmonic(s, rho)) return false;
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
  } else if (loops.empty() && chi == 2) {
    pl.opened = 0;
    std::vector<std::vector<int>> l2;
    if (!chainLoops(boundaryEdges(cx, s, 0), l2) || l2.size() != 1) return false;
    onCircle(l2[0], 1.0, kPi / 4, 1, pl);
    fixBoundaryMids(s, pl);
    pl.method = "sphere";
  } else {
    return false;
  }
  return harmonic(s, pl);
}


SheetDiagram assemble(const Complex& cx, const Dual& dual, int sheet, const Surface& s, const Placement& pl, bool local) {
  SheetDiagram d;
  d.sheet = sheet;
  d.topology = dual.sheets[size_t(sheet)].topology;
  d.method = local ? "local" : pl.method;
  d.local = local;
  for (int v = 0; v < s.nCorner; ++v) d.cells.push_back({s.verts[size_t(v)], pl.pos[size_t(v)]});
  d.quads = s.quad;
  std::vector<Point2> centre(s.slots.size());
  for (size_t i = 0; i < s.slots.size(); ++i) centre[i] = pl.pos[size_t(s.centre(int(i)))];
  auto edgeMid = [&](int i, int f) { return pl.pos[size_t(s.mid[size_t(i)][size_t(f)])]; };
  // The opened face (sphere): its mid-edge midpoints on the circle in angular order, and its crossing.
  std::map<int, double> openAngle;  // face -> angle of its mid-edge midpoint
  Point2 openedCrossing;
  int openOrder[6] = {-1, -1, -1, -1, -1, -1};
  if (pl.opened >= 0) {
    Slot os = s.slots[size_t(pl.opened)];
    std::vector<std::pair<double, int>> byAngle;
    for (int f = 0; f < 6; ++f)
      if (axisOfFace(f) != os.axis) {
        Point2 m = edgeMid(pl.opened, f);
        double t = std::atan2(m.y, m.x);
        if (t < 0) t += 2 * kPi;
        openAngle[f] = t;
        byAngle.push_back({t, f});
      }
    std::sort(byAngle.begin(), byAngle.end());
    for (int k = 0; k < 4; ++k) openOrder[byAngle[size_t(k)].second] = k;
    double t1 = byAngle[1].first;
    openedCrossing = {1.2 * std::cos(t1), 1.2 * std::sin(t1)};
    d.openedHex = os.hex;
    d.openedAxis = os.axis;
    d.note = "the face of hex " + std::to_string(os.hex) + " (axis " + std::to_string(os.axis) + ") is opened: it is the outside";
  }
  for (size_t i = 0; i < s.slots.size(); ++i) {
    Slot sl = s.slots[i];
    int b = (sl.axis + 1) % 3, c = (sl.axis + 2) % 3;
    SheetDiagram::Crossing x{sl.hex, sl.axis, int(i) == pl.opened ? openedCrossing : centre[i],
                             {dual.chordOf[size_t(sl.hex)][size_t(b)], dual.chordOf[size_t(sl.hex)][size_t(c)]}, int(i) == pl.opened};
    d.crossings.push_back(x);
  }
  // Route through the opened face, outside its square: its mid-edges in angular order are 0..3;
  // the pair (0,2) runs on an arc of radius 1.2 that passes the crossing at angle 1; the pair (1,3)
  // leaves radially through the crossing and runs on an arc of radius 1.4. They meet only there.
  auto outsideRoute = [&](int in, int out, std::vector<Point2>& pts) {
    int kin = openOrder[in], kout = openOrder[out];
    int a = kin < kout ? in : out, b = kin < kout ? out : in;
    double ta = openAngle[a], tb = openAngle[b];
    auto P = [](double r, double t) { return Point2{r * std::cos(t), r * std::sin(t)}; };
    std::vector<Point2> route;
    const int steps = 24;
    if (std::min(kin, kout) == 0) {  // inner arc a -> b, through the crossing
      double t1 = std::atan2(openedCrossing.y, openedCrossing.x);
      if (t1 < 0) t1 += 2 * kPi;
      for (int k = 0; k <= steps; ++k) {
        double t = ta + (tb - ta) * k / steps;
        if (k > 0) {
          double tp = ta + (tb - ta) * (k - 1) / steps;
          if (t1 > tp && t1 < t) route.push_back(openedCrossing);
        }
        route.push_back(P(1.2, t));
      }
    } else {  // out through the crossing, outer arc a -> b
      route.push_back(openedCrossing);
      for (int k = 0; k <= steps; ++k) route.push_back(P(1.4, ta + (tb - ta) * k / steps));
    }
    if (kin > kout) std::reverse(route.begin(), route.end());
    for (Point2 p : route) pts.push_back(p);
    pts.push_back(edgeMid(pl.opened, out));
  };
  // Chords: walk each (face, chord axis) pair once.
  std::map<std::pair<int, int>, bool> done;
  for (size_t i0 = 0; i0 < s.slots.size(); ++i0)
    for (int b0 : {(s.slots[i0].axis + 1) % 3, (s.slots[i0].axis + 2) % 3}) {
      if (done[{int(i0), b0}]) continue;
      // Walk backwards to an end (or once round).
      int i = int(i0), b = b0, entry = 2 * b0;
      bool closed = false;
      for (size_t guard = 0; guard <= s.slots.size(); ++guard) {
        int j = s.neighbour(cx, i, entry);
        if (j < 0) break;
        Gluing g = cx.gluing(s.slots[size_t(i)].hex, entry);
        i = j;
        b = axisOfFace(g.face);
        entry = oppositeFace(g.face);
        if (i == int(i0) && b == b0) {
          closed = true;
          break;
        }
      }
      if (closed) {
        i = int(i0);
        b = b0;
        entry = 2 * b0;
      }
      int in = closed ? 2 * b0 : entry;  // the face we enter through
      SheetDiagram::ChordLine line;
      Slot first = s.slots[size_t(i)];
      line.chord = dual.chordOf[size_t(first.hex)][size_t(b)];
      line.otherSheet = dual.sheetOf[size_t(first.hex)][size_t(3 - first.axis - b)];
      line.closed = closed;
      int startI = i, startB = b;
      for (size_t guard = 0; guard <= 2 * s.slots.size(); ++guard) {
        done[{i, b}] = true;
        int out = oppositeFace(in);
        Slot sl = s.slots[size_t(i)];
        Point2 pin = edgeMid(i, in), pout = edgeMid(i, out);
        if (line.points.empty()) {
          line.points.push_back(pin);
          if (s.neighbour(cx, i, in) < 0) d.boundary.push_back({sl.hex, in, pin});
        }
        if (i == pl.opened) {
          outsideRoute(in, out, line.points);
        } else {
          line.points.push_back(centre[size_t(i)]);
          line.points.push_back(pout);
        }
        line.hexes.push_back(sl.hex);
        int j = s.neighbour(cx, i, out);
        if (j < 0) {
          d.boundary.push_back({sl.hex, out, pout});
          break;
        }
        Gluing g = cx.gluing(sl.hex, out);
        i = j;
        b = axisOfFace(g.face);
        in = g.face;
        if (i == startI && b == startB) break;
      }
      d.chords.push_back(std::move(line));
    }
  // Boundary loops (outer first) as polylines of the placed vertices.
  std::vector<std::vector<int>> loops;
  chainLoops(boundaryEdges(cx, s, pl.opened), loops);
  std::sort(loops.begin(), loops.end(), [](const auto& a, const auto& b) { return a.size() > b.size(); });
  for (const auto& l : loops) {
    std::vector<Point2> poly;
    for (int v : l) poly.push_back(pl.pos[size_t(v)]);
    d.loops.push_back(poly);
  }
  return d;
}

// Slots of the sheet within `rings` rings of the seeds; a ring adds every slot sharing a
// mid-surface vertex (a primal edge) with the piece, so one ring around a grid hex is 3x3.
std::vector<Slot> neighbourhood(const Complex& cx, const Dual& dual, int sheet, const std::vector<Slot>& seeds, int rings) {
  std::vector<Slot> out = seeds;
  std::vector<int> depth(seeds.size(), 0);
  for (size_t i = 0; i < out.size(); ++i) {
    if (depth[i] >= rings) continue;
    auto c = midCycle(out[i].axis);
    for (int e : c)
      for (EdgeRef x : cx.edgeCycle({out[i].hex, e})) {
        Slot n{x.hex, axisOfEdge(x.edge)};
        if (dual.sheetOf[size_t(n.hex)][size_t(n.axis)] != sheet) continue;
        if (std::find(out.begin(), out.end(), n) != out.end()) continue;
        out.push_back(n);
        depth.push_back(depth[i] + 1);
      }
  }
  return out;
}

}  // namespace

namespace {
// The largest neighbourhood (at most `rings` rings) of the seed slots that draws as a planar disk;
// with no ring count working for several seeds, the first seed alone.
SheetDiagram layoutAround(const Complex& cx, const Dual& dual, int sheet, const std::vector<Slot>& seeds, int rings) {
  for (int k = std::max(rings, 0); k >= 0; --k) {
    Surface s = buildSurface(cx, neighbourhood(cx, dual, sheet, seeds, k));
    Placement pl;
    if (!place(cx, s, pl)) continue;
    SheetDiagram d = assemble(cx, dual, sheet, s, pl, true);
    if (k > 0) {  // a degenerate neighbourhood may not draw planar: take fewer rings
      try {
        checkDiagram(d, d.crossings.size());
      } catch (const Error&) {
        continue;
      }
    }
    d.note = "the sheet within " + std::to_string(k) + " ring(s) of the chosen hexes" +
             (k < rings ? " (more rings do not draw as a planar disk)" : "") + (d.openedHex >= 0 ? "; " + d.note : "");
    return d;
  }
  if (seeds.size() > 1) return layoutAround(cx, dual, sheet, {seeds[0]}, rings);
  throw Error("sheet diagram: no neighbourhood of hex " + std::to_string(seeds[0].hex) + " on sheet " + std::to_string(sheet) +
              " draws as a planar disk");
}
}  // namespace

SheetDiagram layoutLocal(const Complex& cx, const Dual& dual, int sheet, const std::vector<HexId>& hexes, int rings) {
  if (sheet < 0 || size_t(sheet) >= dual.sheets.size() || !dual.sheets[size_t(sheet)].alive)
    throw Error("sheet diagram: sheet " + std::to_string(sheet) + " does not exist");
  std::vector<Slot> seeds;
  for (HexId h : hexes) {
    if (!cx.isHex(h)) throw Error("sheet diagram: hex " + std::to_string(h) + " does not exist");
    for (int a = 0; a < 3; ++a)
      if (dual.sheetOf[size_t(h)][size_t(a)] == sheet) seeds.push_back({h, a});
  }
  if (seeds.empty()) throw Error("sheet diagram: none of the given hexes lies on sheet " + std::to_string(sheet));
  return layoutAround(cx, dual, sheet, seeds, rings);
}

SheetDiagram layoutSheet(const Complex& cx, const Dual& dual, int sheet) {
  if (sheet < 0 || size_t(sheet) >= dual.sheets.size() || !dual.sheets[size_t(sheet)].alive)
    throw Error("sheet diagram: sheet " + std::to_string(sheet) + " does not exist");
  const Sheet& sh = dual.sheets[size_t(sheet)];
  Surface s = buildSurface(cx, sh.slots);
  Placement pl;
  std::string why = "this sheet is " + sh.topology + (sh.selfIntersecting ? " and self-intersecting" : "") + "; whole sheets are drawn as a disk, annulus or sphere";
  if (place(cx, s, pl)) {
    SheetDiagram d = assemble(cx, dual, sheet, s, pl, false);
    if (sh.slots.size() > 2000) return d;  // big sheets: the planarity check (near-linear but slow) is skipped
    try {
      checkDiagram(d, sh.slots.size());
      return d;
    } catch (const Error& e) {
      why = std::string("the whole-sheet layout is not planar (") + e.what() + ")";
    }
  }
  // Otherwise: the largest neighbourhood of the sheet's first hex that draws as a planar disk.
  int rings = int(sh.slots.size());
  SheetDiagram d = layoutLocal(cx, dual, sheet, {sh.slots[0].hex}, rings);
  d.note = why + "; showing " + d.note;
  return d;
}

std::string diagramJson(const SheetDiagram& d) {
  io::JsonWriter w;
  auto pt = [&](Point2 p) { w.beginArray().value(p.x).value(p.y).endArray(); };
  w.beginObject().key("sheet").value(d.sheet).key("topology").value(d.topology).key("method").value(d.method);
  w.key("local").value(d.local).key("note").value(d.note).key("radius").value(d.radius);
  w.key("openedHex");
  if (d.openedHex >= 0) w.value(int64_t(d.openedHex));
  else w.raw("null");
  w.key("crossings").beginArray();
  for (const auto& c : d.crossings) {
    w.beginObject().key("hex").value(int64_t(c.hex)).key("axis").value(c.axis).key("x").value(c.p.x).key("y").value(c.p.y);
    w.key("chords").beginArray().value(c.chords[0]).value(c.chords[1]).endArray().key("outside").value(c.outside).endObject();
  }
  w.endArray().key("boundary").beginArray();
  for (const auto& b : d.boundary)
    w.beginObject().key("hex").value(int64_t(b.hex)).key("face").value(b.face).key("x").value(b.p.x).key("y").value(b.p.y).endObject();
  w.endArray().key("chords").beginArray();
  for (const auto& c : d.chords) {
    w.beginObject().key("id").value(c.chord).key("otherSheet").value(c.otherSheet).key("closed").value(c.closed);
    w.key("hexes").beginArray();
    for (HexId h : c.hexes) w.value(int64_t(h));
    w.endArray().key("points").beginArray();
    for (Point2 p : c.points) pt(p);
    w.endArray().endObject();
  }
  w.endArray().key("loops").beginArray();
  for (const auto& l : d.loops) {
    w.beginArray();
    for (Point2 p : l) pt(p);
    w.endArray();
  }
  w.endArray().key("cells").beginArray();
  for (const auto& c : d.cells)
    w.beginObject().key("edge").beginArray().value(int64_t(c.edge.hex)).value(c.edge.edge).endArray().key("x").value(c.p.x).key("y").value(c.p.y).endObject();
  w.endArray().endObject();
  return w.str();
}

std::string diagramSvg(const SheetDiagram& d) {
  const double S = 200, M = d.openedHex >= 0 ? 1.65 : 1.2;  // scale; margin in diagram units
  auto X = [&](double x) { return S * (x + M); };
  auto Y = [&](double y) { return S * (M - y); };
  char buf[256];
  std::string out;
  std::snprintf(buf, sizeof buf,
                "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\" "
                "font-family=\"sans-serif\" font-size=\"11\">\n<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n",
                2 * S * M, 2 * S * M + 24, 2 * S * M, 2 * S * M + 24);
  out += buf;
  std::snprintf(buf, sizeof buf, "<text x=\"8\" y=\"%.0f\" font-size=\"13\">sheet %d · %s · %s</text>\n", 2 * S * M + 16, d.sheet,
                d.topology.c_str(), d.method.c_str());
  out += buf;
  if (d.local) {
    std::snprintf(buf, sizeof buf, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"%.1f\" fill=\"none\" stroke=\"#555\" stroke-dasharray=\"6 5\"/>\n", X(0), Y(0), S);
    out += buf;
  }
  for (size_t k = 0; k < d.loops.size(); ++k) {
    std::string pts;
    for (Point2 p : d.loops[k]) {
      std::snprintf(buf, sizeof buf, "%.1f,%.1f ", X(p.x), Y(p.y));
      pts += buf;
    }
    out += "<polygon points=\"" + pts + "\" fill=\"" + std::string(k == 0 ? "#f4f6fa" : "white") + "\" stroke=\"#222\" stroke-width=\"" +
           (d.local ? "0.8" : "1.6") + "\"" + (d.local ? " stroke-dasharray=\"2 3\"" : "") + "/>\n";
  }
  auto hue = [](int id) { return std::to_string(int(std::fmod(id * 137.508, 360.0))); };
  for (const auto& c : d.chords) {
    std::string pts;
    for (Point2 p : c.points) {
      std::snprintf(buf, sizeof buf, "%.1f,%.1f ", X(p.x), Y(p.y));
      pts += buf;
    }
    out += "<polyline points=\"" + pts + "\" fill=\"none\" stroke=\"hsl(" + hue(c.otherSheet) +
           ",65%,45%)\" stroke-width=\"2.2\"><title>chord " + std::to_string(c.chord) + " (with sheet " + std::to_string(c.otherSheet) +
           ")</title></polyline>\n";
  }
  for (const auto& b : d.boundary) {
    std::snprintf(buf, sizeof buf, "<rect x=\"%.1f\" y=\"%.1f\" width=\"5\" height=\"5\" fill=\"#222\"/>\n", X(b.p.x) - 2.5, Y(b.p.y) - 2.5);
    out += buf;
  }
  for (const auto& c : d.crossings) {
    std::snprintf(buf, sizeof buf,
                  "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"4.5\" fill=\"%s\" stroke=\"#111\"/><text x=\"%.1f\" y=\"%.1f\">%d</text>\n", X(c.p.x),
                  Y(c.p.y), c.outside ? "#fc6" : "#fff", X(c.p.x) + 6, Y(c.p.y) - 6, c.hex);
    out += buf;
  }
  return out + "</svg>\n";
}

namespace {
bool segmentsMeet(Point2 a, Point2 b, Point2 c, Point2 d, Point2* at) {
  double d1x = b.x - a.x, d1y = b.y - a.y, d2x = d.x - c.x, d2y = d.y - c.y;
  double den = d1x * d2y - d1y * d2x;
  if (std::fabs(den) < 1e-12) return false;  // parallel (collinear overlaps are not produced here)
  double t = ((c.x - a.x) * d2y - (c.y - a.y) * d2x) / den, u = ((c.x - a.x) * d1y - (c.y - a.y) * d1x) / den;
  const double eps = 1e-9;
  if (t < -eps || t > 1 + eps || u < -eps || u > 1 + eps) return false;
  *at = {a.x + t * d1x, a.y + t * d1y};
  return true;
}
bool near(Point2 a, Point2 b) { return std::hypot(a.x - b.x, a.y - b.y) < 1e-7; }
bool insidePolygon(Point2 p, const std::vector<Point2>& poly) {
  bool in = false;
  for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
    if ((poly[i].y > p.y) != (poly[j].y > p.y) &&
        p.x < (poly[j].x - poly[i].x) * (p.y - poly[i].y) / (poly[j].y - poly[i].y) + poly[i].x)
      in = !in;
  return in;
}
}  // namespace

void checkDiagram(const SheetDiagram& d, size_t expectedSlots) {
  auto fail = [&](const std::string& m) { throw Error("sheet diagram " + std::to_string(d.sheet) + ": " + m); };
  // Every slot exactly once.
  std::vector<std::pair<HexId, int>> seen;
  for (const auto& c : d.crossings) seen.push_back({c.hex, c.axis});
  std::sort(seen.begin(), seen.end());
  if (std::adjacent_find(seen.begin(), seen.end()) != seen.end()) fail("a slot appears twice");
  if (seen.size() != expectedSlots) fail(std::to_string(seen.size()) + " crossings for " + std::to_string(expectedSlots) + " slots");
  // Every crossing joins exactly two chord passes.
  for (const auto& c : d.crossings) {
    int passes = 0;
    for (const auto& ch : d.chords)
      for (Point2 p : ch.points) passes += near(p, c.p);
    if (passes != 2) fail("crossing of hex " + std::to_string(c.hex) + " joins " + std::to_string(passes) + " chord passes, not 2");
  }
  // Chords meet only at crossings (or where consecutive segments join).
  struct Seg {
    Point2 a, b;
    size_t chord, index;
  };
  std::vector<Seg> segs;
  for (size_t k = 0; k < d.chords.size(); ++k)
    for (size_t i = 0; i + 1 < d.chords[k].points.size(); ++i) segs.push_back({d.chords[k].points[i], d.chords[k].points[i + 1], k, i});
  std::map<std::pair<long long, long long>, size_t> crossingAt;  // crossing points by rounded coordinates
  for (size_t k = 0; k < d.crossings.size(); ++k)
    crossingAt[{std::llround(d.crossings[k].p.x * 1e6), std::llround(d.crossings[k].p.y * 1e6)}] = k;
  // Candidate pairs from a uniform grid over the segments' bounding boxes (near-linear).
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (const Seg& g : segs) {
    x0 = std::min({x0, g.a.x, g.b.x});
    y0 = std::min({y0, g.a.y, g.b.y});
    x1 = std::max({x1, g.a.x, g.b.x});
    y1 = std::max({y1, g.a.y, g.b.y});
  }
  const int G = std::max(1, int(std::sqrt(double(segs.size()))));
  const double cw = std::max((x1 - x0) / G, 1e-12), ch = std::max((y1 - y0) / G, 1e-12);
  auto cellOf = [&](double v, double lo, double w) { return std::clamp(int((v - lo) / w), 0, G - 1); };
  std::unordered_map<int64_t, std::vector<size_t>> grid;
  for (size_t i = 0; i < segs.size(); ++i) {
    const Seg& g = segs[i];
    int cx0 = cellOf(std::min(g.a.x, g.b.x) - 1e-9, x0, cw), cx1 = cellOf(std::max(g.a.x, g.b.x) + 1e-9, x0, cw);
    int cy0 = cellOf(std::min(g.a.y, g.b.y) - 1e-9, y0, ch), cy1 = cellOf(std::max(g.a.y, g.b.y) + 1e-9, y0, ch);
    for (int cxx = cx0; cxx <= cx1; ++cxx)
      for (int cyy = cy0; cyy <= cy1; ++cyy) grid[int64_t(cxx) * G + cyy].push_back(i);
  }
  std::set<std::pair<size_t, size_t>> tested;
  for (auto& [cell, list] : grid)
    for (size_t p = 0; p < list.size(); ++p)
      for (size_t q = p + 1; q < list.size(); ++q) {
        size_t i = std::min(list[p], list[q]), j = std::max(list[p], list[q]);
        if (!tested.insert({i, j}).second) continue;
        const Seg &s = segs[i], &t = segs[j];
      bool consecutive = s.chord == t.chord && (s.index + 1 == t.index || t.index + 1 == s.index ||
                                                (d.chords[s.chord].closed && (s.index == 0 || t.index == 0)));
      Point2 at;
      if (!segmentsMeet(s.a, s.b, t.a, t.b, &at)) continue;
      if (consecutive && (near(at, s.a) || near(at, s.b))) continue;
      bool atCrossing = false;
      for (int ox = -1; ox <= 1 && !atCrossing; ++ox)
        for (int oy = -1; oy <= 1 && !atCrossing; ++oy) {
          auto it = crossingAt.find({std::llround(at.x * 1e6) + ox, std::llround(at.y * 1e6) + oy});
          if (it != crossingAt.end()) atCrossing = near(at, d.crossings[it->second].p);
        }
      if (!atCrossing) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "chords %d and %d meet at (%.4f, %.4f), which is not a hex crossing", d.chords[s.chord].chord,
                      d.chords[t.chord].chord, at.x, at.y);
        fail(buf);
      }
    }
  // Interior points inside the outer loop (and outside the inner one).
  if (d.loops.empty()) return;
  for (const auto& c : d.crossings) {
    if (c.outside) continue;
    if (!insidePolygon(c.p, d.loops[0])) fail("crossing of hex " + std::to_string(c.hex) + " lies outside the outer loop");
    if (d.loops.size() > 1 && insidePolygon(c.p, d.loops[1])) fail("crossing of hex " + std::to_string(c.hex) + " lies inside the inner loop");
  }
}

}  // namespace hexdual
