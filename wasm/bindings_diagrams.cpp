// Bindings of sheet diagrams: a sheet's diagram (whole or local) as JSON or as typed arrays, and
// the SVG drawing of a diagram handed back from JavaScript.
#include "bindings_common.hpp"
#include "io/diagram_json.hpp"
#include "io/diagram_svg.hpp"
#include "layout/sheet_diagram.hpp"
#include "wasm_mesh.hpp"

namespace hexdual::wasm {

using emscripten::val;
using emscripten::vecFromJSArray;

namespace {

// The diagram as plain numbers in typed arrays (no JSON): see the SheetDiagram type in index.d.ts.
val diagramArrays(const SheetDiagram& d) {
  std::vector<int32_t> crossHex, crossChords, bHex, chId, chOther, chHexes, cellHex, quads, chPiece;
  std::vector<int8_t> crossAxis, bFace, cellEdge;
  std::vector<uint8_t> crossOutside, chClosed;
  std::vector<double> crossXY, bXY, chXY, loopXY, cellXY;
  std::vector<uint32_t> chOffsets{0}, chHexOffsets{0}, loopOffsets{0};
  for (const auto& c : d.crossings) {
    crossHex.push_back(c.hex);
    crossAxis.push_back(int8_t(c.axis));
    crossXY.insert(crossXY.end(), {c.p.x, c.p.y});
    crossChords.insert(crossChords.end(), {c.chords[0], c.chords[1]});
    crossOutside.push_back(c.outside);
  }
  for (const auto& b : d.boundary) {
    bHex.push_back(b.hex);
    bFace.push_back(int8_t(b.face));
    bXY.insert(bXY.end(), {b.p.x, b.p.y});
  }
  for (const auto& c : d.chords) {
    chId.push_back(c.chord);
    chOther.push_back(c.otherSheet);
    chClosed.push_back(c.closed);
    chPiece.push_back(c.piece);
    for (Point2 p : c.points) chXY.insert(chXY.end(), {p.x, p.y});
    chOffsets.push_back(uint32_t(chXY.size() / 2));
    chHexes.insert(chHexes.end(), c.hexes.begin(), c.hexes.end());
    chHexOffsets.push_back(uint32_t(chHexes.size()));
  }
  for (const auto& loop : d.loops) {
    for (Point2 p : loop) loopXY.insert(loopXY.end(), {p.x, p.y});
    loopOffsets.push_back(uint32_t(loopXY.size() / 2));
  }
  for (const auto& c : d.cells) {
    cellHex.push_back(c.edge.hex);
    cellEdge.push_back(int8_t(c.edge.edge));
    cellXY.insert(cellXY.end(), {c.p.x, c.p.y});
  }
  for (const auto& q : d.quads) quads.insert(quads.end(), q.begin(), q.end());
  // Sides of a cut-open (polygon) sheet: labels, seam pairs and directions.
  std::vector<int32_t> arcPair;
  std::vector<int8_t> arcSign;
  std::vector<uint32_t> arcOffsets{0};
  std::vector<double> arcXY;
  val arcLabel = val::array();
  for (const auto& a : d.arcs) {
    arcLabel.call<void>("push", val(a.label));
    arcPair.push_back(a.pair);
    arcSign.push_back(int8_t(a.sign));
    for (Point2 p : a.points) arcXY.insert(arcXY.end(), {p.x, p.y});
    arcOffsets.push_back(uint32_t(arcXY.size() / 2));
  }

  val o = fields({{"sheet", val(d.sheet)},
                  {"topology", val(d.topology)},
                  {"method", val(d.method)},
                  {"local", val(d.local)},
                  {"note", val(d.note)},
                  {"radius", val(d.radius)},
                  {"euler", val(double(d.euler))},
                  {"openedHex", d.openedHex >= 0 ? val(d.openedHex) : val::null()}});
  o.set("arcs", fields({{"label", arcLabel},
                        {"pair", copyOut("Int32Array", arcPair)},
                        {"sign", copyOut("Int8Array", arcSign)},
                        {"offsets", copyOut("Uint32Array", arcOffsets)},
                        {"xy", copyOut("Float64Array", arcXY)}}));
  o.set("crossings", fields({{"hex", copyOut("Int32Array", crossHex)},
                             {"axis", copyOut("Int8Array", crossAxis)},
                             {"xy", copyOut("Float64Array", crossXY)},
                             {"chords", copyOut("Int32Array", crossChords)},
                             {"outside", copyOut("Uint8Array", crossOutside)}}));
  o.set("boundary", fields({{"hex", copyOut("Int32Array", bHex)},
                            {"face", copyOut("Int8Array", bFace)},
                            {"xy", copyOut("Float64Array", bXY)}}));
  o.set("chords", fields({{"id", copyOut("Int32Array", chId)},
                          {"otherSheet", copyOut("Int32Array", chOther)},
                          {"closed", copyOut("Uint8Array", chClosed)},
                          {"piece", copyOut("Int32Array", chPiece)},
                          {"offsets", copyOut("Uint32Array", chOffsets)},
                          {"xy", copyOut("Float64Array", chXY)},
                          {"hexOffsets", copyOut("Uint32Array", chHexOffsets)},
                          {"hexes", copyOut("Int32Array", chHexes)}}));
  o.set("loops", fields({{"offsets", copyOut("Uint32Array", loopOffsets)}, {"xy", copyOut("Float64Array", loopXY)}}));
  o.set("cells", fields({{"hex", copyOut("Int32Array", cellHex)},
                         {"edge", copyOut("Int8Array", cellEdge)},
                         {"xy", copyOut("Float64Array", cellXY)}}));
  o.set("quads", copyOut("Int32Array", quads));
  return o;
}

Point2 pointAt(const std::vector<double>& xy, size_t i) { return {xy[2 * i], xy[2 * i + 1]}; }

// The inverse of diagramArrays for the fields the SVG drawing reads (core's diagramSvg draws it).
std::string svgFromArrays(val d) {
  auto nums = [](val a) { return vecFromJSArray<double>(a); };
  SheetDiagram s;
  s.sheet = d["sheet"].as<int>();
  s.topology = d["topology"].as<std::string>();
  s.method = d["method"].as<std::string>();
  s.local = d["local"].as<bool>();
  if (d["note"].isString()) s.note = d["note"].as<std::string>();
  s.openedHex = d["openedHex"].isNull() ? -1 : d["openedHex"].as<int>();
  std::vector<double> loopOff = nums(d["loops"]["offsets"]), loopXY = nums(d["loops"]["xy"]);
  for (size_t k = 0; k + 1 < loopOff.size(); ++k) {
    std::vector<Point2> loop;
    for (size_t i = size_t(loopOff[k]); i < size_t(loopOff[k + 1]); ++i) loop.push_back(pointAt(loopXY, i));
    s.loops.push_back(std::move(loop));
  }
  std::vector<double> chId = nums(d["chords"]["id"]), chOther = nums(d["chords"]["otherSheet"]),
                      chOff = nums(d["chords"]["offsets"]), chXY = nums(d["chords"]["xy"]),
                      chPiece = nums(d["chords"]["piece"]);
  for (size_t k = 0; k < chId.size() && k + 1 < chOff.size(); ++k) {
    SheetDiagram::ChordLine c{int(chId[k]), int(chOther[k]), false, {}, {}, k < chPiece.size() ? int(chPiece[k]) : 0};
    for (size_t i = size_t(chOff[k]); i < size_t(chOff[k + 1]); ++i) c.points.push_back(pointAt(chXY, i));
    s.chords.push_back(std::move(c));
  }
  std::vector<double> bXY = nums(d["boundary"]["xy"]);
  for (size_t i = 0; i < bXY.size() / 2; ++i) s.boundary.push_back({-1, 0, pointAt(bXY, i)});
  std::vector<double> cHex = nums(d["crossings"]["hex"]), cXY = nums(d["crossings"]["xy"]),
                      cOut = nums(d["crossings"]["outside"]);
  for (size_t i = 0; i < cHex.size() && 2 * i + 1 < cXY.size(); ++i)
    s.crossings.push_back({HexId(cHex[i]), 0, pointAt(cXY, i), {-1, -1}, i < cOut.size() && cOut[i] != 0});
  if (!d["arcs"].isUndefined() && !d["arcs"].isNull()) {
    std::vector<double> aPair = nums(d["arcs"]["pair"]), aSign = nums(d["arcs"]["sign"]),
                        aOff = nums(d["arcs"]["offsets"]), aXY = nums(d["arcs"]["xy"]);
    std::vector<std::string> aLabel = vecFromJSArray<std::string>(d["arcs"]["label"]);
    for (size_t k = 0; k < aLabel.size() && k + 1 < aOff.size(); ++k) {
      SheetDiagram::Arc a{aLabel[k], int(aPair[k]), int(aSign[k]), {}};
      for (size_t i = size_t(aOff[k]); i < size_t(aOff[k + 1]); ++i) a.points.push_back(pointAt(aXY, i));
      s.arcs.push_back(std::move(a));
    }
  }
  return diagramSvg(s);
}

}  // namespace

std::string WasmMesh::sheetDiagramJson(int id) {
  return guarded(
      "PRECONDITION", [&] { return diagramJson(layoutSheet(cx_, dual(), liveSheet(id))); }, std::string());
}

std::string WasmMesh::localSheetDiagramJson(int id, const std::vector<int>& hexes, int rings) {
  return guarded(
      "PRECONDITION", [&] { return diagramJson(layoutLocal(cx_, dual(), liveSheet(id), hexes, rings)); },
      std::string());
}

val WasmMesh::sheetDiagram(int id, bool local, const std::vector<int>& hexes, int rings) {
  SheetDiagram d;
  bool ok = guarded(
      "PRECONDITION",
      [&] {
        d = local ? layoutLocal(cx_, dual(), liveSheet(id), hexes, rings) : layoutSheet(cx_, dual(), liveSheet(id));
        return true;
      },
      false);
  return ok ? diagramArrays(d) : val::null();
}

std::string diagramToSvg(val d) {
  return guarded(
      "PRECONDITION", [&] { return svgFromArrays(d); }, std::string());
}

}  // namespace hexdual::wasm
