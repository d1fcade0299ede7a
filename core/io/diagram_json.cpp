#include "io/diagram_json.hpp"

#include "io/json.hpp"

namespace hexdual {

namespace {

void point(io::JsonWriter& w, Point2 p) { w.beginArray().value(p.x).value(p.y).endArray(); }

void polyline(io::JsonWriter& w, const std::vector<Point2>& ps) {
  w.beginArray();
  for (Point2 p : ps) point(w, p);
  w.endArray();
}

void writeCrossings(io::JsonWriter& w, const SheetDiagram& d) {
  w.key("crossings").beginArray();
  for (const auto& c : d.crossings) {
    w.beginObject().key("hex").value(int64_t(c.hex)).key("axis").value(c.axis).key("x").value(c.p.x).key("y").value(c.p.y);
    w.key("chords").beginArray().value(c.chords[0]).value(c.chords[1]).endArray();
    w.key("outside").value(c.outside).endObject();
  }
  w.endArray();
}

void writeBoundary(io::JsonWriter& w, const SheetDiagram& d) {
  w.key("boundary").beginArray();
  for (const auto& b : d.boundary)
    w.beginObject().key("hex").value(int64_t(b.hex)).key("face").value(b.face).key("x").value(b.p.x).key("y").value(b.p.y).endObject();
  w.endArray();
}

void writeChords(io::JsonWriter& w, const SheetDiagram& d) {
  w.key("chords").beginArray();
  for (const auto& c : d.chords) {
    w.beginObject().key("id").value(c.chord).key("otherSheet").value(c.otherSheet).key("closed").value(c.closed);
    w.key("piece").value(c.piece).key("hexes").beginArray();
    for (HexId h : c.hexes) w.value(int64_t(h));
    w.endArray().key("points");
    polyline(w, c.points);
    w.endObject();
  }
  w.endArray();
}

void writeLoopsArcsCells(io::JsonWriter& w, const SheetDiagram& d) {
  w.key("loops").beginArray();
  for (const auto& l : d.loops) polyline(w, l);
  w.endArray().key("arcs").beginArray();
  for (const auto& a : d.arcs) {
    w.beginObject().key("label").value(a.label).key("pair").value(a.pair).key("sign").value(a.sign).key("points");
    polyline(w, a.points);
    w.endObject();
  }
  w.endArray().key("cells").beginArray();
  for (const auto& c : d.cells) {
    w.beginObject().key("edge").beginArray().value(int64_t(c.edge.hex)).value(c.edge.edge).endArray();
    w.key("x").value(c.p.x).key("y").value(c.p.y).endObject();
  }
  w.endArray();
}

}  // namespace

std::string diagramJson(const SheetDiagram& d) {
  io::JsonWriter w;
  w.beginObject().key("sheet").value(d.sheet).key("topology").value(d.topology).key("method").value(d.method);
  w.key("local").value(d.local).key("note").value(d.note).key("radius").value(d.radius).key("euler").value(d.euler);
  w.key("openedHex");
  if (d.openedHex >= 0)
    w.value(int64_t(d.openedHex));
  else
    w.raw("null");
  writeCrossings(w, d);
  writeBoundary(w, d);
  writeChords(w, d);
  writeLoopsArcsCells(w, d);
  w.endObject();
  return w.str();
}

}  // namespace hexdual
