#include "layout/sheet_diagram.hpp"

#include <cstdio>

#include "layout/assemble_diagram.hpp"
#include "layout/circle_placement.hpp"
#include "layout/diagram_spread.hpp"
#include "layout/mid_surface.hpp"
#include "layout/polygon_diagram.hpp"

namespace hexdual {

SheetDiagram layoutSheet(const Complex& cx, const Dual& dual, int sheet) {
  if (sheet < 0 || size_t(sheet) >= dual.sheets.size() || !dual.sheets[size_t(sheet)].alive)
    throw Error("sheet diagram: sheet " + std::to_string(sheet) + " does not exist");
  const Sheet& sh = dual.sheets[size_t(sheet)];
  MidSurface s = buildMidSurface(cx, {sh.slots.begin(), sh.slots.end()});
  // Genus 0 (disk, annulus, disk with holes, sphere) is drawn as it is; anything else is cut open
  // into a fundamental polygon, and so is a genus-0 sheet whose drawing crowds (a large sphere
  // behind its opened face, a long tube as an annulus) when the polygon spreads better. Both are
  // Tutte embeddings of a triangulated disk, planar by construction: checkDiagram confirms it.
  Placement pl;
  SheetDiagram d;
  // A sphere opened at one face squeezes its far side by about its size: past a thousand hexes
  // that is never readable, so such a sphere is cut open straight away.
  bool whole = !(sh.topology == "sphere" && sh.slots.size() > 1000) && placeSurface(s, pl, nullptr, DiskBoundary::shaped);
  if (whole) d = assembleDiagram(dual, sheet, s, pl, false);
  if (whole && pl.straightened > 0)
    d.note = "drawn convex: " + std::to_string(pl.straightened) + " reflex corner" + (pl.straightened == 1 ? "" : "s") +
             " of its boundary (three quads meeting it) drawn straight";
  // A disk is drawn in the shape its quads give it (a 100 x 14 sheet as a long rectangle); where
  // that crowds (cones close to the boundary make sharp corners), on the circle when it spreads better.
  const double spread = whole ? diagramSpread(d) : 0;
  if (whole && sh.topology == "disk" && pl.method == "disk" && spread < kReadableSpread) {
    Placement round;
    placeSurface(s, round, nullptr, DiskBoundary::circle);
    SheetDiagram onCircle = assembleDiagram(dual, sheet, s, round, false);
    const double shaped = spread, circle = diagramSpread(onCircle);
    if (circle > shaped) {
      d = std::move(onCircle);
      char buf[160];
      std::snprintf(buf, sizeof buf, "drawn on a circle: in the shape its quads give, crossings crowd (spread %.3f; %.3f on the circle)",
                    shaped, circle);
      d.note = buf;
    }
  }
  if (!whole || (sh.topology != "disk" && spread < kReadableSpread)) {
    SheetDiagram cut = layoutPolygon(dual, sheet, s);
    if (!whole || diagramSpread(cut) > spread) d = std::move(cut);
  }
  d.euler = sh.euler;
  checkDiagram(d, sh.slots.size());
  return d;
}

}  // namespace hexdual
