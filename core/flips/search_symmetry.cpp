// The problem's symmetries (SearchOptions::symmetry): candidate vertex maps of the start (the
// 4-cube boundary's 384, or a bounding box's 48) that keep the host and fix the canonical forms of
// start and goal; the search then stores one state per orbit.
#include "flips/search_parts.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace hexdual::flipsearch {
using namespace tables;

// Candidate vertex maps: for the 4-cube boundary its 384 symmetries (vertex id = coordinate
// bits), otherwise the 48 symmetries of the bounding box of the vertex positions.
std::vector<std::vector<VertexId>> candidateMaps(const Complex& cx) {
  std::vector<std::vector<VertexId>> out;
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  if (cx.numHexes() == 8 && cx.vertexCapacity() == 16) {
    std::array<int, 4> p{0, 1, 2, 3};
    do {
      for (int flip = 0; flip < 16; ++flip) {
        std::vector<VertexId> m(16);
        for (int v = 0; v < 16; ++v) {
          int w = 0;
          for (int i = 0; i < 4; ++i) w |= (((v >> i) & 1) ^ ((flip >> i) & 1)) << p[size_t(i)];
          m[size_t(v)] = w;
        }
        out.push_back(m);
      }
    } while (std::next_permutation(p.begin(), p.end()));
    return out;
  }
  std::map<std::array<long, 3>, VertexId> at;
  std::array<double, 3> lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  auto coords = [](Vec3 q) { return std::array<double, 3>{q.x, q.y, q.z}; };
  for (VertexId v : cx.vertices()) {
    auto c = coords(cx.position(v));
    for (int i = 0; i < 3; ++i)
      lo[size_t(i)] = std::min(lo[size_t(i)], c[size_t(i)]), hi[size_t(i)] = std::max(hi[size_t(i)], c[size_t(i)]);
    at[{std::lround(2 * c[0]), std::lround(2 * c[1]), std::lround(2 * c[2])}] = v;
  }
  for (auto& pm : perms)
    for (int flip = 0; flip < 8; ++flip) {
      std::vector<VertexId> m(size_t(cx.vertexCapacity()), -1);
      bool ok = true;
      for (VertexId v : cx.vertices()) {
        auto c = coords(cx.position(v));
        std::array<double, 3> d{};
        for (int i = 0; i < 3; ++i) {
          double x = c[size_t(pm[i])];
          d[size_t(i)] = (flip >> i) & 1 ? lo[size_t(pm[i])] + hi[size_t(pm[i])] - x : x;
        }
        auto it = at.find({std::lround(2 * d[0]), std::lround(2 * d[1]), std::lround(2 * d[2])});
        if (it == at.end())
          ok = false;
        else
          m[size_t(v)] = it->second;
      }
      if (ok) out.push_back(m);
    }
  return out;
}

// The symmetries of a problem: vertex maps that carry the host onto itself and leave the
// canonical forms of start and goal unchanged (so a path up to symmetry ends at the goal itself).
std::vector<std::vector<VertexId>> problemSymmetries(const SearchProblem& pb, const std::vector<uint8_t>& isHost) {
  RegionEncoder enc;
  const std::vector<int64_t> start = enc.form(pb.start, isHost), goal = enc.form(pb.goal, isHost);
  std::vector<std::array<VertexId, 8>> hostSets;
  auto sortedVerts = [](std::array<VertexId, 8> v) {
    std::sort(v.begin(), v.end());
    return v;
  };
  for (HexId h : pb.host) hostSets.push_back(sortedVerts(pb.start.hexVertices(h)));
  std::sort(hostSets.begin(), hostSets.end());
  std::vector<std::vector<VertexId>> out;
  for (const auto& m : candidateMaps(pb.start)) {
    bool identity = true;
    for (size_t v = 0; v < m.size(); ++v) identity = identity && (m[v] == VertexId(v) || m[v] < 0);
    if (identity) continue;
    std::vector<std::array<VertexId, 8>> images;
    for (HexId h : pb.host) {
      auto v = pb.start.hexVertices(h);
      for (VertexId& x : v) x = m[size_t(x)];
      images.push_back(sortedVerts(v));
    }
    std::sort(images.begin(), images.end());
    if (images != hostSets) continue;
    if (enc.form(pb.start, isHost, &m) != start || enc.form(pb.goal, isHost, &m) != goal) continue;
    out.push_back(m);
  }
  return out;
}

}  // namespace hexdual::flipsearch
