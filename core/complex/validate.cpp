// Complex::validate(): every invariant of the complex (docs/model.md), with a message naming the first violation.
#include <algorithm>
#include <cstdio>
#include <string>

#include "complex/complex.hpp"
#include "complex/manifold.hpp"
#include "complex/union_find.hpp"

namespace hexdual {
using namespace tables;

namespace {
std::string hf(HexId h, int f) { return "hex " + std::to_string(h) + " face " + std::to_string(f); }
[[noreturn]] void fail(const std::string& msg) { throw Error("validate: " + msg); }
std::vector<LinkIssue> linkIssues(const Complex& cx, const std::vector<int32_t>& edgeClass);
}  // namespace

void Complex::validate() const { validateImpl(nullptr); }

void Complex::validateAcceptingNonManifoldVertices() {
  std::vector<VertexId> accepted;
  validateImpl(&accepted);
  nonManifold_ = std::move(accepted);
}

void Complex::validateImpl(std::vector<VertexId>* accepted) const {
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
      if (edgeCycleSize({h, e}) != size_t(classSize[size_t(k)]))
        fail("edge at hex " + std::to_string(h) + " edge " + std::to_string(e) + " does not form one cycle or fan");
    }

  if (accepted) {
    for (const LinkIssue& li : linkIssues(*this, cls)) accepted->push_back(li.vertex);
  } else {
    validateLinks(cls);
  }

  // Euler characteristic of a 3-manifold with boundary: chi(M) = chi(boundary) / 2.
  Counts c = countsFrom(cls, numEdges);
  int64_t chi = c.vertices - c.edges + c.quads - c.hexes;
  int64_t chiB = c.boundaryVertices - c.boundaryEdges + c.boundaryQuads;
  if ((accepted ? accepted->empty() : nonManifold_.empty()) && 2 * chi != chiB)
    fail("Euler characteristic V-E+F-H = " + std::to_string(chi) + " but the boundary's is " + std::to_string(chiB) +
         " (expected twice)");
}

namespace {
// Why a connected vertex link with T triangles (hex corners), V vertices (edges at the vertex) and
// `boundarySides` unglued sides is not a sphere (no boundary) or a disk; empty when it is.
std::string linkEulerProblem(int64_t linkV, int64_t linkT, int64_t boundarySides) {
  int64_t linkE = (3 * linkT - boundarySides) / 2 + boundarySides;
  int64_t chi = linkV - linkE + linkT;
  if (boundarySides == 0 && chi != 2)
    return "is interior but its link is not a sphere (Euler characteristic " + std::to_string(chi) + ")";
  if (boundarySides > 0 && chi != 1)
    return "is on the boundary but its link is not a disk (Euler characteristic " + std::to_string(chi) + ")";
  return {};
}

// Every vertex whose link is not a sphere or a disk; the link's triangles are the vertex's hex
// corners, joined across glued faces.
std::vector<LinkIssue> linkIssues(const Complex& cx, const std::vector<int32_t>& edgeClass) {
  const size_t nv = size_t(cx.vertexCapacity());
  // Group (hex, corner) incidences by vertex (counting sort).
  std::vector<int32_t> start(nv + 1, 0);
  for (HexId h : cx.hexes())
    for (VertexId v : cx.hexVertices(h)) ++start[size_t(v) + 1];
  for (size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
  std::vector<std::pair<HexId, int>> inc(size_t(start.back()));
  std::vector<int32_t> fill(start.begin(), start.end() - 1);
  for (HexId h : cx.hexes())
    for (int c = 0; c < 8; ++c) inc[size_t(fill[size_t(cx.vertex(h, c))]++)] = {h, c};

  std::vector<LinkIssue> issues;
  std::vector<int32_t> edges;
  UnionFind uf;  // one for every vertex's corners: no allocation per vertex
  for (size_t v = 0; v < nv; ++v) {
    size_t b = size_t(start[v]), e = size_t(start[v + 1]);
    if (b == e) continue;
    auto first = inc.begin() + long(b), last = inc.begin() + long(e);  // sorted by (hex, corner)
    uf.reset(e - b);
    int64_t boundarySides = 0;
    edges.clear();
    for (size_t i = b; i < e; ++i) {
      auto [h, c] = inc[i];
      for (int f : facesOfCorner(c)) {
        Gluing g = cx.gluing(h, f);
        if (g.boundary()) {
          ++boundarySides;
          continue;
        }
        std::pair<HexId, int> n{g.hex, cx.mappedCorner(h, f, c)};
        auto it = std::lower_bound(first, last, n);
        if (it == last || *it != n) continue;  // a gluing that breaks vertex consistency (validate() names it)
        uf.unite(i - b, size_t(it - first));
      }
      for (int ed : edgesOfCorner(c)) edges.push_back(edgeClass[size_t(12) * h + ed]);
    }
    size_t components = 0;
    for (size_t i = 0; i < e - b; ++i) components += uf.find(i) == i;
    if (components != 1) {
      issues.push_back({VertexId(v), "is non-manifold: its link has " + std::to_string(components) + " components"});
      continue;
    }
    std::sort(edges.begin(), edges.end());
    int64_t linkV = std::unique(edges.begin(), edges.end()) - edges.begin();
    std::string why = linkEulerProblem(linkV, int64_t(e - b), boundarySides);
    if (!why.empty()) issues.push_back({VertexId(v), why});
  }
  return issues;
}

bool tolerated(const std::vector<VertexId>& nonManifold, VertexId v) {
  return std::binary_search(nonManifold.begin(), nonManifold.end(), v);
}
}  // namespace

std::vector<LinkIssue> vertexLinkIssues(const Complex& cx) {
  int32_t n = 0;
  return linkIssues(cx, cx.edgeClasses(&n));
}

std::string describeLinkIssue(const Complex& cx, const LinkIssue& issue) {
  VertexId v = issue.vertex;
  Vec3 p = cx.position(v);
  char buf[160];
  std::snprintf(buf, sizeof buf, " at (%.9g, %.9g, %.9g)", p.x, p.y, p.z);
  std::string hexes;
  for (HexId h : cx.hexes())
    for (VertexId w : cx.hexVertices(h))
      if (w == v) hexes += (hexes.empty() ? "" : ", ") + std::to_string(h);
  return "vertex " + std::to_string(v) + buf + " in hexes " + hexes + " " + issue.why;
}

void requireManifoldVertices(const Complex& cx, const std::vector<HexId>& hexes, const std::string& op) {
  const auto& bad = cx.nonManifoldVertices();
  if (bad.empty()) return;
  for (HexId h : hexes)
    if (cx.isHex(h))
      for (VertexId v : cx.hexVertices(h))
        if (tolerated(bad, v)) {
          Vec3 p = cx.position(v);
          char buf[160];
          std::snprintf(buf, sizeof buf, " at (%.9g, %.9g, %.9g)", p.x, p.y, p.z);
          throw Error((op.empty() ? std::string("operation") : op) + ": touches non-manifold vertex " + std::to_string(v) + buf +
                      " (its link is not a sphere or a disk; see hexdual validate)");
        }
}

// Every vertex link is a 2-sphere (interior vertex) or a disk (boundary vertex), except the
// non-manifold vertices accepted from the input.
void Complex::validateLinks(const std::vector<int32_t>& edgeClass) const {
  for (const LinkIssue& li : linkIssues(*this, edgeClass))
    if (!tolerated(nonManifold_, li.vertex)) fail("vertex " + std::to_string(li.vertex) + " " + li.why);
}

}  // namespace hexdual

namespace hexdual {

namespace {
// Open-addressing tables sized for n keys: a power of two, at least twice n.
size_t tableSize(size_t n) {
  size_t cap = 16;
  while (cap < 2 * n) cap *= 2;
  return cap;
}
size_t slotOf(uint64_t key, size_t cap) { return size_t((key * 0x9E3779B97F4A7C15ull) >> 40) & (cap - 1); }
}  // namespace

void Complex::validateAround(const std::vector<HexId>& hexList) const {
  // Scratch kept between calls (every operation runs this check): no allocation once warm.
  thread_local std::vector<HexId> once, seen;
  thread_local std::vector<uint64_t> cornerOf, walks;
  thread_local VertexStar star;
  // Each live listed hex once, in list order: a repeat would only repeat the checks (and their message).
  once.clear();
  {
    seen.assign(tableSize(hexList.size()), -1);
    for (HexId h : hexList) {
      if (!isHex(h)) continue;
      size_t i = slotOf(uint64_t(uint32_t(h)), seen.size());
      while (seen[i] >= 0 && seen[i] != h) i = (i + 1) & (seen.size() - 1);
      if (seen[i] == h) continue;
      seen[i] = h;
      once.push_back(h);
    }
  }
  for (HexId h : once) {
    for (int c = 1; c < 8; ++c) {
      VertexId v = verts_[h][c];
      for (int d = 0; d < c; ++d)
        if (verts_[h][d] == v)
          fail("hex " + std::to_string(h) + " uses vertex " + std::to_string(v) + " at corners " + std::to_string(d) +
               " and " + std::to_string(c));
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
  // One corner of each vertex of the listed hexes: entry (v + 1) << 32 | walked << 31 | hex << 3 | corner.
  cornerOf.assign(tableSize(8 * once.size()), 0);
  const size_t mask = cornerOf.size() - 1;
  auto entryOf = [&](VertexId v) -> uint64_t& {
    size_t i = slotOf(uint64_t(uint32_t(v)), cornerOf.size());
    while (cornerOf[i] && (cornerOf[i] >> 32) != uint64_t(uint32_t(v)) + 1) i = (i + 1) & mask;
    return cornerOf[i];
  };
  for (HexId h : once)
    for (int c = 0; c < 8; ++c) {
      uint64_t& e = entryOf(verts_[h][c]);
      if (!e) e = (uint64_t(uint32_t(verts_[h][c])) + 1) << 32 | uint64_t(uint32_t(h)) << 3 | uint64_t(c);
    }
  // Vertex links, walked from that corner: connected, and a sphere or a disk. Inside a transaction
  // only the links its edits changed (the complex was valid at its start). In ascending vertex
  // order, so the first broken link named is the smallest vertex's.
  walks.clear();  // v << 32 | hex << 3 | corner
  constexpr uint64_t kWalked = uint64_t(1) << 31;
  auto take = [&](uint64_t& e) {
    if (!e || (e & kWalked)) return;
    e |= kWalked;
    walks.push_back(((e >> 32) - 1) << 32 | (e & (kWalked - 1)));
  };
  if (journaling_) {
    for (VertexId v : verticesWithEditedStars()) take(entryOf(v));
  } else {
    for (uint64_t& e : cornerOf) take(e);
  }
  std::sort(walks.begin(), walks.end());
  for (uint64_t w : walks) {
    const VertexId v = VertexId(w >> 32);
    if (tolerated(nonManifold_, v)) continue;
    walkStar(HexId((w & 0xFFFFFFFFu) >> 3), int(w & 7u), star);
    if ((int32_t)star.corners.size() != refs_[v]) fail("vertex " + std::to_string(v) + " is non-manifold: its link is not connected");
    std::string why = linkEulerProblem(star.edges, int64_t(star.corners.size()), star.boundarySides);
    if (!why.empty()) fail("vertex " + std::to_string(v) + " " + why);
  }
}

// A vertex's link changes only when a corner at it is added, removed or re-pointed, or a face at it
// is glued or unglued: the vertices of the open transaction's edits, each listed once. A short
// journal (a few hundred edits: every atomic operation) skips a vertex among the last 8 listed, as
// consecutive edits mostly name the same few vertices (a hex's faces unglued in turn, then the hex
// removed), and may list a vertex again further on: validateAround's table takes repeats. A long one
// (a sheet operation) stamps each vertex per call in a per-thread array, one entry per vertex id, so
// each is listed once: extracting a 100³ grid's middle sheet (110,001 edits) lists 10,201 vertices
// where the last-8 rule listed 148,429 (about 560,000 without it), each a probe into validateAround's
// table of 8 entries per hex. The stamps cost 4 bytes per vertex id per thread, kept between calls.
std::vector<VertexId> Complex::verticesWithEditedStars() const {
  // Each edit's vertices, through `add` (one loop per rule, so each inlines its own).
  auto eachVertex = [&](auto&& add) {
    auto addFace = [&](HexId h, int f) {
      for (int c : kFaceCorners[size_t(f)]) add(verts_[size_t(h)][size_t(c)]);
    };
    for (const Edit& e : journal_) {
      if (e.kind == Edit::AddHex || e.kind == Edit::RemoveHex) {
        for (VertexId v : verts_[size_t(e.hex)]) add(v);
      } else if (e.kind == Edit::SetCorner) {
        add(VertexId(e.value));
        add(verts_[size_t(e.hex)][size_t(e.face)]);
      } else if (e.kind == Edit::Glue || e.kind == Edit::Unglue) {
        addFace(e.hex, e.face);
        addFace(wordHex(e.value), wordFace(e.value));
      }
    }
  };
  std::vector<VertexId> out;
  constexpr size_t kStampFrom = 512;  // edits: below, the last-8 rule (no per-vertex array touched)
  if (journal_.size() < kStampFrom) {
    out.reserve(2 * journal_.size());
    std::array<VertexId, 8> recent;
    recent.fill(-1);
    size_t next = 0;
    eachVertex([&](VertexId v) {
      for (VertexId r : recent)
        if (r == v) return;
      recent[next++ & 7] = v;
      out.push_back(v);
    });
    return out;
  }
  thread_local HugeVector<uint32_t> stampsOf;
  thread_local uint32_t epochOf = 0;
  HugeVector<uint32_t>& stamps = stampsOf;  // (one thread-local lookup, not one per vertex)
  growHuge(stamps, size_t(vertexCapacity()), 0u);
  uint32_t epoch = ++epochOf;
  if (epoch == 0) {  // wrapped: every old stamp could match again
    std::fill(stamps.begin(), stamps.end(), 0);
    epoch = epochOf = 1;
  }
  out.reserve(journal_.size() / 4);
  uint32_t* stamp = stamps.data();
  const size_t n = stamps.size();
  eachVertex([&](VertexId v) {
    if (size_t(v) < n) {  // (always: ids stay below the capacity)
      if (stamp[size_t(v)] == epoch) return;
      stamp[size_t(v)] = epoch;
    }
    out.push_back(v);  // (a repeat would only be probed again)
  });
  return out;
}

// The star of a vertex by walking gluings from one corner: its corners, its boundary sides, and its
// edges as classes of (corner, edge) incidences joined across glued faces (each edge's cycle or fan
// round the vertex), without walking whole edge cycles or allocating once warm.
// A valid star has refs corners: the arrays are sized for that once (grown if ever exceeded); the
// index holds at least twice as many. Returns the room for corners.
size_t Complex::sizeStar(VertexStar& st, size_t refs) {
  size_t room = std::max<size_t>(1, refs);
  if (st.corners.size() < room) st.corners.resize(room);
  if (st.link.size() < 3 * room) st.link.resize(3 * room);
  st.index.assign(tableSize(st.corners.size()), 0);
  return st.corners.size();
}

// More corners than the vertex has (an inconsistent gluing elsewhere): twice the room.
void Complex::growStar(VertexStar& st, size_t& room) {
  room *= 2;
  st.corners.resize(room);
  st.link.resize(3 * room);
}

// The index doubled, its first n corners placed again.
void Complex::rehashStar(VertexStar& st, size_t n) {
  st.index.assign(2 * st.index.size(), 0);
  const size_t mask = st.index.size() - 1;
  for (size_t q = 0; q < n; ++q) {
    const uint64_t kq = uint64_t(uint32_t(st.corners[q].first)) << 3 | uint64_t(st.corners[q].second & 7);
    size_t i = slotOf(kq, mask + 1);
    while (st.index[i] && (st.index[i] >> 32) != kq) i = (i + 1) & mask;
    st.index[i] = kq << 32 | (q + 1);
  }
}

void Complex::walkStar(HexId h0, int c0, VertexStar& st) const {
  // The arrays are written through local pointers, counted by n.
  size_t room = sizeStar(st, size_t(refs_[size_t(verts_[size_t(h0)][size_t(c0)])]));
  std::pair<HexId, int>* corners = st.corners.data();
  int* link = st.link.data();
  uint64_t* index = st.index.data();
  size_t mask = st.index.size() - 1;
  auto key = [](HexId h, int c) { return uint64_t(uint32_t(h)) << 3 | uint64_t(c); };
  auto probe = [&](uint64_t k) {  // the index entry of k, or the empty entry where it belongs
    size_t i = slotOf(k, mask + 1);
    while (index[i] && (index[i] >> 32) != k) i = (i + 1) & mask;
    return i;
  };
  auto root = [&](int x) {
    while (link[x] != x) x = link[x] = link[link[x]];
    return x;
  };
  size_t n = 1;
  corners[0] = {h0, c0};
  link[0] = 0, link[1] = 1, link[2] = 2;
  index[probe(key(h0, c0))] = key(h0, c0) << 32 | 1u;
  int classes = 3;
  int64_t boundarySides = 0;
  // A corner's second member holds, above its 3 bits, the axes of its faces already crossed from
  // an earlier corner: crossing back would only find that corner (gluings are symmetric), so skip.
  for (size_t i = 0; i < n; ++i) {
    const HexId h = corners[i].first;
    const int c = corners[i].second & 7, crossed = corners[i].second >> 3;
    for (int k = 0; k < 3; ++k) {
      if (crossed >> k & 1) continue;
      const uint32_t g = glue_[size_t(h)][size_t(2 * k + cornerBit(c, k))];
      if (g == kBoundary) {
        ++boundarySides;
        continue;
      }
      const CornerStep& step = kCornerSteps[size_t(cornerStepIndex(c, k, 0, 0)) + wordFaceOrient(g)];
      const uint64_t k2 = key(wordHex(g), step.corner);
      const size_t at = probe(k2);
      const int arrivedBy = 8 << (wordFace(g) >> 1);  // the axis of the face the step enters by
      if (!index[at]) {  // a new corner j
        const size_t j = n++;
        if (n > room) {
          growStar(st, room);
          corners = st.corners.data();
          link = st.link.data();
        }
        corners[j] = {wordHex(g), step.corner | arrivedBy};
        if (2 * n > mask + 1) {
          rehashStar(st, n);
          index = st.index.data();
          mask = st.index.size() - 1;
        } else {
          index[at] = k2 << 32 | (j + 1);
        }
        // Its two edges in the crossed face are the two of corner i (fresh incidences joined at
        // once: no union-find steps); its third edge starts a class of its own.
        const int a0 = step.axis[0], a1 = step.axis[1], a2 = 3 - a0 - a1;
        link[3 * j + size_t(a0)] = root(int(3 * i) + (k + 1) % 3);
        link[3 * j + size_t(a1)] = root(int(3 * i) + (k + 2) % 3);
        link[3 * j + size_t(a2)] = int(3 * j) + a2;
        classes += 1;
        continue;
      }
      const size_t j = size_t(index[at] & 0xFFFFFFFFu) - 1;
      if (j < i) continue;  // this quad was crossed from corner j's side already: the same edges were joined
      if (j > i) corners[j].second |= arrivedBy;
      // The two edges of c in the face (along the axes other than its normal) and their images.
      for (int e = 0; e < 2; ++e) {
        const int x = root(int(3 * i) + (k + 1 + e) % 3), y = root(int(3 * j) + step.axis[size_t(e)]);
        if (x != y) {
          link[std::max(x, y)] = std::min(x, y);
          --classes;
        }
      }
    }
  }
  st.corners.resize(n);
  st.edges = classes;
  st.boundarySides = boundarySides;
}

}  // namespace hexdual
