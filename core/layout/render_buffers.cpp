#include "layout/render_buffers.hpp"

#include <cmath>

namespace hexdual {
using namespace tables;

namespace {
Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
}  // namespace

RenderBuffers buildRenderBuffers(const Complex& cx, double shrink) {
  RenderBuffers rb;
  const size_t n = size_t(cx.numHexes());
  rb.positions.reserve(n * 72);
  rb.normals.reserve(n * 72);
  rb.indices.reserve(n * 36);
  rb.triangleHex.reserve(n * 12);
  const double keep = 1.0 - shrink;
  for (HexId h : cx.hexes()) {
    Vec3 c = cx.hexCentroid(h);
    Vec3 p[8];
    for (int k = 0; k < 8; ++k) p[k] = c + keep * (cx.position(cx.vertex(h, k)) - c);
    for (int f = 0; f < 6; ++f) {
      const auto& fc = kFaceCorners[f];
      Vec3 nrm = cross(p[fc[2]] - p[fc[0]], p[fc[3]] - p[fc[1]]);
      Vec3 mid = 0.25 * (p[fc[0]] + p[fc[1]] + p[fc[2]] + p[fc[3]]);
      bool outward = dot(nrm, mid - c) >= 0;
      if (!outward) nrm = -1.0 * nrm;
      double len = std::sqrt(dot(nrm, nrm));
      if (len > 0) nrm = (1.0 / len) * nrm;
      uint32_t base = uint32_t(rb.positions.size() / 3);
      for (int q = 0; q < 4; ++q) {
        Vec3 v = p[fc[q]];
        rb.positions.insert(rb.positions.end(), {float(v.x), float(v.y), float(v.z)});
        rb.normals.insert(rb.normals.end(), {float(nrm.x), float(nrm.y), float(nrm.z)});
      }
      // Wind the two triangles counter-clockwise seen from outside.
      if (outward)
        rb.indices.insert(rb.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
      else
        rb.indices.insert(rb.indices.end(), {base, base + 2, base + 1, base, base + 3, base + 2});
      rb.triangleHex.insert(rb.triangleHex.end(), {h, h});
    }
  }
  return rb;
}

}  // namespace hexdual
