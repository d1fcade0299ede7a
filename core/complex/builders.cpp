#include "complex/builders.hpp"

#include "complex/manifold.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace hexdual {
using namespace tables;

Complex makeGrid(int a, int b, int c) {
  return Complex::block(a, b, c);
}

Complex makeRing(int around, int radial, int axial) {
  if (around < 3 || radial < 1 || axial < 1) throw Error("ring: needs at least 3 around and 1 radial and axial layer");
  if (Complex::tooManyHexes(around, radial, axial)) throw Error("ring: more than 2^26 hexes");
  std::vector<Vec3> pts;
  auto vid = [&](int t, int s, int k) { return VertexId((t % around) + around * (s + (radial + 1) * k)); };
  const double pi = std::acos(-1.0), r0 = 1.0 + 0.25 * around / pi;
  for (int k = 0; k <= axial; ++k)
    for (int s = 0; s <= radial; ++s)
      for (int t = 0; t < around; ++t) {
        double ang = 2 * pi * t / around, r = r0 + s;
        pts.push_back({r * std::cos(ang), r * std::sin(ang), double(k)});
      }
  std::vector<std::array<VertexId, 8>> hexes;
  for (int k = 0; k < axial; ++k)
    for (int t = 0; t < around; ++t)
      for (int s = 0; s < radial; ++s) {
        std::array<VertexId, 8> v;
        for (int q = 0; q < 8; ++q) v[q] = vid(t + cornerBit(q, 1), s + cornerBit(q, 0), k + cornerBit(q, 2));
        hexes.push_back(v);
      }
  return fromConnectivity(pts, hexes);
}

Complex makeTwistedRing(int around) {
  if (around < 3) throw Error("twisted ring: needs at least 3 hexes around");
  if (around > Complex::kMaxHexes) throw Error("twisted ring: more than 2^26 hexes");
  const double pi = std::acos(-1.0), r0 = 2.0 + 0.3 * around / pi;
  std::vector<Vec3> pts;
  // Cross-section corner (s, k) of layer t, turned by a quarter turn over the whole ring.
  for (int t = 0; t < around; ++t)
    for (int k = 0; k < 2; ++k)
      for (int s = 0; s < 2; ++s) {
        double turn = 0.5 * pi * t / around, u = s - 0.5, v = k - 0.5;
        double ru = u * std::cos(turn) - v * std::sin(turn), rv = u * std::sin(turn) + v * std::cos(turn);
        double ang = 2 * pi * t / around, r = r0 + ru;
        pts.push_back({r * std::cos(ang), r * std::sin(ang), rv});
      }
  auto vid = [&](int t, int s, int k) {
    if (t == around) {  // the seam: (s, k) meets the first layer's corner a quarter turn on
      int s2 = k, k2 = 1 - s;
      return VertexId(4 * 0 + s2 + 2 * k2);
    }
    return VertexId(4 * t + s + 2 * k);
  };
  std::vector<std::array<VertexId, 8>> hexes;
  for (int t = 0; t < around; ++t) {
    std::array<VertexId, 8> v;
    for (int q = 0; q < 8; ++q) v[size_t(q)] = vid(t + cornerBit(q, 1), cornerBit(q, 0), cornerBit(q, 2));
    hexes.push_back(v);
  }
  return fromConnectivity(pts, hexes);
}

Complex makeTorusShell(int around, int tube, int layers, bool klein) {
  if (around < 3 || tube < 3 || layers < 1 || int64_t(around) * tube * layers > 10'000'000)
    throw Error("torus shell: needs at least 3 around and 3 along the tube, 1 layer, at most 10^7 hexes");
  const double pi = std::acos(-1.0), R = 1.0 + 0.5 * (tube + layers);
  std::vector<Vec3> pts;
  for (int s = 0; s <= layers; ++s)
    for (int p = 0; p < tube; ++p)
      for (int t = 0; t < around; ++t) {
        double th = 2 * pi * t / around, ph = 2 * pi * p / tube, r = 1.0 + 0.4 * s;
        pts.push_back({(R + r * std::cos(ph)) * std::cos(th), (R + r * std::cos(ph)) * std::sin(th), r * std::sin(ph)});
      }
  auto vid = [&](int t, int p, int s) {
    if (t == around && klein) p = tube - p;  // once around, the tube comes back reflected
    return VertexId((t % around) + around * ((p % tube) + tube * s));
  };
  std::vector<std::array<VertexId, 8>> hexes;
  for (int s = 0; s < layers; ++s)
    for (int p = 0; p < tube; ++p)
      for (int t = 0; t < around; ++t) {
        std::array<VertexId, 8> v;
        for (int q = 0; q < 8; ++q) v[size_t(q)] = vid(t + cornerBit(q, 1), p + cornerBit(q, 2), s + cornerBit(q, 0));
        hexes.push_back(v);
      }
  return fromConnectivity(pts, hexes);
}

namespace {
struct FaceKey {
  std::array<VertexId, 4> key;
  HexId hex;
  int face;
  // The vertex ids (ascending, non-negative) as two 64-bit words: the same order as comparing the
  // arrays, in two integer compares instead of a memcmp call and a lexicographic loop (sorting
  // a 1M-hex file's 6M faces spent a sixth of its load in memcmp).
  uint64_t high() const { return uint64_t(uint32_t(key[0])) << 32 | uint32_t(key[1]); }
  uint64_t low() const { return uint64_t(uint32_t(key[2])) << 32 | uint32_t(key[3]); }
  bool operator<(const FaceKey& o) const {
    const uint64_t a = high(), b = o.high();
    if (a != b) return a < b;
    const uint64_t c = low(), d = o.low();
    if (c != d) return c < d;
    return hex != o.hex ? hex < o.hex : face < o.face;
  }
  bool sameQuad(const FaceKey& o) const { return high() == o.high() && low() == o.low(); }
};
std::string quadName(const std::array<VertexId, 4>& k) {
  return "quad (" + std::to_string(k[0]) + "," + std::to_string(k[1]) + "," + std::to_string(k[2]) + "," +
         std::to_string(k[3]) + ")";
}
}  // namespace

Complex fromConnectivity(const std::vector<Vec3>& points, const std::vector<std::array<VertexId, 8>>& hexes,
                         bool allowNonManifoldVertices) {
  Complex cx;
  cx.reserve(hexes.size() + hexes.size() / 8 + 64, points.size() + points.size() / 8 + 64);
  for (Vec3 p : points) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw Error("point " + std::to_string(cx.vertexCapacity()) + " has a coordinate that is not a finite number");
    cx.addVertex(p);
  }
  for (size_t h = 0; h < hexes.size(); ++h) {
    for (int c = 0; c < 8; ++c) {
      VertexId v = hexes[h][c];
      if (v < 0 || v >= (VertexId)points.size())
        throw Error("hex " + std::to_string(h) + " corner " + std::to_string(c) + ": vertex index " + std::to_string(v) +
                    " is out of range (" + std::to_string(points.size()) + " points)");
      for (int d = 0; d < c; ++d)
        if (hexes[h][d] == v) throw Error("hex " + std::to_string(h) + " repeats vertex " + std::to_string(v));
    }
    cx.addHex(hexes[h]);
  }
  std::vector<FaceKey> faces;
  faces.reserve(hexes.size() * 6);
  for (size_t h = 0; h < hexes.size(); ++h)
    for (int f = 0; f < 6; ++f) {
      FaceKey k{{}, HexId(h), f};
      for (int p = 0; p < 4; ++p) k.key[p] = hexes[h][kFaceCorners[f][p]];
      std::sort(k.key.begin(), k.key.end());
      faces.push_back(k);
    }
  std::sort(faces.begin(), faces.end());
  for (size_t i = 0; i < faces.size();) {
    size_t j = i;
    while (j < faces.size() && faces[j].sameQuad(faces[i])) ++j;
    if (j - i > 2) {
      std::string who;
      for (size_t k = i; k < j; ++k) who += (k > i ? ", " : "") + std::to_string(faces[k].hex);
      throw Error(quadName(faces[i].key) + " is shared by " + std::to_string(j - i) + " hexes (" + who +
                  "); a quad has at most two sides");
    }
    if (j - i == 2) {
      const FaceKey &A = faces[i], &B = faces[i + 1];
      auto posInB = [&](int pa) {
        VertexId v = hexes[A.hex][kFaceCorners[A.face][pa]];
        for (int p = 0; p < 4; ++p)
          if (hexes[B.hex][kFaceCorners[B.face][p]] == v) return p;
        return -1;
      };
      int p0 = posInB(0), p1 = posInB(1);
      int orient = orientFromPositions(p0, p1);
      bool cyclic = ((p1 - p0) & 3) == 1 || ((p0 - p1) & 3) == 1;
      for (int p = 0; cyclic && p < 4; ++p) cyclic = posInB(p) == mapPosition(p, orient);
      if (!cyclic)
        throw Error("hexes " + std::to_string(A.hex) + " and " + std::to_string(B.hex) + " share the 4 vertices of " +
                    quadName(A.key) + " in different cyclic orders");
      cx.glue(A.hex, A.face, B.hex, B.face, orient);
    }
    i = j;
  }
  if (allowNonManifoldVertices)
    cx.validateAcceptingNonManifoldVertices();
  else
    cx.validate();
  return cx;
}

}  // namespace hexdual
