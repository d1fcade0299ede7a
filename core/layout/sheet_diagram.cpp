#include "layout/sheet_diagram.hpp"

#include "layout/assemble_diagram.hpp"
#include "layout/circle_placement.hpp"
#include "layout/mid_surface.hpp"
#include "layout/polygon_diagram.hpp"

namespace hexdual {

SheetDiagram layoutSheet(const Complex& cx, const Dual& dual, int sheet) {
  if (sheet < 0 || size_t(sheet) >= dual.sheets.size() || !dual.sheets[size_t(sheet)].alive)
    throw Error("sheet diagram: sheet " + std::to_string(sheet) + " does not exist");
  const Sheet& sh = dual.sheets[size_t(sheet)];
  MidSurface s = buildMidSurface(cx, sh.slots);
  Placement pl;
  std::string why;
  if (placeSurface(s, pl)) {
    SheetDiagram d = assembleDiagram(dual, sheet, s, pl, false);
    d.euler = sh.euler;
    try {
      checkDiagram(d, sh.slots.size());
      return d;
    } catch (const Error& e) {
      why = std::string("the whole-sheet layout is not planar (") + e.what() + ")";
    }
  }
  // Genus > 0, non-orientable, or an annulus or sphere whose layout is not planar: cut open into
  // a fundamental polygon, whose boundary is one convex loop (Tutte's theorem).
  if (sh.topology != "disk") {
    try {
      SheetDiagram d = layoutPolygon(dual, sheet, s);
      checkDiagram(d, sh.slots.size());
      return d;
    } catch (const Error& e) {
      why = std::string("this sheet is ") + sh.topology + (sh.selfIntersecting ? " and self-intersecting" : "") +
            " and its fundamental polygon is not planar (" + e.what() + ")";
    }
  }
  if (why.empty())
    why = "this sheet is " + sh.topology + (sh.selfIntersecting ? " and self-intersecting" : "") + " and does not lay out whole";
  // Otherwise: the largest neighbourhood of the sheet's first hex that draws as a planar disk.
  SheetDiagram d = layoutLocal(cx, dual, sheet, {sh.slots[0].hex}, int(sh.slots.size()));
  d.note = why + "; showing " + d.note;
  return d;
}

}  // namespace hexdual
