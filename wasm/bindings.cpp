// Embind bindings: a thin layer over core. No exception crosses into JS: every fallible call
// catches, stores the message (lastError) and returns null/false; wasm/index.js turns that into
// a JS Error. This is leak-free where throwing through Embind is not (see ../shared/TOOLCHAIN.md).
#include <emscripten/bind.h>
#include <malloc.h>

#include <memory>
#include <string>

#include "complex/builders.hpp"
#include "dual/dual.hpp"
#include "io/io.hpp"
#include "io/json.hpp"
#include "flips/decompositions.hpp"
#include "flips/fourcube.hpp"
#include "layout/render_buffers.hpp"
#include "layout/sheet_diagram.hpp"
#include "ops/oplog.hpp"

using namespace emscripten;
using namespace hexdual;

namespace {

std::string g_lastError;

template <class F>
auto guarded(F&& f, decltype(f()) onError) -> decltype(f()) {
  g_lastError.clear();
  try {
    return f();
  } catch (const std::exception& e) {
    g_lastError = e.what();
  }
  return onError;
}

class WasmMesh {
 public:
  explicit WasmMesh(Complex cx) : cx_(std::move(cx)) {}

  static WasmMesh* grid(int a, int b, int c) {
    return guarded([&] { return new WasmMesh(makeGrid(a, b, c)); }, nullptr);
  }
  // The closed boundary of the 4-cube: the complex the stored flip decompositions are written for.
  static WasmMesh* fourCube() {
    return guarded([&] { return new WasmMesh(makeFourCubeBoundary()); }, nullptr);
  }
  static WasmMesh* ring(int around, int radial, int axial) {
    return guarded([&] { return new WasmMesh(makeRing(around, radial, axial)); }, nullptr);
  }
  // `bytes` arrives from a Uint8Array (Embind copies it into the string).
  static WasmMesh* load(const std::string& bytes, const std::string& name) {
    return guarded([&] { return new WasmMesh(io::readMesh(bytes, name)); }, nullptr);
  }

  std::string infoJson() { return guarded([&] { return io::infoJson(cx_, dual()); }, std::string()); }
  std::string save(const std::string& format, bool binary) {
    return guarded(
        [&] {
          io::Format f = format == "vtk" ? io::Format::Vtk : format == "mesh" ? io::Format::Medit
                         : format == "hxd" ? io::Format::Native
                                           : throw Error("unknown format '" + format + "' (vtk, mesh or hxd)");
          return io::writeMesh(cx_, f, binary);
        },
        std::string());
  }
  // The sheet diagram of a sheet as JSON (the same as `hexdual sheets --json`).
  std::string sheetDiagramJson(int id) {
    return guarded([&] { return diagramJson(layoutSheet(cx_, dual(), id)); }, std::string());
  }
  // A local diagram: the sheet within `rings` rings of the given hexes.
  std::string localSheetDiagramJson(int id, const std::vector<int>& hexes, int rings) {
    return guarded([&] { return diagramJson(layoutLocal(cx_, dual(), id, hexes, rings)); }, std::string());
  }
  // Applies one operation-log step ("pillow h13f5"); returns its inverse step ("" on error).
  std::string applyStep(const std::string& step) {
    return guarded(
        [&] {
          OpResult r = hexdual::applyStep(cx_, step);
          return r.inverse ? formatOpStep(*r.inverse) : std::string("-");
        },
        std::string());
  }
  // Extracts the dual (if stale) and returns the number of sheets: for benchmarks.
  int numSheets() { return guarded([&] { return int(dual().sheets.size()); }, -1); }
  int numChords() { return guarded([&] { return int(dual().chords.size()); }, -1); }
  double memoryBytes() const { return double(cx_.memoryBytes()); }
  bool validate() {
    return guarded(
        [&] {
          cx_.validate();
          return true;
        },
        false);
  }

  // Hex ids of a sheet or chord, one per slot (a hex appears twice on a self-intersecting one).
  val sheetHexes(int id) { return slotsToArray(id, true); }
  val chordHexes(int id) { return slotsToArray(id, false); }

  // Render buffers; the getters return views that wasm/index.js copies at once.
  bool buildRender(double shrink) {
    return guarded(
        [&] {
          rb_ = buildRenderBuffers(cx_, shrink);
          return true;
        },
        false);
  }
  val positions() const { return val(typed_memory_view(rb_.positions.size(), rb_.positions.data())); }
  val normals() const { return val(typed_memory_view(rb_.normals.size(), rb_.normals.data())); }
  val indices() const { return val(typed_memory_view(rb_.indices.size(), rb_.indices.data())); }
  val triangleHex() const { return val(typed_memory_view(rb_.triangleHex.size(), rb_.triangleHex.data())); }

 private:
  const Dual& dual() {
    if (!dual_ || dualRevision_ != cx_.revision()) {
      dual_ = std::make_unique<Dual>(extractDual(cx_));
      dualRevision_ = cx_.revision();
    }
    return *dual_;
  }
  val slotsToArray(int id, bool sheet) {
    const Dual& d = dual();
    size_t n = sheet ? d.sheets.size() : d.chords.size();
    if (id < 0 || size_t(id) >= n) {
      g_lastError = std::string(sheet ? "sheet " : "chord ") + std::to_string(id) + " does not exist";
      return val::null();
    }
    const auto& slots = sheet ? d.sheets[size_t(id)].slots : d.chords[size_t(id)].slots;
    scratch_.clear();
    for (const Slot& s : slots) scratch_.push_back(s.hex);
    return val::global("Int32Array").new_(val(typed_memory_view(scratch_.size(), scratch_.data())));
  }

  Complex cx_;
  std::unique_ptr<Dual> dual_;
  uint64_t dualRevision_ = ~uint64_t(0);
  RenderBuffers rb_;
  std::vector<int32_t> scratch_;
};

std::string lastError() { return g_lastError; }

// The flip classes and their stored decompositions, as JSON (the same facts as `hexdual flip list`).
std::string flipsJson() {
  return guarded(
      [] {
        io::JsonWriter w;
        w.beginArray();
        for (const FlipClass& fc : enumerateFlipClasses()) {
          w.beginObject().key("name").value(fc.name).key("inverse").value(fc.inverse).key("geometric").value(fc.geometric);
          w.key("description").value(fc.description).key("before").beginArray();
          for (HexId h : facetsOf(fc.before)) w.value(int64_t(h));
          w.endArray().key("steps");
          const StoredDecomposition* found = nullptr;
          for (const auto& d : storedDecompositions())
            if (d.problem == fc.name && d.found) found = &d;
          if (found) {
            w.beginArray();
            for (const auto& s : found->steps) w.value(formatOpStep(s));
            w.endArray();
          } else {
            w.raw("null");
          }
          w.endObject();
        }
        w.endArray();
        return w.str();
      },
      std::string());
}
// Bytes allocated by malloc right now: leak tests compare it before and after many calls.
double heapUsed() { return double(mallinfo().uordblks); }

}  // namespace

EMSCRIPTEN_BINDINGS(hexdual) {
  register_vector<int>("IntVector");
  function("lastError", &lastError);
  function("heapUsed", &heapUsed);
  function("flipsJson", &flipsJson);
  class_<WasmMesh>("WasmMesh")
      .class_function("grid", &WasmMesh::grid, allow_raw_pointers())
      .class_function("ring", &WasmMesh::ring, allow_raw_pointers())
      .class_function("fourCube", &WasmMesh::fourCube, allow_raw_pointers())
      .class_function("load", &WasmMesh::load, allow_raw_pointers())
      .function("infoJson", &WasmMesh::infoJson)
      .function("save", &WasmMesh::save)
      .function("validate", &WasmMesh::validate)
      .function("numSheets", &WasmMesh::numSheets)
      .function("sheetDiagramJson", &WasmMesh::sheetDiagramJson)
      .function("localSheetDiagramJson", &WasmMesh::localSheetDiagramJson)
      .function("applyStep", &WasmMesh::applyStep)
      .function("numChords", &WasmMesh::numChords)
      .function("memoryBytes", &WasmMesh::memoryBytes)
      .function("sheetHexes", &WasmMesh::sheetHexes)
      .function("chordHexes", &WasmMesh::chordHexes)
      .function("buildRender", &WasmMesh::buildRender)
      .function("positions", &WasmMesh::positions)
      .function("normals", &WasmMesh::normals)
      .function("indices", &WasmMesh::indices)
      .function("triangleHex", &WasmMesh::triangleHex);
}
