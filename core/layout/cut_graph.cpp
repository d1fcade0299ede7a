#include "layout/cut_graph.hpp"

#include <algorithm>
#include <unordered_map>
#include <unordered_set>

namespace hexdual {
using namespace tables;

namespace {

// A sphere has no cut graph; it is opened along a tree of shortest paths through corners far from
// each other (farthest-point samples), so that long arms of the sphere are slit along their
// length: a harmonic map would squeeze an unslit tube exponentially. The polygon is the tree
// walked round, each of its paths a seam a ... a⁻¹.
void addSlitTree(const MidSurface& s, CutGraph& g) {
  const int kSamples = 12;
  std::vector<std::vector<std::pair<int, int>>> at(size_t(s.nCorner));  // corner -> (edge, other corner)
  for (int m = 0; m < s.nMid; ++m) {
    auto [a, b] = s.midEnds[size_t(m)];
    if (a == b) continue;
    at[size_t(a)].push_back({m, b});
    at[size_t(b)].push_back({m, a});
  }
  std::vector<bool> onTree(size_t(s.nCorner), false);
  std::vector<int> via(size_t(s.nCorner)), queue;
  // Breadth first from the tree (or corner 0): returns the farthest corner, `via` its path back.
  auto farthest = [&](bool fromTree) {
    std::fill(via.begin(), via.end(), -2);
    queue.clear();
    for (int v = 0; v < s.nCorner; ++v)
      if (fromTree ? bool(onTree[size_t(v)]) : v == 0) {
        via[size_t(v)] = -1;
        queue.push_back(v);
      }
    for (size_t q = 0; q < queue.size(); ++q)
      for (auto [m, w] : at[size_t(queue[q])])
        if (via[size_t(w)] == -2) {
          via[size_t(w)] = m;
          queue.push_back(w);
        }
    return queue.back();
  };
  onTree[size_t(farthest(false))] = true;
  for (int k = 0; k < kSamples; ++k) {
    int v = farthest(true);
    if (via[size_t(v)] < 0) break;  // every corner is on the tree
    while (via[size_t(v)] >= 0) {
      int m = via[size_t(v)];
      g.edge[size_t(m)] = true;
      ++g.degree[size_t(s.midEnds[size_t(m)].first)];
      ++g.degree[size_t(s.midEnds[size_t(m)].second)];
      onTree[size_t(v)] = true;
      v = s.midEnds[size_t(m)].first == v ? s.midEnds[size_t(m)].second : s.midEnds[size_t(m)].first;
    }
  }
}

}  // namespace

CutGraph cutGraph(const MidSurface& s) {
  const size_t n = s.slots.size();
  CutGraph g;
  g.cut.assign(n, {false, false, false, false, false, false});
  // A spanning tree of the dual graph (slots joined across sides), breadth first from slot 0.
  std::vector<bool> inTree(size_t(s.nMid), false), seen(n, false);
  std::vector<int> queue;
  for (size_t root = 0; root < n; ++root) {
    if (seen[root]) continue;
    seen[root] = true;
    queue.assign(1, int(root));
    for (size_t q = 0; q < queue.size(); ++q) {
      int i = queue[q];
      for (int f = 0; f < 6; ++f) {
        int j = s.joined(i, f);
        if (axisOfFace(f) == s.slots[size_t(i)].axis || j < 0 || seen[size_t(j)]) continue;
        seen[size_t(j)] = true;
        inTree[size_t(s.mid[size_t(i)][size_t(f)] - s.nCorner)] = true;
        queue.push_back(j);
      }
    }
  }
  // The other edges, then prune: an edge with an end of degree 1 bounds no region.
  g.edge.assign(size_t(s.nMid), false);
  g.degree.assign(size_t(s.nCorner), 0);
  std::vector<std::vector<int>> at(size_t(s.nCorner));
  for (int m = 0; m < s.nMid; ++m) {
    if (inTree[size_t(m)]) continue;
    g.edge[size_t(m)] = true;
    auto [a, b] = s.midEnds[size_t(m)];
    ++g.degree[size_t(a)];
    ++g.degree[size_t(b)];
    at[size_t(a)].push_back(m);
    if (b != a) at[size_t(b)].push_back(m);
  }
  std::vector<int> leaves;
  for (int v = 0; v < s.nCorner; ++v)
    if (g.degree[size_t(v)] == 1) leaves.push_back(v);
  while (!leaves.empty()) {
    int v = leaves.back();
    leaves.pop_back();
    if (g.degree[size_t(v)] != 1) continue;
    for (int m : at[size_t(v)]) {
      if (!g.edge[size_t(m)]) continue;
      g.edge[size_t(m)] = false;
      auto [a, b] = s.midEnds[size_t(m)];
      int w = a == v ? b : a;
      --g.degree[size_t(v)];
      if (--g.degree[size_t(w)] == 1) leaves.push_back(w);
      break;
    }
  }
  bool empty = std::find(g.edge.begin(), g.edge.end(), true) == g.edge.end();
  if (empty && s.nCorner > 1) addSlitTree(s, g);
  for (int m = 0; m < s.nMid; ++m) {
    if (!g.edge[size_t(m)] || s.midBoundary[size_t(m)]) continue;
    auto [i, f] = s.midSide[size_t(m)];
    g.cut[size_t(i)][size_t(f)] = true;
    g.cut[size_t(s.neighbour(i, f))][size_t(s.adjFace[size_t(i)][size_t(f)])] = true;
  }
  return g;
}

std::string seamLabel(int pair, int sign) {
  std::string l(1, char('a' + pair % 26));
  if (pair >= 26) l += std::to_string(pair / 26 + 1);
  return sign < 0 ? l + "\u207b\u00b9" : l;
}

FundamentalPolygon fundamentalPolygon(const MidSurface& s, const CutGraph& g, const MidSurface& open,
                                      const std::vector<BoundaryEdge>& edges, const std::vector<int>& loop) {
  FundamentalPolygon p;
  const size_t L = loop.size();
  auto fromOf = [&](size_t k) { return open.origin[size_t(edges[size_t(loop[k])].from)]; };
  auto branch = [&](size_t k) { return g.degree[size_t(fromOf(k))] != 2; };
  size_t k0 = 0;
  while (k0 < L && !branch(k0)) ++k0;
  if (k0 == L) k0 = 0;  // the cut graph is one cycle: its first corner stands for the branch
  std::unordered_set<int> corners;
  std::unordered_map<int, size_t> firstSide;  // smallest edge of a seam -> its first side
  int boundarySides = 0;
  for (size_t t = 0; t < L; ++t) {
    size_t k = (k0 + t) % L;
    if (t == 0 || branch(k)) {
      p.sides.emplace_back();
      corners.insert(fromOf(k));
    }
    p.sides.back().edges.push_back(loop[k]);
  }
  for (size_t i = 0; i < p.sides.size(); ++i) {
    PolygonSide& side = p.sides[i];
    const BoundaryEdge& first = edges[size_t(side.edges.front())];
    int m0 = s.mid[size_t(first.slot)][size_t(first.face)] - s.nCorner;
    if (s.midBoundary[size_t(m0)]) {
      ++boundarySides;
      continue;
    }
    int key = s.nMid;
    for (int k : side.edges) key = std::min(key, s.mid[size_t(edges[size_t(k)].slot)][size_t(edges[size_t(k)].face)] - s.nCorner);
    auto [it, isFirst] = firstSide.try_emplace(key, i);
    if (isFirst) {
      side.pair = p.pairs++;
      continue;
    }
    const PolygonSide& a = p.sides[it->second];
    side.pair = a.pair;
    // Glued in the same direction when both sides start with the same edge at the same corner.
    const BoundaryEdge& af = edges[size_t(a.edges.front())];
    int am0 = s.mid[size_t(af.slot)][size_t(af.face)] - s.nCorner;
    bool sameStart = open.origin[size_t(af.from)] == open.origin[size_t(first.from)];
    bool loopEdge = s.midEnds[size_t(m0)].first == s.midEnds[size_t(m0)].second;
    side.sign = am0 == m0 && (side.edges.size() > 1 || (sameStart && !loopEdge)) ? 1 : -1;
  }
  p.branchCorners = int(corners.size());
  p.euler = 1 + int64_t(p.branchCorners) - int64_t(p.pairs + boundarySides);
  return p;
}

}  // namespace hexdual
