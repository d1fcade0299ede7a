// Embind registration of the package's module (wasm/index.js wraps it; index.d.ts types it). The
// bindings are grouped by what they bind: bindings_complex.cpp, bindings_io.cpp,
// bindings_dual.cpp, bindings_diagrams.cpp and bindings_operations.cpp define WasmMesh's methods
// (wasm_mesh.hpp) and the module's functions; bindings_common.hpp holds the error channel (no
// exception crosses into JS); render and picking bindings live in bindings_view.cpp.
#include <emscripten/bind.h>
#include <malloc.h>

#include <string>

#include "bindings_common.hpp"
#include "wasm_mesh.hpp"

using namespace emscripten;
using namespace hexdual;
using namespace hexdual::wasm;

namespace {

std::string lastError() { return g_lastError; }
std::string lastErrorCode() { return g_lastErrorCode; }

int isomorphicMeshes(WasmMesh& a, WasmMesh& b, bool boundaryFree) { return a.isomorphicTo(b, boundaryFree); }

// Bytes allocated by malloc right now: leak tests compare it before and after many calls.
double heapUsed() { return double(mallinfo().uordblks); }

}  // namespace

EMSCRIPTEN_BINDINGS(hexdual) {
  register_vector<int>("IntVector");
  function("lastError", &lastError);
  function("lastErrorCode", &lastErrorCode);
  function("heapUsed", &heapUsed);
  function("flipsJson", &flipsJson);
  function("isomorphic", &isomorphicMeshes);
  function("diagramToSvg", &diagramToSvg);
  class_<WasmMesh>("WasmMesh")
      .class_function("grid", &WasmMesh::grid, allow_raw_pointers())
      .class_function("ring", &WasmMesh::ring, allow_raw_pointers())
      .class_function("fourCube", &WasmMesh::fourCube, allow_raw_pointers())
      .class_function("load", &WasmMesh::load, allow_raw_pointers())
      .function("infoJson", &WasmMesh::infoJson)
      .function("countsJson", &WasmMesh::countsJson)
      .function("save", &WasmMesh::save)
      .function("saveBytes", &WasmMesh::saveBytes)
      .function("validate", &WasmMesh::validate)
      .function("numSheets", &WasmMesh::numSheets)
      .function("sheetDiagramJson", &WasmMesh::sheetDiagramJson)
      .function("localSheetDiagramJson", &WasmMesh::localSheetDiagramJson)
      .function("sheetDiagram", &WasmMesh::sheetDiagram)
      .function("applyStep", &WasmMesh::applyStep)
      .function("applyReport", &WasmMesh::applyReport)
      .function("applyLog", &WasmMesh::applyLog)
      .function("undo", &WasmMesh::undo)
      .function("redo", &WasmMesh::redo)
      .function("undoDepth", &WasmMesh::undoDepth)
      .function("redoDepth", &WasmMesh::redoDepth)
      .function("log", &WasmMesh::log)
      .function("candidates", &WasmMesh::candidatesJson)
      .function("flip", &WasmMesh::flip)
      .function("canonicalHash", &WasmMesh::canonicalHash)
      .function("hexCenters", &WasmMesh::hexCenters)
      .function("numChords", &WasmMesh::numChords)
      .function("memoryBytes", &WasmMesh::memoryBytes)
      .function("sheetHexes", &WasmMesh::sheetHexes)
      .function("chordHexes", &WasmMesh::chordHexes)
      .function("buildRender", &WasmMesh::buildRender)
      .function("positions", &WasmMesh::positions)
      .function("normals", &WasmMesh::normals)
      .function("indices", &WasmMesh::indices)
      .function("triangleHex", &WasmMesh::triangleHex)
      .function("complexAddress", &WasmMesh::complexAddress)
      .function("setSmoothing", &WasmMesh::setSmoothing)
      .function("smoothing", &WasmMesh::smoothing)
      .function("dualAddress", &WasmMesh::dualAddress)
      .function("trackerAddress", &WasmMesh::trackerAddress);
}
