#include <doctest/doctest.h>

#include <algorithm>

#include "complex/builders.hpp"
#include "complex/canonical.hpp"
#include "flips/decompositions.hpp"
#include "flips/fourcube.hpp"
#include "helpers.hpp"
#include "ops/oplog.hpp"
#include "ops/ops.hpp"
#include "ops/ring_splits.hpp"

using namespace hexdual;
using namespace hexdual::test;

namespace {
// The edge that quads f and g of a ring split's band share, named from f's hex.
EdgeRef sharedEdge(const Complex& cx, const OpArg& band) {
  std::vector<int> corners;
  for (int p = 0; p < 4; ++p) {
    int c = tables::kFaceCorners[size_t(band.local)][size_t(p)];
    VertexId v = cx.vertex(band.hex, c);
    for (int q = 0; q < 4; ++q)
      if (cx.vertex(band.second.hex, tables::kFaceCorners[size_t(band.second.face)][size_t(q)]) == v) corners.push_back(c);
  }
  REQUIRE(corners.size() == 2);
  return {band.hex, tables::edgeBetween(corners[0], corners[1])};
}

std::vector<std::string> texts(const std::vector<OpStep>& steps) {
  std::vector<std::string> out;
  for (const OpStep& s : steps) out.push_back(formatOpStep(s));
  return out;
}

// Every stored ring split of `problem`, checked from every edge of its loop: offered verbatim, or
// (`sameResult`, records of the first search engine, which wrote quad sides differently) as a
// split that gives the same complex.
int checkStoredRingSplits(const std::string& problem, bool sameResult = false) {
  const StoredDecomposition* d = storedFor(problem);
  REQUIRE(d != nullptr);
  Complex cx = makeFourCubeBoundary();
  int checked = 0;
  for (const OpStep& step : d->steps) {
    if (step.op == OpKind::RingSplit) {
      const std::string want = formatOpStep(step);
      for (const OpArg& band : step.args) {
        std::vector<OpStep> offered = ringSplitsThrough(cx, sharedEdge(cx, band));
        std::vector<std::string> got = texts(offered);
        INFO(problem << ": " << want << " through " << band.hex << "; offered " << got.size());
        if (!sameResult) {
          CHECK(std::find(got.begin(), got.end(), want) != got.end());
        } else {
          Complex target = cx;
          applyStep(target, step);
          CHECK(std::any_of(offered.begin(), offered.end(), [&](const OpStep& s) {
            Complex x = cx;
            applyStep(x, s);
            return canonicalHash(x) == canonicalHash(target);
          }));
        }
        ++checked;
      }
    }
    applyStep(cx, step);
  }
  return checked;
}
}  // namespace

TEST_CASE("ring splits through an edge: every stored ring split is offered verbatim at each edge of its loop") {
  // 4-4v: three ring splits of 4, 4 and 6 edges; 5-3c: one of 4 edges.
  CHECK(checkStoredRingSplits("4-4v") == 4 + 4 + 6);
  CHECK(checkStoredRingSplits("5-3c", true) == 4);
}

TEST_CASE("ring splits through an edge: the hex push of the 4-cube is one of them (docs/flips.md)") {
  Complex cx = makeFourCubeBoundary();
  OpStep want = parseOpStep("ringsplit h6f0/h2f4 h0f3/h2f3 h0f5/h2f5 h0f2/h2f2");
  std::vector<std::string> got = texts(ringSplitsThrough(cx, sharedEdge(cx, want.args[0])));
  CHECK(std::find(got.begin(), got.end(), formatOpStep(want)) != got.end());
  // The same split gives the 2-6 flip's result (the hex push h0f0 on the quad between facets 0 and 2).
  Complex pushed = makeFourCubeBoundary(), split = makeFourCubeBoundary();
  applyStep(pushed, parseOpStep("hexpush h0f0"));
  applyStep(split, want);
  CHECK(canonicalHash(pushed) == canonicalHash(split));
}

TEST_CASE("ring splits through an edge: each applies and adds one hex per band; a ring collapse is undone by one of them") {
  Complex cx = makeRing(8, 3, 3);
  const Complex start = cx;
  // The middle ring of the O-grid: hex (t=0, s=1, k=1) = 25, its y-edge 4 runs around the ring.
  OpResult r = ringCollapse(cx, {25, 4});
  REQUIRE(r.inverse.has_value());
  EdgeRef e = sharedEdge(cx, r.inverse->args[0]);
  std::vector<OpStep> splits = ringSplitsThrough(cx, e, 8);
  CHECK(!splits.empty());
  int undoes = 0;
  for (const OpStep& s : splits) {
    Complex work = cx;
    const int64_t hexes = work.numHexes();
    applyStep(work, s);
    work.validate();
    CHECK(work.numHexes() - hexes == int64_t(s.args.size()));
    undoes += canonicalHash(work) == canonicalHash(start);
  }
  MESSAGE(splits.size() << " ring splits through " << e.hex << "e" << e.edge << "; " << undoes << " give back the O-grid");
  CHECK(splits.size() == 54);
  CHECK(undoes == 2);  // the split back, with either side of the first quad keeping the loop's vertex ids
  CHECK_THROWS_WITH(ringSplitsThrough(cx, {999, 0}), "ringsplit: no edge h999e0");
}
