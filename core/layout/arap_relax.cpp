#include "layout/arap_relax.hpp"

#include <algorithm>
#include <cmath>

namespace hexdual {

namespace {

Point2 sub(Point2 a, Point2 b) { return {a.x - b.x, a.y - b.y}; }
double cross(Point2 a, Point2 b) { return a.x * b.y - a.y * b.x; }

// The largest t such that on pos + s * dir, s < t, no triangle's (doubled) area falls to its floor.
double globalStep(const Triangulation& t, const std::vector<Point2>& pos, const std::vector<Point2>& dir,
                  const std::vector<double>& floor) {
  double tmax = 1e300;
  for (size_t k = 0; k < t.tris.size() && tmax > 0; ++k) {
    const auto& tri = t.tris[k];
    Point2 a = pos[size_t(tri[0])], da = dir[size_t(tri[0])];
    Point2 B = sub(pos[size_t(tri[1])], a), C = sub(pos[size_t(tri[2])], a);
    Point2 dB = sub(dir[size_t(tri[1])], da), dC = sub(dir[size_t(tri[2])], da);
    // area(s) - floor = c0 + c1 s + c2 s^2
    double c0 = cross(B, C) - floor[k], c1 = cross(B, dC) + cross(dB, C), c2 = cross(dB, dC);
    if (c0 <= 0) return 0;
    double root = 1e300;
    if (c2 == 0) {
      if (c1 < 0) root = -c0 / c1;
    } else {
      double disc = c1 * c1 - 4 * c2 * c0;
      if (disc >= 0) {
        double sq = std::sqrt(disc), q = -0.5 * (c1 + (c1 >= 0 ? sq : -sq));
        for (double r : {q / c2, q != 0 ? c0 / q : 1e300})
          if (r > 0) root = std::min(root, r);
      }
    }
    tmax = std::min(tmax, root);
  }
  return tmax;
}

// Area floors: half a triangle's area now, at most a twentieth of its reference's.
std::vector<double> areaFloors(const Triangulation& t, const std::vector<Point2>& pos, double scale) {
  std::vector<double> floor(t.tris.size());
  for (size_t k = 0; k < t.tris.size(); ++k) {
    double ref = scale * scale * cross(sub(t.ref[k][1], t.ref[k][0]), sub(t.ref[k][2], t.ref[k][0]));
    floor[k] = std::min(0.5 * signedArea2(t, pos, k), 0.05 * ref);
  }
  return floor;
}

// Per triangle: the rotation (cos, sin) best taking its reference edges onto its drawn edges.
using Refs = std::vector<std::array<Point2, 3>>;

std::vector<Point2> bestRotations(const Triangulation& t, const Refs& ref, const std::vector<Point2>& pos, double scale) {
  std::vector<Point2> rot(t.tris.size());
  for (size_t k = 0; k < t.tris.size(); ++k) {
    double A = 0, B = 0;
    for (int e = 0; e < 3; ++e) {
      Point2 x = sub(pos[size_t(t.tris[k][size_t(e)])], pos[size_t(t.tris[k][size_t((e + 1) % 3)])]);
      Point2 r = sub(ref[k][size_t(e)], ref[k][size_t((e + 1) % 3)]);
      A += scale * (x.x * r.x + x.y * r.y);
      B += scale * (x.y * r.x - x.x * r.y);
    }
    double len2 = A * A + B * B;
    double inv = len2 > 0 ? 1 / std::sqrt(len2) : 0;
    rot[k] = len2 > 0 ? Point2{A * inv, B * inv} : Point2{1, 0};
  }
  return rot;
}

// b_i = sum over triangles and their edges ij of R_t (r_i - r_j), scaled.
std::vector<Point2> arapRhs(const Triangulation& t, const Refs& ref, const std::vector<Point2>& rot, double scale) {
  std::vector<Point2> b(size_t(t.vertices), Point2{0, 0});
  for (size_t k = 0; k < t.tris.size(); ++k) {
    const Point2 R = rot[k];
    for (int e = 0; e < 3; ++e)
      for (int o : {(e + 1) % 3, (e + 2) % 3}) {
        Point2 r = sub(ref[k][size_t(e)], ref[k][size_t(o)]);
        Point2& bi = b[size_t(t.tris[k][size_t(e)])];
        bi.x += scale * (R.x * r.x - R.y * r.y);
        bi.y += scale * (R.y * r.x + R.x * r.y);
      }
  }
  return b;
}

// Reference scale: total reference area equal to the drawing's.
double referenceScale(const Triangulation& t, const std::vector<Point2>& pos) {
  double drawn = 0, ref = 0;
  for (size_t k = 0; k < t.tris.size(); ++k) {
    drawn += signedArea2(t, pos, k);
    ref += cross(sub(t.ref[k][1], t.ref[k][0]), sub(t.ref[k][2], t.ref[k][0]));
  }
  return ref > 0 ? std::sqrt(drawn / ref) : 1.0;
}

// Moves each free vertex in turn towards its target as far as its own triangles allow (other
// vertices where they are): one blocked triangle holds back only its own corners, not the drawing.
double moveTowards(const Triangulation& t, const std::vector<int>& triStart, const std::vector<int>& triOf,
                   const std::vector<bool>& fixed, const std::vector<double>& floor, const std::vector<Point2>& target,
                   std::vector<Point2>& pos) {
  double moved = 0;
  for (size_t v = 0; v < pos.size(); ++v) {
    if (fixed[v] || triStart[v] == triStart[v + 1]) continue;
    const Point2 d = sub(target[v], pos[v]);
    double step = 1;
    for (int j = triStart[v]; j < triStart[v + 1]; ++j) {
      const auto& tri = t.tris[size_t(triOf[size_t(j)])];
      int k = tri[0] == int(v) ? 0 : tri[1] == int(v) ? 1 : 2;
      // Area with v moved by s d: A0 + s * cross(d, next - prev) (v, next, prev counter-clockwise).
      Point2 next = pos[size_t(tri[size_t((k + 1) % 3)])], prev = pos[size_t(tri[size_t((k + 2) % 3)])];
      double a0 = cross(sub(next, pos[v]), sub(prev, pos[v])) - floor[size_t(triOf[size_t(j)])];
      double slope = cross(d, sub(next, prev));
      if (slope < 0) step = std::min(step, a0 > 0 ? 0.9 * a0 / -slope : 0.0);
    }
    pos[v] = {pos[v].x + step * d.x, pos[v].y + step * d.y};
    moved = std::max(moved, step * (std::fabs(d.x) + std::fabs(d.y)));
  }
  return moved;
}

}  // namespace

RelaxStats arapRelax(const Triangulation& t, const DiskSolver& solver, const std::vector<bool>& fixed,
                     std::vector<Point2>& pos, int iterations, double scale) {
  RelaxStats st;
  if (scale <= 0) scale = referenceScale(t, pos);
  const std::vector<double> floor = areaFloors(t, pos, scale);
  // Converged when no vertex moves a hundredth of a quad's size (in a drawing of radius 1).
  const double settled = 0.01 * scale;
  std::vector<int> triStart(pos.size() + 1, 0), triOf(3 * t.tris.size());
  for (const auto& tri : t.tris)
    for (int v : tri) ++triStart[size_t(v) + 1];
  for (size_t v = 0; v < pos.size(); ++v) triStart[v + 1] += triStart[v];
  std::vector<int> fill(triStart.begin(), triStart.end() - 1);
  for (size_t k = 0; k < t.tris.size(); ++k)
    for (int v : t.tris[k]) triOf[size_t(fill[size_t(v)]++)] = int(k);
  std::vector<Point2> target, dir(pos.size());
  const Refs& ref = t.ref;
  for (; st.iterations < iterations; ++st.iterations) {
    std::vector<Point2> rhs = arapRhs(t, ref, bestRotations(t, ref, pos, scale), scale);
    target = pos;
    solver.solve(target, &rhs);
    // All together as far as no triangle thins to its floor (a squeezed cluster opens as a whole),
    // then each vertex on by itself (a blocked triangle holds back only its own corners).
    for (size_t v = 0; v < pos.size(); ++v) dir[v] = sub(target[v], pos[v]);
    const double step = std::min(1.0, 0.9 * globalStep(t, pos, dir, floor));
    for (size_t v = 0; v < pos.size(); ++v) pos[v] = {pos[v].x + step * dir[v].x, pos[v].y + step * dir[v].y};
    st.lastMove = moveTowards(t, triStart, triOf, fixed, floor, target, pos);
    if (st.lastMove < settled) break;
  }
  return st;
}

}  // namespace hexdual
