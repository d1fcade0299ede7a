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

// Whether the extraction's result is a valid complex whatever the validity check would find, so
// that its commit walks no vertex link (Transaction::commitValidByConstruction). The argument:
// - Only the links of the merged vertices change: every corner, quad and gluing the extraction
//   edits has all its vertices among them (each vertex of a sheet hex ends a collapsed edge).
//   Distinct corners are required before (requireDistinctCorners), and the new gluings match
//   vertex for vertex (orientByVertices).
// - The link of the merged vertex of edge e = v0v1 is link(v0) and link(v1) with the corners of
//   the hexes round e taken out (the umbrellas D0, D1 round e's link vertex), glued along their
//   rims: the quads at v0 and at v1 of those hexes, which the extraction glues pairwise in order.
// - When every hex at v0 and at v1 is a hex round e (one edge joins them), the rims are simple
//   (the far ends of the rim edges are distinct vertices), every rim quad is glued (no run ends on
//   the boundary or folds) and the corners off the sheet stay face-connected (no split):
//   * e closed, v1 inside: link(v1) minus D1 is a disk with the rim as boundary, so the new link
//     is link(v0) with D0 replaced by a disk: a sphere or a disk as link(v0) was (and the same
//     with v0 and v1 exchanged);
//   * e closed, v0 and v1 both on the boundary: an annulus. Not certified (the check refuses it);
//   * e a fan (both ends on the boundary): two disks glued along an arc of each boundary: a disk.
// Anything else (folds, boundary runs, splits, doubled edges, a vertex with more sheet hexes than
// e's): not certified, and the validity check decides as before.
// tests/test_valid_by_construction.cpp checks the claim on every certified extraction it meets.
bool validByConstruction(const Complex& cx, const std::vector<Run>& runs, const MergeClasses& edges, const VertexMerges& m) {
  if (m.split >= 0 || m.removedCorners.size() != 2 * edges.size()) return false;
  for (const Run& r : runs)
    if (r.hexes.size() != 1 || cx.isBoundary(r.before) || cx.isBoundary(r.after)) return false;
  std::array<VertexId, 64> rim0, rim1;  // far ends of the rim edges at v0 and at v1 (each named twice on a cycle)
  auto distinct = [](std::array<VertexId, 64>& a, size_t n) {
    std::sort(a.begin(), a.begin() + std::ptrdiff_t(n));
    return size_t(std::unique(a.begin(), a.begin() + std::ptrdiff_t(n)) - a.begin());
  };
  for (size_t k = 0; k < edges.size(); ++k) {
    const auto [h, c0] = edges[k][0];
    const VertexId v0 = cx.vertex(h, c0);
    size_t round = 0, n0 = 0, n1 = 0;  // hexes round e; rim ends listed
    auto visit = [&](EdgeRef cur) {
      ++round;
      const int a = axisOfEdge(cur.edge);
      for (int c : kEdgeCorners[size_t(cur.edge)]) {
        const bool atV0 = cx.vertex(cur.hex, c) == v0;
        for (int b = 0; b < 3; ++b)
          if (b != a) (atV0 ? rim0[n0++] : rim1[n1++]) = cx.vertex(cur.hex, flipAxis(c, b));
      }
    };
    const EdgeRef start{h, edgeBetween(c0, edges[k][1].second)};
    bool closed = false;
    visit(start);
    for (int dir = 0; dir < 2 && !closed; ++dir) {
      EdgeRef cur = start;
      int exit = facesOfEdge(start.edge)[size_t(dir)];
      while (cx.stepAroundEdge(cur, exit)) {
        if (cur == start) {
          closed = true;
          break;
        }
        if (round == 31) return false;  // (a large edge cycle: left to the check)
        visit(cur);
      }
    }
    if (n0 != 2 * round || n1 != 2 * round) return false;
    if (m.removedCorners[2 * k] != int(round) || m.removedCorners[2 * k + 1] != int(round)) return false;
    if (closed && (round < 2 || m.boundaryMembers[k] == 2)) return false;
    const size_t want = closed ? round : round + 1;
    if (distinct(rim0, n0) != want || distinct(rim1, n1) != want) return false;
  }
  return true;
}

// Everything the extraction decides before it edits (each step refuses with its rule).
struct ExtractionPlan {
  SheetHexes sheet;
  std::vector<Run> runs;
  MergeClasses edges;
  VertexMerges merges;
  std::vector<std::pair<QuadSide, QuadSide>> glues;
};
ExtractionPlan planExtraction(const Complex& cx, EdgeRef e, const std::string& op) {
  ExtractionPlan p;
  p.sheet = sheetThrough(cx, e, op);
  requireManifold(cx, p.sheet.hexes, op);
  p.runs = runsOf(cx, p.sheet, op);
  p.edges = collapsedEdges(cx, p.sheet, op);
  // planMerges asks of every corner of every merged vertex's star whether its hex is the sheet's:
  // a bit per hex of the mesh when that bitmap is small beside the sheet (at most 8 words per sheet
  // hex, which plans far more than that per hex: a 100³ layer's 10,000 hexes, 15,625 words), else
  // the sheet's map, so a small sheet on a large mesh costs what it is.
  const size_t words = (size_t(cx.hexCapacity()) + 63) / 64;
  if (words <= 8 * p.sheet.hexes.size()) {
    std::vector<uint64_t> inSheet(words, 0);
    for (HexId h : p.sheet.hexes) inSheet[size_t(h) >> 6] |= uint64_t(1) << (size_t(h) & 63);
    p.merges = planMerges(cx, p.edges, [&](HexId h) { return inSheet[size_t(h) >> 6] >> (size_t(h) & 63) & 1; });
  } else {
    p.merges = planMerges(cx, p.edges, [&](HexId h) { return p.sheet.axisOf(h) >= 0; });
  }
  requireDistinctCorners(cx, p.merges, op);
  p.glues = gluesOf(cx, p.runs, p.merges, op);
  return p;
}
}  // namespace

bool sheetExtractValidByConstruction(const Complex& cx, EdgeRef e) {
  try {
    const ExtractionPlan p = planExtraction(cx, e, opName(OpKind::SheetExtract));
    return validByConstruction(cx, p.runs, p.edges, p.merges);
  } catch (const Error&) {
    return false;
  }
}

OpResult sheetExtract(Complex& cx, EdgeRef e) {
  const OpKind kind = OpKind::SheetExtract;
  const std::string op = opName(kind);
  const ExtractionPlan p = planExtraction(cx, e, op);
  const SheetHexes& sheet = p.sheet;
  const VertexMerges& m = p.merges;
  OpResult res;
  res.op = kind;
  res.removedHexes = sheet.hexes;
  reportInverse(cx, res, p.runs, sheet, m.split);  // names quads by their outside sides, which survive
  const bool certified = validByConstruction(cx, p.runs, p.edges, m);

  const bool countEuler = collapsesProperArc(cx, p.edges, m);
  const EulerBefore before{cx.numVertices(), countEuler ? edgesAt(cx, m.members) : -1, cx.numQuads(), cx.numHexes()};
  Transaction tx(cx, collapseEdits(sheet.hexes.size(), m, p.glues.size()));
  for (HexId h : sheet.hexes)
    for (int f = 0; f < 6; ++f) cx.unglue(h, f);
  for (HexId h : sheet.hexes) cx.removeHex(h);
  applyMerges(cx, m);
  finishCollapse(cx, tx, res, m, p.glues, before, m.anchors, op, certified);
  return res;
}

}  // namespace hexdual
