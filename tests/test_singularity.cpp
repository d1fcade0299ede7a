// The singularity graph (analysis/singularity.hpp) and the dual through an edge: exact counts on
// meshes built so their irregular edges are known (grids, an O-grid, n-gon prisms), after a hex
// push and a pillow, and on development meshes, each cross-checked by an independent count.
#include <doctest/doctest.h>

#include <cmath>
#include <map>
#include <set>

#include "analysis/edge_dual.hpp"
#include "analysis/singularity.hpp"
#include "complex/builders.hpp"
#include "dev_mesh.hpp"
#include "dual/dual.hpp"
#include "helpers.hpp"
#include "ops/oplog.hpp"

using namespace hexdual;
using namespace hexdual::test;

namespace {

// k layers of a square core and 4 hexes around it (an O-grid of a cylinder): the core's 4
// vertical edges have valence 3, the rims of the two end faces valence 1.
Complex makeOGrid(int layers) {
  std::vector<Vec3> pts;
  const double c[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (int z = 0; z <= layers; ++z)
    for (double scale : {1.0, 2.5})
      for (const auto& xy : c) pts.push_back({scale * xy[0], scale * xy[1], double(z)});
  std::vector<std::array<VertexId, 8>> hexes;
  auto quad = [&](std::array<int, 4> q, int z) {
    std::array<VertexId, 8> h;
    for (int k = 0; k < 4; ++k) h[size_t(k)] = 8 * z + q[size_t(k)], h[size_t(k + 4)] = 8 * (z + 1) + q[size_t(k)];
    hexes.push_back(h);
  };
  for (int z = 0; z < layers; ++z) {
    quad({0, 1, 2, 3}, z);
    for (int i = 0; i < 4; ++i) quad({i, 4 + i, 4 + (i + 1) % 4, (i + 1) % 4}, z);
  }
  return fromConnectivity(pts, hexes);
}

// k layers of an n-gon split into n quads around its centre: the axis has valence n, the n
// polygon corners' vertical edges and the two rims valence 1.
Complex makePrism(int n, int layers) {
  const double pi = std::acos(-1.0);
  std::vector<Vec3> pts;
  for (int z = 0; z <= layers; ++z) {
    pts.push_back({0, 0, double(z)});
    std::vector<Vec3> corner;
    for (int i = 0; i < n; ++i) corner.push_back({2 * std::cos(2 * pi * i / n), 2 * std::sin(2 * pi * i / n), double(z)});
    pts.insert(pts.end(), corner.begin(), corner.end());
    for (int i = 0; i < n; ++i) pts.push_back(0.5 * (corner[size_t(i)] + corner[size_t((i + 1) % n)]));
  }
  auto p = [&](int i, int z) { return VertexId(z * (1 + 2 * n) + 1 + (i + n) % n); };
  auto m = [&](int i, int z) { return VertexId(z * (1 + 2 * n) + 1 + n + (i + n) % n); };
  std::vector<std::array<VertexId, 8>> hexes;
  for (int z = 0; z < layers; ++z)
    for (int i = 0; i < n; ++i) {
      VertexId c0 = VertexId(z * (1 + 2 * n)), c1 = VertexId((z + 1) * (1 + 2 * n));
      hexes.push_back({c0, m(i - 1, z), p(i, z), m(i, z), c1, m(i - 1, z + 1), p(i, z + 1), m(i, z + 1)});
    }
  return fromConnectivity(pts, hexes);
}

// Irregular edges counted without the complex's edge classes: by vertex pair (valid only where no
// two edges share their ends), boundary when a boundary quad has the pair as a side.
struct PairCount {
  std::map<int, int64_t> interior, boundary;
};
PairCount countByVertexPairs(const Complex& cx) {
  std::map<std::pair<VertexId, VertexId>, int> valence;
  for (HexId h : cx.hexes())
    for (int e = 0; e < 12; ++e) {
      VertexId a = cx.vertex(h, tables::kEdgeCorners[size_t(e)][0]), b = cx.vertex(h, tables::kEdgeCorners[size_t(e)][1]);
      ++valence[{std::min(a, b), std::max(a, b)}];
    }
  std::set<std::pair<VertexId, VertexId>> onBoundary;
  for (const auto& q : cx.boundaryQuads())
    for (int k = 0; k < 4; ++k) {
      VertexId a = q.vertices[size_t(k)], b = q.vertices[size_t((k + 1) % 4)];
      onBoundary.insert({std::min(a, b), std::max(a, b)});
    }
  PairCount out;
  for (auto [pair, n] : valence) {
    const bool bd = onBoundary.count(pair) > 0;
    if (n != (bd ? 2 : 4)) ++(bd ? out.boundary : out.interior)[n];
  }
  return out;
}

// The valences of all edges add up to 12 per hex: regular ones count 4 (interior) or 2 (boundary).
void checkValenceSum(const Complex& cx, const SingularityGraph& g) {
  const Counts c = cx.counts();
  int64_t sum = 4 * (c.edges - c.boundaryEdges - g.counts.interiorEdges) + 2 * (c.boundaryEdges - g.counts.boundaryEdges);
  for (const SingularEdge& e : g.edges) sum += e.valence;
  CHECK(sum == 12 * c.hexes);
}

// `twinned`: boundary edges of valence 1 that share both ends with another such edge (two hexes
// touching along an edge only): a vertex pair counts the two as one regular boundary edge.
void checkAgainstPairs(const Complex& cx, const SingularityGraph& g, int64_t twinned = 0) {
  PairCount p = countByVertexPairs(cx);
  if (twinned) p.boundary[1] += twinned;
  CHECK(g.counts.interiorByValence == p.interior);
  CHECK(g.counts.boundaryByValence == p.boundary);
  checkValenceSum(cx, g);
}

// Every edge lies on exactly one curve, curves chain through shared vertices, and their ends are
// irregular vertices.
void checkCurves(const SingularityGraph& g) {
  std::vector<int> seen(g.edges.size(), 0);
  std::set<VertexId> irregular;
  for (const SingularVertex& v : g.vertices) irregular.insert(v.vertex);
  for (size_t c = 0; c < g.curves.size(); ++c) {
    const SingularCurve& cv = g.curves[c];
    for (size_t k = 0; k < cv.edges.size(); ++k) {
      const SingularEdge& e = g.edges[size_t(cv.edges[k])];
      ++seen[size_t(cv.edges[k])];
      CHECK(e.curve == int(c));
      CHECK(e.valence == cv.valence);
      if (k + 1 < cv.edges.size() || cv.closed) {
        const SingularEdge& n = g.edges[size_t(cv.edges[(k + 1) % cv.edges.size()])];
        const bool shared = e.vertices[0] == n.vertices[0] || e.vertices[0] == n.vertices[1] || e.vertices[1] == n.vertices[0] ||
                            e.vertices[1] == n.vertices[1];
        CHECK(shared);
      }
    }
    if (!cv.closed) CHECK((irregular.count(cv.ends[0]) && irregular.count(cv.ends[1])));
  }
  for (int s : seen) CHECK(s == 1);
}

}  // namespace

TEST_CASE("singularities: a grid has no irregular interior edge; its 12 box edges are boundary valence 1") {
  Complex cx = makeGrid(3, 4, 5);
  SingularityGraph g = singularityGraph(cx);
  CHECK(g.counts.interiorEdges == 0);
  CHECK(g.counts.boundaryByValence == std::map<int, int64_t>{{1, 4 * (3 + 4 + 5)}});
  CHECK(g.counts.vertices == 8);  // the box corners, where 3 feature curves meet
  CHECK(g.counts.boundaryVertices == 8);
  CHECK(g.counts.curves == 12);
  for (const SingularVertex& v : g.vertices) CHECK(v.degree == 3);
  checkAgainstPairs(cx, g);
  checkCurves(g);
}

TEST_CASE("singularities: an O-grid has four valence-3 curves along its core's corners") {
  const int layers = 3;
  Complex cx = makeOGrid(layers);
  SingularityGraph g = singularityGraph(cx);
  CHECK(g.counts.interiorByValence == std::map<int, int64_t>{{3, 4 * layers}});
  CHECK(g.counts.boundaryByValence == std::map<int, int64_t>{{1, 8}});  // the two rims
  CHECK(g.counts.vertices == 8);  // the valence-3 curves end on the two end faces
  CHECK(g.counts.curves == 6);    // 4 open interior curves, 2 closed rims
  int closed = 0;
  for (const SingularCurve& c : g.curves) {
    closed += c.closed;
    CHECK(c.edges.size() == size_t(c.boundary ? 4 : layers));
  }
  CHECK(closed == 2);
  checkAgainstPairs(cx, g);
  checkCurves(g);
}

TEST_CASE("singularities: n-gon prisms have an axis of valence n (3 and 5)") {
  for (int n : {3, 5}) {
    CAPTURE(n);
    const int layers = 2;
    Complex cx = makePrism(n, layers);
    SingularityGraph g = singularityGraph(cx);
    CHECK(g.counts.interiorByValence == std::map<int, int64_t>{{n, layers}});
    CHECK(g.counts.boundaryByValence == std::map<int, int64_t>{{1, n * layers + 4 * n}});
    CHECK(g.counts.vertices == 2 + 2 * n);  // the axis' two ends and the polygon's corners at both ends
    CHECK(g.counts.boundaryVertices == 2 + 2 * n);
    CHECK(g.counts.curves == 1 + 3 * n);
    checkAgainstPairs(cx, g);
    checkCurves(g);
  }
}

TEST_CASE("singularities: a prism with 4 sides is regular inside") {
  Complex cx = makePrism(4, 2);
  CHECK(singularityGraph(cx).counts.interiorEdges == 0);
}

TEST_CASE("singularities: a hex push in a grid makes the new quad's and the pushed quad's edges valence 3") {
  Complex cx = makeGrid(4, 4, 4);
  applyStep(cx, "hexpush h21f1");  // hexes (1,1,1) and (2,1,1), both inside
  SingularityGraph g = singularityGraph(cx);
  // Measured (and checked by vertex pairs below): 16 edges of valence 3 and 16 of valence 5 around
  // the new quad r and the pushed quad q.
  CHECK(g.counts.interiorByValence == std::map<int, int64_t>{{3, 16}, {5, 16}});
  CHECK(g.counts.boundaryEdges == 4 * 12);
  CHECK(g.counts.curves == 44);
  checkAgainstPairs(cx, g);
  checkCurves(g);
}

TEST_CASE("singularities: a pillow's doubled edges are counted as separate edges") {
  Complex cx = makeGrid(3, 3, 3);
  applyStep(cx, "pillow h13f1");
  SingularityGraph g = singularityGraph(cx);
  // Measured: 8 edges of the pillow pair have valence 2 and 4 have valence 6 (checked by the
  // valence sum; a vertex-pair count cannot see the doubled edges).
  CHECK(g.counts.interiorByValence == std::map<int, int64_t>{{2, 8}, {6, 4}});
  checkValenceSum(cx, g);  // a vertex-pair count cannot see doubled edges
  checkCurves(g);
}

TEST_CASE("singularities: a chord push's doubled edges each have their own valence") {
  Complex cx = makeGrid(3, 3, 3);
  applyStep(cx, "chordpush h13e0 h13f2 h13f4");
  SingularityGraph g = singularityGraph(cx);
  checkValenceSum(cx, g);
  checkCurves(g);
  int64_t two = g.counts.interiorByValence.count(2) ? g.counts.interiorByValence.at(2) : 0;
  CHECK(two > 0);  // the blind pair's edges
}

TEST_CASE("edge dual: a valence-3 edge of the O-grid: one sheet crossing it, three chords around") {
  Complex cx = makeOGrid(2);
  Dual dual = extractDual(cx);
  SingularityGraph g = singularityGraph(cx);
  const SingularEdge* e = nullptr;
  for (const SingularEdge& s : g.edges)
    if (!s.boundary) e = &s;
  REQUIRE(e);
  EdgeDual d = edgeDual(cx, dual, e->ref);
  CHECK(d.valence == 3);
  CHECK(!d.boundary);
  CHECK(d.hexes.size() == 3);
  CHECK(d.quads.size() == 3);
  CHECK(d.chords.size() == 3);
  CHECK(d.sheet == dual.sheetAt(e->ref.hex, tables::axisOfEdge(e->ref.edge)));
  for (const EdgeDual::Quad& q : d.quads) CHECK(q.sheet != d.sheet);
  CHECK(errorOf([&] { edgeDual(cx, dual, {999, 0}); }) == "edgedual: hex 999 does not exist");
  CHECK(errorOf([&] { edgeDual(cx, dual, {0, 12}); }) == "edgedual: local edge 12 is out of range");
}

TEST_CASE("singularities: development meshes, cross-checked by vertex pairs") {
  struct Expect {
    std::map<int, int64_t> interior, boundary;
    int64_t vertices, curves;
    int64_t twinned = 0;
  };
  // Measured with this code; the vertex-pair count below checks the edges independently.
  const std::map<std::string, Expect> expected = {
      {"MOAB_125hex.vtk.gz", {{}, {{1, 60}}, 8, 12}},
      {"MOAB_hex_2048.vtk.gz", {{}, {{1, 160}}, 8, 12}},
      {"MOAB_brick.vtk.gz", {{}, {{1, 120}}, 8, 12}},
      {"MOAB_hexes_mixed.vtk.gz", {{}, {{1, 20}}, 8, 12}},
      {"G_cylinder_1.vtk.gz", {{}, {{1, 104}}, 8, 12}},
      {"G_cylinder_2.vtk.gz", {{{3, 63}, {5, 35}}, {{1, 76}}, 28, 16}},
      {"P_double-torus.vtk.gz", {{}, {{1, 192}, {3, 16}}, 8, 16}},
      {"P_kitten.mesh.gz", {{{3, 349}, {5, 134}, {6, 24}, {7, 5}, {8, 4}}, {}, 147, 214}},
      {"P_joint.vtk.gz", {{{5, 54}}, {{1, 202}, {3, 24}}, 24, 28}},
      {"P_rockarm.vtk.gz", {{{3, 44}, {5, 2}}, {{1, 328}, {3, 126}, {4, 8}}, 49, 88, 16}},  // 8 edges where two parts touch
      {"P_big_buddy.mesh.gz", {{{3, 1436}, {5, 108}, {6, 12}}, {}, 152, 190}},
      {"ECR_block_stresstest_in.mesh.gz", {{{3, 360}, {5, 112}}, {}, 96, 120}},
      {"ECR_cap_in.mesh.gz", {{{3, 378}, {5, 166}}, {}, 72, 90}},
  };  // P_hex_sphere.vtk.gz is refused (its 8-node cells are typed as tets): no graph
  if (!std::filesystem::is_directory(devMeshDir())) {
    MESSAGE("skipped: no development-set meshes at " << devMeshDir().string());
    return;
  }
  for (const auto& [name, want] : expected) {
    CAPTURE(name);
    Complex cx = readDevMesh(devMeshDir() / name);
    SingularityGraph g = singularityGraph(cx);
    MESSAGE(name << ": interior " << g.counts.interiorEdges << " boundary " << g.counts.boundaryEdges << " vertices "
                 << g.counts.vertices << " curves " << g.counts.curves);
    for (auto [v, n] : g.counts.interiorByValence) MESSAGE("  interior valence " << v << ": " << n);
    for (auto [v, n] : g.counts.boundaryByValence) MESSAGE("  boundary valence " << v << ": " << n);
    CHECK(g.counts.interiorByValence == want.interior);
    CHECK(g.counts.boundaryByValence == want.boundary);
    CHECK(g.counts.vertices == want.vertices);
    CHECK(g.counts.curves == want.curves);
    checkAgainstPairs(cx, g, want.twinned);
    checkCurves(g);
  }
}
