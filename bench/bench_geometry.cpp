// Geometry after every step (docs/operations.md, "Geometry after every step"): for random
// candidate steps of every kind on the given meshes, how many leave a regular hex (not degenerate
// by construction) newly inverted, with the smoothing off (the operations' own placement,
// measured) and on; and what the smoothing costs per step, by kind, on grids of two sizes.
//   hexdual_bench_geometry [--steps N] [--seed S] [--cost-only] [--no-cost] [--list] FILE|grid:N|ring:A,R,Z ...
// (--list: prints each step the smoothing leaves with a newly inverted hex that is not certified;
// --kind NAME: that kind only.)
// An inverse kind (unpillow, chordpull, hexpull, ringsplit, facesplit) has no candidates on a
// fresh mesh: its steps are the reported inverses of random steps of the kind before it, which
// are applied first (smoothed).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "complex/builders.hpp"
#include "geometry/degenerate.hpp"
#include "geometry/quality_stats.hpp"
#include "geometry/scaled_jacobian.hpp"
#include "io/io.hpp"
#include "ops/candidates.hpp"
#include "ops/op_table.hpp"
#include "ops/oplog.hpp"

using namespace hexdual;

namespace {

constexpr StepOptions kMeasure{StepGeometry::Measure};

Complex readMesh(const std::string& path) {
  if (path.rfind("grid:", 0) == 0) {
    const int n = std::atoi(path.c_str() + 5);
    return makeGrid(n, n, n);
  }
  if (path.rfind("ring:", 0) == 0) {
    int a = 0, r = 0, z = 0;
    if (std::sscanf(path.c_str() + 5, "%d,%d,%d", &a, &r, &z) != 3) throw Error("ring:A,R,Z expected: " + path);
    return makeRing(a, r, z);
  }
  if (path.size() < 3 || path.substr(path.size() - 3) != ".gz") return io::readFile(path);
  const std::string base = path.substr(path.rfind('/') + 1);
  const std::string tmp =
      "/tmp/hexdual-bench-geometry-" + base.substr(0, base.size() - 3);  // keeps the format's extension
  if (std::system(("gzip -dc '" + path + "' > '" + tmp + "'").c_str()) != 0) throw Error("gzip failed: " + path);
  return io::readFile(tmp);
}

// Regular hexes inverted now (ids): a step's inverted hexes outside this set are new.
std::set<HexId> regularInverted(const Complex& cx) {
  std::set<HexId> out;
  for (HexId h : cx.hexes())
    if (scaledJacobian(cx, h) <= 0 && !degenerateByConstruction(cx, h)) out.insert(h);
  return out;
}

int newlyInverted(const StepQuality& q, const std::set<HexId>& before) {
  int n = 0;
  for (HexId h : q.inverted) n += !before.count(h);
  return n;
}

// A random step of `kind` on cx (after `setup`, applied smoothed, when kind is an inverse).
struct Sample {
  std::vector<OpStep> setup;
  OpStep step;
};

std::optional<Sample> sample(const Complex& cx, OpKind kind, const std::vector<std::vector<OpStep>>& byKind,
                             std::mt19937& rng) {
  const std::vector<OpStep>& own = byKind[size_t(kind)];
  if (!own.empty()) return Sample{{}, own[rng() % own.size()]};
  const int k = int(kind);
  if (k % 2 == 0 || byKind[size_t(k - 1)].empty())
    return std::nullopt;  // the table pairs each kind with its inverse next
  const std::vector<OpStep>& fwd = byKind[size_t(k - 1)];
  for (int tries = 0; tries < 20; ++tries) {
    const OpStep& f = fwd[rng() % fwd.size()];
    Complex probe = cx;
    OpResult r = applyStep(probe, f, kSmoothStep);
    if (r.inverse && r.inverse->op == kind) return Sample{{f}, *r.inverse};
  }
  return std::nullopt;
}

// Whether an entity the step names (a hex's corners, a quad's, an edge's ends) is on the boundary.
bool namesBoundary(const Complex& cx, const OpStep& st, const std::set<VertexId>& boundary) {
  auto quad = [&](QuadSide q) {
    for (int c : tables::kFaceCorners[size_t(q.face)])
      if (boundary.count(cx.vertex(q.hex, c))) return true;
    return false;
  };
  for (const OpArg& a : st.args) {
    if (a.kind == OpArg::Hex)
      for (VertexId v : cx.hexVertices(a.hex))
        if (boundary.count(v)) return true;
    if ((a.kind == OpArg::Quad || a.kind == OpArg::Pair) && quad(a.quad())) return true;
    if (a.kind == OpArg::Pair && quad(a.second)) return true;
    if (a.kind == OpArg::Edge)
      for (int c : tables::kEdgeCorners[size_t(a.local)])
        if (boundary.count(cx.vertex(a.hex, c))) return true;
  }
  return false;
}

struct Tally {
  int steps = 0, off = 0, on = 0, onPinned = 0, onBoundary = 0, degenerate = 0, widened = 0, kept = 0;
  double worstOff = 1, worstOn = 1;
  int64_t evaluations = 0, maxEvaluations = 0;
};

bool gList = false;
std::string gKind;  // --kind NAME: only that kind (and, for an inverse kind, its forward steps)  // --list: print each smoothed step that leaves an uncertified newly inverted hex

void measureStep(Complex& cx, const Sample& s, Tally& t) {
  std::set<VertexId> boundary;
  for (const auto& q : cx.boundaryQuads()) boundary.insert(q.vertices.begin(), q.vertices.end());
  std::vector<Complex::EditLog> undo;
  for (const OpStep& st : s.setup) undo.push_back(applyStep(cx, st, kSmoothStep).edits);
  const std::set<HexId> before = regularInverted(cx);
  const bool atBoundary = namesBoundary(cx, s.step, boundary);
  OpResult off = applyStep(cx, s.step, kMeasure);
  cx.undo(off.edits);
  OpResult on = applyStep(cx, s.step, kSmoothStep);
  if (gList && newlyInverted(on.quality, before) > 0 && on.quality.pinned.size() != on.quality.inverted.size()) {
    std::string setup;
    for (const OpStep& st : s.setup) setup += formatOpStep(st) + ";";
    std::printf("    uncertified: %.100s%.100s  inverted %zu pinned %zu rings %d kept %d\n", setup.c_str(),
                formatOpStep(s.step).c_str(), on.quality.inverted.size(), on.quality.pinned.size(), on.quality.rings,
                int(on.quality.kept));
  }
  cx.undo(on.edits);
  for (auto it = undo.rbegin(); it != undo.rend(); ++it) cx.undo(*it);
  ++t.steps;
  t.off += newlyInverted(off.quality, before) > 0;
  const bool inv = newlyInverted(on.quality, before) > 0;
  t.on += inv;
  t.onPinned += inv && on.quality.pinned.size() == on.quality.inverted.size();
  t.onBoundary += inv && atBoundary;
  t.degenerate += !on.quality.degenerate.empty();
  t.widened += on.quality.rings > 0;
  t.kept += on.quality.kept;
  t.worstOff = std::min(t.worstOff, off.quality.afterRegular);
  t.worstOn = std::min(t.worstOn, on.quality.afterRegular);
  t.evaluations += on.quality.evaluations;
  t.maxEvaluations = std::max(t.maxEvaluations, on.quality.evaluations);
}

void randomSteps(const std::string& name, Complex& cx, int perKind, unsigned seed) {
  const QualityStats q = qualityStats(cx);
  std::printf("%s: %lld hexes, scaled Jacobian min %.4f, %lld <= 0\n", name.c_str(), (long long)q.hexes, q.min,
              (long long)q.nonPositive);
  std::vector<std::vector<OpStep>> byKind;
  for (const OpInfo& info : allOps())
    byKind.push_back(info.candidates == CandidateSet::None ? std::vector<OpStep>{} : candidates(cx, info.kind));
  std::mt19937 rng(seed);
  for (const OpInfo& info : allOps()) {
    if (!gKind.empty() && gKind != info.name) continue;
    Tally t;
    for (int k = 0; k < perKind; ++k)
      if (std::optional<Sample> s = sample(cx, info.kind, byKind, rng)) measureStep(cx, *s, t);
    if (t.steps == 0) {
      std::printf("  %-13s no steps\n", info.name);
      continue;
    }
    std::printf(
        "  %-13s steps %4d  newly inverted: off %4d (%5.1f%%)  on %4d (%5.1f%%; %d certified, %d naming a boundary "
        "vertex)  widened %4d  kept %3d  "
        "degenerate pair %4d  worst regular SJ off %7.3f on %7.3f  evaluations mean %lld max %lld\n",
        info.name, t.steps, t.off, 100.0 * t.off / t.steps, t.on, 100.0 * t.on / t.steps, t.onPinned, t.onBoundary,
        t.widened, t.kept, t.degenerate, t.worstOff, t.worstOn, (long long)(t.evaluations / t.steps),
        (long long)t.maxEvaluations);
  }
}

// A step at the centre of an n^3 grid for each kind: candidates of a 4^3 grid naming its hex
// (1,1,1) (every id moved to the centre), and the inverses of those.
OpStep centred(OpStep st, int n) {
  const int c = n / 2 - 1;
  auto move = [&](HexId h) { return (h % 4 + c) + n * ((h / 4 % 4 + c) + n * (h / 16 + c)); };
  for (OpArg& a : st.args) {
    a.hex = move(a.hex);
    if (a.kind == OpArg::Pair) a.second.hex = move(a.second.hex);
  }
  return st;
}

std::optional<Sample> centreSample(OpKind kind) {
  Complex small = makeGrid(4, 4, 4);
  std::vector<std::vector<OpStep>> byKind;
  for (const OpInfo& info : allOps()) {
    byKind.emplace_back();
    if (info.candidates == CandidateSet::None) continue;
    for (const OpStep& st : candidates(small, info.kind))
      if (st.args[0].hex == 21) byKind.back().push_back(st);  // hex (1,1,1)
  }
  std::mt19937 rng(1);
  return sample(small, kind, byKind, rng);
}

// CPU µs of one step at the centre of an n^3 grid (minimum of `reps`, measured and smoothed
// interleaved), with the smoothing's corner-energy evaluations.
void cost(int n, OpKind kind, int reps) {
  std::optional<Sample> s = centreSample(kind);
  if (!s) return;
  Complex cx = makeGrid(n, n, n);
  OpStep st = centred(s->step, n);
  for (const OpStep& setup : s->setup) {  // an inverse kind: the inverse of its forward step, here
    OpResult r = applyStep(cx, centred(setup, n), kSmoothStep);
    st = *r.inverse;
  }
  double best[2] = {1e30, 1e30};
  StepQuality q;
  for (int r = 0; r < reps; ++r)
    for (int smooth = 0; smooth < 2; ++smooth) {
      const auto t0 = std::chrono::steady_clock::now();
      OpResult res = applyStep(cx, st, smooth ? kSmoothStep : kMeasure);
      const auto t1 = std::chrono::steady_clock::now();
      best[smooth] = std::min(best[smooth], std::chrono::duration<double, std::micro>(t1 - t0).count());
      if (smooth) q = res.quality;
      cx.undo(res.edits);
    }
  std::printf(
      "  grid %2d^3 %-38s measured %8.1f us  smoothed %8.1f us  (+%8.1f us; %6lld evaluations, %3zu vertices moved, %d "
      "rings)\n",
      n, formatOpStep(st).c_str(), best[0], best[1], best[1] - best[0], (long long)q.evaluations, q.moved.size(),
      q.rings);
}

}  // namespace

int main(int argc, char** argv) {
  int perKind = 100;
  unsigned seed = 20261122;
  bool costs = true, samples = true;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--steps" && i + 1 < argc)
      perKind = std::atoi(argv[++i]);
    else if (a == "--seed" && i + 1 < argc)
      seed = unsigned(std::strtoul(argv[++i], nullptr, 10));
    else if (a == "--cost-only")
      samples = false;
    else if (a == "--no-cost")
      costs = false;
    else if (a == "--list")
      gList = true;
    else if (a == "--kind" && i + 1 < argc)
      gKind = argv[++i];
    else
      files.push_back(a);
  }
  if (samples) {
    std::printf("seed %u, %d random candidate steps per kind (each applied measured, undone, smoothed, undone)\n", seed,
                perKind);
    for (const std::string& f : files) {
      try {
        Complex cx = readMesh(f);
        randomSteps(f.substr(f.rfind('/') + 1), cx, perKind, seed);
      } catch (const Error& e) {  // a refused file (P_hex_sphere is mislabelled): say so, go on
        std::printf("%s: refused: %s\n", f.c_str(), e.what());
      }
      std::fflush(stdout);
    }
  }
  if (!costs) return 0;
  std::printf("cost per step at the centre of a grid (wall-clock us, minimum of 7, measured/smoothed interleaved)\n");
  for (const OpInfo& info : allOps())
    for (int n : {10, 60}) cost(n, info.kind, 7);
  return 0;
}
