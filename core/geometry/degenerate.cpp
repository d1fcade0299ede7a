#include "geometry/degenerate.hpp"

#include <algorithm>
#include <array>

#include "geometry/scaled_jacobian.hpp"

namespace hexdual {

namespace {

bool lowValenceEdge(const Complex& cx, HexId h) {
  for (int e = 0; e < 12; ++e) {
    EdgeRef cur{h, e};
    int exitFace = tables::facesOfEdge(e)[0];
    for (int steps = 1; steps <= 2; ++steps) {  // back at (h, e) within two steps: valence <= 2
      if (!cx.stepAroundEdge(cur, exitFace)) break;
      if (cur == EdgeRef{h, e}) return true;
    }
  }
  return false;
}

std::array<VertexId, 3> frame(const Complex& cx, HexId h, int c) {
  const int* f = kCornerFrame[c];
  return {cx.vertex(h, f[0]), cx.vertex(h, f[1]), cx.vertex(h, f[2])};
}

// Whether b is an odd permutation of a (false when they are not the same three ids).
bool oddPermutation(const std::array<VertexId, 3>& a, const std::array<VertexId, 3>& b) {
  int at[3];
  for (int i = 0; i < 3; ++i) {
    const auto it = std::find(b.begin(), b.end(), a[size_t(i)]);
    if (it == b.end()) return false;
    at[i] = int(it - b.begin());
  }
  if (at[0] == at[1] || at[1] == at[2] || at[0] == at[2]) return false;
  return (at[0] > at[1]) + (at[0] > at[2]) + (at[1] > at[2]) == 1 ||
         (at[0] > at[1]) + (at[0] > at[2]) + (at[1] > at[2]) == 3;
}

// starOf(h, c): the corners at hex h's corner c (walked, or read from a VertexStars).
template <class StarOf>
bool mirroredFrame(const Complex& cx, HexId h, StarOf&& starOf) {
  for (int c = 0; c < 8; ++c) {
    const std::array<VertexId, 3> mine = frame(cx, h, c);
    for (auto [h2, c2] : starOf(h, c))
      if (h2 != h && oddPermutation(mine, frame(cx, h2, c2))) return true;
  }
  return false;
}

}  // namespace

const std::vector<std::pair<HexId, int>>& VertexStars::of(HexId h, int corner) {
  const VertexId v = cx_.vertex(h, corner);
  const auto& nm = cx_.nonManifoldVertices();
  if (std::binary_search(nm.begin(), nm.end(), v)) return walked_ = cx_.cornersOfVertex(h, corner);
  auto [at, added] = known_.try_emplace(v);
  if (added) at->second = cx_.cornersOfVertex(h, corner);
  return at->second;
}

bool degenerateByConstruction(const Complex& cx, HexId h, VertexStars& stars) {
  return lowValenceEdge(cx, h) ||
         mirroredFrame(cx, h, [&](HexId hh, int c) -> const std::vector<std::pair<HexId, int>>& { return stars.of(hh, c); });
}

bool degenerateByConstruction(const Complex& cx, HexId h) {
  return lowValenceEdge(cx, h) || mirroredFrame(cx, h, [&](HexId hh, int c) { return cx.cornersOfVertex(hh, c); });
}

}  // namespace hexdual
