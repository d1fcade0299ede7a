#include "layout/dual_points.hpp"

#include <algorithm>
#include <array>

namespace hexdual {
using namespace tables;

namespace {
Vec3 faceCentre(const Complex& cx, HexId h, int f) {
  Vec3 s;
  for (int c : kFaceCorners[size_t(f)]) s = s + cx.position(cx.vertex(h, c));
  return 0.25 * s;
}

// Neighbour hex ids across h's faces (-1 on the boundary).
std::array<HexId, 6> faceNeighbours(const Complex& cx, HexId h) {
  std::array<HexId, 6> nb{};
  for (int f = 0; f < 6; ++f) nb[size_t(f)] = cx.gluing(h, f).hex;
  return nb;
}

void push(std::vector<float>& out, Vec3 p) { out.insert(out.end(), {float(p.x), float(p.y), float(p.z)}); }
}  // namespace

bool isDegenerateHex(const Complex& cx, HexId h) {
  auto nb = faceNeighbours(cx, h);
  for (int f = 0; f < 6; ++f)
    for (int g = f + 1; g < 6; ++g)
      if (nb[size_t(f)] >= 0 && nb[size_t(f)] == nb[size_t(g)]) return true;
  return false;
}

std::vector<Vec3> dualPoints(const Complex& cx) {
  std::vector<Vec3> centroid(size_t(cx.hexCapacity())), out(size_t(cx.hexCapacity()));
  for (HexId h : cx.hexes()) centroid[size_t(h)] = cx.hexCentroid(h);
  for (HexId h : cx.hexes()) {
    const Vec3 c = centroid[size_t(h)];
    auto nb = faceNeighbours(cx, h);
    Vec3 sum;
    int count = 0;
    for (int f = 0; f < 6; ++f) {
      HexId n = nb[size_t(f)];
      if (n < 0) {
        sum = sum + 2.0 * (faceCentre(cx, h, f) - c);
        ++count;
      } else if (std::find(nb.begin(), nb.begin() + f, n) == nb.begin() + f) {
        sum = sum + (centroid[size_t(n)] - c);
        ++count;
      }
    }
    out[size_t(h)] = c + (0.5 / count) * sum;
  }
  return out;
}

DualOverlay buildDualOverlay(const Complex& cx, const Dual& dual, const std::vector<HexId>* only) {
  DualOverlay o;
  const std::vector<Vec3> dp = dualPoints(cx);
  std::vector<uint8_t> keep(size_t(cx.hexCapacity()), only ? 0 : 1);
  if (only)
    for (HexId h : *only)
      if (cx.isHex(h)) keep[size_t(h)] = 1;
  auto kept = [&](HexId h) { return keep[size_t(h)] != 0; };
  auto placed = [&](HexId h, Vec3 p) { return p - cx.hexCentroid(h) + dp[size_t(h)]; };
  for (const Sheet& s : dual.sheets) {
    if (!s.alive) continue;
    for (Slot sl : s.slots) {
      if (!kept(sl.hex)) continue;
      uint32_t base = uint32_t(o.sheetPositions.size() / 3);
      // Edges 4a+k run along axis a; k = ub + 2 vb, so 0,1,3,2 walks the quad around.
      for (int k : {0, 1, 3, 2}) {
        const auto& ec = kEdgeCorners[size_t(4 * sl.axis + k)];
        Vec3 mid = 0.5 * (cx.position(cx.vertex(sl.hex, ec[0])) + cx.position(cx.vertex(sl.hex, ec[1])));
        push(o.sheetPositions, placed(sl.hex, mid));
      }
      o.sheetIndices.insert(o.sheetIndices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
      o.sheetTriangle.insert(o.sheetTriangle.end(), {s.id, s.id});
    }
  }
  for (const Chord& ch : dual.chords) {
    if (!ch.alive || ch.slots.empty()) continue;
    std::vector<Vec3> line;
    std::vector<HexId> lineHex;  // the hex each point belongs to
    auto add = [&](HexId h, Vec3 p) {
      line.push_back(p);
      lineHex.push_back(h);
    };
    auto end = [&](Slot sl, bool first) {
      for (int f : {2 * sl.axis, 2 * sl.axis + 1}) {
        if (!cx.isBoundary({sl.hex, f})) continue;
        // The first slot's boundary face starts the line; with one slot both faces are ends.
        if (ch.slots.size() > 1 || first == (f == 2 * sl.axis)) {
          add(sl.hex, placed(sl.hex, faceCentre(cx, sl.hex, f)));
          return;
        }
      }
    };
    if (!ch.closed) end(ch.slots.front(), true);
    for (Slot sl : ch.slots) add(sl.hex, dp[size_t(sl.hex)]);
    if (ch.closed) add(ch.slots.front().hex, dp[size_t(ch.slots.front().hex)]);
    else end(ch.slots.back(), false);
    for (size_t i = 0; i + 1 < line.size(); ++i) {
      if (!kept(lineHex[i]) || !kept(lineHex[i + 1])) continue;
      push(o.chordPositions, line[i]);
      push(o.chordPositions, line[i + 1]);
      o.chordSegment.push_back(ch.id);
    }
  }
  for (HexId h : cx.hexes()) {
    if (!kept(h)) continue;
    push(o.dualVertices, dp[size_t(h)]);
    o.dualVertexHex.push_back(h);
  }
  return o;
}

}  // namespace hexdual
