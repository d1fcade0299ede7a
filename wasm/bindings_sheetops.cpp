// The sheet operations' package calls that are not steps (steps go through WasmMesh.applyReport
// like every other): the preview of a step and the selection through a picked edge or quad. Its
// own EMSCRIPTEN_BINDINGS block; it reads the mesh through the addresses WasmMesh hands out
// (complexAddress, dualAddress, trackerAddress: same module, same heap), like bindings_view.cpp.
// Every call returns JSON: the result, or {"error","code"} (no exception crosses into JS).
#include <emscripten/bind.h>

#include <string>

#include "addressed.hpp"  // complexAt
#include "dual/dual_tracker.hpp"
#include "io/json.hpp"
#include "io/preview_json.hpp"
#include "ops/oplog.hpp"
#include "ops/preview.hpp"
#include "ops/selection.hpp"

using namespace emscripten;
using namespace hexdual;

namespace {

using wasm::complexAt;

template <class F>
std::string guardedJson(const char* code, F&& f) {
  try {
    return f();
  } catch (const std::exception& e) {
    const std::string message = e.what();
    io::JsonWriter w;
    w.beginObject().key("error").value(message).key("code").value(message.rfind("oplog:", 0) == 0 ? "PARSE" : code).endObject();
    return w.str();
  }
}

// What `step` would change, or its refusal with the rule; the mesh and its dual unchanged.
std::string sheetopsPreview(double complexAddress, double trackerAddress, const std::string& step, bool smooth) {
  return guardedJson("PRECONDITION", [&] {
    const OpStep s = parseOpStep(step);
    const auto& tracker = *reinterpret_cast<const DualTracker*>(uintptr_t(trackerAddress));
    const StepOptions options{smooth ? StepGeometry::Smooth : StepGeometry::Measure};  // as WasmMesh::stepOptions
    return io::previewJson(previewStep(complexAt(complexAddress), tracker, s, options), s);
  });
}

// The sheet through edge `local` of `hex` (kind "edge") or the chord through its face (kind "face").
std::string sheetopsSelect(double complexAddress, double dualAddress, int hex, const std::string& kind, int local) {
  return guardedJson("PRECONDITION", [&] {
    const Complex& cx = complexAt(complexAddress);
    const Dual& dual = *reinterpret_cast<const Dual*>(uintptr_t(dualAddress));
    if (kind == "edge") return io::selectionJson(selectSheet(cx, dual, EdgeRef{hex, local}));
    if (kind == "face") return io::selectionJson(selectChord(cx, dual, QuadSide{hex, local}));
    throw Error("select: pick an edge ({ hex, edge }) or a quad ({ hex, face })");
  });
}

}  // namespace

EMSCRIPTEN_BINDINGS(hexdual_sheetops) {
  function("sheetopsPreview", &sheetopsPreview);
  function("sheetopsSelect", &sheetopsSelect);
}
