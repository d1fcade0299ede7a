// Sheet diagrams (TK03 §1.1): one dual sheet drawn flat, planar by construction. Its mid-surface is
// a quad mesh (one quad per (hex, axis) slot of the sheet, one vertex per primal edge crossing
// it), fanned into a simplicial triangulation; the outer boundary loop goes on a circle, holes are
// closed by virtual rings, and Tutte's embedding places the rest (planar for any positive weights,
// Floater 2003), relaxed towards square quads without flipping a triangle (ARAP). Every hex
// appears as the crossing of two chords; chords are polylines through the quads' centres. One
// algorithm per file: mid_surface, boundary_loops, triangulation, tutte_embedding, arap_relax,
// circle_placement, cut_graph, assemble_diagram, polygon_diagram, local_diagram, check_diagram,
// diagram_spread; writers in io/diagram_json and io/diagram_svg.
#pragma once
#include "dual/dual.hpp"
#include "io/diagram_json.hpp"
#include "io/diagram_svg.hpp"
#include "layout/check_diagram.hpp"
#include "layout/diagram.hpp"
#include "layout/local_diagram.hpp"

namespace hexdual {

// The whole sheet, always: disks, annuli, disks with holes and spheres are drawn as they are;
// sheets of genus > 0 and non-orientable sheets — and a genus-0 sheet whose drawing would crowd
// (a large sphere, a long tube) — are cut open into a fundamental polygon (method "polygon").
// Throws Error only for a sheet that does not exist, or if the drawing's certificate or
// checkDiagram fails (a bug, not a property of the sheet).
SheetDiagram layoutSheet(const Complex& cx, const Dual& dual, int sheet);

}  // namespace hexdual
