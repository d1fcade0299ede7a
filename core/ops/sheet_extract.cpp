// Sheet extraction (Borden, Benzley & Shepherd 2002): collapse every edge of a sheet's edge
// class. The sheet's hexes vanish and the quads on either side are glued. Dually: the sheet
// disappears, every chord crossing it loses the hexes where it crossed, the chords lying in it
// disappear. Cost: the sheet and the stars of its vertices.
#include <algorithm>

#include "ops/sheet_support.hpp"
#include "ops/support.hpp"

namespace hexdual {
using namespace tables;
using namespace ops;

namespace {

// Consecutive hexes of the sheet along a chord crossing it, and the faces by which the chord
// enters the first and leaves the last (their gluings: the quads the extraction glues).
struct Run {
  std::vector<HexId> hexes;
  QuadSide before, after;
};

// From hex h out through face x, the hexes of the sheet the chord passes next while it stays in
// the sheet, and the face it leaves the last one by; `closed` when it comes back to h.
struct RunWalk {
  std::vector<HexId> hexes;
  QuadSide last;
  bool closed = false;
};
RunWalk walkRun(const Complex& cx, const SheetHexes& sheet, HexId h, int x) {
  RunWalk w;
  w.last = {h, x};
  for (size_t guard = 0; guard <= sheet.hexes.size(); ++guard) {
    const Gluing g = cx.gluing(w.last);
    if (g.boundary() || sheet.axisOf(g.hex) != axisOfFace(g.face)) break;  // the chord leaves the sheet
    if (g.hex == h) {
      w.closed = true;
      break;
    }
    w.hexes.push_back(g.hex);
    w.last = {g.hex, oppositeFace(g.face)};
  }
  return w;
}

std::string hexList(const std::vector<HexId>& hexes) {
  std::string s;
  for (size_t i = 0; i < hexes.size() && i < 8; ++i) s += (i ? ", " : "") + std::to_string(hexes[i]);
  return s + (hexes.size() > 8 ? ", ..." : "");
}

// Every sheet hex lies in one run. Refuses a chord that never leaves the sheet (no-sides).
std::vector<Run> runsOf(const Complex& cx, const SheetHexes& sheet, const std::string& op) {
  std::vector<Run> runs;
  IdMap<uint8_t> placed(sheet.hexes.size());
  for (HexId h : sheet.hexes) {
    if (placed.count(h)) continue;
    const int a = sheet.axisOf(h);
    RunWalk up = walkRun(cx, sheet, h, 2 * a + 1);
    if (up.closed)
      refuse(op, "no-sides", "the chord through " + hexName(h) + " is closed and lies in the sheet; nothing is on either side of it");
    RunWalk down = walkRun(cx, sheet, h, 2 * a);
    Run r;
    r.hexes.assign(down.hexes.rbegin(), down.hexes.rend());
    r.hexes.push_back(h);
    r.hexes.insert(r.hexes.end(), up.hexes.begin(), up.hexes.end());
    r.before = down.last;
    r.after = up.last;
    if (cx.isBoundary(r.before) && cx.isBoundary(r.after))
      refuse(op, "no-sides", "the chord through " + hexName(h) + " runs from boundary to boundary inside the sheet (hexes " +
                                 hexList(r.hexes) + "); no hex would be left there");
    for (HexId x : r.hexes) placed.emplace(x, 1);
    runs.push_back(std::move(r));
  }
  return runs;
}

// The edge class: one merge (its two ends) per edge. Refuses a vertex on two edges of the class
// with different other ends (self-touching): three vertices would become one.
MergeClasses collapsedEdges(const Complex& cx, const SheetHexes& sheet, const std::string& op) {
  IdMap<VertexId> partner(2 * sheet.hexes.size());  // a sheet of n hexes: about 2n vertices
  MergeClasses classes;
  classes.corners.reserve(4 * sheet.hexes.size());
  classes.begin.reserve(2 * sheet.hexes.size() + 1);
  auto pairUp = [&](VertexId v, VertexId w) {
    auto [it, fresh] = partner.emplace(v, w);
    if (!fresh && *it != w)
      refuse(op, "self-touching",
             "the sheet touches itself at vertex " + std::to_string(v) + ": its edges to " + std::to_string(*it) +
                 " and to " + std::to_string(w) + " would merge three vertices into one");
    return fresh;
  };
  for (HexId h : sheet.hexes) {
    const int a = sheet.axisOf(h);
    for (int k = 0; k < 4; ++k) {
      const int c0 = kEdgeCorners[size_t(4 * a + k)][0], c1 = kEdgeCorners[size_t(4 * a + k)][1];
      const VertexId v0 = cx.vertex(h, c0), v1 = cx.vertex(h, c1);
      const bool fresh = pairUp(v0, v1);
      pairUp(v1, v0);
      if (fresh) {
        const std::pair<HexId, int> ends[2] = {{h, c0}, {h, c1}};
        classes.add(ends);
      }
    }
  }
  return classes;
}

// The pairs of quads to glue: both outside ends of every run whose ends are both interior. They
// must carry the same vertices once merged.
std::vector<std::pair<QuadSide, QuadSide>> gluesOf(const Complex& cx, const std::vector<Run>& runs, const VertexMerges& m,
                                                   const std::string& op) {
  std::vector<std::pair<QuadSide, QuadSide>> out;
  for (const Run& r : runs) {
    if (cx.isBoundary(r.before) || cx.isBoundary(r.after)) continue;
    const Gluing p = cx.gluing(r.before), n = cx.gluing(r.after);
    const QuadSide P{p.hex, p.face}, N{n.hex, n.face};
    auto merged = [&](QuadSide s) {
      std::array<VertexId, 4> v = faceVertexSet(cx, s.hex, s.face);
      for (VertexId& x : v) x = m.target(x);
      std::sort(v.begin(), v.end());
      return v;
    };
    if (P == N || merged(P) != merged(N))
      refuse(op, "invalid-result", "the quads " + entityName(P) + " and " + entityName(N) + " on either side of " +
                                       hexName(r.hexes[0]) + " would not meet vertex for vertex");
    out.push_back({P, N});
  }
  return out;
}

// The insertion that gives the sheet back: along the glued quads, every one named by its side
// on the sheet's "up" side (or every one by its "down" side), so the side named moves onto the new
// vertices and the inserted layer is the sheet again. It splits every glued vertex back in two
// when each end of the collapsed edge had its corners off the sheet connected across faces
// (usually: the link of a vertex minus the star of one edge; not where the link is pinched there),
// and it cannot move a boundary quad's outer side: every run ending on the boundary must end on
// the same side of the sheet.
// None when a chord crosses the sheet twice in a row (it folds back on itself), except for a
// sphere of 2 hexes (a minimal pillow: its inverse is a pillow), or when the sheet is one-sided.
void reportInverse(const Complex& cx, OpResult& res, const std::vector<Run>& runs, const SheetHexes& sheet, VertexId split) {
  const Run* fold = nullptr;
  for (const Run& r : runs)
    if (r.hexes.size() > 1 && !fold) fold = &r;
  auto outside = [&](QuadSide s) { return QuadSide{cx.gluing(s).hex, cx.gluing(s).face}; };
  if (fold) {
    if (runs.size() == 1 && sheet.hexes.size() == 2 && !cx.isBoundary(fold->before) && !cx.isBoundary(fold->after))
      res.inverse = makeStep(OpKind::Pillow, outside(fold->before));
    else
      res.noInverse = "the sheet folds back on itself: a chord crosses it twice in a row (hexes " + hexList(fold->hexes) +
                      "), which no sheet insertion gives back";
    return;
  }
  if (split >= 0) {
    res.noInverse = "around vertex " + std::to_string(split) +
                    " the hexes off the sheet touch only at the vertex: no sheet insertion gives it back";
    return;
  }
  const auto up = sheetUp(cx, sheet);
  if (up.empty()) {
    res.noInverse = "the sheet is one-sided: no sheet insertion gives it back";
    return;
  }
  // Per run, its end on the up side and on the down side (a run of one hex: its two faces across).
  auto upEnd = [&](const Run& r) { return up.at(r.hexes[0]) > 0 ? r.after : r.before; };
  auto downEnd = [&](const Run& r) { return up.at(r.hexes[0]) > 0 ? r.before : r.after; };
  bool boundaryUp = false, boundaryDown = false;
  for (const Run& r : runs) {
    boundaryUp = boundaryUp || cx.isBoundary(upEnd(r));
    boundaryDown = boundaryDown || cx.isBoundary(downEnd(r));
  }
  if (boundaryUp && boundaryDown) {
    res.noInverse = "the sheet meets the boundary on both of its sides: no sheet insertion gives it back";
    return;
  }
  OpStep inv{OpKind::SheetInsert, {}, 0};
  for (const Run& r : runs)  // the side that moves: the up side, unless the boundary is there
    inv.args.push_back(OpArg::of(outside(boundaryDown ? upEnd(r) : downEnd(r))));
  res.inverse = std::move(inv);
}

// Whether a collapsed edge joins two boundary vertices through the interior (a proper arc): only
// then can the collapse change the topology (collapsing arcs with at most one end on the boundary
// keeps it; every applied step's Δ is compared with full counts in the tests), so only then is the
// Euler characteristic counted.
bool collapsesProperArc(const Complex& cx, const MergeClasses& edges, const VertexMerges& m) {
  for (size_t k = 0; k < edges.size(); ++k) {
    if (m.boundaryMembers[k] < 2) continue;
    const auto [h, c0] = edges[k][0];
    EdgeRef cur{h, edgeBetween(c0, edges[k][1].second)};
    const EdgeRef start = cur;
    int exit = facesOfEdge(cur.edge)[0];
    bool closed = false;
    for (size_t n = 0; n <= size_t(12) * size_t(cx.numHexes()) && cx.stepAroundEdge(cur, exit); ++n)
      if (cur == start) {
        closed = true;
        break;
      }
    if (closed) return true;
  }
  return false;
}

}  // namespace

OpResult sheetExtract(Complex& cx, EdgeRef e) {
  const OpKind kind = OpKind::SheetExtract;
  const std::string op = opName(kind);
  const SheetHexes sheet = sheetThrough(cx, e, op);
  requireManifold(cx, sheet.hexes, op);
  const std::vector<Run> runs = runsOf(cx, sheet, op);
  const auto edges = collapsedEdges(cx, sheet, op);
  std::vector<uint64_t> inSheet((size_t(cx.hexCapacity()) + 63) / 64, 0);  // a bit per hex: what planMerges asks most
  for (HexId h : sheet.hexes) inSheet[size_t(h) >> 6] |= uint64_t(1) << (size_t(h) & 63);
  const VertexMerges m = planMerges(cx, edges, [&](HexId h) { return inSheet[size_t(h) >> 6] >> (size_t(h) & 63) & 1; });
  requireDistinctCorners(cx, m, op);
  const auto glues = gluesOf(cx, runs, m, op);
  OpResult res;
  res.op = kind;
  res.removedHexes = sheet.hexes;
  reportInverse(cx, res, runs, sheet, m.split);  // names quads by their outside sides, which survive

  const bool countEuler = collapsesProperArc(cx, edges, m);
  const EulerBefore before{cx.numVertices(), countEuler ? edgesAt(cx, m.members) : -1, cx.numQuads(), cx.numHexes()};
  Transaction tx(cx);
  for (HexId h : sheet.hexes)
    for (int f = 0; f < 6; ++f) cx.unglue(h, f);
  for (HexId h : sheet.hexes) cx.removeHex(h);
  applyMerges(cx, m);
  finishCollapse(cx, tx, res, m, glues, before, m.anchors, op);
  return res;
}

}  // namespace hexdual
