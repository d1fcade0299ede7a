#include "layout/polygon_diagram.hpp"

#include <cmath>

#include "layout/assemble_diagram.hpp"
#include "layout/boundary_loops.hpp"
#include "layout/circle_placement.hpp"
#include "layout/cut_graph.hpp"

namespace hexdual {

SheetDiagram layoutPolygon(const Dual& dual, int sheet, const MidSurface& s) {
  auto fail = [&](const std::string& why) { throw Error("sheet diagram " + std::to_string(sheet) + ": " + why); };
  const int64_t euler = eulerCharacteristic(s);
  CutGraph g = cutGraph(s);
  MidSurface open = cutOpen(s, g.cut);
  std::vector<BoundaryEdge> edges = boundaryEdges(open);
  std::vector<std::vector<int>> loops;
  if (!open.orientable || !chainLoops(edges, loops) || loops.size() != 1 || loops[0].size() < 3 ||
      eulerCharacteristic(open) != 1)
    fail("the surface cut open is not a disk");
  FundamentalPolygon poly = fundamentalPolygon(s, g, open, edges, loops[0]);
  // The polygon on the unit circle: each side gets half its share by count, half by length, so
  // that short seams stay visible next to long boundary sides.
  std::vector<double> angle(size_t(open.nCorner), 0);
  const double turn = 2 * std::acos(-1.0), total = double(loops[0].size()), nSides = double(poly.sides.size());
  double t = 0;
  for (const PolygonSide& side : poly.sides) {
    double step = turn * (0.5 / nSides + 0.5 * double(side.edges.size()) / total) / double(side.edges.size());
    for (int k : side.edges) {
      angle[size_t(edges[size_t(k)].from)] = t;
      t += step;
    }
  }
  Placement pl;
  placeDisk(open, angle, pl, "polygon");
  SheetDiagram d = assembleDiagram(dual, sheet, open, pl, false);
  if (poly.euler != euler)
    fail("the polygon's Euler characteristic " + std::to_string(poly.euler) + " is not the surface's " +
         std::to_string(euler));
  std::string word;
  for (const PolygonSide& side : poly.sides) {
    SheetDiagram::Arc arc;
    arc.pair = side.pair;
    arc.sign = side.sign;
    arc.label = side.pair < 0 ? "\u2202" : seamLabel(side.pair, side.sign);
    for (int k : side.edges) {
      const BoundaryEdge& e = edges[size_t(k)];
      arc.points.push_back(pl.pos[size_t(e.from)]);
      arc.points.push_back(pl.pos[size_t(open.mid[size_t(e.slot)][size_t(e.face)])]);
    }
    arc.points.push_back(pl.pos[size_t(edges[size_t(side.edges.back())].to)]);
    word += (word.empty() ? "" : " ") + arc.label;
    d.arcs.push_back(std::move(arc));
  }
  d.euler = euler;
  // For a reader who has not met fundamental polygons: dashed sides with the same letter are one
  // seam, glued back together; ∂ sides are the mesh boundary. The word lists the sides in order.
  const bool boundary = word.find("\u2202") != std::string::npos;
  d.note = "cut open along " + std::to_string(poly.pairs) + (poly.pairs == 1 ? " seam" : " seams") +
           ": dashed sides with the same letter are the same seam" + (boundary ? ", \u2202 the mesh boundary" : "") +
           " (sides in order: " + word + ")";
  return d;
}

}  // namespace hexdual
