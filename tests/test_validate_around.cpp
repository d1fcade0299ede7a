// Complex::validateAround, the operations' local validity check: its vertex-star walk (one
// corner-step table lookup per crossed quad, a hashed index of the star's corners) agrees with
// the global validate() on degenerate gluings, large stars and broken links.
#include <doctest/doctest.h>

#include "complex/builders.hpp"
#include "helpers.hpp"
#include "io/io.hpp"
#include "ops/oplog.hpp"

using namespace hexdual;
using namespace hexdual::test;

namespace {
// Two hexes, face f of hex 0 glued to face f2 of hex 1 with orientation o (vertices shared accordingly).
Complex gluedPair(int f, int f2, int o) {
  Complex cx;
  std::array<VertexId, 8> a{}, b{};
  for (int c = 0; c < 8; ++c) a[size_t(c)] = cx.addVertex({double(c), 0, 0});
  b.fill(-1);
  for (int p = 0; p < 4; ++p)
    b[size_t(tables::kFaceCorners[size_t(f2)][size_t(tables::mapPosition(p, o))])] =
        a[size_t(tables::kFaceCorners[size_t(f)][size_t(p)])];
  for (int c = 0; c < 8; ++c)
    if (b[size_t(c)] < 0) b[size_t(c)] = cx.addVertex({double(c), 1, 0});
  cx.addHex(a);
  cx.addHex(b);
  cx.glue(0, f, 1, f2, o);
  return cx;
}
// Two hexes touching only at one vertex (hex 0's corner 6 is hex 1's corner 0), made without validation.
Complex touchingAtOneVertex(VertexId& shared) {
  Complex cx;
  std::array<VertexId, 8> a{}, b{};
  for (int c = 0; c < 8; ++c) a[size_t(c)] = cx.addVertex({double(c), 0, 0});
  b[0] = shared = a[6];
  for (int c = 1; c < 8; ++c) b[size_t(c)] = cx.addVertex({double(c), 1, 0});
  cx.addHex(a);
  cx.addHex(b);
  return cx;
}
}  // namespace

TEST_CASE("validateAround: two hexes glued by every face pair and orientation have disk links") {
  int checked = 0;
  for (int f = 0; f < 6; ++f)
    for (int f2 = 0; f2 < 6; ++f2)
      for (int o = 0; o < 8; ++o) {
        CAPTURE(f);
        CAPTURE(f2);
        CAPTURE(o);
        Complex cx = gluedPair(f, f2, o);
        CHECK(errorOf([&] { cx.validate(); }) == "");
        CHECK(errorOf([&] { cx.validateAround({0, 1}); }) == "");
        ++checked;
      }
  CHECK(checked == 288);
}

TEST_CASE("validateAround: sphere links inside grids and rings, and a pillow pair sharing 5 quads") {
  for (Complex cx : {makeGrid(2, 2, 2), makeGrid(3, 4, 5), makeRing(8, 3, 3)}) {
    std::vector<HexId> all;
    for (HexId h : cx.hexes()) all.push_back(h);
    CHECK(errorOf([&] { cx.validateAround(all); }) == "");
  }
  Complex pillowPair = io::readNative(kPillowNative, "pillow.hxd");
  CHECK(errorOf([&] { pillowPair.validateAround({0, 1, 2, 3}); }) == "");
}

TEST_CASE("validateAround: a 4x4x4 block whose hexes are numbered in all 48 symmetries of the cube") {
  // Hex number m lists its corners in symmetry 29m mod 48 (all 48 occur), so the gluings
  // use every face pair and orientation code round interior vertices (sphere links).
  std::vector<Vec3> pts;
  const int n = 4;
  auto vid = [&](int i, int j, int k) { return VertexId(i + (n + 1) * (j + (n + 1) * k)); };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) pts.push_back({double(i), double(j), double(k)});
  const int perms[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  std::vector<std::array<VertexId, 8>> hexes;
  int sym = 0;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i, ++sym) {
        const int s = (29 * sym) % 48;
        const int* p = perms[s / 8];
        std::array<VertexId, 8> h{};
        for (int c = 0; c < 8; ++c) {
          int bit[3];  // local corner c, read in the symmetry's frame
          for (int a = 0; a < 3; ++a) bit[a] = tables::cornerBit(c, p[a]) ^ ((s >> a) & 1);
          h[size_t(c)] = vid(i + bit[0], j + bit[1], k + bit[2]);
        }
        hexes.push_back(h);
      }
  Complex cx = fromConnectivity(pts, hexes);
  std::vector<HexId> all;
  for (HexId h : cx.hexes()) all.push_back(h);
  CHECK(cx.numHexes() == 64);
  CHECK(errorOf([&] { cx.validateAround(all); }) == "");
}

TEST_CASE("validateAround: a boundary vertex with a large star after repeated pillows") {
  Complex cx = makeGrid(3, 3, 3);
  // Pillow the quad between the corner hex 0 and its +x neighbour 30 times: each pillow lands
  // between hex 0 and the previous one, so the star of hex 0's corner vertices on that quad grows.
  for (int i = 0; i < 30; ++i) applyStep(cx, "pillow h0f1");
  int starOfCorner1 = 0;  // hex corners at the vertex of hex 0's corner 1 (on the grid's boundary)
  for (HexId x : cx.hexes())
    for (VertexId v : cx.hexVertices(x)) starOfCorner1 += v == cx.vertex(0, 1);
  CHECK(starOfCorner1 == 2 + 2 * 30);
  std::vector<HexId> all;
  for (HexId x : cx.hexes()) all.push_back(x);
  CHECK(errorOf([&] { cx.validateAround(all); }) == "");
  CHECK(errorOf([&] { cx.validate(); }) == "");
}

TEST_CASE("validateAround: two hexes touching at one vertex: its link is not connected") {
  VertexId shared = -1;
  Complex cx = touchingAtOneVertex(shared);
  CHECK(errorOf([&] {
          cx.validateAround({0, 1});
        }) == "validate: vertex " + std::to_string(shared) + " is non-manifold: its link is not connected");
}

TEST_CASE(
    "validateAround in a transaction: the links its edits changed are checked, the others were valid at its start") {
  // Ungluing the quad between the two hexes of a 2x1x1 grid splits the links of its 4 vertices.
  Complex grid = makeGrid(2, 1, 1);
  grid.beginTransaction();
  grid.unglue(0, 1);
  const VertexId first = std::min({grid.vertex(0, 1), grid.vertex(0, 2), grid.vertex(0, 5), grid.vertex(0, 6)});
  CHECK(errorOf([&] {
          grid.validateAround({0, 1});
        }) == "validate: vertex " + std::to_string(first) + " is non-manifold: its link is not connected");
  grid.rollbackTransaction();
  CHECK(errorOf([&] { grid.validateAround({0, 1}); }) == "");

  // Two hexes touching at one vertex, made before the transaction: an edit that moves a vertex
  // (no topological edit) leaves that link unchecked; outside a transaction it is checked.
  VertexId shared = -1;
  Complex cx = touchingAtOneVertex(shared);
  cx.beginTransaction();
  cx.setPosition(cx.vertex(0, 0), {0, 0, 1});
  CHECK(errorOf([&] { cx.validateAround({0, 1}); }) == "");
  cx.rollbackTransaction();
  CHECK(errorOf([&] {
          cx.validateAround({0, 1});
        }) == "validate: vertex " + std::to_string(shared) + " is non-manifold: its link is not connected");
}

TEST_CASE("validateAround in a long transaction (512 edits or more: each edited vertex listed once) checks every link its edits changed") {
  // A 6x6x6 grid: the quad between hexes 0 and 1 unglued first, then 300 other quads unglued and
  // glued back (600 more edits). The first edit's 4 vertices must still be checked, at every call.
  Complex grid = makeGrid(6, 6, 6);
  const VertexId first = std::min({grid.vertex(0, 1), grid.vertex(0, 2), grid.vertex(0, 5), grid.vertex(0, 6)});
  auto regluedMany = [&](bool breakFirst) {
    grid.beginTransaction();
    if (breakFirst) grid.unglue(0, 1);
    int reglued = 0;
    for (HexId h = 2; h < grid.hexCapacity() && reglued < 300; ++h)
      for (int f = 0; f < 6 && reglued < 300; ++f) {
        const Gluing g = grid.gluing(h, f);
        if (g.boundary() || g.hex < 2) continue;
        grid.unglue(h, f);
        grid.glue(h, f, g.hex, g.face, g.orient);
        ++reglued;
      }
    REQUIRE(reglued == 300);
  };
  std::vector<HexId> all;
  for (HexId h = 0; h < grid.hexCapacity(); ++h) all.push_back(h);
  const std::string broken = "validate: vertex " + std::to_string(first) + " is non-manifold: its link is not connected";
  regluedMany(true);
  CHECK(errorOf([&] { grid.validateAround(all); }) == broken);
  CHECK(errorOf([&] { grid.validateAround(all); }) == broken);  // a second call lists the vertices again
  grid.rollbackTransaction();
  regluedMany(false);
  CHECK(errorOf([&] { grid.validateAround(all); }) == "");
  grid.rollbackTransaction();
  CHECK(errorOf([&] { grid.validateAround(all); }) == "");
}
