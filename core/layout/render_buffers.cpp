#include "layout/render_buffers.hpp"

#include <cmath>

#include "layout/dual_points.hpp"

namespace hexdual {
using namespace tables;

namespace {
Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
void push(std::vector<float>& out, Vec3 p) { out.insert(out.end(), {float(p.x), float(p.y), float(p.z)}); }

// A degenerate hex is drawn at this fraction of a regular hex's size.
constexpr double kDegenerateScale = 0.6;

void addFace(RenderBuffers& rb, const Vec3 (&p)[8], Vec3 centre, HexId h, int f) {
  const auto& fc = kFaceCorners[size_t(f)];
  Vec3 nrm = cross(p[fc[2]] - p[fc[0]], p[fc[3]] - p[fc[1]]);
  Vec3 mid = 0.25 * (p[fc[0]] + p[fc[1]] + p[fc[2]] + p[fc[3]]);
  bool outward = dot(nrm, mid - centre) >= 0;
  if (!outward) nrm = -1.0 * nrm;
  double len = std::sqrt(dot(nrm, nrm));
  if (len > 0) nrm = (1.0 / len) * nrm;
  uint32_t base = uint32_t(rb.positions.size() / 3);
  for (int q = 0; q < 4; ++q) {
    push(rb.positions, p[fc[q]]);
    push(rb.normals, nrm);
  }
  // Wind the two triangles counter-clockwise seen from outside.
  if (outward)
    rb.indices.insert(rb.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  else
    rb.indices.insert(rb.indices.end(), {base, base + 2, base + 1, base, base + 3, base + 2});
  rb.triangleHex.insert(rb.triangleHex.end(), {h, h});
  rb.triangleFace.insert(rb.triangleFace.end(), {uint8_t(f), uint8_t(f)});
}
}  // namespace

std::vector<HexId> drawnHexes(const Complex& cx, const DrawnHexes& drawn) {
  auto hidden = [&](HexId h) { return size_t(h) < drawn.hidden.size() && drawn.hidden[size_t(h)] != 0; };
  auto exposed = [&](HexId h) {
    for (int f = 0; f < 6; ++f) {
      const HexId g = cx.gluing(h, f).hex;
      if (g < 0 || hidden(g)) return true;
    }
    return false;
  };
  std::vector<uint8_t> always(size_t(cx.hexCapacity()), 0);
  for (HexId h : drawn.always)
    if (h >= 0 && h < cx.hexCapacity()) always[size_t(h)] = 1;
  std::vector<HexId> out;
  for (HexId h : cx.hexes())
    if (always[size_t(h)] || (!hidden(h) && (!drawn.shell || exposed(h)))) out.push_back(h);
  return out;
}

RenderBuffers buildRenderBuffers(const Complex& cx, double shrink, bool edges, const DrawnHexes& drawn) {
  RenderBuffers rb;
  const std::vector<HexId> hexes = drawnHexes(cx, drawn);
  const size_t n = hexes.size();
  rb.positions.reserve(n * 72);
  rb.normals.reserve(n * 72);
  rb.indices.reserve(n * 36);
  rb.triangleHex.reserve(n * 12);
  rb.triangleFace.reserve(n * 12);
  if (edges) rb.edgePositions.reserve(n * 72);
  const std::vector<Vec3> dp = dualPoints(cx);
  for (HexId h : hexes) {
    const Vec3 c = cx.hexCentroid(h), d = dp[size_t(h)];
    const double keep = (1.0 - shrink) * (isDegenerateHex(cx, h) ? kDegenerateScale : 1.0);
    Vec3 p[8];
    for (int k = 0; k < 8; ++k) p[k] = d + keep * (cx.position(cx.vertex(h, k)) - c);
    for (int f = 0; f < 6; ++f) addFace(rb, p, d, h, f);
    if (!edges) continue;
    for (int e = 0; e < 12; ++e) {
      push(rb.edgePositions, p[kEdgeCorners[size_t(e)][0]]);
      push(rb.edgePositions, p[kEdgeCorners[size_t(e)][1]]);
      rb.edgeHex.push_back(h);
      rb.edgeLocal.push_back(uint8_t(e));
    }
  }
  return rb;
}

}  // namespace hexdual
