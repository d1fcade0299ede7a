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
void embed(const MidSurface& s, Placement& pl, const std::vector<bool>& fixed) {
  DiskSolver solver(pl.tri, fixed);
  if (!solver.ok()) throw Error("sheet diagram: the Tutte solve failed");
  solver.solve(pl.pos, nullptr);
  if (!pl.tri.tris.empty() && signedArea2(pl.tri, pl.pos, 0) < 0)
    for (Point2& p : pl.pos) p.y = -p.y;  // the mirror image: the boundary stays on its circle
  int bad = flippedTriangle(pl.tri, pl.pos);
  if (bad < 0) arapRelax(pl.tri, solver, fixed, pl.pos, kRelaxIterations);
  if (bad < 0) bad = flippedTriangle(pl.tri, pl.pos);
  if (bad >= 0)
    throw Error("sheet diagram: triangle " + std::to_string(bad) + " of the " + pl.method +
                " drawing is flipped or flat: the drawing is not an embedding");
  if (pl.tri.withMids) return;
  for (int m = 0; m < s.nMid; ++m) {
    auto [a, b] = s.midEnds[size_t(m)];
    pl.pos[size_t(s.nCorner + m)] = {0.5 * (pl.pos[size_t(a)].x + pl.pos[size_t(b)].x),
                                     0.5 * (pl.pos[size_t(a)].y + pl.pos[size_t(b)].y)};
  }
}

void start(Placement& pl, std::vector<bool>& fixed) {
  pl.pos.assign(size_t(pl.tri.vertices), {});
  fixed.assign(size_t(pl.tri.vertices), false);
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

bool placeSurface(const MidSurface& s, Placement& pl, std::string* why) {
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
    fixLoopOnCircle(pl.tri, outer, evenAngles(s, pl.tri, outer, 0), pl, fixed);
  }
  embed(s, pl, fixed);
  return true;
}

}  // namespace hexdual
