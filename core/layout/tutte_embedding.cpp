#include "layout/tutte_embedding.hpp"

#include <Eigen/Sparse>
#include <algorithm>

namespace hexdual {

// Neighbours in compressed rows: vertex v's are nb[start[v] .. start[v+1]), with weights w.
struct DiskSolver::Impl {
  int n = 0, m = 0;
  std::vector<int> start, nb;
  std::vector<double> w;
  std::vector<int> unk;           // per vertex: its unknown, or -1 (fixed, unused or eliminated)
  std::vector<double> W;          // per vertex: its total weight (used for eliminated centres)
  std::vector<uint8_t> kind;      // 0 unused, 1 fixed, 2 unknown, 3 eliminated centre
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;
  bool ok = true;
};

namespace {

enum : uint8_t { kUnused, kFixed, kUnknown, kEliminated };

// Every triangle edge, once per triangle it bounds, merged into weights per neighbour.
void buildRows(const Triangulation& t, DiskSolver::Impl& s) {
  // Count, place (a counting sort by vertex), then merge repeats within each short row.
  std::vector<int> count(size_t(s.n) + 1, 0);
  for (const auto& tri : t.tris)
    for (int v : tri) count[size_t(v) + 1] += 2;
  for (int v = 0; v < s.n; ++v) count[size_t(v) + 1] += count[size_t(v)];
  std::vector<int> fill(count.begin(), count.end() - 1), raw(size_t(count.back()));
  for (const auto& tri : t.tris)
    for (int k = 0; k < 3; ++k) {
      int a = tri[size_t(k)], b = tri[size_t((k + 1) % 3)];
      raw[size_t(fill[size_t(a)]++)] = b;
      raw[size_t(fill[size_t(b)]++)] = a;
    }
  s.start.assign(size_t(s.n) + 1, 0);
  s.nb.reserve(raw.size() / 2 + 8);
  s.w.reserve(raw.size() / 2 + 8);
  for (int v = 0; v < s.n; ++v) {
    auto first = raw.begin() + count[size_t(v)], last = raw.begin() + count[size_t(v) + 1];
    std::sort(first, last);
    for (auto it = first; it != last; ++it) {
      if (it != first && *it == *(it - 1)) {
        s.w.back() += 1;
        continue;
      }
      s.nb.push_back(*it);
      s.w.push_back(1);
    }
    s.start[size_t(v) + 1] = int(s.nb.size());
  }
}

}  // namespace

DiskSolver::DiskSolver(const Triangulation& t, const std::vector<bool>& fixed) : impl_(std::make_unique<Impl>()) {
  Impl& s = *impl_;
  s.n = t.vertices;
  buildRows(t, s);
  s.kind.assign(size_t(s.n), kUnused);
  s.unk.assign(size_t(s.n), -1);
  s.W.assign(size_t(s.n), 0);
  for (int v = 0; v < s.n; ++v) {
    for (int k = s.start[size_t(v)]; k < s.start[size_t(v) + 1]; ++k) s.W[size_t(v)] += s.w[size_t(k)];
    if (s.start[size_t(v)] == s.start[size_t(v) + 1]) continue;  // a 4-triangle fan leaves mid vertices out
    s.kind[size_t(v)] = fixed[size_t(v)] ? kFixed : t.centre[size_t(v)] ? kEliminated : kUnknown;
    if (s.kind[size_t(v)] == kUnknown) s.unk[size_t(v)] = s.m++;
  }
  // Row p: W_p x_p - sum_{q unknown} w_pq x_q - sum_{c eliminated} w_pc (sum_b w_cb x_b) / W_c = rhs,
  // the fixed x_b moved to the right (in solve()).
  std::vector<Eigen::Triplet<double>> trip;
  trip.reserve(size_t(s.m) * 12);
  for (int p = 0; p < s.n; ++p) {
    const int row = s.unk[size_t(p)];
    if (row < 0) continue;
    auto link = [&](int b, double c) {  // -c x_b on the left
      if (s.kind[size_t(b)] == kUnknown) trip.push_back({row, s.unk[size_t(b)], -c});
    };
    trip.push_back({row, row, s.W[size_t(p)]});
    for (int k = s.start[size_t(p)]; k < s.start[size_t(p) + 1]; ++k) {
      int q = s.nb[size_t(k)];
      double wq = s.w[size_t(k)];
      if (s.kind[size_t(q)] != kEliminated) {
        link(q, wq);
        continue;
      }
      for (int j = s.start[size_t(q)]; j < s.start[size_t(q) + 1]; ++j)
        link(s.nb[size_t(j)], wq * s.w[size_t(j)] / s.W[size_t(q)]);
    }
  }
  if (s.m == 0) return;
  Eigen::SparseMatrix<double> L(s.m, s.m);
  L.setFromTriplets(trip.begin(), trip.end());
  s.ldlt.compute(L);
  s.ok = s.ldlt.info() == Eigen::Success;
}

DiskSolver::~DiskSolver() = default;
bool DiskSolver::ok() const { return impl_->ok; }

void DiskSolver::solve(std::vector<Point2>& pos, const std::vector<Point2>* rhs) const {
  const Impl& s = *impl_;
  auto b = [&](int v) { return rhs ? (*rhs)[size_t(v)] : Point2{}; };
  Eigen::VectorXd bx(s.m), by(s.m);
  for (int p = 0; p < s.n; ++p) {
    const int row = s.unk[size_t(p)];
    if (row < 0) continue;
    double x = b(p).x, y = b(p).y;
    for (int k = s.start[size_t(p)]; k < s.start[size_t(p) + 1]; ++k) {
      const int q = s.nb[size_t(k)];
      const double wq = s.w[size_t(k)];
      if (s.kind[size_t(q)] == kFixed) {
        x += wq * pos[size_t(q)].x;
        y += wq * pos[size_t(q)].y;
      } else if (s.kind[size_t(q)] == kEliminated) {  // the centre's own right-hand side, and its fixed neighbours
        const double f = wq / s.W[size_t(q)];
        x += f * b(q).x;
        y += f * b(q).y;
        for (int j = s.start[size_t(q)]; j < s.start[size_t(q) + 1]; ++j) {
          const int c = s.nb[size_t(j)];
          if (s.kind[size_t(c)] != kFixed) continue;
          x += f * s.w[size_t(j)] * pos[size_t(c)].x;
          y += f * s.w[size_t(j)] * pos[size_t(c)].y;
        }
      }
    }
    bx[row] = x;
    by[row] = y;
  }
  if (s.m > 0) {
    Eigen::VectorXd X = s.ldlt.solve(bx), Y = s.ldlt.solve(by);
    for (int v = 0; v < s.n; ++v)
      if (s.unk[size_t(v)] >= 0) pos[size_t(v)] = {X[s.unk[size_t(v)]], Y[s.unk[size_t(v)]]};
  }
  for (int v = 0; v < s.n; ++v) {
    if (s.kind[size_t(v)] != kEliminated) continue;
    double px = b(v).x, py = b(v).y;
    for (int k = s.start[size_t(v)]; k < s.start[size_t(v) + 1]; ++k) {
      px += s.w[size_t(k)] * pos[size_t(s.nb[size_t(k)])].x;
      py += s.w[size_t(k)] * pos[size_t(s.nb[size_t(k)])].y;
    }
    pos[size_t(v)] = {px / s.W[size_t(v)], py / s.W[size_t(v)]};
  }
}

double signedArea2(const Triangulation& t, const std::vector<Point2>& pos, size_t k) {
  Point2 a = pos[size_t(t.tris[k][0])], b = pos[size_t(t.tris[k][1])], c = pos[size_t(t.tris[k][2])];
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

int flippedTriangle(const Triangulation& t, const std::vector<Point2>& pos) {
  for (size_t k = 0; k < t.tris.size(); ++k)
    if (!(signedArea2(t, pos, k) > 0)) return int(k);
  return -1;
}

}  // namespace hexdual
