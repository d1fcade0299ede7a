#include <doctest/doctest.h>
#include <algorithm>
#include <map>
#include <random>

#include <cstdio>
#include <fstream>

#include "complex/builders.hpp"
#include "complex/huge_pages.hpp"
#include "helpers.hpp"
#include "io/io.hpp"
#include "ops/oplog.hpp"

using namespace hexdual;
using namespace hexdual::test;

TEST_CASE("grid counts follow the formulas for several sizes") {
  for (auto [a, b, c] : {std::array<int, 3>{1, 1, 1}, {2, 3, 4}, {3, 3, 3}, {5, 1, 2}, {4, 4, 4}}) {
    CAPTURE(a);
    CAPTURE(b);
    CAPTURE(c);
    Complex cx = makeGrid(a, b, c);
    cx.validate();
    Counts k = cx.counts();
    CHECK(k.vertices == (a + 1) * (b + 1) * (c + 1));
    CHECK(k.edges == a * (b + 1) * (c + 1) + (a + 1) * b * (c + 1) + (a + 1) * (b + 1) * c);
    CHECK(k.quads == (a + 1) * b * c + a * (b + 1) * c + a * b * (c + 1));
    CHECK(k.hexes == a * b * c);
    CHECK(k.boundaryQuads == 2 * (a * b + b * c + c * a));
    CHECK(k.vertices - k.edges + k.quads - k.hexes == 1);
  }
}

// makeGrid before Complex::block: vertices and hexes added one by one, every face pair glued.
Complex gridOneByOne(int a, int b, int c) {
  Complex cx;
  for (int k = 0; k <= c; ++k)
    for (int j = 0; j <= b; ++j)
      for (int i = 0; i <= a; ++i) cx.addVertex({double(i), double(j), double(k)});
  auto vid = [&](int i, int j, int k) { return VertexId(i + (a + 1) * (j + (b + 1) * k)); };
  auto hid = [&](int i, int j, int k) { return HexId(i + a * (j + b * k)); };
  for (int k = 0; k < c; ++k)
    for (int j = 0; j < b; ++j)
      for (int i = 0; i < a; ++i) {
        std::array<VertexId, 8> v;
        for (int q = 0; q < 8; ++q)
          v[size_t(q)] = vid(i + tables::cornerBit(q, 0), j + tables::cornerBit(q, 1), k + tables::cornerBit(q, 2));
        cx.addHex(v);
      }
  for (int k = 0; k < c; ++k)
    for (int j = 0; j < b; ++j)
      for (int i = 0; i < a; ++i) {
        if (i + 1 < a) cx.glue(hid(i, j, k), 1, hid(i + 1, j, k), 0, 0);
        if (j + 1 < b) cx.glue(hid(i, j, k), 3, hid(i, j + 1, k), 2, 0);
        if (k + 1 < c) cx.glue(hid(i, j, k), 5, hid(i, j, k + 1), 4, 0);
      }
  return cx;
}

TEST_CASE("Complex::block (makeGrid) is the state adding and gluing one by one gives, corner counts included") {
  for (auto [a, b, c] : {std::array<int, 3>{1, 1, 1}, {2, 3, 4}, {5, 1, 2}, {1, 4, 1}, {6, 5, 7}}) {
    CAPTURE(a);
    CAPTURE(b);
    CAPTURE(c);
    const Complex fast = makeGrid(a, b, c), slow = gridOneByOne(a, b, c);
    CHECK(stateDump(fast) == stateDump(slow));
    fast.validate();
    // The corner counts per vertex, which the dump does not show: removing the hexes one by one
    // frees each vertex at its last corner, at the same removal in both.
    Complex f = fast, s = slow;
    for (HexId h = 0; h < s.hexCapacity(); ++h) {
      for (int face = 0; face < 6; ++face) {
        f.unglue(h, face);
        s.unglue(h, face);
      }
      f.removeHex(h);
      s.removeHex(h);
      REQUIRE(f.numVertices() == s.numVertices());
      for (VertexId v = 0; v < s.vertexCapacity(); ++v) REQUIRE(f.isVertex(v) == s.isVertex(v));
    }
    CHECK(f.numVertices() == 0);
  }
  CHECK(errorOf([] { makeGrid(0, 2, 2); }) == "grid: every dimension must be at least 1");
  CHECK(errorOf([] { makeGrid(1 << 9, 1 << 9, 1 << 9); }) == "grid: more than 2^26 hexes");
  // Products that wrap a 64-bit integer (2^63, 2^66, 2^78) are refused too, not allocated.
  CHECK(errorOf([] { makeGrid(1 << 21, 1 << 21, 1 << 21); }) == "grid: more than 2^26 hexes");
  CHECK(errorOf([] { makeGrid(1 << 22, 1 << 22, 1 << 22); }) == "grid: more than 2^26 hexes");
  CHECK(errorOf([] { makeGrid(1 << 26, 1 << 26, 1 << 26); }) == "grid: more than 2^26 hexes");
  CHECK(errorOf([] { makeRing(1 << 21, 1 << 21, 1 << 21); }) == "ring: more than 2^26 hexes");
}

TEST_CASE("a ring mesh 8x2x2 has the O-grid's counts") {
  Complex cx = makeRing(8, 2, 2);
  Counts k = cx.counts();
  CHECK(k.hexes == 32);
  CHECK(k.vertices == 8 * 3 * 3);
  CHECK(k.boundaryQuads == 64);  // inner and outer cylinders 16 each, two end annuli 16 each
  CHECK(k.quads == (6 * 32 + 64) / 2);
  CHECK(k.vertices - k.edges + k.quads - k.hexes == 0);      // a solid torus
}

TEST_CASE("hex ids are stable; removeHex leaves a tombstone and compact renumbers") {
  Complex cx = makeGrid(3, 1, 1);
  for (int f = 0; f < 6; ++f) cx.unglue(2, f);
  cx.removeHex(2);
  CHECK(cx.numHexes() == 2);
  CHECK_FALSE(cx.isHex(2));
  CHECK(cx.isHex(1));
  CHECK(cx.hexCapacity() == 3);
  CHECK(cx.numVertices() == 12);
  cx.validate();
  cx.compact();
  CHECK(cx.hexCapacity() == 2);
  CHECK(cx.vertexCapacity() == 12);
  cx.validate();
  CHECK(cx.counts().quads == 11);
}

TEST_CASE("edge cycles: interior edges close, boundary edges are fans") {
  Complex cx = makeGrid(2, 2, 2);
  // Hex 0 edge along z at x=1,y=1 (corners 2-6) is the grid's central z-edge of the bottom layer.
  int e = tables::edgeBetween(2, 6);
  bool closed = false;
  auto cyc = cx.edgeCycle({0, e}, &closed);
  CHECK(closed);
  CHECK(cyc.size() == 4);
  auto fan = cx.edgeCycle({0, tables::edgeBetween(0, 4)}, &closed);
  CHECK_FALSE(closed);
  CHECK(fan.size() == 1);
  // The same by count: the central edge's 4, a corner's fan of 1, and the fan of 2 along a boundary
  // edge that hexes 0 and 1 share (hex 0's edge 1-5, on the y = 0 face).
  CHECK(cx.edgeCycleSize({0, e}) == 4);
  CHECK(cx.edgeCycleSize({0, tables::edgeBetween(0, 4)}) == 1);
  CHECK(cx.edgeCycleSize({0, tables::edgeBetween(1, 5)}) == 2);
  CHECK(cx.edgeCycle({0, tables::edgeBetween(1, 5)}).size() == 2);
  // edgeCycleSize counts what edgeCycle lists, for every incidence of cycles, fans, a twisted ring's
  // edges and the doubled edges of a pillow (validate() uses the count).
  size_t incidences = 0;
  for (const Complex& m : {makeGrid(3, 2, 2), makeRing(5, 2, 1), makeTwistedRing(5), io::readNative(kPillowNative, "pillow")})
    for (HexId h : m.hexes())
      for (int ed = 0; ed < 12; ++ed) {
        REQUIRE(m.edgeCycleSize({h, ed}) == m.edgeCycle({h, ed}).size());
        ++incidences;
      }
  CHECK(incidences == 12 * (12 + 10 + 5 + 4));
}

TEST_CASE("validate names the first violation") {
  Complex cx = makeGrid(2, 1, 1);
  // Point a corner of hex 1 at a far vertex: the gluing no longer matches vertices.
  VertexId extra = cx.addVertex({9, 9, 9});
  cx.setCorner(1, 0, extra);
  CHECK(contains(errorOf([&] { cx.validate(); }), "validate: hex 0 face 1 is glued to hex 1 face 0 but corner"));
}

TEST_CASE("validate rejects a non-manifold vertex (two hexes touching at a corner)") {
  std::vector<Vec3> pts;
  for (int i = 0; i < 15; ++i) pts.push_back({double(i), 0, 0});
  // Hexes 0..7 and 7..14 share only vertex 7.
  auto msg = errorOf([&] { fromConnectivity(pts, {{0, 1, 2, 3, 4, 5, 6, 7}, {7, 8, 9, 10, 11, 12, 13, 14}}); });
  CHECK(contains(msg, "vertex 7 is non-manifold: its link has 2 components"));
}

TEST_CASE("fromConnectivity rejects three hexes on one quad and twisted quads") {
  std::vector<Vec3> pts(16);
  auto three = errorOf([&] {
    fromConnectivity(pts, {{0, 1, 2, 3, 4, 5, 6, 7}, {4, 5, 6, 7, 8, 9, 10, 11}, {4, 5, 6, 7, 12, 13, 14, 15}});
  });
  CHECK(contains(three, "quad (4,5,6,7) is shared by 3 hexes (0, 1, 2)"));
  auto twisted = errorOf([&] { fromConnectivity(pts, {{0, 1, 2, 3, 4, 5, 6, 7}, {4, 6, 5, 7, 8, 9, 10, 11}}); });
  CHECK(contains(twisted, "share the 4 vertices of quad (4,5,6,7) in different cyclic orders"));
  auto repeat = errorOf([&] { fromConnectivity(pts, {{0, 1, 2, 3, 4, 5, 6, 6}}); });
  CHECK(contains(repeat, "hex 0 repeats vertex 6"));
}

TEST_CASE("a pillow pair inserted by hand through the native format is a valid complex") {
  Complex cx = io::readNative(kPillowNative, "pillow.hxd");
  cx.validate();
  Counts k = cx.counts();
  Counts g = makeGrid(1, 1, 2).counts();
  // OPERATIONS.md: a minimal pillow changes (V,E,F,H) by (+4,+8,+6,+2).
  CHECK(k.vertices - g.vertices == 4);
  CHECK(k.edges - g.edges == 8);
  CHECK(k.quads - g.quads == 6);
  CHECK(k.hexes - g.hexes == 2);
  CHECK(k.boundaryQuads == g.boundaryQuads);
  // X and Y really do share all 8 vertices, and two quads have the same 4 vertices.
  auto x = cx.hexVertices(2), y = cx.hexVertices(3);
  std::sort(x.begin(), x.end());
  std::sort(y.begin(), y.end());
  CHECK(x == y);
}

TEST_CASE("edges(), vertices() and boundaryQuads() list each entity once") {
  Complex cx = io::readNative(kPillowNative, "p.hxd");
  Counts k = cx.counts();
  CHECK(int64_t(cx.edges().size()) == k.edges);
  CHECK(int64_t(cx.vertices().size()) == k.vertices);
  CHECK(int64_t(cx.quads().size()) == k.quads);
  auto bq = cx.boundaryQuads();
  CHECK(int64_t(bq.size()) == k.boundaryQuads);
  // Doubled quads are distinct: the pillow has two interior quads on vertices {4,5,6,7}.
  int onQ = 0;
  for (QuadSide q : cx.quads()) {
    std::array<VertexId, 4> v;
    for (int p = 0; p < 4; ++p) v[size_t(p)] = cx.vertex(q.hex, tables::kFaceCorners[size_t(q.face)][size_t(p)]);
    std::sort(v.begin(), v.end());
    onQ += v == std::array<VertexId, 4>{4, 5, 6, 7};
  }
  CHECK(onQ == 2);
}

namespace {
// The VmFlags line of the mapping holding p ("" where /proc cannot tell or there are no THPs).
std::string vmFlagsAt(const void* p) {
#if defined(__linux__)
  if (!std::ifstream("/sys/kernel/mm/transparent_hugepage/enabled")) return "";
  const auto at = reinterpret_cast<uintptr_t>(p);
  std::ifstream smaps("/proc/self/smaps");
  std::string line, flags;
  bool inside = false;
  while (std::getline(smaps, line)) {
    const std::string first = line.substr(0, line.find(' '));
    unsigned long lo = 0, hi = 0;
    if (first.find(':') == std::string::npos && std::sscanf(first.c_str(), "%lx-%lx", &lo, &hi) == 2)
      inside = lo <= at && at < hi;  // a mapping's header line
    else if (inside && line.rfind("VmFlags:", 0) == 0)
      flags = line;
  }
  return flags;
#else
  (void)p;
  return "";
#endif
}
}  // namespace

TEST_CASE("reserveHuge keeps the contents and, on Linux, advises huge pages for large storage") {
  std::vector<int32_t> v = {7, 8, 9};
  reserveHuge(v, size_t(4) << 20);  // 16 MiB
  CHECK(v.capacity() >= (size_t(4) << 20));
  CHECK(v == std::vector<int32_t>{7, 8, 9});
  std::vector<int32_t> w = {1, 2};
  assignHuge(w, 5, int32_t(-1));
  CHECK(w == std::vector<int32_t>(5, -1));
  CHECK(w.capacity() >= withHeadroom(5));  // new storage keeps an eighth more (and 64) for growth
  // The mapping holding the middle of the storage carries the kernel's huge-page advice flag.
  // Kernels without transparent huge pages (or /proc without VmFlags) cannot show the advice.
  const std::string flags = vmFlagsAt(v.data() + (size_t(2) << 20));
  if (flags.empty()) {
    MESSAGE("no transparent huge pages or no VmFlags here: the advice is not checked");
    return;
  }
  INFO("VmFlags of the storage's mapping: " << flags);
  CHECK(flags.find(" hg") != std::string::npos);
}

TEST_CASE("HugePageAllocator: 1 MiB and up in whole advised 2 MiB pages; growHuge moves; reserveRoom leaves room") {
  // Small storage is operator new's; from 1 MiB up (on Linux) it starts on a 2 MiB boundary, so no
  // part of it is left to 4 KiB pages, and carries the huge-page advice.
  std::vector<int64_t, HugePageAllocator<int64_t>> small(100, 5), big(size_t(3) << 17, 6);  // 800 B, 3 MiB
  CHECK(small.size() == 100);
  CHECK(small.back() == 5);
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  // The threshold is exactly 1 MiB of storage.
  CHECK_FALSE(HugePageAllocator<int64_t>::huge((size_t(1) << 17) - 1));
  CHECK(HugePageAllocator<int64_t>::huge(size_t(1) << 17));
  CHECK_FALSE(HugePageAllocator<int64_t>::huge(100));
  CHECK(reinterpret_cast<uintptr_t>(big.data()) % (size_t(2) << 20) == 0);
  const std::string flags = vmFlagsAt(big.data());
  if (flags.empty())
    MESSAGE("no transparent huge pages or no VmFlags here: the advice is not checked");
  else
    CHECK(flags.find(" hg") != std::string::npos);
#endif
  big.push_back(7);  // regrown: contents kept, storage freed by the same allocator (ASan checks)
  CHECK(big.size() == (size_t(3) << 17) + 1);
  CHECK(big.front() == 6);
  CHECK(big.back() == 7);
  // growHuge moves what it regrows (a copied string would keep its own buffer) and fills the rest.
  std::vector<std::string> names = {std::string(100, 'a'), "b"};
  names.shrink_to_fit();
  const char* buffer = names[0].data();
  growHuge(names, 5, std::string("new"));
  CHECK(names.size() == 5);
  CHECK(names[0].data() == buffer);
  CHECK(names[1] == "b");
  CHECK(names[4] == "new");
  // reserveRoom: room for as many again (and 64) before anything is listed.
  std::vector<int32_t> perChord;
  reserveRoom(perChord, 1000);
  CHECK(perChord.capacity() >= 2064);
  CHECK(perChord.empty());
}

namespace {
// The plain walk cornersOfVertex replaced: breadth first over facesOfCorner, a linear search for repeats.
std::vector<std::pair<HexId, int>> cornersByPlainWalk(const Complex& cx, HexId h, int corner) {
  std::vector<std::pair<HexId, int>> out{{h, corner}};
  for (size_t i = 0; i < out.size(); ++i) {
    auto [hh, cc] = out[i];
    for (int f : tables::facesOfCorner(cc)) {
      if (cx.gluing(hh, f).boundary()) continue;
      std::pair<HexId, int> n{cx.gluing(hh, f).hex, cx.mappedCorner(hh, f, cc)};
      if (std::find(out.begin(), out.end(), n) == out.end()) out.push_back(n);
    }
  }
  return out;
}
}  // namespace

TEST_CASE("cornersOfVertex lists a vertex's corners in the plain walk's order, large stars included") {
  // Repeated pillows at one vertex's quads and random pillows and hex pushes elsewhere (fixed seed).
  const unsigned seed = 20261204;
  MESSAGE("seed " << seed);
  std::mt19937 rng(seed);
  Complex cx = makeGrid(4, 4, 4);
  size_t largest = 0;
  // Steps named directly (no candidate lists: the sanitizer build validates the whole complex
  // after every operation); a refused one changes nothing.
  for (int step = 0; step < 300; ++step) {
    std::vector<HexId> alive;
    for (HexId x : cx.hexes()) alive.push_back(x);
    const HexId h = step % 2 ? alive[rng() % alive.size()] : alive[0];
    const char* op = step % 3 == 2 ? "hexpush" : "pillow";
    std::string why;
    tryApplyStep(cx, std::string(op) + " h" + std::to_string(h) + "f" + std::to_string(step % 2 ? rng() % 6 : step % 6), &why);
  }
  std::map<VertexId, size_t> refs;  // corners per vertex (every star here is connected)
  for (HexId h : cx.hexes())
    for (int c = 0; c < 8; ++c) ++refs[cx.vertex(h, c)];
  for (HexId h : cx.hexes())
    for (int c = 0; c < 8; ++c) {
      const auto walked = cx.cornersOfVertex(h, c);
      REQUIRE(walked == cornersByPlainWalk(cx, h, c));
      CHECK(walked.size() == refs[cx.vertex(h, c)]);
      largest = std::max(largest, walked.size());
    }
  MESSAGE("largest star: " << largest << " corners");
  CHECK(largest > 32);
}
