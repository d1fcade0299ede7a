#include "geometry/max_min.hpp"

#include <algorithm>
#include <limits>

#include "geometry/scaled_jacobian.hpp"

namespace hexdual {

namespace {

double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

// Dense tableau for: maximise x0 subject to A x <= b, x >= 0, b >= 0 (slacks make the start basis).
struct Tableau {
  int rows = 0, cols = 0;  // constraint rows; columns = variables + slacks + right-hand side
  std::vector<double> a;   // (rows + 1) x cols, the last row the objective (reduced costs)
  std::vector<int> basis;  // per row: its basic variable
  double& at(int r, int c) { return a[size_t(r) * size_t(cols) + size_t(c)]; }
};

void pivot(Tableau& t, int pr, int pc) {
  const double inv = 1 / t.at(pr, pc);
  for (int c = 0; c < t.cols; ++c) t.at(pr, c) *= inv;
  for (int r = 0; r <= t.rows; ++r) {
    if (r == pr) continue;
    const double f = t.at(r, pc);
    if (f == 0) continue;
    for (int c = 0; c < t.cols; ++c) t.at(r, c) -= f * t.at(pr, c);
  }
  t.basis[size_t(pr)] = pc;
}

// Bland's rule: the lowest-index entering column with a negative reduced cost, the leaving row by
// the ratio test (ties to the lowest basic index). False when the pivot limit is reached.
bool solve(Tableau& t) {
  const int rhs = t.cols - 1;
  for (int step = 0; step < 500; ++step) {
    int pc = -1;
    for (int c = 0; c < rhs && pc < 0; ++c)
      if (t.at(t.rows, c) < 0) pc = c;
    if (pc < 0) return true;
    int pr = -1;
    double best = std::numeric_limits<double>::infinity();
    for (int r = 0; r < t.rows; ++r) {
      if (!(t.at(r, pc) > 0)) continue;
      const double ratio = t.at(r, rhs) / t.at(r, pc);
      if (ratio < best || (ratio == best && pr >= 0 && t.basis[size_t(r)] < t.basis[size_t(pr)])) best = ratio, pr = r;
    }
    if (pr < 0) return false;  // unbounded: cannot happen with the box
    pivot(t, pr, pc);
  }
  return false;
}

}  // namespace

AffineFunction cornerDeterminantIn(const std::array<Vec3, 4>& p, int k) {
  const Vec3 e1 = p[1] - p[0], e2 = p[2] - p[0], e3 = p[3] - p[0];
  if (k == 0) {  // det(a-q, b-q, c-q) = det(a, b, c) - q . (b x c + c x a + a x b)
    return {Vec3{} - (cross(p[2], p[3]) + cross(p[3], p[1]) + cross(p[1], p[2])), det3(p[1], p[2], p[3])};
  }
  const Vec3 n = k == 1 ? cross(e2, e3) : k == 2 ? cross(e3, e1) : cross(e1, e2);
  return {n, -dot(n, p[0])};
}

Vec3 maximiseMinimum(const std::vector<AffineFunction>& fs, Vec3 p0, double radius) {
  if (fs.empty() || !(radius > 0)) return p0;
  // p = p0 - radius + v (v in [0, 2 radius]^3), t = tLow + tau (tau >= 0), where tLow is the
  // smallest value at the box corner v = 0, so v = 0, tau = 0 is feasible.
  const Vec3 corner = p0 - Vec3{radius, radius, radius};
  double tLow = std::numeric_limits<double>::infinity();
  for (const AffineFunction& f : fs) tLow = std::min(tLow, dot(f.g, corner) + f.h);
  const int vars = 4, rows = int(fs.size()) + 3;
  Tableau t;
  t.rows = rows;
  t.cols = vars + rows + 1;
  t.a.assign(size_t(rows + 1) * size_t(t.cols), 0.0);
  t.basis.resize(size_t(rows));
  const int rhs = t.cols - 1;
  for (int r = 0; r < rows; ++r) {
    if (r < int(fs.size())) {  // tau - g . v <= f(corner) - tLow
      const AffineFunction& f = fs[size_t(r)];
      t.at(r, 0) = 1, t.at(r, 1) = -f.g.x, t.at(r, 2) = -f.g.y, t.at(r, 3) = -f.g.z;
      t.at(r, rhs) = dot(f.g, corner) + f.h - tLow;
    } else {  // v_i <= 2 radius
      t.at(r, 1 + r - int(fs.size())) = 1;
      t.at(r, rhs) = 2 * radius;
    }
    t.at(r, vars + r) = 1;
    t.basis[size_t(r)] = vars + r;
  }
  t.at(rows, 0) = -1;  // maximise tau
  if (!solve(t)) return p0;
  double x[4] = {0, 0, 0, 0};
  for (int r = 0; r < rows; ++r)
    if (t.basis[size_t(r)] < vars) x[t.basis[size_t(r)]] = t.at(r, rhs);
  return corner + Vec3{x[1], x[2], x[3]};
}

}  // namespace hexdual
