// Helpers of the sheet operations: refusals with rule names, the sheet through an edge, its
// two sides, and vertex merges (sheet_support.hpp).
#include "ops/sheet_support.hpp"

#include <algorithm>
#include <array>
#include <unordered_set>

#include "complex/manifold.hpp"
#include "complex/sorted_ids.hpp"
#include "dual/dual.hpp"
#include "ops/support.hpp"

namespace hexdual {

std::string ruleOf(const std::string& message) {
  // "<op>: <rule>: ...": both words are lower-case with hyphens, so a sentence is never a rule.
  auto word = [&](size_t from) {
    size_t i = from;
    while (i < message.size() && ((message[i] >= 'a' && message[i] <= 'z') || message[i] == '-')) ++i;
    return i > from && message.compare(i, 2, ": ") == 0 ? i : std::string::npos;
  };
  const size_t opEnd = word(0);
  if (opEnd == std::string::npos) return "";
  const size_t ruleEnd = word(opEnd + 2);
  return ruleEnd == std::string::npos ? "" : message.substr(opEnd + 2, ruleEnd - opEnd - 2);
}

}  // namespace hexdual

namespace hexdual::ops {
using namespace tables;

void refuse(const std::string& op, const char* rule, const std::string& details) {
  throw Error(op + ": " + rule + ": " + details);
}

void requireEdge(const Complex& cx, EdgeRef e, const std::string& op) {
  if (!cx.isHex(e.hex)) refuse(op, "no-such-entity", hexName(e.hex) + " does not exist");
  if (e.edge < 0 || e.edge > 11) refuse(op, "no-such-entity", "local edge " + std::to_string(e.edge) + " is not 0..11");
}

void requireManifold(const Complex& cx, const std::vector<HexId>& hexes, const std::string& op) {
  requireManifoldVertices(cx, hexes, op + ": non-manifold-vertex");
}

void commitOrRefuse(Transaction& tx, OpResult& r, const std::vector<HexId>& touched, const std::string& op,
                    bool validByConstruction) {
  try {
    if (validByConstruction)
      tx.commitValidByConstruction(r, touched);  // (still refuses a vertex the input left non-manifold)
    else
      tx.commit(r, touched);
  } catch (const Error& e) {  // still open: the transaction rolls back as this unwinds
    const std::string why = e.what();
    const bool link = why.find("link") != std::string::npos || why.find("non-manifold") != std::string::npos;
    refuse(op, link ? "non-manifold-result" : "invalid-result", "the result would not be a valid complex (" + why + ")");
  }
}

SheetHexes sheetThrough(const Complex& cx, EdgeRef e, const std::string& op) {
  requireEdge(cx, e, op);
  SheetHexes s;
  std::vector<std::pair<HexId, int>> stack{{e.hex, axisOfEdge(e.edge)}};
  s.axis.emplace(e.hex, int8_t(axisOfEdge(e.edge)));
  while (!stack.empty()) {
    auto [h, a] = stack.back();
    stack.pop_back();
    s.hexes.push_back(h);
    for (int f : kParallelFaces[size_t(a)]) {
      const Gluing g = cx.gluing(h, f);
      if (g.boundary()) continue;
      const int a2 = kCrossings[size_t(crossingIndex(f, a, g.face, g.orient))].axis;
      auto [it, fresh] = s.axis.emplace(g.hex, int8_t(a2));
      if (fresh) stack.push_back({g.hex, a2});
      else if (*it != a2)
        refuse(op, "self-intersecting",
               "the sheet through " + entityName(e) + " passes " + hexName(g.hex) + " twice (along its local axes " +
                   std::to_string(*it) + " and " + std::to_string(a2) + ")");
    }
  }
  std::sort(s.hexes.begin(), s.hexes.end());
  return s;
}

IdMap<int8_t> sheetUp(const Complex& cx, const SheetHexes& sheet) {
  IdMap<int8_t> up(sheet.hexes.size());
  for (HexId start : sheet.hexes) {
    if (up.count(start)) continue;
    up.emplace(start, int8_t(1));
    std::vector<HexId> stack{start};
    while (!stack.empty()) {
      const HexId h = stack.back();
      stack.pop_back();
      const int a = sheet.axisOf(h);
      for (int f : kParallelFaces[size_t(a)]) {
        const Gluing g = cx.gluing(h, f);
        if (g.boundary()) continue;
        // A corner low along a: its image is low along the neighbour's axis when the senses agree.
        const int c = kFaceCorners[size_t(f)][0];  // f is parallel to a: flipping along a stays on f
        const int low = cornerBit(c, a) == 0 ? c : flipAxis(c, a);
        const int image = cx.mappedCorner(h, f, low);
        const int8_t sense = int8_t(up.at(h) * (cornerBit(image, sheet.axisOf(g.hex)) == 0 ? 1 : -1));
        auto [it, fresh] = up.emplace(g.hex, sense);
        if (fresh) stack.push_back(g.hex);
        else if (*it != sense) return {};
      }
    }
  }
  return up;
}

namespace {
using Corners = std::vector<std::pair<HexId, int>>;

// A vertex's star walked across the faces between its corners: the corners (as
// Complex::cornersOfVertex lists them), the glued face pairs between them (`links`, by index in
// `corners`), and whether one of them has a boundary face at the vertex. Each face pair is crossed
// once: a corner keeps, per axis, whether its face there was already crossed from the other side.
// A hex holds a vertex at one corner at most (validate), so a corner is new exactly when its hex is.
// The arrays are kept between walks and only ever grow; the walk's part is counted by its sizes.
struct StarWalk {
  Corners cornerRoom;
  std::vector<uint8_t> crossedRoom;
  std::vector<std::pair<uint32_t, uint32_t>> linkRoom;  // 3 per corner of room: a corner crosses 3 faces at most
  size_t size = 0, linkCount = 0;
  bool boundary = false;
  std::span<const std::pair<HexId, int>> corners() const { return {cornerRoom.data(), size}; }
  std::span<const std::pair<uint32_t, uint32_t>> links() const { return {linkRoom.data(), linkCount}; }
  void grow(size_t room) { cornerRoom.resize(room), crossedRoom.resize(room), linkRoom.resize(3 * room); }
};
void walkStarOf(const Complex& cx, HexId h, int c, StarWalk& st) {
  // Written through raw pointers into the kept arrays (grown when a star outgrows them).
  if (st.cornerRoom.size() < 16) st.grow(16);
  auto* corners = st.cornerRoom.data();
  uint8_t* crossed = st.crossedRoom.data();
  auto* links = st.linkRoom.data();
  size_t n = 1, nLinks = 0;
  std::array<int8_t, 32> slot;  // hex -> its corner's index, while n <= 16
  slot.fill(-1);
  slot[(uint32_t(h) * 0x9E3779B1u) >> 27] = 0;
  corners[0] = {h, c};
  crossed[0] = 0;
  st.boundary = false;
  for (size_t i = 0; i < n; ++i) {
    const auto [hh, cc] = corners[i];
    for (int k = 0; k < 3; ++k) {
      if (crossed[i] >> k & 1) continue;
      const uint32_t w = cx.gluingWords(hh)[size_t(2 * k + cornerBit(cc, k))];  // (indexes the step table undecoded)
      if (w == Complex::kBoundaryWord) {
        st.boundary = true;
        continue;
      }
      const Gluing g{Complex::wordHex(w), Complex::wordFace(w), Complex::wordOrient(w)};
      const uint8_t arrived = uint8_t(1u << (g.face >> 1));
      // The corner of g.hex (a hex holds the vertex at one corner): through a 32-entry table by hex
      // while the star has at most 16 corners, by a scan beyond.
      size_t j = n;
      if (n <= 16) {
        size_t at = (uint32_t(g.hex) * 0x9E3779B1u) >> 27;
        while (slot[at] >= 0 && corners[size_t(slot[at])].first != g.hex) at = (at + 1) & 31;
        if (slot[at] >= 0) j = size_t(slot[at]);
        else if (n < 16) slot[at] = int8_t(n);
      } else {
        j = 0;
        while (j < n && corners[j].first != g.hex) ++j;
      }
      if (j == n) {
        if (n == st.cornerRoom.size()) {
          st.grow(2 * n);
          corners = st.cornerRoom.data(), crossed = st.crossedRoom.data(), links = st.linkRoom.data();
        }
        corners[n] = {g.hex, kCornerSteps[size_t(cornerStepIndex(cc, k, 0, 0)) + Complex::wordFaceOrient(w)].corner};
        crossed[n++] = 0;
      }
      crossed[j] |= arrived;
      links[nLinks++] = {uint32_t(i), uint32_t(j)};
    }
  }
  st.size = n;
  st.linkCount = nLinks;
}

// The star's corners off the removed hexes (into `outside`), and whether they are connected across
// the faces between them (the star's links with both ends outside).
template <class Removed>
bool outsideConnected(const StarWalk& st, const Removed& removed, Corners& outside, std::vector<int>& parent) {
  outside.clear();
  const auto corners = st.corners();
  parent.assign(corners.size(), -1);  // -1: removed; else a union-find link among the outside corners
  for (size_t i = 0; i < corners.size(); ++i)
    if (!removed(corners[i].first)) {
      parent[i] = int(i);
      outside.push_back(corners[i]);
    }
  auto find = [&](int x) {
    while (parent[size_t(x)] != x) x = parent[size_t(x)] = parent[size_t(parent[size_t(x)])];
    return x;
  };
  size_t pieces = outside.size();
  for (auto [i, j] : st.links()) {
    if (parent[i] < 0 || parent[j] < 0) continue;
    const int a = find(int(i)), b = find(int(j));
    if (a != b) parent[size_t(std::max(a, b))] = std::min(a, b), --pieces;
  }
  return pieces <= 1;
}

}  // namespace


VertexMerges planMerges(const Complex& cx, const MergeClasses& classes, const std::function<bool(HexId)>& removed) {
  VertexMerges m;
  m.into.reserve(2 * classes.size());
  StarWalk star;
  std::vector<Corners> outside;  // per vertex of the class: its corners off the removed hexes
  std::vector<int> parent;
  m.members.reserve(classes.corners.size());
  m.removedCorners.reserve(classes.corners.size());
  for (size_t q = 0; q < classes.size(); ++q) {
    const std::span<const std::pair<HexId, int>> cls = classes[q];
    VertexId keep = -1, keepAny = -1;
    Vec3 sumB, sumAll;
    int nB = 0;
    outside.resize(std::max(outside.size(), cls.size()));
    for (size_t k = 0; k < cls.size(); ++k) {
      const auto [h, c] = cls[k];
      const VertexId v = cx.vertex(h, c);
      walkStarOf(cx, h, c, star);
      const bool onBoundary = star.boundary;
      sumAll = sumAll + cx.position(v);
      keepAny = keepAny < 0 ? v : std::min(keepAny, v);
      if (onBoundary) {
        sumB = sumB + cx.position(v);
        ++nB;
        keep = keep < 0 ? v : std::min(keep, v);
      }
      if (!outsideConnected(star, removed, outside[k], parent) && m.split < 0) m.split = v;
      m.removedCorners.push_back(int(star.size - outside[k].size()));
    }
    if (keep < 0) keep = keepAny;
    std::pair<HexId, int> anchor{-1, 0};
    for (size_t k = 0; k < cls.size() && anchor.first < 0; ++k)
      if (!outside[k].empty()) anchor = outside[k][0];
    if (anchor.first >= 0) m.anchors.push_back(anchor);
    m.members.insert(m.members.end(), cls.begin(), cls.end());
    m.boundaryMembers.push_back(nB);
    for (size_t k = 0; k < cls.size(); ++k) {
      const VertexId v = cx.vertex(cls[k].first, cls[k].second);
      m.into.emplace(v, keep);
      if (v == keep) continue;
      m.dropped.push_back(v);
      m.renamed.insert(m.renamed.end(), outside[k].begin(), outside[k].end());  // only corners whose vertex changes
    }
    m.placed.push_back({keep, nB ? (1.0 / nB) * sumB : (1.0 / double(cls.size())) * sumAll});
  }
  std::sort(m.dropped.begin(), m.dropped.end());
  for (auto [h, c] : m.renamed) m.renamedHexes.push_back(h);
  sortUniqueIds(m.renamedHexes);
  return m;
}

int64_t edgesAt(const Complex& cx, const std::vector<std::pair<HexId, int>>& vertices) {
  // Per vertex, its edges are the vertices of its link: the (corner, axis) pairs of its star joined
  // across the faces between the corners (a small union-find, no hashing of incidences). An edge
  // is counted once at each end in the set, twice at an end whose other end is not.
  std::unordered_set<VertexId> in;
  for (auto [h, c] : vertices) in.insert(cx.vertex(h, c));
  std::unordered_set<VertexId> done;
  StarWalk walk;
  std::vector<int> parent;
  int64_t twice = 0;
  for (auto [h, c] : vertices) {
    if (!done.insert(cx.vertex(h, c)).second) continue;
    walkStarOf(cx, h, c, walk);
    const auto star = walk.corners();
    parent.resize(3 * star.size());
    for (size_t i = 0; i < parent.size(); ++i) parent[i] = int(i);
    auto find = [&](int x) {
      while (parent[size_t(x)] != x) x = parent[size_t(x)] = parent[size_t(parent[size_t(x)])];
      return x;
    };
    for (size_t i = 0; i < star.size(); ++i) {
      auto [hh, cc] = star[i];
      for (int k = 0; k < 3; ++k) {
        const int f = facesOfCorner(cc)[size_t(k)];
        if (cx.isBoundary({hh, f})) continue;
        const Gluing g = cx.gluing(hh, f);
        const CornerStep& st = kCornerSteps[size_t(cornerStepIndex(cc, k, g.face, g.orient))];
        const size_t j = size_t(std::find(star.begin(), star.end(), std::pair<HexId, int>{g.hex, st.corner}) - star.begin());
        for (int t = 0; t < 2; ++t) parent[size_t(find(int(3 * i) + (k + 1 + t) % 3))] = find(int(3 * j) + st.axis[size_t(t)]);
      }
    }
    for (size_t x = 0; x < parent.size(); ++x)
      if (find(int(x)) == int(x)) {
        auto [eh, ec] = star[x / 3];
        twice += in.count(cx.vertex(eh, flipAxis(ec, int(x % 3)))) ? 1 : 2;
      }
  }
  return twice / 2;
}

void keepTopologyOrUndo(Complex& cx, const EulerBefore& before, int64_t edgesAfter, const OpResult& r, const std::string& op) {
  const int64_t dChi = (cx.numVertices() - before.vertices) - (edgesAfter - before.edgesAround) +
                       (cx.numQuads() - before.quads) - (cx.numHexes() - before.hexes);
  if (dChi == 0) return;
  cx.undo(r.edits);  // exact: the complex as before the operation, revision included
  refuse(op, "topology-change",
         "the result would have Euler characteristic V-E+F-H " + std::string(dChi > 0 ? "+" : "") + std::to_string(dChi) +
             " from the mesh's: merging these vertices would " + (dChi < 0 ? "open a handle (a tunnel)" : "close a tunnel or split the mesh"));
}

void finishCollapse(Complex& cx, Transaction& tx, OpResult& res, const VertexMerges& m,
                    const std::vector<std::pair<QuadSide, QuadSide>>& glues, const EulerBefore& before,
                    const std::vector<std::pair<HexId, int>>& after, const std::string& op, bool validByConstruction) {
  std::vector<HexId> touched = m.renamedHexes;
  for (auto [a, b] : glues) {
    const int o = a == b ? -1 : orientByVertices(cx, a.hex, a.face, b.hex, b.face);
    if (o < 0) refuse(op, "invalid-result", "after the collapse " + entityName(a) + " and " + entityName(b) + " cannot be glued");
    cx.glue(a.hex, a.face, b.hex, b.face, o);
    touched.push_back(a.hex);
    touched.push_back(b.hex);
  }
  commitOrRefuse(tx, res, touched, op, validByConstruction);
  if (before.edgesAround >= 0) keepTopologyOrUndo(cx, before, edgesAt(cx, after), res, op);
  res.removedVertices = m.dropped;
  for (auto [v, p] : m.placed)
    if (!cx.isVertex(v)) res.removedVertices.push_back(v);
  std::sort(res.removedVertices.begin(), res.removedVertices.end());
}

void requireDistinctCorners(const Complex& cx, const VertexMerges& m, const std::string& op) {
  for (HexId h : m.renamedHexes) {
    std::array<VertexId, 8> v = cx.hexVertices(h);
    for (VertexId& x : v) x = m.target(x);
    for (int i = 0; i < 8; ++i)
      for (int j = 0; j < i; ++j)
        if (v[size_t(i)] == v[size_t(j)])
          refuse(op, "hex-vertices-merge",
                 hexName(h) + " would lose a corner: its vertices " + std::to_string(cx.vertex(h, j)) + " and " +
                     std::to_string(cx.vertex(h, i)) + " would merge into " + std::to_string(v[size_t(i)]));
  }
}

void applyMerges(Complex& cx, const VertexMerges& m) {
  for (auto [h, c] : m.renamed) cx.setCorner(h, c, m.target(cx.vertex(h, c)));
  for (auto [v, p] : m.placed) cx.setPosition(v, p);
}

}  // namespace hexdual::ops
