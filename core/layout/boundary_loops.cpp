#include "layout/boundary_loops.hpp"

#include <unordered_map>

namespace hexdual {
using namespace tables;

std::vector<BoundaryEdge> boundaryEdges(const MidSurface& s, int skipSlot) {
  std::vector<BoundaryEdge> out;
  for (size_t i = 0; i < s.slots.size(); ++i) {
    if (int(i) == skipSlot) continue;
    for (int f = 0; f < 6; ++f) {
      if (axisOfFace(f) == s.slots[i].axis) continue;
      int j = s.joined(int(i), f);
      if (j >= 0 && j != skipSlot) continue;
      auto [u, v] = s.sideCorners(int(i), f);
      bool forward = false;
      for (int k = 0; k < 4; ++k)
        if (s.quad[i][size_t(k)] == u) forward = s.quad[i][size_t((k + 1) & 3)] == v;
      if ((s.sign[i] > 0) != forward) std::swap(u, v);
      out.push_back({u, v, int(i), f});
    }
  }
  return out;
}

bool chainLoops(const std::vector<BoundaryEdge>& edges, std::vector<std::vector<int>>& loops) {
  std::unordered_map<int, int> next;  // corner -> the edge leaving it
  next.reserve(edges.size());
  for (size_t k = 0; k < edges.size(); ++k)
    if (!next.emplace(edges[k].from, int(k)).second) return false;
  std::vector<bool> used(edges.size(), false);
  for (size_t k0 = 0; k0 < edges.size(); ++k0) {
    if (used[k0]) continue;
    std::vector<int> loop;
    int k = int(k0);
    while (!used[size_t(k)]) {
      used[size_t(k)] = true;
      loop.push_back(k);
      auto it = next.find(edges[size_t(k)].to);
      if (it == next.end()) return false;
      k = it->second;
    }
    if (k != int(k0)) return false;
    loops.push_back(std::move(loop));
  }
  return true;
}

std::vector<int> loopCorners(const std::vector<BoundaryEdge>& edges, const std::vector<int>& loop) {
  std::vector<int> corners;
  corners.reserve(loop.size());
  for (int k : loop) corners.push_back(edges[size_t(k)].from);
  return corners;
}

}  // namespace hexdual
