// Sheet insertion (pillowing a surface of quads) and pillowing a shrink set: the inverse of
// sheet extraction (sheet_extract.cpp). Every vertex of the surface splits in two, one side of
// the surface moves onto the new vertices, and a layer of new hexes (the new sheet) fills the gap.
// Cost: the surface and the stars of its vertices.
#include <algorithm>

#include "complex/id_map.hpp"
#include "ops/sheet_support.hpp"
#include "ops/support.hpp"

namespace hexdual {
using namespace tables;
using namespace ops;

namespace {

// The surface: its quads by the side named, every side of them (by hex: the walls a vertex's
// corners are split by), its vertices in order of first appearance and the quads at each.
struct Surface {
  std::vector<QuadSide> named;
  IdMap<uint8_t> walls;  // per hex: its faces that are a side of a quad of the surface (bit f)
  std::vector<VertexId> vertices;
  std::vector<std::array<int32_t, 4>> placeAt;  // per quad: the place of its vertex at each position
  std::vector<std::vector<std::pair<size_t, int>>> quadsAt;  // per vertex: (quad, position in its named side)
  bool isWall(QuadSide s) const { return walls.get(s.hex, 0) >> s.face & 1; }
};

Surface surfaceOf(const Complex& cx, const std::vector<QuadSide>& sides, const std::string& op) {
  if (sides.empty()) refuse(op, "empty", "needs at least one quad");
  Surface s;
  std::vector<QuadSide> seen;
  for (QuadSide q : sides) {
    if (!cx.isHex(q.hex)) refuse(op, "no-such-entity", hexName(q.hex) + " does not exist");
    if (q.face < 0 || q.face > 5) refuse(op, "no-such-entity", "local face " + std::to_string(q.face) + " is not 0..5");
    seen.push_back(cx.canonical(q));
    s.named.push_back(q);
    auto wall = [&](QuadSide w) { *s.walls.emplace(w.hex, 0).first |= uint8_t(1u << w.face); };
    wall(q);
    if (!cx.isBoundary(q)) wall({cx.gluing(q).hex, cx.gluing(q).face});
  }
  std::sort(seen.begin(), seen.end());
  if (auto d = std::adjacent_find(seen.begin(), seen.end()); d != seen.end())
    refuse(op, "duplicate", "quad " + entityName(*d) + " is named twice");
  IdMap<int32_t> place(s.named.size() + 64);  // vertex -> its place in s.vertices
  s.placeAt.resize(s.named.size());
  for (size_t i = 0; i < s.named.size(); ++i)
    for (int p = 0; p < 4; ++p) {
      const VertexId v = cx.vertex(s.named[i].hex, kFaceCorners[size_t(s.named[i].face)][size_t(p)]);
      auto [at, fresh] = place.emplace(v, int32_t(s.vertices.size()));
      if (fresh) {
        s.vertices.push_back(v);
        s.quadsAt.emplace_back();
      }
      s.quadsAt[size_t(*at)].push_back({i, p});
      s.placeAt[i][size_t(p)] = *at;
    }
  return s;
}

// The smallest incidence of an edge, and whether its fan reaches the boundary (no allocation).
std::pair<EdgeRef, bool> edgeKey(const Complex& cx, EdgeRef e) {
  EdgeRef best = e;
  const auto fs = facesOfEdge(e.edge);
  const size_t limit = size_t(12) * size_t(cx.numHexes()) + 1;
  for (int dir = 0; dir < 2; ++dir) {
    EdgeRef cur = e;
    int exit = fs[size_t(dir)];
    for (size_t n = 0; n < limit; ++n) {
      if (!cx.stepAroundEdge(cur, exit)) break;
      if (cur == e) return {best, false};
      if (cur < best) best = cur;
    }
  }
  return {best, true};
}

// The edges of the surface: each must lie on two of its quads, or on one where it ends on the
// mesh boundary. Returns the pairs (quad, position) whose new hexes share a side quad.
std::vector<std::pair<std::pair<size_t, int>, std::pair<size_t, int>>> surfaceEdges(const Complex& cx, const Surface& s,
                                                                                     const std::string& op) {
  std::unordered_map<int64_t, std::vector<std::pair<size_t, int>>> along;
  std::vector<int64_t> order;
  std::unordered_map<int64_t, bool> onBoundary;
  for (size_t i = 0; i < s.named.size(); ++i)
    for (int p = 0; p < 4; ++p) {
      const auto [key, boundary] = edgeKey(cx, {s.named[i].hex, kFaceEdges[size_t(s.named[i].face)][size_t(p)]});
      const int64_t k = int64_t(key.hex) * 16 + key.edge;
      if (along[k].empty()) order.push_back(k);
      along[k].push_back({i, p});
      onBoundary[k] = boundary;
    }
  std::vector<std::pair<std::pair<size_t, int>, std::pair<size_t, int>>> pairs;
  for (int64_t k : order) {
    const auto& q = along[k];
    const EdgeRef e{HexId(k / 16), int(k % 16)};
    if (q.size() > 2)
      refuse(op, "non-manifold-surface", "edge " + entityName(e) + " lies on " + std::to_string(q.size()) + " quads of the surface");
    if (q.size() == 1 && !onBoundary[k])
      refuse(op, "open-surface", "the surface ends inside the mesh at edge " + entityName(e) +
                                     " (only quad " + entityName(s.named[q[0].first]) + " of it is there)");
    if (q.size() == 2) pairs.push_back({q[0], q[1]});
  }
  return pairs;
}

// The corners of one surface vertex split by the walls into pieces; the piece that moves.
struct VertexSides {
  std::vector<std::pair<HexId, int>> corners;
  std::vector<int> piece;
  int moving = -1;
  int pieceOf(HexId h, int c) const {
    for (size_t i = 0; i < corners.size(); ++i)
      if (corners[i] == std::pair<HexId, int>{h, c}) return piece[i];
    return -1;
  }
};

VertexSides splitByWalls(const Complex& cx, const Surface& s, std::pair<HexId, int> seed) {
  VertexSides vs;
  vs.corners = cx.cornersOfVertex(seed.first, seed.second);
  vs.piece.assign(vs.corners.size(), -1);
  int pieces = 0;
  for (size_t start = 0; start < vs.corners.size(); ++start) {
    if (vs.piece[start] >= 0) continue;
    std::vector<size_t> stack{start};
    vs.piece[start] = pieces;
    while (!stack.empty()) {
      auto [h, c] = vs.corners[stack.back()];
      stack.pop_back();
      for (int f : facesOfCorner(c)) {
        if (cx.isBoundary({h, f}) || s.isWall({h, f})) continue;
        const std::pair<HexId, int> n{cx.gluing(h, f).hex, cx.mappedCorner(h, f, c)};
        const size_t j = size_t(std::find(vs.corners.begin(), vs.corners.end(), n) - vs.corners.begin());
        if (vs.piece[j] < 0) {
          vs.piece[j] = pieces;
          stack.push_back(j);
        }
      }
    }
    ++pieces;
  }
  return vs;
}

// The moving side of every quad: the named side of the first quad of each connected part of
// the surface, carried across it vertex by vertex. At every vertex the moving sides must lie in
// one piece of its corners and the other sides outside it.
struct Plan {
  std::vector<VertexSides> at;   // per surface vertex
  std::vector<QuadSide> moving;  // per quad
};

Plan orient(const Complex& cx, const Surface& s, const std::string& op) {
  Plan plan;
  for (size_t k = 0; k < s.vertices.size(); ++k) {
    const auto [i, p] = s.quadsAt[k][0];
    plan.at.push_back(splitByWalls(cx, s, {s.named[i].hex, kFaceCorners[size_t(s.named[i].face)][size_t(p)]}));
  }
  // The corner of side `side` of quad i at its position p (positions of the named side).
  auto cornerAt = [&](size_t i, int p, bool other) {
    const QuadSide q = s.named[i];
    const int c = kFaceCorners[size_t(q.face)][size_t(p)];
    if (!other) return std::pair<HexId, int>{q.hex, c};
    return std::pair<HexId, int>{cx.gluing(q).hex, cx.mappedCorner(q.hex, q.face, c)};
  };
  std::vector<int8_t> flip(s.named.size(), -1);  // 0: the named side moves, 1: the other side
  for (size_t start = 0; start < s.named.size(); ++start) {
    if (flip[start] >= 0) continue;
    flip[start] = 0;
    std::vector<size_t> queue{start};
    for (size_t qi = 0; qi < queue.size(); ++qi) {
      const size_t i = queue[qi];
      for (int p = 0; p < 4; ++p) {
        const size_t k = size_t(s.placeAt[i][size_t(p)]);
        VertexSides& vs = plan.at[k];
        auto [h, c] = cornerAt(i, p, flip[i]);
        const int piece = vs.pieceOf(h, c);
        if (vs.moving < 0) vs.moving = piece;
        for (auto [j, q] : s.quadsAt[k]) {
          if (flip[j] >= 0) continue;
          if (vs.pieceOf(cornerAt(j, q, false).first, cornerAt(j, q, false).second) == vs.moving) flip[j] = 0;
          else if (!cx.isBoundary(s.named[j]) && vs.pieceOf(cornerAt(j, q, true).first, cornerAt(j, q, true).second) == vs.moving)
            flip[j] = 1;
          else continue;
          queue.push_back(j);
        }
      }
    }
  }
  for (size_t k = 0; k < s.vertices.size(); ++k)
    for (auto [j, q] : s.quadsAt[k]) {
      const VertexSides& vs = plan.at[k];
      auto mine = cornerAt(j, q, flip[j]);
      // (written only on a refusal: a 100³ layer has 40,000 of these pairs)
      const QuadSide quad = s.named[j];  // (a structured binding: clang 14 lambdas do not capture one)
      auto where = [&] { return "vertex " + std::to_string(s.vertices[k]) + " (quad " + entityName(quad) + ")"; };
      if (!cx.isBoundary(s.named[j])) {  // both sides of a quad on one side: the surface comes back turned over
        auto theirs = cornerAt(j, q, !flip[j]);
        if (vs.pieceOf(theirs.first, theirs.second) == vs.moving)
          refuse(op, "one-sided", "the surface does not separate the hexes at " + where() + " into two sides");
      }
      if (vs.pieceOf(mine.first, mine.second) != vs.moving)
        refuse(op, "non-manifold-surface", "the surface passes " + where() + " more than once: it is pinched there");
    }
  for (size_t i = 0; i < s.named.size(); ++i)
    plan.moving.push_back(flip[i] ? QuadSide{cx.gluing(s.named[i]).hex, cx.gluing(s.named[i]).face} : s.named[i]);
  return plan;
}

// The side quad of new hex h (its bottom on the surface) between bottom vertices a and b.
int sideFaceBetween(const Complex& cx, HexId h, VertexId a, VertexId b) {
  for (int f = 0; f < 4; ++f) {
    int hits = 0;
    for (int c : kFaceCorners[size_t(f)])
      if (cornerBit(c, 2) == 0) hits += cx.vertex(h, c) == a || cx.vertex(h, c) == b;
    if (hits == 2) return f;
  }
  return -1;
}

// The new hex's bottom (its face 4, in kFaceCorners[4] order) on the moving quad m's vertices.
// Every face's corner cycle in kFaceCorners turns about +axis: inward for even faces (face 4's,
// +z, points into its hex), outward for odd ones. The new hex lies on the moving hex's side of m,
// so an odd face's cycle is reversed: otherwise the new hex is mirrored (scaled Jacobian -1).
std::array<VertexId, 4> bottomOf(const Complex& cx, QuadSide m) {
  static constexpr int kReversed[4] = {0, 3, 2, 1};
  std::array<VertexId, 4> v;
  for (int p = 0; p < 4; ++p)
    v[size_t(p)] = cx.vertex(m.hex, kFaceCorners[size_t(m.face)][size_t(m.face % 2 ? kReversed[p] : p)]);
  return v;
}

// What the edit needs, all read before it: per quad the old vertices of its moving side (the new
// hex's bottom) and its staying side (none on the boundary); per shared surface edge the two
// quads and the edge's ends.
struct Layer {
  std::vector<std::array<VertexId, 4>> bottom;
  std::vector<QuadSide> staying;
  struct SideGlue {
    size_t a, b;
    VertexId u, w;
  };
  std::vector<SideGlue> sides;
  std::vector<HexId> edited;  // the hexes that move onto new vertices or get a new hex glued on
};

Layer layerOf(const Complex& cx, const Surface& s, const Plan& plan,
              const std::vector<std::pair<std::pair<size_t, int>, std::pair<size_t, int>>>& pairs) {
  Layer l;
  for (size_t i = 0; i < s.named.size(); ++i) {
    const QuadSide m = plan.moving[i];
    l.bottom.push_back(bottomOf(cx, m));
    l.staying.push_back(cx.isBoundary(m) ? QuadSide{-1, 0} : QuadSide{cx.gluing(m).hex, cx.gluing(m).face});
  }
  for (auto [a, b] : pairs) {
    const QuadSide q = s.named[a.first];
    l.sides.push_back({a.first, b.first, cx.vertex(q.hex, kFaceCorners[size_t(q.face)][size_t(a.second)]),
                       cx.vertex(q.hex, kFaceCorners[size_t(q.face)][size_t((a.second + 1) & 3)])});
  }
  for (const VertexSides& vs : plan.at)
    for (size_t j = 0; j < vs.corners.size(); ++j)
      if (vs.piece[j] == vs.moving) l.edited.push_back(vs.corners[j].first);
  for (size_t i = 0; i < s.named.size(); ++i) {
    l.edited.push_back(plan.moving[i].hex);
    if (l.staying[i].hex >= 0) l.edited.push_back(l.staying[i].hex);
  }
  std::sort(l.edited.begin(), l.edited.end());
  l.edited.erase(std::unique(l.edited.begin(), l.edited.end()), l.edited.end());
  return l;
}

// Splits the surface's vertices (the moving piece takes the copy, placed a quarter of the way
// toward the moving hexes) and opens the surface's interior quads.
std::unordered_map<VertexId, VertexId> splitVertices(Complex& cx, const Surface& s, const Plan& plan, OpResult& res) {
  std::unordered_map<VertexId, VertexId> copy;
  for (size_t k = 0; k < s.vertices.size(); ++k) {
    const VertexSides& vs = plan.at[k];
    Vec3 centre;
    int n = 0;
    for (size_t j = 0; j < vs.corners.size(); ++j)
      if (vs.piece[j] == vs.moving) centre = centre + cx.hexCentroid(vs.corners[j].first), ++n;
    const Vec3 p = cx.position(s.vertices[k]);
    const VertexId v = cx.addVertex(p + 0.25 * ((1.0 / n) * centre - p));
    copy[s.vertices[k]] = v;
    res.createdVertices.push_back(v);
  }
  for (QuadSide m : plan.moving) cx.unglue(m.hex, m.face);
  for (size_t k = 0; k < s.vertices.size(); ++k) {
    const VertexSides& vs = plan.at[k];
    for (size_t j = 0; j < vs.corners.size(); ++j)
      if (vs.piece[j] == vs.moving) cx.setCorner(vs.corners[j].first, vs.corners[j].second, copy[s.vertices[k]]);
  }
  return copy;
}

// Everything an insertion checks and reads before it edits (its rules but the final validity check).
struct Planned {
  Surface s;
  Plan plan;
  Layer layer;
};
Planned planInsertion(const Complex& cx, const std::vector<QuadSide>& sides, const std::string& op) {
  Planned p{surfaceOf(cx, sides, op), {}, {}};
  const auto pairs = surfaceEdges(cx, p.s, op);
  p.plan = orient(cx, p.s, op);
  p.layer = layerOf(cx, p.s, p.plan, pairs);
  requireManifold(cx, p.layer.edited, op);
  return p;
}

OpResult insertAlong(Complex& cx, const std::vector<QuadSide>& sides, OpKind kind) {
  const std::string op = opName(kind);
  const Planned planned = planInsertion(cx, sides, op);
  const Surface& s = planned.s;
  const Plan& plan = planned.plan;
  const Layer& layer = planned.layer;
  // Its edits: a new vertex per surface vertex and its moving corners, per quad an unglue, a new
  // hex and two glues, a glue per shared surface edge.
  size_t edits = s.vertices.size() + 4 * s.named.size() + layer.sides.size();
  for (const VertexSides& vs : plan.at) edits += size_t(std::count(vs.piece.begin(), vs.piece.end(), vs.moving));

  Transaction tx(cx, edits);
  OpResult res;
  res.op = kind;
  const auto copy = splitVertices(cx, s, plan, res);
  std::vector<HexId> touched = layer.edited;
  for (size_t i = 0; i < s.named.size(); ++i) {  // one hex per quad: old vertices below, copies above
    std::array<VertexId, 8> v;
    for (int p = 0; p < 4; ++p) {
      v[size_t(kFaceCorners[4][size_t(p)])] = layer.bottom[i][size_t(p)];
      v[size_t(kFaceCorners[5][size_t(p)])] = copy.at(layer.bottom[i][size_t(p)]);
    }
    const HexId h = cx.addHex(v);
    res.createdHexes.push_back(h);
    glueByVertices(cx, h, 5, plan.moving[i].hex, plan.moving[i].face);
    if (layer.staying[i].hex >= 0) glueByVertices(cx, h, 4, layer.staying[i].hex, layer.staying[i].face);
    touched.push_back(h);
  }
  for (const Layer::SideGlue& g : layer.sides) {
    const HexId a = res.createdHexes[g.a], b = res.createdHexes[g.b];
    glueByVertices(cx, a, sideFaceBetween(cx, a, g.u, g.w), b, sideFaceBetween(cx, b, g.u, g.w));
  }
  res.inverse = makeStep(OpKind::SheetExtract, EdgeRef{res.createdHexes[0], 8});  // an edge across the new layer
  commitOrRefuse(tx, res, touched, op);
  return res;
}

}  // namespace


OpResult sheetInsert(Complex& cx, const std::vector<QuadSide>& quads) { return insertAlong(cx, quads, OpKind::SheetInsert); }

OpResult sheetPillow(Complex& cx, const std::vector<HexId>& hexes) {
  const std::string op = opName(OpKind::SheetPillow);
  std::vector<HexId> set = hexes;
  std::sort(set.begin(), set.end());
  if (set.empty()) refuse(op, "empty", "needs at least one hex");
  if (const auto d = std::adjacent_find(set.begin(), set.end()); d != set.end())
    refuse(op, "duplicate", hexName(*d) + " is named twice");  // as sheet-insert refuses a quad named twice
  std::vector<QuadSide> sides;
  for (HexId h : set) {
    if (!cx.isHex(h)) refuse(op, "no-such-entity", hexName(h) + " does not exist");
    for (int f = 0; f < 6; ++f)
      if (!cx.isBoundary({h, f}) && !std::binary_search(set.begin(), set.end(), cx.gluing(h, f).hex)) sides.push_back({h, f});
  }
  if (sides.empty()) refuse(op, "no-surface", "no quad lies between the set and the rest of the mesh");
  return insertAlong(cx, sides, OpKind::SheetPillow);
}

}  // namespace hexdual
