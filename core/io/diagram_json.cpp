#include "io/diagram_json.hpp"

#include "io/json.hpp"

namespace hexdual {

std::string diagramJson(const SheetDiagram& d) {
  io::JsonWriter w;
  auto pt = [&](Point2 p) { w.beginArray().value(p.x).value(p.y).endArray(); };
  auto polyline = [&](const std::vector<Point2>& ps) {
    w.beginArray();
    for (Point2 p : ps) pt(p);
    w.endArray();
  };
  w.beginObject().key("sheet").value(d.sheet).key("topology").value(d.topology).key("method").value(d.method);
  w.key("local").value(d.local).key("note").value(d.note).key("radius").value(d.radius).key("euler").value(d.euler);
  w.key("openedHex");
  if (d.openedHex >= 0) w.value(int64_t(d.openedHex));
  else w.raw("null");
  w.key("crossings").beginArray();
  for (const auto& c : d.crossings) {
    w.beginObject().key("hex").value(int64_t(c.hex)).key("axis").value(c.axis).key("x").value(c.p.x).key("y").value(c.p.y);
    w.key("chords").beginArray().value(c.chords[0]).value(c.chords[1]).endArray().key("outside").value(c.outside).endObject();
  }
  w.endArray().key("boundary").beginArray();
  for (const auto& b : d.boundary)
    w.beginObject().key("hex").value(int64_t(b.hex)).key("face").value(b.face).key("x").value(b.p.x).key("y").value(b.p.y).endObject();
  w.endArray().key("chords").beginArray();
  for (const auto& c : d.chords) {
    w.beginObject().key("id").value(c.chord).key("otherSheet").value(c.otherSheet).key("closed").value(c.closed).key("piece").value(c.piece);
    w.key("hexes").beginArray();
    for (HexId h : c.hexes) w.value(int64_t(h));
    w.endArray().key("points");
    polyline(c.points);
    w.endObject();
  }
  w.endArray().key("loops").beginArray();
  for (const auto& l : d.loops) polyline(l);
  w.endArray().key("arcs").beginArray();
  for (const auto& a : d.arcs) {
    w.beginObject().key("label").value(a.label).key("pair").value(a.pair).key("sign").value(a.sign).key("points");
    polyline(a.points);
    w.endObject();
  }
  w.endArray().key("cells").beginArray();
  for (const auto& c : d.cells)
    w.beginObject().key("edge").beginArray().value(int64_t(c.edge.hex)).value(c.edge.edge).endArray().key("x").value(c.p.x).key("y").value(c.p.y).endObject();
  w.endArray().endObject();
  return w.str();
}

}  // namespace hexdual
