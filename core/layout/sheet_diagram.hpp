// Sheet diagrams (TK03 §1.1): one dual sheet drawn flat. Its mid-surface is a quad mesh (one quad
// per (hex, axis) slot of the sheet, one vertex per primal edge crossing it); boundary loops go
// on circles, interior vertices by a harmonic (Tutte) solve; every hex appears as the crossing of
// two chords; chords are polylines through the quads' centres. One algorithm per file:
// mid_surface, boundary_loops, circle_placement, cut_graph, assemble_diagram, polygon_diagram,
// local_diagram, check_diagram; writers in io/diagram_json and io/diagram_svg.
#pragma once
#include "dual/dual.hpp"
#include "io/diagram_json.hpp"
#include "io/diagram_svg.hpp"
#include "layout/check_diagram.hpp"
#include "layout/diagram.hpp"
#include "layout/local_diagram.hpp"

namespace hexdual {

// The whole sheet. Disks, annuli and spheres are laid out directly; sheets of genus > 0 and
// non-orientable sheets are cut open into a fundamental polygon (method "polygon"). Only a sheet
// whose layout fails checkDiagram falls back to the largest disk-shaped neighbourhood of its first
// hex (method "local", with a note saying why).
SheetDiagram layoutSheet(const Complex& cx, const Dual& dual, int sheet);

}  // namespace hexdual
