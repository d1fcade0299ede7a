// Geometry after every step (docs/operations.md): for random candidate steps of every kind on the
// given meshes, how many leave a hex inverted that is not degenerate by construction, with the
// smoothing off and on; and the smoothing's cost per step on grids of two sizes.
//   hexdual_bench_geometry [--steps N] [--seed S] FILE...
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "complex/builders.hpp"
#include "geometry/quality_stats.hpp"
#include "io/io.hpp"
#include "ops/candidates.hpp"
#include "ops/op_table.hpp"
#include "ops/oplog.hpp"

using namespace hexdual;

namespace {

Complex readMesh(const std::string& path) {
  if (path.size() < 3 || path.substr(path.size() - 3) != ".gz") return io::readFile(path);
  const std::string base = path.substr(path.rfind('/') + 1);
  const std::string tmp = "/tmp/hexdual-bench-geometry-" + base.substr(0, base.size() - 3);  // keeps the format's extension
  if (std::system(("gzip -dc '" + path + "' > '" + tmp + "'").c_str()) != 0) throw Error("gzip failed: " + path);
  return io::readFile(tmp);
}

struct Tally {
  int steps = 0, invertedOff = 0, invertedOn = 0, degenerate = 0;
  double minAfterOff = 1, minAfterOn = 1;  // over the steps' afterRegular
};

void randomSteps(const std::string& name, Complex& cx, int perKind, unsigned seed) {
  const QualityStats q = qualityStats(cx);
  std::printf("%s: %lld hexes, scaled Jacobian min %.3f, %lld <= 0\n", name.c_str(), (long long)q.hexes, q.min, (long long)q.nonPositive);
  std::mt19937 rng(seed);
  for (const OpInfo& info : allOps()) {
    if (info.candidates == CandidateSet::None) continue;
    const std::vector<OpStep> steps = candidates(cx, info.kind);
    Tally t;
    for (int k = 0; k < perKind && !steps.empty(); ++k) {
      const OpStep& st = steps[rng() % steps.size()];
      OpResult off = applyStep(cx, st, StepOptions{false});
      cx.undo(off.edits);
      OpResult on = applyStep(cx, st, StepOptions{true});
      cx.undo(on.edits);
      ++t.steps;
      t.invertedOff += !off.quality.inverted.empty();
      t.invertedOn += !on.quality.inverted.empty();
      t.degenerate += !on.quality.degenerate.empty();
      t.minAfterOff = std::min(t.minAfterOff, off.quality.afterRegular);
      t.minAfterOn = std::min(t.minAfterOn, on.quality.afterRegular);
    }
    std::printf("  %-13s candidates %6zu  steps %4d  inverted: off %4d (%5.1f%%)  on %4d (%5.1f%%)  degenerate pair %4d  worst regular SJ off %.3f on %.3f\n",
                info.name, steps.size(), t.steps, t.invertedOff, t.steps ? 100.0 * t.invertedOff / t.steps : 0.0, t.invertedOn,
                t.steps ? 100.0 * t.invertedOn / t.steps : 0.0, t.degenerate, t.minAfterOff, t.minAfterOn);
  }
}

// CPU µs of one step (minimum of `reps`), smoothing off and on, at the centre of an n^3 grid.
void cost(int n, const char* stepText, int reps) {
  Complex cx = makeGrid(n, n, n);
  const OpStep st = parseOpStep(stepText);
  double best[2] = {1e30, 1e30};
  int64_t evaluations = 0;
  for (int r = 0; r < reps; ++r)
    for (int smooth = 0; smooth < 2; ++smooth) {
      const auto t0 = std::chrono::steady_clock::now();
      OpResult res = applyStep(cx, st, StepOptions{smooth == 1});
      const auto t1 = std::chrono::steady_clock::now();
      best[smooth] = std::min(best[smooth], std::chrono::duration<double, std::micro>(t1 - t0).count());
      evaluations = res.quality.evaluations;
      cx.undo(res.edits);
    }
  std::printf("  grid %d^3 %-28s off %8.1f us  on %8.1f us  (smoothing +%.1f us, %lld hex evaluations)\n", n, stepText, best[0], best[1],
              best[1] - best[0], (long long)evaluations);
}

}  // namespace

int main(int argc, char** argv) {
  int perKind = 100;
  unsigned seed = 20261122;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--steps" && i + 1 < argc) perKind = std::atoi(argv[++i]);
    else if (a == "--seed" && i + 1 < argc) seed = unsigned(std::strtoul(argv[++i], nullptr, 10));
    else files.push_back(a);
  }
  std::printf("seed %u, %d random candidate steps per kind (each applied with smoothing off, undone, on, undone)\n", seed, perKind);
  for (const std::string& f : files) {
    Complex cx = readMesh(f);
    randomSteps(f.substr(f.rfind('/') + 1), cx, perKind, seed);
  }
  std::printf("cost per step (CPU us, minimum of 7, off/on interleaved)\n");
  for (int n : {10, 60}) {
    const int c = n / 2, h = c + n * (c + n * c);  // hex (c, c, c)
    cost(n, ("hexpush h" + std::to_string(h) + "f1").c_str(), 7);
    cost(n, ("pillow h" + std::to_string(h) + "f1").c_str(), 7);
    cost(n, ("chordpush h" + std::to_string(h) + "e0 h" + std::to_string(h) + "f2 h" + std::to_string(h) + "f4").c_str(), 7);
  }
  return 0;
}
