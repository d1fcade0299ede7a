// Column (chord) collapse (Merkley et al. 2007): the boundary-reaching form of ring collapse
// (ring_collapse.cpp, TK03 §4.4). The chord's cross-section collapses along one diagonal all the
// way along it; at an open chord's two ends the boundary quads collapse too, so the boundary quad
// mesh changes. Dually: the chord disappears and the two sheets crossing along it are cut there
// and re-joined crosswise. Cost: the chord and the stars of its vertices.
#include <algorithm>
#include <unordered_set>

#include "ops/sheet_support.hpp"
#include "ops/support.hpp"

namespace hexdual {
using namespace tables;
using namespace ops;

namespace {

// One hex of the column: its axis along the chord, the faces it is entered and left by (in the
// walk's direction), the edge of the collapsing diagonal and one edge of the kept diagonal.
struct ColumnHex {
  HexId hex;
  int axis, entry, exit, diag, keep;
};

// The edge along axis `to` of the neighbour across face f at the image of edge `edge`'s corner on f.
int acrossFace(const Complex& cx, HexId h, int f, int edge, int to) {
  const int c0 = kEdgeCorners[size_t(edge)][0];
  const int onFace = positionInFace(f, c0) >= 0 ? c0 : kEdgeCorners[size_t(edge)][1];
  return edgesOfCorner(cx.mappedCorner(h, f, onFace))[size_t(to)];
}

// The next hex of the column beyond face f of `cur` (f its exit, or its entry walking back).
ColumnHex beyond(const Complex& cx, const ColumnHex& cur, int f, bool forward) {
  const Gluing g = cx.gluing(cur.hex, f);
  const int a = axisOfFace(g.face);
  const int entry = forward ? g.face : oppositeFace(g.face);
  return {g.hex, a, entry, oppositeFace(entry), acrossFace(cx, cur.hex, f, cur.diag, a), acrossFace(cx, cur.hex, f, cur.keep, a)};
}

// The chord through e's hex along e's axis, from one boundary end to the other, or once round.
std::vector<ColumnHex> walkColumn(const Complex& cx, EdgeRef e, const std::string& op) {
  requireEdge(cx, e, op);
  const int a = axisOfEdge(e.edge);
  const ColumnHex start{e.hex, a, 2 * a, 2 * a + 1, e.edge, e.edge ^ 2};
  std::vector<ColumnHex> fwd{start}, back;
  std::unordered_set<HexId> seen{e.hex};
  auto add = [&](std::vector<ColumnHex>& list, const ColumnHex& x) {
    if (!seen.insert(x.hex).second)
      refuse(op, "self-intersecting", "the chord through " + entityName(e) + " passes " + hexName(x.hex) + " twice");
    list.push_back(x);
  };
  for (ColumnHex cur = start; !cx.isBoundary({cur.hex, cur.exit});) {
    const ColumnHex next = beyond(cx, cur, cur.exit, true);
    if (next.hex == start.hex && next.axis == start.axis) {  // closed: it must come back untwisted
      if (next.entry != start.entry) refuse(op, "twisted", "the chord through " + entityName(e) + " returns reversed");
      if (next.diag != start.diag && next.diag != (start.diag ^ 3))
        refuse(op, "twisted", "carried round the chord, the diagonal of " + entityName(e) + " comes back as the other diagonal");
      return fwd;
    }
    add(fwd, next);
    cur = fwd.back();
  }
  for (ColumnHex cur = start; !cx.isBoundary({cur.hex, cur.entry});) {
    add(back, beyond(cx, cur, cur.entry, false));
    cur = back.back();
  }
  std::reverse(back.begin(), back.end());
  back.insert(back.end(), fwd.begin(), fwd.end());
  return back;
}

// The vertex lines of the two diagonal edges merge pairwise (a union-find keyed by vertex id).
MergeClasses diagonalClasses(const Complex& cx, const std::vector<ColumnHex>& column) {
  std::unordered_map<VertexId, VertexId> parent;
  std::unordered_map<VertexId, std::pair<HexId, int>> cornerOf;
  auto find = [&](VertexId v) {
    while (parent.at(v) != v) v = parent[v] = parent.at(parent.at(v));
    return v;
  };
  std::vector<VertexId> order;
  for (const ColumnHex& r : column)
    for (int k = 0; k < 2; ++k) {
      const int c1 = kEdgeCorners[size_t(r.diag)][size_t(k)], c2 = kEdgeCorners[size_t(r.diag ^ 3)][size_t(k)];
      for (int c : {c1, c2})
        if (parent.emplace(cx.vertex(r.hex, c), cx.vertex(r.hex, c)).second) {
          cornerOf[cx.vertex(r.hex, c)] = {r.hex, c};
          order.push_back(cx.vertex(r.hex, c));
        }
      const VertexId x = find(cx.vertex(r.hex, c1)), y = find(cx.vertex(r.hex, c2));
      if (x != y) parent[std::max(x, y)] = std::min(x, y);
    }
  std::unordered_map<VertexId, size_t> classOf;
  std::vector<std::vector<std::pair<HexId, int>>> classes;
  for (VertexId v : order) {
    auto [it, fresh] = classOf.emplace(find(v), classes.size());
    if (fresh) classes.emplace_back();
    classes[it->second].push_back(cornerOf.at(v));
  }
  MergeClasses out;
  for (const auto& cls : classes) out.add(cls);
  return out;
}

// The side quads glued to each other once the column is gone: from every side facing a hex
// outside the column, through the collapse partners (the two sides at a kept edge) to the next
// side facing outside, or to the boundary (then the first side becomes boundary).
std::vector<std::pair<QuadSide, QuadSide>> sideGlues(const Complex& cx, const std::vector<ColumnHex>& column) {
  std::unordered_map<HexId, const ColumnHex*> in;
  for (const ColumnHex& r : column) in[r.hex] = &r;
  auto partner = [&](QuadSide s) {
    const ColumnHex& r = *in.at(s.hex);
    for (int kept : {r.keep, r.keep ^ 3}) {
      const auto fs = facesOfEdge(kept);
      if (s.face == fs[0]) return QuadSide{s.hex, fs[1]};
      if (s.face == fs[1]) return QuadSide{s.hex, fs[0]};
    }
    return QuadSide{-1, 0};
  };
  std::vector<std::pair<QuadSide, QuadSide>> glues;
  std::unordered_set<int64_t> done;
  auto key = [](QuadSide s) { return int64_t(s.hex) * 8 + s.face; };
  for (const ColumnHex& r : column)
    for (int f = 0; f < 6; ++f) {
      if (axisOfFace(f) == r.axis || done.count(key({r.hex, f})) || cx.isBoundary({r.hex, f}) || in.count(cx.gluing(r.hex, f).hex)) continue;
      done.insert(key({r.hex, f}));
      const QuadSide start{cx.gluing(r.hex, f).hex, cx.gluing(r.hex, f).face};
      for (QuadSide cur = partner({r.hex, f}); done.insert(key(cur)).second;) {
        if (cx.isBoundary(cur)) break;
        const Gluing n = cx.gluing(cur);
        if (!in.count(n.hex)) {
          glues.push_back({start, {n.hex, n.face}});
          break;
        }
        done.insert(key({n.hex, n.face}));
        cur = partner({n.hex, n.face});
      }
    }
  return glues;
}

// The vertices of the kept diagonal's lines: they do not merge, but those only the column uses
// vanish with it, and so do their edges. Each by a corner, and (second) by a corner off the
// column for those that stay: the edge count around the collapse includes them.
std::pair<std::vector<std::pair<HexId, int>>, std::vector<std::pair<HexId, int>>> keptLines(
    const Complex& cx, const std::vector<ColumnHex>& column, const std::function<bool(HexId)>& removed) {
  std::vector<std::pair<HexId, int>> all, staying;
  std::unordered_set<VertexId> seen;
  for (const ColumnHex& r : column)
    for (int kept : {r.keep, r.keep ^ 3})
      for (int c : kEdgeCorners[size_t(kept)]) {
        if (!seen.insert(cx.vertex(r.hex, c)).second) continue;
        all.push_back({r.hex, c});
        for (auto corner : cx.cornersOfVertex(r.hex, c))
          if (!removed(corner.first)) {
            staying.push_back(corner);
            break;
          }
      }
  return {all, staying};
}

}  // namespace

OpResult columnCollapse(Complex& cx, EdgeRef e) {
  const OpKind kind = OpKind::ColumnCollapse;
  const std::string op = opName(kind);
  const std::vector<ColumnHex> column = walkColumn(cx, e, op);
  std::vector<HexId> hexes;
  for (const ColumnHex& r : column) hexes.push_back(r.hex);
  std::sort(hexes.begin(), hexes.end());
  requireManifold(cx, hexes, op);
  auto removed = [&](HexId h) { return std::binary_search(hexes.begin(), hexes.end(), h); };
  const VertexMerges m = planMerges(cx, diagonalClasses(cx, column), removed);
  requireDistinctCorners(cx, m, op);
  const auto glues = sideGlues(cx, column);

  auto [around, aroundAfter] = keptLines(cx, column, removed);
  around.insert(around.end(), m.members.begin(), m.members.end());
  aroundAfter.insert(aroundAfter.end(), m.anchors.begin(), m.anchors.end());
  const EulerBefore before{cx.numVertices(), edgesAt(cx, around), cx.numQuads(), cx.numHexes()};
  Transaction tx(cx, collapseEdits(hexes.size(), m, glues.size()));
  for (HexId h : hexes)
    for (int f = 0; f < 6; ++f) cx.unglue(h, f);
  for (HexId h : hexes) cx.removeHex(h);
  applyMerges(cx, m);
  OpResult res;
  res.op = kind;
  res.removedHexes = hexes;
  res.noInverse = "a column collapse has no inverse step in the operation log";
  finishCollapse(cx, tx, res, m, glues, before, aroundAfter, op);
  return res;
}

}  // namespace hexdual
