#include "flips/fourcube.hpp"

#include <algorithm>
#include <array>
#include <map>

#include "complex/builders.hpp"

namespace hexdual {
using namespace tables;

Complex makeFourCubeBoundary() {
  std::vector<Vec3> pts;
  for (int b = 0; b < 16; ++b) {
    double x[4] = {double(b & 1), double((b >> 1) & 1), double((b >> 2) & 1), double((b >> 3) & 1)};
    // An oblique projection: the 4th axis shrinks toward the centre (a Schlegel-like picture).
    double s = 1.0 - 0.5 * x[3];
    pts.push_back({0.5 + s * (x[0] - 0.5), 0.5 + s * (x[1] - 0.5), 0.5 + s * (x[2] - 0.5)});
  }
  std::vector<std::array<VertexId, 8>> hexes;
  for (int axis = 0; axis < 4; ++axis)
    for (int side = 0; side < 2; ++side) {
      int freeAxes[3], n = 0;
      for (int a = 0; a < 4; ++a)
        if (a != axis) freeAxes[n++] = a;
      std::array<VertexId, 8> v;
      for (int c = 0; c < 8; ++c) {
        int b = side << axis;
        for (int k = 0; k < 3; ++k) b |= cornerBit(c, k) << freeAxes[k];
        v[size_t(c)] = VertexId(b);
      }
      hexes.push_back(v);
    }
  return fromConnectivity(pts, hexes);
}

Complex subcomplex(const Complex& cx, const std::vector<HexId>& keep) {
  Complex out;
  out.reserve(size_t(cx.hexCapacity()), size_t(cx.vertexCapacity()));
  for (VertexId v = 0; v < cx.vertexCapacity(); ++v) out.addVertex(cx.position(v));
  std::vector<uint8_t> in(size_t(cx.hexCapacity()), 0);
  for (HexId h : keep) in[size_t(h)] = 1;
  for (HexId h = 0; h < cx.hexCapacity(); ++h) out.addHex(cx.isHex(h) ? cx.hexVertices(h) : cx.hexVertices(keep.at(0)));
  for (HexId h = 0; h < cx.hexCapacity(); ++h)
    if (in[size_t(h)])
      for (int f = 0; f < 6; ++f) {
        Gluing g = cx.gluing(h, f);
        if (!g.boundary() && in[size_t(g.hex)] && QuadSide{h, f} < QuadSide{g.hex, g.face}) out.glue(h, f, g.hex, g.face, g.orient);
      }
  for (HexId h = 0; h < cx.hexCapacity(); ++h)
    if (!in[size_t(h)]) out.removeHex(h);
  return out;
}

std::vector<HexId> facetsOf(uint8_t mask) {
  std::vector<HexId> out;
  for (int k = 0; k < 8; ++k)
    if (mask & (1 << k)) out.push_back(k);
  return out;
}

namespace {

const Complex& fourCube() {
  static const Complex c = makeFourCubeBoundary();
  return c;
}

// The 384 symmetries of the 4-cube acting on facet masks.
std::vector<std::array<int, 8>> facetSymmetries() {
  std::vector<std::array<int, 8>> out;
  std::array<int, 4> perm{0, 1, 2, 3};
  do {
    for (int flip = 0; flip < 16; ++flip) {
      std::array<int, 8> m{};
      for (int axis = 0; axis < 4; ++axis)
        for (int side = 0; side < 2; ++side) {
          int a2 = perm[size_t(axis)];
          m[size_t(2 * axis + side)] = 2 * a2 + (side ^ ((flip >> a2) & 1));
        }
      out.push_back(m);
    }
  } while (std::next_permutation(perm.begin(), perm.end()));
  return out;
}

uint8_t canonicalMask(uint8_t mask) {
  static const auto syms = facetSymmetries();
  uint8_t best = 0xff;
  for (const auto& s : syms) {
    uint8_t img = 0;
    for (int k = 0; k < 8; ++k)
      if (mask & (1 << k)) img = uint8_t(img | (1 << s[size_t(k)]));
    best = std::min(best, img);
  }
  return best;
}

bool adjacent(int a, int b) { return a / 2 != b / 2; }  // distinct facets meet unless opposite

Counts interiorCounts(uint8_t mask) {
  Complex s = subcomplex(fourCube(), facetsOf(mask));
  Counts c = s.counts();
  return {c.vertices - c.boundaryVertices, c.edges - c.boundaryEdges, c.quads - c.boundaryQuads, c.hexes, 0, 0, 0};
}

std::string typeName(uint8_t mask) {
  auto f = facetsOf(mask);
  int n = int(f.size());
  bool allAdjacent = true;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < i; ++j) allAdjacent = allAdjacent && adjacent(f[size_t(i)], f[size_t(j)]);
  std::string base = std::to_string(n) + "-" + std::to_string(8 - n);
  if (n == 3 || n == 5) {
    // Type of the 3-side: around an edge (pairwise adjacent) or a column.
    uint8_t three = n == 3 ? mask : uint8_t(~mask);
    auto t = facetsOf(three);
    bool edge = adjacent(t[0], t[1]) && adjacent(t[0], t[2]) && adjacent(t[1], t[2]);
    return base + (edge ? "e" : "c");
  }
  if (n == 4) return base + (allAdjacent ? "v" : "m");
  return base;
}

}  // namespace

bool isBall(uint8_t mask) {
  if (mask == 0 || mask == 0xff) return false;
  auto f = facetsOf(mask);
  // Connected through shared quads.
  std::vector<int> seen{f[0]};
  for (size_t i = 0; i < seen.size(); ++i)
    for (int g : f)
      if (adjacent(seen[i], g) && std::find(seen.begin(), seen.end(), g) == seen.end()) seen.push_back(g);
  if (seen.size() != f.size()) return false;
  Complex s = subcomplex(fourCube(), f);
  try {
    s.validate();  // manifold: every vertex link a disk or a sphere
  } catch (const Error&) {
    return false;
  }
  Counts c = s.counts();
  return c.vertices - c.edges + c.quads - c.hexes == 1 && c.boundaryVertices - c.boundaryEdges + c.boundaryQuads == 2;
}

std::vector<FlipClass> enumerateFlipClasses() {
  std::map<uint8_t, bool> classes;  // canonical before-mask
  for (int m = 1; m < 255; ++m)
    if (isBall(uint8_t(m)) && isBall(uint8_t(~m))) classes[canonicalMask(uint8_t(m))] = true;
  static const std::map<std::string, std::pair<bool, std::string>> info = {
      {"1-7", {true, "one hex becomes seven: a central hex and six around it (traditional pillow)"}},
      {"2-6", {true, "two hexes sharing a quad become six (hex push)"}},
      {"3-5e", {true, "three hexes around an edge become five"}},
      {"3-5c", {false, "three hexes in a column become five"}},
      {"4-4v", {true, "four hexes around a vertex become the other four (triple-hex push)"}},
      {"4-4m", {false, "four hexes of the mixed type become the other four"}},
  };
  std::vector<FlipClass> out;
  for (auto [mask, _] : classes) {
    FlipClass fc;
    fc.before = mask;
    fc.name = typeName(mask);
    fc.inverse = typeName(canonicalMask(uint8_t(~mask)));
    std::string forward = fc.name;
    if (fc.name[0] > '4') forward = fc.inverse;  // 7-1 is the inverse of 1-7
    auto it = info.find(forward);
    if (it != info.end()) {
      fc.geometric = it->second.first;
      fc.description = (forward == fc.name ? "" : "inverse: ") + it->second.second;
    }
    fc.interiorBefore = interiorCounts(mask);
    fc.interiorAfter = interiorCounts(uint8_t(~mask));
    out.push_back(fc);
  }
  std::sort(out.begin(), out.end(), [](const FlipClass& a, const FlipClass& b) { return a.name < b.name; });
  return out;
}

const FlipClass& flipClass(const std::string& name) {
  static const std::vector<FlipClass> all = enumerateFlipClasses();
  std::string names;
  for (const FlipClass& c : all) {
    if (c.name == name) return c;
    names += (names.empty() ? "" : ", ") + c.name;
  }
  throw Error("flip: unknown flip '" + name + "' (known: " + names + ")");
}

}  // namespace hexdual
