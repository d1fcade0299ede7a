// View data for the explorer (web/): render buffers with per-triangle hex and local face, edge
// lines, dual points, the dual overlay, quality, and per-hex sheet/chord ids. Its own
// EMSCRIPTEN_BINDINGS block; it reads the mesh through the addresses WasmMesh hands out
// (complexAddress/dualAddress: same module, same heap) so bindings.cpp stays the package's.
#include <emscripten/bind.h>

#include <string>

#include "dual/dual.hpp"
#include "layout/dual_points.hpp"
#include "layout/quality.hpp"
#include "layout/render_buffers.hpp"
#include "ops/candidates.hpp"
#include "ops/op_table.hpp"
#include "ops/oplog.hpp"

using namespace emscripten;
using namespace hexdual;

namespace {

template <class T>
val copyOut(const char* type, const std::vector<T>& v) {
  return val::global(type).new_(val(typed_memory_view(v.size(), v.data())));
}

const Complex& complexAt(double address) { return *reinterpret_cast<const Complex*>(uintptr_t(address)); }
const Dual& dualAt(double address) { return *reinterpret_cast<const Dual*>(uintptr_t(address)); }

// Every fallible call returns an object with `error` set instead of throwing (see bindings.cpp).
template <class F>
val guardedObject(F&& f) {
  try {
    return f();
  } catch (const std::exception& e) {
    val out = val::object();
    out.set("error", std::string(e.what()));
    return out;
  }
}

val viewRenderBuffers(double complexAddress, double shrink, bool edges) {
  return guardedObject([&] {
    RenderBuffers rb = buildRenderBuffers(complexAt(complexAddress), shrink, edges);
    val out = val::object();
    out.set("positions", copyOut("Float32Array", rb.positions));
    out.set("normals", copyOut("Float32Array", rb.normals));
    out.set("indices", copyOut("Uint32Array", rb.indices));
    out.set("triangleHex", copyOut("Int32Array", rb.triangleHex));
    out.set("triangleFace", copyOut("Uint8Array", rb.triangleFace));
    if (edges) {
      out.set("edgePositions", copyOut("Float32Array", rb.edgePositions));
      out.set("edgeHex", copyOut("Int32Array", rb.edgeHex));
      out.set("edgeLocal", copyOut("Uint8Array", rb.edgeLocal));
    }
    return out;
  });
}

val viewDualPoints(double complexAddress) {
  return guardedObject([&] {
    std::vector<Vec3> dp = dualPoints(complexAt(complexAddress));
    std::vector<float> flat;
    flat.reserve(dp.size() * 3);
    for (Vec3 p : dp) flat.insert(flat.end(), {float(p.x), float(p.y), float(p.z)});
    val out = val::object();
    out.set("points", copyOut("Float32Array", flat));
    return out;
  });
}

val viewDualOverlay(double complexAddress, double dualAddress) {
  return guardedObject([&] {
    DualOverlay o = buildDualOverlay(complexAt(complexAddress), dualAt(dualAddress));
    val out = val::object();
    out.set("sheetPositions", copyOut("Float32Array", o.sheetPositions));
    out.set("sheetIndices", copyOut("Uint32Array", o.sheetIndices));
    out.set("sheetTriangle", copyOut("Int32Array", o.sheetTriangle));
    out.set("chordPositions", copyOut("Float32Array", o.chordPositions));
    out.set("chordSegment", copyOut("Int32Array", o.chordSegment));
    out.set("dualVertices", copyOut("Float32Array", o.dualVertices));
    out.set("dualVertexHex", copyOut("Int32Array", o.dualVertexHex));
    return out;
  });
}

val viewQuality(double complexAddress) {
  return guardedObject([&] {
    QualityReport q = measureQuality(complexAt(complexAddress));
    val out = val::object();
    out.set("scaledJacobian", copyOut("Float32Array", q.scaledJacobian));
    out.set("inverted", copyOut("Int32Array", q.inverted));
    out.set("min", q.min);
    out.set("max", q.max);
    return out;
  });
}

// Sheet and chord ids per hex and axis (3 + 3 per hex id, -1 for tombstones).
val viewHexDual(double dualAddress) {
  return guardedObject([&] {
    const Dual& d = dualAt(dualAddress);
    std::vector<int32_t> sheets, chords;
    sheets.reserve(d.sheetOf.size() * 3);
    chords.reserve(d.chordOf.size() * 3);
    for (const auto& s : d.sheetOf) sheets.insert(sheets.end(), s.begin(), s.end());
    for (const auto& c : d.chordOf) chords.insert(chords.end(), c.begin(), c.end());
    val out = val::object();
    out.set("sheetOf", copyOut("Int32Array", sheets));
    out.set("chordOf", copyOut("Int32Array", chords));
    return out;
  });
}

// Local numbering tables: corners of each face (in buffer order) and of each edge.
val viewTables() {
  std::vector<int32_t> face, edge;
  for (const auto& f : tables::kFaceCorners) face.insert(face.end(), f.begin(), f.end());
  for (const auto& e : tables::kEdgeCorners) edge.insert(edge.end(), e.begin(), e.end());
  val out = val::object();
  out.set("faceCorners", copyOut("Int32Array", face));
  out.set("edgeCorners", copyOut("Int32Array", edge));
  return out;
}

// Every step of `op` that applies anywhere (ops/candidates.hpp); the explorer's palette uses it
// until the package offers candidates near a selection.
val viewCandidates(double complexAddress, const std::string& op) {
  return guardedObject([&] {
    val out = val::object();
    val steps = val::array();
    const OpInfo* info = findOp(op);
    if (!info) throw Error("unknown operation '" + op + "'");
    for (const OpStep& s : candidates(complexAt(complexAddress), info->kind)) steps.call<void>("push", formatOpStep(s));
    out.set("steps", steps);
    return out;
  });
}

}  // namespace

EMSCRIPTEN_BINDINGS(hexdual_view) {
  function("viewRenderBuffers", &viewRenderBuffers);
  function("viewDualPoints", &viewDualPoints);
  function("viewDualOverlay", &viewDualOverlay);
  function("viewQuality", &viewQuality);
  function("viewHexDual", &viewHexDual);
  function("viewTables", &viewTables);
  function("viewCandidates", &viewCandidates);
}
