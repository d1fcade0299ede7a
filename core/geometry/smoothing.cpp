#include "geometry/smoothing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "complex/hex_tables.hpp"

namespace hexdual {

namespace {

constexpr int kMaxSweeps = 60;
constexpr int kMaxUntangleSweeps = 30;
constexpr double kEpsilon = 1e-3;    // Escobar's epsilon, times the region's volume scale
constexpr double kConverged = 1e-2;  // a sweep whose largest move is below this (times the vertex scale) ends them
constexpr double kArmijo = 1e-4;

double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
double& coord(Vec3& p, int d) { return d == 0 ? p.x : d == 1 ? p.y : p.z; }

// Cholesky of the symmetric 3x3 `a` plus mu on the diagonal; false when not positive definite.
bool cholesky(const double a[3][3], double mu, double l[3][3]) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j <= i; ++j) {
      double s = a[i][j] + (i == j ? mu : 0);
      for (int k = 0; k < j; ++k) s -= l[i][k] * l[j][k];
      if (i == j) {
        if (!(s > 0)) return false;
        l[i][i] = std::sqrt(s);
      } else {
        l[i][j] = s / l[j][j];
      }
    }
  return true;
}

// Solves (H + mu I) d = -g with the smallest mu in 0, m, 10m, ... that makes it positive definite
// (m: a thousandth of H's largest diagonal entry); false when none of them does.
bool newtonDirection(const double h[3][3], Vec3 g, Vec3& d) {
  double l[3][3] = {};
  const double m = 1e-3 * std::max({std::fabs(h[0][0]), std::fabs(h[1][1]), std::fabs(h[2][2]), 1e-300});
  double mu = 0;
  for (int tries = 0; !cholesky(h, mu, l); ++tries) {
    if (tries == 12) return false;
    mu = tries == 0 ? m : 10 * mu;
  }
  const double b[3] = {-g.x, -g.y, -g.z};
  double y[3], x[3];
  for (int i = 0; i < 3; ++i) {
    double s = b[i];
    for (int k = 0; k < i; ++k) s -= l[i][k] * y[k];
    y[i] = s / l[i][i];
  }
  for (int i = 2; i >= 0; --i) {
    double s = y[i];
    for (int k = i + 1; k < 3; ++k) s -= l[k][i] * x[k];
    x[i] = s / l[i][i];
  }
  d = {x[0], x[1], x[2]};
  return true;
}

// The Hessian of vertex i's energy at p by forward differences of the gradient g there (symmetrised);
// false when a probe hits the barrier.
bool hessian(SmoothingRegion& r, size_t i, Vec3 p, Vec3 g, double delta2, double out[3][3]) {
  const double step = 1e-6 * r.scale[i];
  double col[3][3];
  for (int d = 0; d < 3; ++d) {
    Vec3 q = p, gd;
    coord(q, d) += step;
    if (std::isinf(vertexEnergy(r, i, q, delta2, &gd))) return false;
    const Vec3 diff = (1 / step) * (gd - g);
    col[d][0] = diff.x, col[d][1] = diff.y, col[d][2] = diff.z;
  }
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) out[a][b] = 0.5 * (col[a][b] + col[b][a]);
  return true;
}

// One damped Newton step of free vertex i (steepest descent when the Hessian is unusable), at most
// one vertex scale long, backtracked until the energy falls enough. Returns the move / scale.
double newtonStep(SmoothingRegion& r, size_t i, double delta2) {
  const double s = r.scale[i];
  if (s <= 0 || r.incidence[i].empty()) return 0;
  const Vec3 p = r.pos[i];
  Vec3 g;
  const double f0 = vertexEnergy(r, i, p, delta2, &g);
  const double gn = std::sqrt(dot(g, g));
  if (!std::isfinite(f0) || gn == 0) return 0;
  double h[3][3];
  Vec3 dir;
  if (!hessian(r, i, p, g, delta2, h) || !newtonDirection(h, g, dir) || !(dot(g, dir) < 0)) dir = (-s / gn) * g;
  const double len = std::sqrt(dot(dir, dir));
  if (len > s) dir = (s / len) * dir;
  const double slope = dot(g, dir);
  for (double t = 1; t > 1e-4; t *= 0.5) {
    const Vec3 q = p + t * dir;
    if (vertexEnergy(r, i, q, delta2, nullptr) <= f0 + kArmijo * t * slope) {
      r.pos[i] = q;
      return t * std::sqrt(dot(dir, dir)) / s;
    }
  }
  return 0;
}

// Sweeps until the barrier phase converges, the softened phase stalls, kMaxSweeps, or the budget.
int sweep(SmoothingRegion& r) {
  const double eps = kEpsilon * r.volumeScale;
  r.doomedDelta2 = eps * eps;
  int n = 0;
  while (n < kMaxSweeps && r.evaluations < r.budget) {
    const double sigma = minCornerDeterminant(r);
    const double delta2 = sigma < eps ? eps * (eps - sigma) : 0;
    double largest = 0;
    for (size_t i = 0; i < r.free.size(); ++i) largest = std::max(largest, newtonStep(r, i, delta2));
    ++n;
    if (largest < kConverged) break;
  }
  return n;
}

double minimumOf(const std::vector<AffineFunction>& fs, Vec3 p) {
  double m = std::numeric_limits<double>::infinity();
  for (const AffineFunction& f : fs) m = std::min(m, dot(f.g, p) + f.h);
  return m;
}

// Freitag-Plassmann sweeps: each free vertex in turn to where the smallest (scaled) determinant
// of its corners is largest, within half its scale; until every corner in the energy is positive,
// a sweep gains nothing, or kMaxUntangleSweeps.
int untangle(SmoothingRegion& r) {
  int n = 0;
  while (n < kMaxUntangleSweeps && r.evaluations < r.budget && !(minCornerDeterminant(r) > 0)) {
    bool gained = false;
    for (size_t i = 0; i < r.free.size(); ++i) {
      const std::vector<AffineFunction> fs = cornerFunctions(r, i);
      const Vec3 q = maximiseMinimum(fs, r.pos[i], 0.5 * r.scale[i]);
      if (minimumOf(fs, q) > minimumOf(fs, r.pos[i]) + 1e-9 && keepsFloors(r, i, q)) r.pos[i] = q, gained = true;
    }
    ++n;
    if (!gained) break;
  }
  return n;
}

// How good the positions are: fewer inverted counted hexes, then a larger smallest scaled corner.
struct Outcome {
  int inverted = 0;
  double worst = 0;
  bool betterThan(const Outcome& o) const {
    return inverted < o.inverted || (inverted == o.inverted && worst > o.worst);
  }
};
Outcome outcome(const SmoothingRegion& r) { return {invertedHexes(r), worstScaledCorner(r)}; }

// The best positions seen at the checkpoints (the first of equals): a later phase can lose what an
// earlier one reached (the softened sweeps after a max-min untangling may tangle a corner again).
struct BestSeen {
  bool any = false;
  Outcome outcome;
  std::vector<Vec3> pos;
  void offer(const SmoothingRegion& r) {
    const Outcome o = hexdual::outcome(r);
    if (!any || o.betterThan(outcome)) any = true, outcome = o, pos = r.pos;
  }
};

// One attempt from the current positions: Escobar sweeps, and while tangled max-min untangling
// then Escobar again; with maxMinFirst the untangling goes first. Offers each phase's result.
int attempt(SmoothingRegion& r, bool maxMinFirst, BestSeen& best) {
  int n = 0;
  if (maxMinFirst && !(minCornerDeterminant(r) > 0)) n += untangle(r), best.offer(r);
  n += sweep(r);
  best.offer(r);
  if (!(minCornerDeterminant(r) > 0)) n += untangle(r), best.offer(r), n += sweep(r), best.offer(r);
  return n;
}

// A third start: each free vertex at the mean, over the faces of its hexes whose other three
// vertices are not free, of the point completing the face as a parallelogram (the face's two
// neighbours of the corner, less the opposite one); a vertex with no such face keeps its start.
// The sweeps move one vertex at a time, so two free vertices of a hex whose six others are fixed
// can close on each other, every corner between them going to zero and none above it (a hex push
// whose new hex has two boundary quads on a curved boundary: P_joint); from here they start apart.
std::vector<Vec3> parallelogramStart(const SmoothingRegion& r, const std::vector<Vec3>& start) {
  std::vector<Vec3> out = start;
  for (size_t i = 0; i < r.free.size(); ++i) {
    Vec3 sum;
    int n = 0;
    for (auto [hx, c] : r.incidence[i])
      for (int f : tables::facesOfCorner(c)) {
        const auto& face = tables::kFaceCorners[size_t(f)];
        const int k = tables::positionInFace(f, c);
        const auto& ref = r.corners[size_t(hx)];
        const int32_t prev = ref[size_t(face[size_t((k + 3) & 3)])];
        const int32_t next = ref[size_t(face[size_t((k + 1) & 3)])];
        const int32_t opposite = ref[size_t(face[size_t((k + 2) & 3)])];
        if (prev >= 0 || next >= 0 || opposite >= 0) continue;  // a free vertex among them
        sum = sum + r.at(prev) + r.at(next) - r.at(opposite);
        ++n;
      }
    if (n) out[i] = (1.0 / n) * sum;
  }
  return out;
}

}  // namespace

SmoothingStats smoothVertices(Complex& cx, std::vector<FreeVertex> free, const std::vector<HexId>& near,
                              int64_t budget, bool validBefore) {
  std::sort(free.begin(), free.end(), [](const FreeVertex& a, const FreeVertex& b) { return a.vertex < b.vertex; });
  SmoothingRegion r = buildSmoothingRegion(cx, free, near);
  r.budget = budget;
  SmoothingStats st;
  const std::vector<Vec3> start = r.pos;
  const Outcome before = outcome(r);
  BestSeen best;
  st.sweeps = attempt(r, false, best);
  r.pos = best.pos;
  if (!(minCornerDeterminant(r) > 0)) {  // still tangled: again from the start, max-min untangling first
    r.pos = start;
    st.sweeps += attempt(r, true, best);
    r.pos = best.pos;
  }
  // Still tangled: once more from the faces' parallelograms, kept only when it untangles every
  // counted hex; only where no hex around was inverted before the step (on a mesh tangled already,
  // ECR_block_stresstest_in, it traded the counted hexes for new inversions and took the budget of
  // the wider rings).
  if (validBefore && !(minCornerDeterminant(r) > 0)) {
    BestSeen restart;
    r.pos = parallelogramStart(r, start);
    st.sweeps += attempt(r, false, restart);
    if (restart.outcome.inverted == 0 && best.outcome.inverted > 0) best = restart;
    r.pos = best.pos;
  }
  if (before.betterThan(best.outcome)) r.pos = start, best.outcome = before;  // never worse than the operation's own placement
  st.invertedBefore = before.inverted;
  st.invertedAfter = best.outcome.inverted;
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
