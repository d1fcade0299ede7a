// Complex::validate(): every invariant of the complex (docs/model.md), with a message naming the first violation.
#include <algorithm>
#include <string>

#include "complex/complex.hpp"
#include "complex/union_find.hpp"

namespace hexdual {
using namespace tables;

namespace {
std::string hf(HexId h, int f) { return "hex " + std::to_string(h) + " face " + std::to_string(f); }
[[noreturn]] void fail(const std::string& msg) { throw Error("validate: " + msg); }
// A connected vertex link with T triangles (hex corners), V vertices (edges at the vertex) and
// `boundarySides` unglued sides must be a sphere (no boundary) or a disk.
void checkLinkEuler(const std::string& name, int64_t linkV, int64_t linkT, int64_t boundarySides) {
  int64_t linkE = (3 * linkT - boundarySides) / 2 + boundarySides;
  int64_t chi = linkV - linkE + linkT;
  if (boundarySides == 0 && chi != 2)
    fail(name + " is interior but its link is not a sphere (Euler characteristic " + std::to_string(chi) + ")");
  if (boundarySides > 0 && chi != 1)
    fail(name + " is on the boundary but its link is not a disk (Euler characteristic " + std::to_string(chi) + ")");
}
}  // namespace

void Complex::validate() const {
  // Vertex ids, reference counts, distinct corners.
  std::vector<int32_t> refs(pos_.size(), 0);
  int64_t hexCount = 0, boundarySides = 0;
  for (HexId h : hexes()) {
    ++hexCount;
    for (int c = 0; c < 8; ++c) {
      VertexId v = verts_[h][c];
      if (v < 0 || v >= (VertexId)pos_.size())
        fail("hex " + std::to_string(h) + " corner " + std::to_string(c) + " has no vertex");
      ++refs[v];
      for (int d = 0; d < c; ++d)
        if (verts_[h][d] == v)
          fail("hex " + std::to_string(h) + " uses vertex " + std::to_string(v) + " at corners " + std::to_string(d) +
               " and " + std::to_string(c));
    }
    // Gluings: symmetric, to a live hex, vertex-consistent.
    for (int f = 0; f < 6; ++f) {
      Gluing g = gluing(h, f);
      if (g.boundary()) {
        ++boundarySides;
        continue;
      }
      if (!isHex(g.hex)) fail(hf(h, f) + " is glued to missing hex " + std::to_string(g.hex));
      if (g.hex == h && g.face == f) fail(hf(h, f) + " is glued to itself");
      Gluing back = gluing(g.hex, g.face);
      if (back.hex != h || back.face != f || back.orient != inverseOrient(g.orient))
        fail(hf(h, f) + " is glued to " + hf(g.hex, g.face) + ", which is not glued back the same way");
      for (int p = 0; p < 4; ++p) {
        int c = kFaceCorners[f][p], c2 = kFaceCorners[g.face][mapPosition(p, g.orient)];
        if (verts_[h][c] != verts_[g.hex][c2])
          fail(hf(h, f) + " is glued to " + hf(g.hex, g.face) + " but corner " + std::to_string(c) + " (vertex " +
               std::to_string(verts_[h][c]) + ") meets vertex " + std::to_string(verts_[g.hex][c2]));
      }
    }
  }
  int64_t vertexCount = 0;
  for (size_t v = 0; v < refs.size(); ++v) {
    if (refs[v] != refs_[v]) fail("vertex " + std::to_string(v) + " reference count is stale");
    vertexCount += refs[v] > 0;
  }
  if (hexCount != numHexes_ || vertexCount != numVertices_ || boundarySides != numBoundarySides_)
    fail("cached counts are stale");

  // Edge cycles: walking around every edge visits exactly its class (no twisted or broken cycles).
  int32_t numEdges = 0;
  auto cls = edgeClasses(&numEdges);
  std::vector<int32_t> classSize(size_t(numEdges), 0);
  for (HexId h : hexes())
    for (int e = 0; e < 12; ++e) ++classSize[size_t(cls[size_t(12) * h + e])];
  std::vector<uint8_t> seen(size_t(numEdges), 0);
  for (HexId h : hexes())
    for (int e = 0; e < 12; ++e) {
      int32_t k = cls[size_t(12) * h + e];
      if (seen[size_t(k)]) continue;
      seen[size_t(k)] = 1;
      auto cyc = edgeCycle({h, e});
      if ((int32_t)cyc.size() != classSize[size_t(k)])
        fail("edge at hex " + std::to_string(h) + " edge " + std::to_string(e) + " does not form one cycle or fan");
    }

  validateLinks(cls);

  // Euler characteristic of a 3-manifold with boundary: chi(M) = chi(boundary) / 2.
  Counts c = counts();
  int64_t chi = c.vertices - c.edges + c.quads - c.hexes;
  int64_t chiB = c.boundaryVertices - c.boundaryEdges + c.boundaryQuads;
  if (2 * chi != chiB)
    fail("Euler characteristic V-E+F-H = " + std::to_string(chi) + " but the boundary's is " + std::to_string(chiB) +
         " (expected twice)");
}

// Every vertex link is a 2-sphere (interior vertex) or a disk (boundary vertex).
void Complex::validateLinks(const std::vector<int32_t>& edgeClass) const {
  // Group (hex, corner) incidences by vertex (counting sort).
  std::vector<int32_t> start(pos_.size() + 1, 0);
  for (HexId h : hexes())
    for (VertexId v : verts_[h]) ++start[size_t(v) + 1];
  for (size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
  std::vector<std::pair<HexId, int>> inc(size_t(start.back()));
  std::vector<int32_t> fill(start.begin(), start.end() - 1);
  for (HexId h : hexes())
    for (int c = 0; c < 8; ++c) inc[size_t(fill[size_t(verts_[h][c])]++)] = {h, c};

  std::vector<int32_t> edges;
  for (size_t v = 0; v < pos_.size(); ++v) {
    size_t b = size_t(start[v]), e = size_t(start[v + 1]);
    if (b == e) continue;
    auto first = inc.begin() + long(b), last = inc.begin() + long(e);  // sorted by (hex, corner)
    UnionFind uf(e - b);
    int64_t boundarySides = 0;
    edges.clear();
    for (size_t i = b; i < e; ++i) {
      auto [h, c] = inc[i];
      for (int f : facesOfCorner(c)) {
        Gluing g = gluing(h, f);
        if (g.boundary()) {
          ++boundarySides;
          continue;
        }
        std::pair<HexId, int> n{g.hex, mappedCorner(h, f, c)};
        auto it = std::lower_bound(first, last, n);
        uf.unite(i - b, size_t(it - first));
      }
      for (int ed : edgesOfCorner(c)) edges.push_back(edgeClass[size_t(12) * h + ed]);
    }
    size_t components = 0;
    for (size_t i = 0; i < e - b; ++i) components += uf.find(i) == i;
    std::string name = "vertex " + std::to_string(v);
    if (components != 1) fail(name + " is non-manifold: its link has " + std::to_string(components) + " components");
    std::sort(edges.begin(), edges.end());
    int64_t linkV = std::unique(edges.begin(), edges.end()) - edges.begin();
    int64_t linkT = int64_t(e - b);
    checkLinkEuler(name, linkV, linkT, boundarySides);
  }
}

}  // namespace hexdual

namespace hexdual {

void Complex::validateAround(const std::vector<HexId>& hexList) const {
  std::vector<VertexId> verts;
  for (HexId h : hexList) {
    if (!isHex(h)) continue;
    for (int c = 0; c < 8; ++c) {
      VertexId v = verts_[h][c];
      for (int d = 0; d < c; ++d)
        if (verts_[h][d] == v)
          fail("hex " + std::to_string(h) + " uses vertex " + std::to_string(v) + " at corners " + std::to_string(d) +
               " and " + std::to_string(c));
      verts.push_back(v);
    }
    for (int f = 0; f < 6; ++f) {
      Gluing g = gluing(h, f);
      if (g.boundary()) continue;
      if (!isHex(g.hex)) fail(hf(h, f) + " is glued to missing hex " + std::to_string(g.hex));
      Gluing back = gluing(g.hex, g.face);
      if (back.hex != h || back.face != f || back.orient != inverseOrient(g.orient))
        fail(hf(h, f) + " is glued to " + hf(g.hex, g.face) + ", which is not glued back the same way");
      for (int p = 0; p < 4; ++p) {
        int c = kFaceCorners[f][p], c2 = kFaceCorners[g.face][mapPosition(p, g.orient)];
        if (verts_[h][c] != verts_[g.hex][c2])
          fail(hf(h, f) + " is glued to " + hf(g.hex, g.face) + " but their vertices differ");
      }
    }
  }
  std::sort(verts.begin(), verts.end());
  verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
  // Vertex links, found by walking from one corner: connected, and a sphere or a disk.
  for (VertexId v : verts) {
    HexId h0 = -1;
    int c0 = -1;
    for (HexId h : hexList)
      if (isHex(h))
        for (int c = 0; c < 8 && h0 < 0; ++c)
          if (verts_[h][c] == v) {
            h0 = h;
            c0 = c;
          }
    auto corners = cornersOfVertex(h0, c0);
    std::string name = "vertex " + std::to_string(v);
    if ((int32_t)corners.size() != refs_[v])
      fail(name + " is non-manifold: its link is not connected");
    int64_t boundarySides = 0;
    std::vector<EdgeRef> edges;
    for (auto [h, c] : corners) {
      for (int f : facesOfCorner(c)) boundarySides += gluing(h, f).boundary();
      for (int e : edgesOfCorner(c)) edges.push_back(canonical(EdgeRef{h, e}));
    }
    std::sort(edges.begin(), edges.end());
    int64_t linkV = std::unique(edges.begin(), edges.end()) - edges.begin();
    int64_t linkT = int64_t(corners.size());
    checkLinkEuler(name, linkV, linkT, boundarySides);
  }
}

}  // namespace hexdual
