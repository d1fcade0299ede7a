#include "layout/mid_surface.hpp"

#include <algorithm>
#include <unordered_map>
#include <unordered_set>

#include "complex/union_find.hpp"

namespace hexdual {
using namespace tables;

std::array<int, 4> midCycle(int axis) { return {4 * axis + 0, 4 * axis + 1, 4 * axis + 3, 4 * axis + 2}; }

int cyclePos(int axis, int edge) {
  auto c = midCycle(axis);
  for (int i = 0; i < 4; ++i)
    if (c[size_t(i)] == edge) return i;
  return -1;
}

std::array<int, 2> edgesOnFace(int face, int axis) {
  std::array<int, 2> r{-1, -1};
  int n = 0;
  for (int p = 0; p < 4; ++p) {
    int e = kFaceEdges[size_t(face)][size_t(p)];
    if (axisOfEdge(e) == axis) r[size_t(n++)] = e;
  }
  return r;
}

std::pair<int, int> MidSurface::sideCorners(int i, int f) const {
  int a = slots[size_t(i)].axis;
  auto e = edgesOnFace(f, a);
  return {quad[size_t(i)][size_t(cyclePos(a, e[0]))], quad[size_t(i)][size_t(cyclePos(a, e[1]))]};
}

namespace {

// Mid vertices, the degenerate flag and the orientation, from the corners and the joined sides.
void linkMidSurface(MidSurface& s) {
  const size_t n = s.slots.size();
  s.nCorner = int(s.verts.size());
  s.mid.assign(n, {-1, -1, -1, -1, -1, -1});
  s.midEnds.clear();
  s.midSide.clear();
  s.midBoundary.clear();
  for (size_t i = 0; i < n; ++i)
    for (int f = 0; f < 6; ++f) {
      if (axisOfFace(f) == s.slots[i].axis || s.mid[i][size_t(f)] >= 0) continue;
      int id = int(s.midEnds.size());
      s.midEnds.push_back(s.sideCorners(int(i), f));
      s.midSide.push_back({int(i), f});
      s.mid[i][size_t(f)] = s.nCorner + id;
      int j = s.joined(int(i), f);
      s.midBoundary.push_back(j < 0);
      if (j >= 0) s.mid[size_t(j)][size_t(s.adjFace[i][size_t(f)])] = s.nCorner + id;
    }
  s.nMid = int(s.midEnds.size());
  s.degenerate = false;
  {
    std::unordered_set<uint64_t> ends;  // hashing the sorted corners of quads collides only on a repeat
    std::vector<std::array<int, 4>> sorted(s.quad);
    for (auto& q : sorted) std::sort(q.begin(), q.end());
    std::sort(sorted.begin(), sorted.end());
    s.degenerate = std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
    for (auto [a, b] : s.midEnds)
      if (!ends.insert(uint64_t(uint32_t(std::min(a, b))) << 32 | uint32_t(std::max(a, b))).second) s.degenerate = true;
  }
  // Orientation by propagation: neighbouring quads run over their shared side in opposite directions.
  auto dirIn = [&](int q, int x, int y) {  // +1 when quad q's cycle runs x -> y
    for (int k = 0; k < 4; ++k)
      if (s.quad[size_t(q)][size_t(k)] == x) return s.quad[size_t(q)][size_t((k + 1) & 3)] == y ? 1 : -1;
    return 0;
  };
  s.sign.assign(n, 0);
  s.orientable = true;
  std::vector<int> stack;
  for (size_t start = 0; start < n; ++start) {
    if (s.sign[start]) continue;
    s.sign[start] = 1;
    stack.push_back(int(start));
    while (!stack.empty()) {
      int i = stack.back();
      stack.pop_back();
      for (int f = 0; f < 6; ++f) {
        if (axisOfFace(f) == s.slots[size_t(i)].axis) continue;
        int j = s.joined(i, f);
        if (j < 0) continue;
        auto [u, v] = s.sideCorners(i, f);
        int want = -s.sign[size_t(i)] * dirIn(i, u, v) * dirIn(j, u, v);
        if (!s.sign[size_t(j)]) {
          s.sign[size_t(j)] = int8_t(want);
          stack.push_back(j);
        } else if (s.sign[size_t(j)] != want) {
          s.orientable = false;
        }
      }
    }
  }
}

}  // namespace

MidSurface buildMidSurface(const Complex& cx, std::vector<Slot> slots) {
  MidSurface s;
  std::sort(slots.begin(), slots.end());
  s.slots = std::move(slots);
  const size_t n = s.slots.size();
  auto find = [&](Slot x) {
    auto it = std::lower_bound(s.slots.begin(), s.slots.end(), x);
    return it != s.slots.end() && *it == x ? int(it - s.slots.begin()) : -1;
  };
  s.adj.assign(n, {-1, -1, -1, -1, -1, -1});
  s.adjFace.assign(n, {-1, -1, -1, -1, -1, -1});
  for (size_t i = 0; i < n; ++i)
    for (int f = 0; f < 6; ++f) {
      if (axisOfFace(f) == s.slots[i].axis) continue;
      Gluing g = cx.gluing(s.slots[i].hex, f);
      if (g.boundary()) continue;
      s.adj[i][size_t(f)] = find({g.hex, mapAxisAcross(cx, s.slots[i].hex, f, s.slots[i].axis)});
      s.adjFace[i][size_t(f)] = int8_t(g.face);
    }
  std::unordered_map<uint64_t, int> vid;
  vid.reserve(2 * n);
  for (Slot sl : s.slots) {
    std::array<int, 4> q;
    auto c = midCycle(sl.axis);
    for (int k = 0; k < 4; ++k) {
      EdgeRef e = cx.canonical(EdgeRef{sl.hex, c[size_t(k)]});
      auto [it, ins] = vid.try_emplace(uint64_t(uint32_t(e.hex)) << 4 | uint32_t(e.edge), int(s.verts.size()));
      if (ins) {
        s.verts.push_back(e);
        s.origin.push_back(it->second);
      }
      q[size_t(k)] = it->second;
    }
    s.quad.push_back(q);
  }
  linkMidSurface(s);
  return s;
}

MidSurface cutOpen(const MidSurface& s, const std::vector<std::array<bool, 6>>& cut) {
  MidSurface c;
  c.slots = s.slots;
  c.adj = s.adj;
  c.adjFace = s.adjFace;
  c.cut = cut;
  const size_t n = s.slots.size();
  // Corners become wedges: the quad corners around a corner joined across uncut sides.
  UnionFind wedges(4 * n);
  for (size_t i = 0; i < n; ++i)
    for (int f = 0; f < 6; ++f) {
      int j = c.joined(int(i), f);
      if (axisOfFace(f) == s.slots[i].axis || j < 0) continue;
      int g = s.adjFace[i][size_t(f)];
      auto ei = edgesOnFace(f, s.slots[i].axis), ej = edgesOnFace(g, s.slots[size_t(j)].axis);
      for (int p = 0; p < 2; ++p) {
        int ki = cyclePos(s.slots[i].axis, ei[size_t(p)]);
        int u = s.quad[i][size_t(ki)];
        for (int q = 0; q < 2; ++q) {
          int kj = cyclePos(s.slots[size_t(j)].axis, ej[size_t(q)]);
          if (s.quad[size_t(j)][size_t(kj)] == u) {
            wedges.unite(4 * i + size_t(ki), 4 * size_t(j) + size_t(kj));
            break;
          }
        }
      }
    }
  std::vector<int> id(4 * n, -1);
  c.quad.resize(n);
  for (size_t k = 0; k < 4 * n; ++k) {
    size_t r = wedges.find(k);
    if (id[r] < 0) {
      id[r] = int(c.verts.size());
      c.verts.push_back(s.verts[size_t(s.quad[r / 4][r % 4])]);
      c.origin.push_back(s.origin[size_t(s.quad[r / 4][r % 4])]);
    }
    c.quad[k / 4][k % 4] = id[r];
  }
  linkMidSurface(c);
  return c;
}

}  // namespace hexdual
