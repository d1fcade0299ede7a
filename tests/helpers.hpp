// Shared helpers for the doctest suites.
#pragma once
#include <algorithm>
#include <cstdio>
#include <functional>
#include <random>
#include <string>

#include <doctest/doctest.h>

#include "complex/builders.hpp"
#include "complex/complex.hpp"
#include "dual/dual.hpp"

namespace hexdual::test {

// The complex read again with every vertex id moved (a shuffle drawn from `seed`, boundary ids too),
// the hexes listed backwards and each hex's corners turned a quarter about its z axis; `perm` gets
// the new id of each old vertex id. Gluings come from shared quads, as a file reader's do.
inline Complex renumbered(const Complex& cx, unsigned seed, std::vector<VertexId>* permOut = nullptr) {
  std::vector<VertexId> perm(size_t(cx.vertexCapacity()));
  for (size_t i = 0; i < perm.size(); ++i) perm[i] = VertexId(i);
  std::mt19937 rng(seed);
  std::shuffle(perm.begin(), perm.end(), rng);
  std::vector<Vec3> pos(perm.size());
  for (size_t i = 0; i < perm.size(); ++i) pos[size_t(perm[i])] = cx.positions()[i];
  std::vector<std::array<VertexId, 8>> hexes;
  for (HexId h = cx.hexCapacity() - 1; h >= 0; --h) {
    if (!cx.isHex(h)) continue;
    auto v = cx.hexVertices(h);
    for (VertexId& x : v) x = perm[size_t(x)];
    hexes.push_back({v[1], v[2], v[3], v[0], v[5], v[6], v[7], v[4]});
  }
  if (permOut) *permOut = perm;
  return fromConnectivity(pos, hexes);
}

// The message of the Error thrown by f, or "" when nothing was thrown.
inline std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

inline bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// s with the first occurrence of `from` replaced by `to` (which must occur).
inline std::string replaced(std::string s, const std::string& from, const std::string& to) {
  auto i = s.find(from);
  REQUIRE(i != std::string::npos);
  return s.replace(i, from.size(), to);
}

inline int countTopology(const Dual& d, const std::string& t) {
  int n = 0;
  for (const auto& s : d.sheets) n += s.topology == t;
  return n;
}

// The two hexes A, B of a 1x1x2 grid with a pillow pair X, Y inserted between them by hand,
// in the native format: A | q | X || Y | q' | B, X and Y on the same 8 vertices sharing 5 quads.
inline const char* kPillowNative =
    "hexdual 1\n"
    "vertices 16\n"
    "0 0 0\n1 0 0\n0 1 0\n1 1 0\n"
    "0 0 1\n1 0 1\n0 1 1\n1 1 1\n"
    "0 0 2\n1 0 2\n0 1 2\n1 1 2\n"
    "0 0 1.3\n1 0 1.3\n1 1 1.3\n0 1 1.3\n"
    "hexes 4\n"
    "0 1 3 2 4 5 7 6\n"      // A
    "4 5 7 6 8 9 11 10\n"    // B
    "4 5 7 6 12 13 14 15\n"  // X: q below, new vertices above
    "12 13 14 15 4 5 7 6\n"  // Y: the mirror of X, q' above
    "gluings 7\n"
    "0 5 2 4 0\n"  // A | q | X
    "2 5 3 4 0\n"  // X | Y across the new vertices
    "3 5 1 4 0\n"  // Y | q' | B
    "2 0 3 0 7\n2 1 3 1 7\n2 2 3 2 5\n2 3 3 3 5\n"
    "end\n";

}  // namespace hexdual::test

#include <sstream>

namespace hexdual::test {
// Everything observable about a complex, ids and tombstones included: equal dumps = same state.
inline std::string stateDump(const Complex& cx) {
  // Raw bytes, not text: equal dumps = bit-equal ids, gluings and positions. (Printing every
  // coordinate at 17 digits made the whole-set sweeps spend half their time in printf.)
  std::string o;
  auto put = [&o](auto x) { o.append(reinterpret_cast<const char*>(&x), sizeof x); };
  put(int64_t(cx.hexCapacity()));
  put(int64_t(cx.vertexCapacity()));
  put(int64_t(cx.numHexes()));
  put(int64_t(cx.numVertices()));
  put(int64_t(cx.numBoundaryQuads()));
  put(uint64_t(cx.revision()));
  for (HexId h = 0; h < cx.hexCapacity(); ++h) {
    put(char(cx.isHex(h)));
    if (!cx.isHex(h)) continue;
    for (int c = 0; c < 8; ++c) put(int64_t(cx.vertex(h, c)));
    for (int f = 0; f < 6; ++f) {
      const Gluing g = cx.gluing(h, f);
      put(int64_t(g.hex));
      put(int32_t(g.face));
      put(int32_t(g.orient));
    }
  }
  for (VertexId v = 0; v < cx.vertexCapacity(); ++v) {
    const Vec3 p = cx.position(v);
    put(char(cx.isVertex(v)));
    put(p.x);
    put(p.y);
    put(p.z);
  }
  return o;
}
}  // namespace hexdual::test

// The development-set meshes: devMeshDir(), readDevMesh().
#include "dev_mesh.hpp"

#ifdef HEXDUAL_CLI
#include <array>
#include <cstdio>
#include <sys/wait.h>
namespace hexdual::test {
// The CLI's exit status and its stdout and stderr together.
struct CliRun {
  int status;
  std::string out;
};
inline CliRun runCli(const std::string& args) {
  std::string cmd = std::string(HEXDUAL_CLI) + " " + args + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  REQUIRE(p);
  std::string out;
  std::array<char, 4096> buf;
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) out.append(buf.data(), n);
  int st = pclose(p);
  return {WEXITSTATUS(st), out};
}
}  // namespace hexdual::test
#endif
