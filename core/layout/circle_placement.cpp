#include "layout/circle_placement.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "layout/boundary_loops.hpp"
#include "layout/arap_relax.hpp"
#include "layout/tutte_embedding.hpp"

namespace hexdual {
using namespace tables;

namespace {

// Loop k of the triangulation on the unit circle: corners at their angles (per corner id), mid
// vertices (when the fan has them) halfway between their corners.
void fixLoopOnCircle(const Triangulation& t, size_t k, const std::vector<double>& angle, Placement& pl,
                     std::vector<bool>& fixed) {
  const std::vector<int>& loop = t.loops[k];
  const size_t per = t.withMids ? 2 : 1, nc = loop.size() / per;
  for (size_t j = 0; j < nc; ++j) {
    double a0 = angle[size_t(loop[per * j])], a1 = angle[size_t(loop[per * ((j + 1) % nc)])];
    while (a1 <= a0) a1 += 2 * std::numbers::pi;
    for (size_t p = 0; p < per; ++p) {
      double a = a0 + (a1 - a0) * double(p) / double(per);
      int v = loop[per * j + p];
      pl.pos[size_t(v)] = {std::cos(a), std::sin(a)};
      fixed[size_t(v)] = true;
    }
  }
}

// Angles (per corner id) spreading loop k's corners evenly round the circle from `phase`.
std::vector<double> evenAngles(const MidSurface& s, const Triangulation& t, size_t k, double phase) {
  std::vector<double> a(size_t(s.nCorner), 0);
  const size_t n = t.loopEdges[k].size();
  for (size_t j = 0; j < n; ++j) a[size_t(t.edges[size_t(t.loopEdges[k][j])].from)] = phase + 2 * std::numbers::pi * double(j) / double(n);
  return a;
}

// Rings of virtual vertices closing a hole of n vertices: about its radius in edge lengths, so the
// hole is drawn about as large as a disk of the sheet with that boundary would be.
int holeRings(size_t n) { return int(double(n) / (2 * std::numbers::pi)); }

// ARAP rounds: most drawings settle in a few; a lens or a blind chord opens up within a dozen.
constexpr int kRelaxIterations = 8;

// Tutte's drawing (planar by construction), turned counter-clockwise, relaxed towards square
// quads without flipping a triangle; then the certificate, and the mid vertices a 4-triangle fan
// leaves out halfway between their corners, on the corners' segment.
void start(Placement& pl, std::vector<bool>& fixed) {
  pl.pos.assign(size_t(pl.tri.vertices), {});
  fixed.assign(size_t(pl.tri.vertices), false);
  pl.straightened = 0;  // a drawing on the circle straightens nothing
}

// The first flipped or flat triangle of the drawing, or -1 when it is an embedding.
int tryEmbed(Placement& pl, const std::vector<bool>& fixed, const DiskSolver& solver) {
  if (!solver.ok()) throw Error("sheet diagram: the Tutte solve failed");
  solver.solve(pl.pos, nullptr);
  if (!pl.tri.tris.empty() && signedArea2(pl.tri, pl.pos, 0) < 0)
    for (Point2& p : pl.pos) p.y = -p.y;  // the mirror image: the boundary keeps its shape
  int bad = flippedTriangle(pl.tri, pl.pos);
  if (bad < 0) arapRelax(pl.tri, solver, fixed, pl.pos, kRelaxIterations);
  if (bad < 0) bad = flippedTriangle(pl.tri, pl.pos);
  return bad;
}

void placeMids(const MidSurface& s, Placement& pl) {
  if (pl.tri.withMids) return;
  for (int m = 0; m < s.nMid; ++m) {
    auto [a, b] = s.midEnds[size_t(m)];
    pl.pos[size_t(s.nCorner + m)] = {0.5 * (pl.pos[size_t(a)].x + pl.pos[size_t(b)].x),
                                     0.5 * (pl.pos[size_t(a)].y + pl.pos[size_t(b)].y)};
  }
}

void embed(const MidSurface& s, Placement& pl, const std::vector<bool>& fixed) {
  int bad = tryEmbed(pl, fixed, DiskSolver(pl.tri, fixed));
  if (bad >= 0)
    throw Error("sheet diagram: triangle " + std::to_string(bad) + " of the " + pl.method +
                " drawing is flipped or flat: the drawing is not an embedding");
  placeMids(s, pl);
}

// The shape of a disk's boundary read from its quads, as if each were a unit square. A boundary
// corner on q quads turns the loop by (2 - q) quarter turns (one quad: a convex corner; two: a
// straight side). An interior corner on k quads is a cone whose (4 - k) quarter turns a flat drawing
// has to put somewhere on the boundary: they go where a random walk from the cone leaves the disk
// (its harmonic measure, one solve with the Tutte system), as a conformal flattening would. Reflex
// turns are drawn straight, the turns scaled to one full turn and kEvenTurn of it spread over every
// loop vertex, so the polygon is strictly convex and Tutte's theorem holds as on the circle. Sides get
// unit length, then the least change of lengths that closes the polygon. So a 100 x 14 sheet is a
// 100 x 14 rectangle, and a sheet wrapped round a box's corners is rounded where its cones are
// instead of squeezed against a circle.
constexpr double kEvenTurn = 0.002;

struct LoopTurns {
  std::vector<double> turn;  // per loop vertex, radians (>= 0: reflex turns drawn straight)
  int straightened = 0;      // reflex boundary corners among them
};

// Each loop vertex's turn: its own (2 - q) quarter turns plus its share of the cones' turns.
LoopTurns loopTurns(const MidSurface& s, const Triangulation& t, size_t k, const DiskSolver& solver,
                    const std::vector<bool>& fixed, std::vector<Point2>& scratch) {
  const std::vector<int>& loop = t.loops[k];
  std::vector<int> quadsAt(size_t(s.nCorner), 0);
  for (const auto& q : s.quad)
    for (int j = 0; j < 4; ++j)
      if (std::find(q.begin(), q.begin() + j, q[size_t(j)]) == q.begin() + j) ++quadsAt[size_t(q[size_t(j)])];
  const double pi = std::numbers::pi;
  std::vector<Point2> cone(size_t(t.vertices), Point2{0, 0});
  bool cones = false;
  for (int v = 0; v < s.nCorner; ++v)
    if (!fixed[size_t(v)] && quadsAt[size_t(v)] != 4) cone[size_t(v)].x = (4 - quadsAt[size_t(v)]) * pi / 2, cones = true;
  std::vector<double> exitTurn(size_t(t.vertices), 0);
  if (cones) {  // the flow out of the disk at each boundary vertex: the cones' harmonic measure there
    std::fill(scratch.begin(), scratch.end(), Point2{0, 0});
    solver.solve(scratch, &cone);
    for (const auto& tri : t.tris)
      for (int e = 0; e < 3; ++e) {
        const int u = tri[size_t(e)], v = tri[size_t((e + 1) % 3)];
        if (fixed[size_t(u)] && !fixed[size_t(v)]) exitTurn[size_t(u)] += scratch[size_t(v)].x;
        if (fixed[size_t(v)] && !fixed[size_t(u)]) exitTurn[size_t(v)] += scratch[size_t(u)].x;
      }
  }
  LoopTurns out;
  out.turn.assign(loop.size(), 0);
  for (size_t j = 0; j < loop.size(); ++j) {
    const int v = loop[j];
    double tj = exitTurn[size_t(v)];
    if (v < s.nCorner) tj += (2 - quadsAt[size_t(v)]) * pi / 2;
    if (v < s.nCorner && quadsAt[size_t(v)] >= 3 && tj < -1e-9) ++out.straightened;
    out.turn[j] = std::max(0.0, tj);
  }
  return out;
}

// The strictly convex polygon with these turns and sides as near unit length as closes it (vertex j
// starts side j), and per vertex whether it is a marked corner; empty when there is none (too little
// turning, a spike, a side shrunk).
std::vector<Point2> convexPolygon(const std::vector<double>& turn, std::vector<bool>& corner) {
  const double pi = std::numbers::pi;
  const size_t m = turn.size();
  double total = 0;
  for (double tj : turn) total += tj;
  if (m < 3 || total < pi) return {};
  std::vector<Point2> dir(m);
  corner.assign(m, false);
  double theta = 0, mxx = 0, mxy = 0, myy = 0, rx = 0, ry = 0;
  for (size_t j = 0; j < m; ++j) {
    const double tj = (1 - kEvenTurn) * turn[j] * 2 * pi / total + kEvenTurn * 2 * pi / double(m);
    if (tj > 0.8 * pi) return {};  // a spike: the circle draws it better
    corner[j] = tj > pi / 12;      // more than a sixth of a quarter turn: where a side starts
    theta += tj;
    dir[j] = {std::cos(theta), std::sin(theta)};
    mxx += dir[j].x * dir[j].x, mxy += dir[j].x * dir[j].y, myy += dir[j].y * dir[j].y;
    rx += dir[j].x, ry += dir[j].y;
  }
  // Lengths 1 - dir . lambda, the least change that closes the polygon (sum of length x dir = 0).
  const double det = mxx * myy - mxy * mxy;
  if (det <= 1e-12) return {};
  const double lx = (myy * rx - mxy * ry) / det, ly = (mxx * ry - mxy * rx) / det;
  std::vector<Point2> at(m);
  Point2 p{0, 0};
  for (size_t j = 0; j < m; ++j) {
    const double len = 1 - dir[j].x * lx - dir[j].y * ly;
    if (len < 0.3) return {};
    at[(j + 1) % m] = p = {p.x + dir[j].x * len, p.y + dir[j].y * len};
  }
  return at;
}

// Turns the polygon so that its sides are level (a rectangle's horizontal and vertical; a shape with
// no quarter-turn axis, such as a pentagon, by its longest side from corner to corner), lays it down
// (longer extent horizontal, as panels and pages are wider than tall), centres it and scales it into
// the unit circle.
void levelAndFit(std::vector<Point2>& at, const std::vector<bool>& corner) {
  const size_t m = at.size();
  double c4 = 0, s4 = 0, perimeter = 0;  // the sides' dominant direction modulo a quarter turn
  for (size_t j = 0; j < m; ++j) {
    const double dx = at[(j + 1) % m].x - at[j].x, dy = at[(j + 1) % m].y - at[j].y, len = std::hypot(dx, dy);
    c4 += len * std::cos(4 * std::atan2(dy, dx)), s4 += len * std::sin(4 * std::atan2(dy, dx));
    perimeter += len;
  }
  double level = -std::atan2(s4, c4) / 4;
  if (std::hypot(c4, s4) < 0.5 * perimeter) {
    double best = 0;
    for (size_t a = 0; a < m; ++a) {
      if (!corner[a]) continue;
      size_t b = (a + 1) % m;
      while (!corner[b]) b = (b + 1) % m;
      const double len = std::hypot(at[b].x - at[a].x, at[b].y - at[a].y);
      if (len > best) best = len, level = -std::atan2(at[b].y - at[a].y, at[b].x - at[a].x);
    }
  }
  const double cl = std::cos(level), sl = std::sin(level);
  for (Point2& q : at) q = {cl * q.x - sl * q.y, sl * q.x + cl * q.y};
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const Point2& q : at) x0 = std::min(x0, q.x), x1 = std::max(x1, q.x), y0 = std::min(y0, q.y), y1 = std::max(y1, q.y);
  if (y1 - y0 > 1.05 * (x1 - x0))
    for (Point2& q : at) q = {-q.y, q.x};
  Point2 centre{0, 0};
  for (const Point2& q : at) centre.x += q.x / double(m), centre.y += q.y / double(m);
  double radius = 0;
  for (const Point2& q : at) radius = std::max(radius, std::hypot(q.x - centre.x, q.y - centre.y));
  for (Point2& q : at) q = {(q.x - centre.x) / radius, (q.y - centre.y) / radius};
}

// Places loop k of a disk on the polygon its quads give; false (pl unchanged but for scratch in
// pl.pos) when they give none.
bool shapedLoop(const MidSurface& s, const Triangulation& t, size_t k, const DiskSolver& solver,
                const std::vector<bool>& fixed, Placement& pl) {
  const LoopTurns turns = loopTurns(s, t, k, solver, fixed, pl.pos);
  std::vector<bool> corner;
  std::vector<Point2> at = convexPolygon(turns.turn, corner);
  if (at.empty()) return false;
  levelAndFit(at, corner);
  for (size_t j = 0; j < at.size(); ++j) pl.pos[size_t(t.loops[k][j])] = at[j];
  pl.straightened = turns.straightened;
  return true;
}

}  // namespace

int64_t eulerCharacteristic(const MidSurface& s) {
  int64_t interiorSides = 0, boundarySides = 0;
  for (size_t i = 0; i < s.slots.size(); ++i)
    for (int f = 0; f < 6; ++f)
      if (axisOfFace(f) != s.slots[i].axis) (s.joined(int(i), f) >= 0 ? interiorSides : boundarySides)++;
  return int64_t(s.nCorner) - (interiorSides / 2 + boundarySides) + int64_t(s.slots.size());
}

void placeDisk(const MidSurface& s, const std::vector<double>& cornerAngle, Placement& pl, const std::string& method) {
  pl.method = method;
  pl.tri = triangulate(s, -1);
  if (pl.tri.loops.size() != 1) throw Error("sheet diagram: the surface cut open is not a disk");
  std::vector<bool> fixed;
  start(pl, fixed);
  fixLoopOnCircle(pl.tri, 0, cornerAngle, pl, fixed);
  embed(s, pl, fixed);
}

bool placeSurface(const MidSurface& s, Placement& pl, std::string* why, DiskBoundary disk) {
  auto refuse = [&](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  if (!s.orientable) return refuse("it is not orientable");
  std::vector<BoundaryEdge> edges = boundaryEdges(s);
  std::vector<std::vector<int>> loops;
  if (!chainLoops(edges, loops)) return refuse("its boundary does not chain into loops");
  const int64_t chi = eulerCharacteristic(s);
  if (chi != 2 - int64_t(loops.size()))
    return refuse("its Euler characteristic " + std::to_string(chi) + " with " + std::to_string(loops.size()) +
                  " boundary loop(s) is not a sphere's with holes");
  std::vector<bool> fixed;
  if (loops.empty()) {  // a sphere: slot 0's face is opened and becomes the outside
    pl.opened = 0;
    pl.method = "sphere";
    pl.tri = triangulate(s, pl.opened);
    start(pl, fixed);
    fixLoopOnCircle(pl.tri, 0, evenAngles(s, pl.tri, 0, std::numbers::pi / 4), pl, fixed);
  } else {
    pl.method = loops.size() == 1 ? "disk" : loops.size() == 2 ? "annulus" : "holes";
    pl.tri = triangulate(s, -1);
    const size_t outer = pl.tri.outer;
    for (size_t k = 0; k < pl.tri.loops.size(); ++k)
      if (k != outer) fillHole(pl.tri, k, holeRings(pl.tri.loops[k].size()));
    start(pl, fixed);
    // A disk's boundary takes the shape its quads give it when they give one; the circle otherwise.
    if (loops.size() == 1 && disk == DiskBoundary::shaped) {
      for (int v : pl.tri.loops[outer]) fixed[size_t(v)] = true;
      DiskSolver solver(pl.tri, fixed);
      if (solver.ok() && shapedLoop(s, pl.tri, outer, solver, fixed, pl) && tryEmbed(pl, fixed, solver) < 0) {
        placeMids(s, pl);
        return true;
      }
      start(pl, fixed);
    }
    fixLoopOnCircle(pl.tri, outer, evenAngles(s, pl.tri, outer, 0), pl, fixed);
  }
  embed(s, pl, fixed);
  return true;
}

}  // namespace hexdual
