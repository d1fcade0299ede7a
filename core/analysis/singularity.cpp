#include "analysis/singularity.hpp"

#include <algorithm>

namespace hexdual {

namespace {

// Valence, boundary flag and smallest incidence of every edge class, in one pass over the slots.
struct EdgeClassFacts {
  std::vector<int32_t> valence;
  std::vector<uint8_t> boundary;
  std::vector<EdgeRef> first;
};

EdgeClassFacts edgeClassFacts(const Complex& cx) {
  int32_t n = 0;
  const std::vector<int32_t> cls = cx.edgeClasses(&n);
  EdgeClassFacts f{std::vector<int32_t>(size_t(n), 0), std::vector<uint8_t>(size_t(n), 0),
                   std::vector<EdgeRef>(size_t(n))};
  for (HexId h : cx.hexes())
    for (int e = 0; e < 12; ++e) {
      const size_t k = size_t(cls[size_t(12) * size_t(h) + size_t(e)]);
      if (f.valence[k]++ == 0) f.first[k] = {h, e};  // (hex, edge) order: the first is the smallest
      for (int face : tables::facesOfEdge(e))
        if (cx.isBoundary({h, face})) f.boundary[k] = 1;
    }
  return f;
}

std::vector<uint8_t> boundaryVertexMask(const Complex& cx) {
  std::vector<uint8_t> mask(size_t(cx.vertexCapacity()), 0);
  for (const Complex::BoundaryQuad& q : cx.boundaryQuads())
    for (VertexId v : q.vertices) mask[size_t(v)] = 1;
  return mask;
}

bool sameKind(const SingularEdge& a, const SingularEdge& b) { return a.boundary == b.boundary && a.valence == b.valence; }

// The singular edges at each vertex, and which vertices a curve passes through (exactly two
// singular edges there, of one kind).
struct Incidence {
  std::vector<std::vector<int>> at;  // per vertex id
  std::vector<uint8_t> passThrough;
};

Incidence incidence(const Complex& cx, const std::vector<SingularEdge>& edges) {
  Incidence in{std::vector<std::vector<int>>(size_t(cx.vertexCapacity())), {}};
  for (size_t i = 0; i < edges.size(); ++i)
    for (VertexId v : edges[i].vertices) in.at[size_t(v)].push_back(int(i));
  in.passThrough.assign(in.at.size(), 0);
  for (size_t v = 0; v < in.at.size(); ++v) {
    const auto& e = in.at[v];
    in.passThrough[v] = e.size() == 2 && sameKind(edges[size_t(e[0])], edges[size_t(e[1])]);
  }
  return in;
}

VertexId otherEnd(const SingularEdge& e, VertexId v) { return e.vertices[0] == v ? e.vertices[1] : e.vertices[0]; }

// From edge i, leaving through vertex v: the edges met until the curve ends (not including i);
// `end` is the vertex it ends at, or -1 when the walk came back to i (a closed curve).
std::vector<int> walkFrom(const std::vector<SingularEdge>& edges, const Incidence& in, int i, VertexId v, VertexId& end) {
  std::vector<int> out;
  int cur = i;
  while (in.passThrough[size_t(v)]) {
    const auto& two = in.at[size_t(v)];
    int next = two[0] == cur ? two[1] : two[0];
    if (next == i) {
      end = -1;
      return out;
    }
    out.push_back(next);
    v = otherEnd(edges[size_t(next)], v);
    cur = next;
  }
  end = v;
  return out;
}

SingularCurve traceCurve(const std::vector<SingularEdge>& edges, const Incidence& in, int first) {
  const SingularEdge& e = edges[size_t(first)];
  SingularCurve c{{}, e.valence, e.boundary, false, {-1, -1}};
  VertexId back = -1, ahead = -1;
  std::vector<int> before = walkFrom(edges, in, first, e.vertices[0], back);
  if (back < 0) {  // closed: one walk round from `first`
    c.closed = true;
    c.edges.push_back(first);
    c.edges.insert(c.edges.end(), before.rbegin(), before.rend());
    return c;
  }
  std::vector<int> after = walkFrom(edges, in, first, e.vertices[1], ahead);
  c.edges.assign(before.rbegin(), before.rend());
  c.edges.push_back(first);
  c.edges.insert(c.edges.end(), after.begin(), after.end());
  c.ends = {back, ahead};
  return c;
}

void countAll(SingularityGraph& g) {
  SingularityCounts& n = g.counts;
  for (const SingularEdge& e : g.edges) {
    ++(e.boundary ? n.boundaryByValence : n.interiorByValence)[e.valence];
    ++(e.boundary ? n.boundaryEdges : n.interiorEdges);
  }
  n.vertices = int64_t(g.vertices.size());
  n.boundaryVertices = std::count_if(g.vertices.begin(), g.vertices.end(), [](const SingularVertex& v) { return v.boundary; });
  n.curves = int64_t(g.curves.size());
}

}  // namespace

SingularityGraph singularityGraph(const Complex& cx) {
  SingularityGraph g;
  const EdgeClassFacts f = edgeClassFacts(cx);
  for (size_t k = 0; k < f.valence.size(); ++k) {
    const bool boundary = f.boundary[k] != 0;
    if (f.valence[k] == (boundary ? 2 : 4)) continue;
    const EdgeRef r = f.first[k];
    const auto& ends = tables::kEdgeCorners[size_t(r.edge)];
    g.edges.push_back({r, {cx.vertex(r.hex, ends[0]), cx.vertex(r.hex, ends[1])}, f.valence[k], boundary, -1});
  }
  const Incidence in = incidence(cx, g.edges);
  const std::vector<uint8_t> onBoundary = boundaryVertexMask(cx);
  for (size_t v = 0; v < in.at.size(); ++v)
    if (!in.at[v].empty() && !in.passThrough[v]) g.vertices.push_back({VertexId(v), onBoundary[v] != 0, int(in.at[v].size())});
  for (size_t i = 0; i < g.edges.size(); ++i) {
    if (g.edges[i].curve >= 0) continue;  // the first edge met of each curve is its smallest
    g.curves.push_back(traceCurve(g.edges, in, int(i)));
    for (int k : g.curves.back().edges) g.edges[size_t(k)].curve = int(g.curves.size() - 1);
  }
  countAll(g);
  return g;
}

}  // namespace hexdual
