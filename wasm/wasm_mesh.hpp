// The package's Mesh: a complex with its dual (kept current by a DualTracker so that sheet and chord
// ids survive operations), its undo/redo history and its render buffers. Its methods are defined
// by what they bind: bindings_complex.cpp (building, comparing, validating, rendering),
// bindings_io.cpp (reading and writing files), bindings_dual.cpp (sheets and chords),
// bindings_diagrams.cpp (sheet diagrams), bindings_operations.cpp (steps, logs, undo/redo, flips).
// bindings.cpp registers them all with Embind.
#pragma once
#include <emscripten/bind.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "complex/complex.hpp"
#include "dual/dual.hpp"
#include "dual/dual_tracker.hpp"
#include "io/io.hpp"
#include "layout/render_buffers.hpp"
#include "ops/oplog.hpp"
#include "ops/report.hpp"

namespace hexdual::wasm {

using emscripten::val;

// One entry of the undo list: the core's step report, or a flip applied directly (no log step).
struct StepRecord {
  StepReport report;
  DualIdMemo ids;  // what undo needs to give the dual its ids back
  std::string flipName;  // non-empty for a direct flip
  std::vector<int> flipHexes;
  bool loggable() const { return flipName.empty(); }
};

class WasmMesh {
 public:
  explicit WasmMesh(Complex cx) : cx_(std::move(cx)) {}

  // ---- complex (bindings_complex.cpp) ----
  static WasmMesh* grid(int a, int b, int c);
  // The closed boundary of the 4-cube: the complex the stored flip decompositions are written for.
  static WasmMesh* fourCube();
  static WasmMesh* ring(int around, int radial, int axial);
  // boundaryFree: any isomorphism (vertex ids free), else the boundary's vertex ids kept.
  std::string canonicalHash(bool boundaryFree);
  // 1 when isomorphic, 0 when not, -1 on error.
  int isomorphicTo(const WasmMesh& other, bool boundaryFree);
  // Centroid of every hex, 3 numbers per hex id (NaN for removed ids).
  val hexCenters();
  double memoryBytes() const { return double(cx_.memoryBytes()); }
  bool validate();
  // Render buffers; the getters return views that wasm/index.js copies at once.
  bool buildRender(double shrink);
  // For wasm/bindings_view.cpp (same module): where the complex and its current dual live.
  double complexAddress() const { return double(uintptr_t(&cx_)); }
  // Whether steps place their new and moved vertices by the local smoothing (StepOptions).
  void setSmoothing(bool on) { smooth_ = on; }
  bool smoothing() const { return smooth_; }
  // Steps are smoothed, or (smoothing off) only measured, like the CLI's apply and --no-smooth.
  StepOptions stepOptions() const { return {smooth_ ? StepGeometry::Smooth : StepGeometry::Measure}; }
  double dualAddress();
  // For wasm/bindings_sheetops.cpp: the tracker (a preview copies it, to report the ids a step would give).
  double trackerAddress();
  val positions() const { return val(emscripten::typed_memory_view(rb_.positions.size(), rb_.positions.data())); }
  val normals() const { return val(emscripten::typed_memory_view(rb_.normals.size(), rb_.normals.data())); }
  val indices() const { return val(emscripten::typed_memory_view(rb_.indices.size(), rb_.indices.data())); }
  val triangleHex() const { return val(emscripten::typed_memory_view(rb_.triangleHex.size(), rb_.triangleHex.data())); }

  // ---- files (bindings_io.cpp) ----
  // `bytes` arrives from a Uint8Array (Embind copies it into the string).
  // hexesOnly: read the hex part of a file that also has tets/prisms/pyramids (io::ReadOptions).
  static WasmMesh* load(const std::string& bytes, const std::string& name, bool hexesOnly);
  std::string infoJson();
  // V, E, F, H and boundary quads in O(1): E from the Euler characteristic V - E + F - H, counted
  // once (one pass over the edges) and kept by every operation (each step's dE is derived from it;
  // the sheet operations refuse a topology-change, docs/operations.md).
  std::string countsJson();
  std::string save(const std::string& format, bool binary);
  // The file's bytes as a Uint8Array (binary VTK included); null on error.
  val saveBytes(const std::string& format, bool binary);

  // ---- dual (bindings_dual.cpp) ----
  // Extracts the dual (if stale) and returns the number of sheet and chord ids: for benchmarks.
  // Live sheets and chords (ids retired by operations are not counted; ids need not be dense).
  int numSheets();
  int numChords();
  // Hex ids of a sheet or chord, one per slot (a hex appears twice on a self-intersecting one).
  val sheetHexes(int id) { return slotsToArray(id, true); }
  val chordHexes(int id) { return slotsToArray(id, false); }

  // ---- sheet diagrams (bindings_diagrams.cpp) ----
  // The sheet diagram of a sheet as JSON (the same as `hexdual sheets --json`).
  std::string sheetDiagramJson(int id);
  // A local diagram: the sheet within `rings` rings of the given hexes.
  std::string localSheetDiagramJson(int id, const std::vector<int>& hexes, int rings);
  // The same diagram as typed arrays; `local` selects layoutLocal around `hexes`.
  val sheetDiagram(int id, bool local, const std::vector<int>& hexes, int rings);

  // ---- operations (bindings_operations.cpp) ----
  // Applies one operation-log step ("pillow h13f5"); returns its inverse step ("" on error).
  std::string applyStep(const std::string& step);
  // Applies one step and returns its report as JSON ("" on error; the mesh is then unchanged).
  std::string applyReport(const std::string& step);
  // Applies the steps of a log (text or URL form), at most stopAt of them (-1: all); all or
  // nothing: on an error the steps already applied by this call are undone. JSON array of reports.
  std::string applyLog(const std::string& logText, int stopAt);
  // Undoes the last applied step exactly (the engine's edit journal); "" when there is none.
  std::string undo();
  // Re-applies the last undone step; its report as JSON.
  std::string redo();
  int undoDepth() const { return int(history_.size()); }
  int redoDepth() const { return int(redo_.size()); }
  // The applied steps as an operation log ("v1;..."), or its URL form.
  std::string log(bool url);
  // Steps of `op` (or of every operation when op is empty) that apply, as JSON strings; with
  // nearKind "hex", "quad" or "edge", only those whose arguments name that entity.
  std::string candidatesJson(const std::string& op, const std::string& nearKind, int hex, int local);
  // A cubical flip on the named hexes (like `hexdual flip NAME --at ...`); JSON array of reports
  // (one per atomic step with viaAtomic, else one).
  std::string flip(const std::string& name, const std::vector<int>& hexes, bool viaAtomic);

 private:
  // dual (bindings_dual.cpp): the tracker, made on first use; the dual settles the chord lists
  // changed since the last read; a sheet id that an operation retired is an error.
  DualTracker& tracker();
  const Dual& dual() { return tracker().dual(); }
  int liveSheet(int id);
  val slotsToArray(int id, bool sheet);
  // operations (bindings_operations.cpp)
  std::string record(StepRecord s);
  std::string apply(const OpStep& step);
  std::string applyFlip(const std::string& name, const std::vector<int>& hexes, bool viaAtomic);
  void undoOne();
  void requireNear(const std::string& kind, int hex, int local) const;
  bool mentions(const OpStep& step, const std::string& kind, int hex, int local) const;

  std::optional<io::ReadReport> file_;  // what the reader found, for info() of a loaded file
  std::optional<int64_t> euler_;        // V - E + F - H, counted at the first countsJson()
  Complex cx_;
  std::unique_ptr<DualTracker> tracker_;
  std::vector<StepRecord> history_, redo_;
  bool smooth_ = true;
  RenderBuffers rb_;
  std::vector<int32_t> scratch_;
};

// Free functions of the module (registered in bindings.cpp).
std::string flipsJson();                // bindings_operations.cpp
std::string diagramToSvg(val diagram);  // bindings_diagrams.cpp

}  // namespace hexdual::wasm
