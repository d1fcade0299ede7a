// Embind bindings: a thin layer over core. No exception crosses into JS: every fallible call
// catches, stores the message and an error code (lastError, lastErrorCode) and returns
// null/false/""; wasm/index.js turns that into a HexdualError. This is leak-free where throwing
// through Embind is not (see TOOLCHAIN.md). Render and picking bindings live in bindings_view.cpp.
#include <emscripten/bind.h>
#include <malloc.h>

#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <memory>
#include <new>
#include <optional>
#include <string>

#include "complex/builders.hpp"
#include "complex/canonical.hpp"
#include "dual/dual.hpp"
#include "dual/dual_tracker.hpp"
#include "flips/decompositions.hpp"
#include "flips/flip.hpp"
#include "flips/fourcube.hpp"
#include "io/io.hpp"
#include "io/json.hpp"
#include "layout/render_buffers.hpp"
#include "layout/sheet_diagram.hpp"
#include "ops/candidates.hpp"
#include "ops/op_table.hpp"
#include "ops/oplog.hpp"
#include "ops/report.hpp"

using namespace emscripten;
using namespace hexdual;

namespace {

std::string g_lastError, g_lastErrorCode;

// The error code a message belongs to when the call's own code is too coarse.
std::string classify(const std::string& message, const char* code) {
  if (message.rfind("oplog:", 0) == 0) return "PARSE";
  if (message.rfind("validate:", 0) == 0 || message.find("would not be a valid complex") != std::string::npos)
    return "INVALID_RESULT";
  if (message.find("more than 2^") != std::string::npos) return "LIMIT";
  return code;
}

// Runs f; on an exception keeps its message and code and returns onError. `code` is the kind of
// failure the call usually has (PARSE for readers, PRECONDITION for operations, ...).
template <class F>
auto guarded(const char* code, F&& f, decltype(f()) onError) -> decltype(f()) {
  g_lastError.clear();
  g_lastErrorCode.clear();
  try {
    return f();
  } catch (const std::bad_alloc&) {
    g_lastError = "out of memory: the WebAssembly heap cannot grow further";
    g_lastErrorCode = "LIMIT";
  } catch (const std::exception& e) {
    g_lastError = e.what();
    g_lastErrorCode = classify(g_lastError, code);
  }
  return onError;
}

// A JS object with these properties.
val fields(std::initializer_list<std::pair<const char*, val>> props) {
  val o = val::object();
  for (const auto& [name, value] : props) o.set(name, value);
  return o;
}

template <class T>
val copyOut(const char* type, const std::vector<T>& v) {
  return val::global(type).new_(val(typed_memory_view(v.size(), v.data())));
}

// One entry of the undo list: the core's step report, or a flip applied directly (no log step).
struct StepRecord {
  StepReport report;
  std::string flipName;  // non-empty for a direct flip
  std::vector<int> flipHexes;
  bool loggable() const { return flipName.empty(); }
};

// {"flip": "NAME [h,..]" or null, "report": the core's step report (as `hexdual apply --json`)}.
std::string recordJson(const StepRecord& s, size_t index) {
  std::string flip = s.loggable() ? "null" : io::JsonWriter::quote(s.flipName + " " + io::idList(s.flipHexes));
  return "{\"flip\":" + flip + ",\"report\":" + io::stepReportJson(s.report, index) + "}";
}

std::string hexString(uint64_t h) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

io::Format formatNamed(const std::string& format) {
  if (format == "vtk") return io::Format::Vtk;
  if (format == "mesh") return io::Format::Medit;
  if (format == "hxd") return io::Format::Native;
  throw Error("unknown format '" + format + "' (vtk, mesh or hxd)");
}

template <class T>
int countAlive(const std::vector<T>& items) {
  int n = 0;
  for (const T& x : items) n += x.alive ? 1 : 0;
  return n;
}

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

  val o = fields({{"sheet", val(d.sheet)}, {"topology", val(d.topology)}, {"method", val(d.method)}, {"local", val(d.local)},
                  {"note", val(d.note)}, {"radius", val(d.radius)}, {"euler", val(double(d.euler))},
                  {"openedHex", d.openedHex >= 0 ? val(d.openedHex) : val::null()}});
  o.set("arcs", fields({{"label", arcLabel}, {"pair", copyOut("Int32Array", arcPair)}, {"sign", copyOut("Int8Array", arcSign)},
                        {"offsets", copyOut("Uint32Array", arcOffsets)}, {"xy", copyOut("Float64Array", arcXY)}}));
  o.set("crossings", fields({{"hex", copyOut("Int32Array", crossHex)}, {"axis", copyOut("Int8Array", crossAxis)},
                             {"xy", copyOut("Float64Array", crossXY)}, {"chords", copyOut("Int32Array", crossChords)},
                             {"outside", copyOut("Uint8Array", crossOutside)}}));
  o.set("boundary", fields({{"hex", copyOut("Int32Array", bHex)}, {"face", copyOut("Int8Array", bFace)}, {"xy", copyOut("Float64Array", bXY)}}));
  o.set("chords", fields({{"id", copyOut("Int32Array", chId)}, {"otherSheet", copyOut("Int32Array", chOther)},
                          {"closed", copyOut("Uint8Array", chClosed)}, {"piece", copyOut("Int32Array", chPiece)},
                          {"offsets", copyOut("Uint32Array", chOffsets)},
                          {"xy", copyOut("Float64Array", chXY)}, {"hexOffsets", copyOut("Uint32Array", chHexOffsets)},
                          {"hexes", copyOut("Int32Array", chHexes)}}));
  o.set("loops", fields({{"offsets", copyOut("Uint32Array", loopOffsets)}, {"xy", copyOut("Float64Array", loopXY)}}));
  o.set("cells", fields({{"hex", copyOut("Int32Array", cellHex)}, {"edge", copyOut("Int8Array", cellEdge)}, {"xy", copyOut("Float64Array", cellXY)}}));
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
  std::vector<double> chId = nums(d["chords"]["id"]), chOther = nums(d["chords"]["otherSheet"]), chOff = nums(d["chords"]["offsets"]),
                      chXY = nums(d["chords"]["xy"]), chPiece = nums(d["chords"]["piece"]);
  for (size_t k = 0; k < chId.size() && k + 1 < chOff.size(); ++k) {
    SheetDiagram::ChordLine c{int(chId[k]), int(chOther[k]), false, {}, {}, k < chPiece.size() ? int(chPiece[k]) : 0};
    for (size_t i = size_t(chOff[k]); i < size_t(chOff[k + 1]); ++i) c.points.push_back(pointAt(chXY, i));
    s.chords.push_back(std::move(c));
  }
  std::vector<double> bXY = nums(d["boundary"]["xy"]);
  for (size_t i = 0; i < bXY.size() / 2; ++i) s.boundary.push_back({-1, 0, pointAt(bXY, i)});
  std::vector<double> cHex = nums(d["crossings"]["hex"]), cXY = nums(d["crossings"]["xy"]), cOut = nums(d["crossings"]["outside"]);
  for (size_t i = 0; i < cHex.size() && 2 * i + 1 < cXY.size(); ++i)
    s.crossings.push_back({HexId(cHex[i]), 0, pointAt(cXY, i), {-1, -1}, i < cOut.size() && cOut[i] != 0});
  if (!d["arcs"].isUndefined() && !d["arcs"].isNull()) {
    std::vector<double> aPair = nums(d["arcs"]["pair"]), aSign = nums(d["arcs"]["sign"]), aOff = nums(d["arcs"]["offsets"]),
                        aXY = nums(d["arcs"]["xy"]);
    std::vector<std::string> aLabel = vecFromJSArray<std::string>(d["arcs"]["label"]);
    for (size_t k = 0; k < aLabel.size() && k + 1 < aOff.size(); ++k) {
      SheetDiagram::Arc a{aLabel[k], int(aPair[k]), int(aSign[k]), {}};
      for (size_t i = size_t(aOff[k]); i < size_t(aOff[k + 1]); ++i) a.points.push_back(pointAt(aXY, i));
      s.arcs.push_back(std::move(a));
    }
  }
  return diagramSvg(s);
}

class WasmMesh {
 public:
  explicit WasmMesh(Complex cx) : cx_(std::move(cx)) {}

  static WasmMesh* grid(int a, int b, int c) {
    return guarded("PRECONDITION", [&] { return new WasmMesh(makeGrid(a, b, c)); }, nullptr);
  }
  // The closed boundary of the 4-cube: the complex the stored flip decompositions are written for.
  static WasmMesh* fourCube() {
    return guarded("PRECONDITION", [&] { return new WasmMesh(makeFourCubeBoundary()); }, nullptr);
  }
  static WasmMesh* ring(int around, int radial, int axial) {
    return guarded("PRECONDITION", [&] { return new WasmMesh(makeRing(around, radial, axial)); }, nullptr);
  }
  // `bytes` arrives from a Uint8Array (Embind copies it into the string).
  // hexesOnly: read the hex part of a file that also has tets/prisms/pyramids (io::ReadOptions).
  static WasmMesh* load(const std::string& bytes, const std::string& name, bool hexesOnly) {
    return guarded("PARSE", [&] {
      io::ReadOptions opt;
      opt.hexesOnly = hexesOnly;
      io::ReadReport rep;
      auto* m = new WasmMesh(io::readMesh(bytes, name, opt, &rep));
      m->file_ = rep;
      return m;
    }, nullptr);
  }

  std::string infoJson() { return guarded("PRECONDITION", [&] { return io::infoJson(cx_, dual(), file_ ? &*file_ : nullptr); }, std::string()); }
  std::string save(const std::string& format, bool binary) {
    return guarded("PRECONDITION", [&] { return io::writeMesh(cx_, formatNamed(format), binary); }, std::string());
  }
  // The file's bytes as a Uint8Array (binary VTK included); null on error.
  val saveBytes(const std::string& format, bool binary) {
    std::string bytes;
    if (!guarded("PRECONDITION", [&] { bytes = io::writeMesh(cx_, formatNamed(format), binary); return true; }, false))
      return val::null();
    return val::global("Uint8Array").new_(val(typed_memory_view(bytes.size(), reinterpret_cast<const uint8_t*>(bytes.data()))));
  }
  // The sheet diagram of a sheet as JSON (the same as `hexdual sheets --json`).
  std::string sheetDiagramJson(int id) {
    return guarded("PRECONDITION", [&] { return diagramJson(layoutSheet(cx_, dual(), liveSheet(id))); }, std::string());
  }
  // A local diagram: the sheet within `rings` rings of the given hexes.
  std::string localSheetDiagramJson(int id, const std::vector<int>& hexes, int rings) {
    return guarded("PRECONDITION", [&] { return diagramJson(layoutLocal(cx_, dual(), liveSheet(id), hexes, rings)); }, std::string());
  }
  // The same diagram as typed arrays; `local` selects layoutLocal around `hexes`.
  val sheetDiagram(int id, bool local, const std::vector<int>& hexes, int rings) {
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
  // Applies one operation-log step ("pillow h13f5"); returns its inverse step ("" on error).
  std::string applyStep(const std::string& step) {
    return guarded("PRECONDITION", [&] {
      apply(parseOpStep(step));
      const OpResult& r = history_.back().report.result;
      return r.inverse ? formatOpStep(*r.inverse) : std::string("-");
    }, std::string());
  }
  // Applies one step and returns its report as JSON ("" on error; the mesh is then unchanged).
  std::string applyReport(const std::string& step) {
    return guarded("PRECONDITION", [&] { return apply(parseOpStep(step)); }, std::string());
  }
  // Applies the steps of a log (text or URL form), at most stopAt of them (-1: all); all or
  // nothing: on an error the steps already applied by this call are undone. JSON array of reports.
  std::string applyLog(const std::string& logText, int stopAt) {
    size_t mark = history_.size();
    std::vector<StepRecord> redoKept = redo_;
    std::string out = guarded("PRECONDITION", [&] {
      OpLog log = !logText.empty() && logText[0] >= '0' && logText[0] <= '9' ? decodeOpLogUrl(logText) : parseOpLog(logText);
      size_t n = stopAt < 0 ? log.steps.size() : std::min(log.steps.size(), size_t(stopAt));
      std::string json = "[";
      for (size_t k = 0; k < n; ++k) {
        try {
          json += (k ? "," : "") + apply(log.steps[k]);
        } catch (const Error& e) {
          throw Error("step " + std::to_string(k + 1) + " (" + formatOpStep(log.steps[k]) + "): " + e.what());
        }
      }
      return json + "]";
    }, std::string());
    if (out.empty()) {
      std::string message = g_lastError, code = g_lastErrorCode;
      while (history_.size() > mark) undoOne();
      redo_ = std::move(redoKept);
      g_lastError = message;
      g_lastErrorCode = code;
    }
    return out;
  }
  // Undoes the last applied step exactly (the engine's edit journal); "" when there is none.
  std::string undo() {
    return guarded("PRECONDITION", [&] {
      if (history_.empty()) throw Error("undo: nothing to undo");
      const StepRecord& last = history_.back();
      std::string text = last.loggable() ? formatOpStep(last.report.step) : "flip " + last.flipName + " " + io::idList(last.flipHexes);
      undoOne();
      return text;
    }, std::string());
  }
  // Re-applies the last undone step; its report as JSON.
  std::string redo() {
    return guarded("PRECONDITION", [&] {
      if (redo_.empty()) throw Error("redo: nothing to redo");
      StepRecord s = std::move(redo_.back());
      redo_.pop_back();
      std::vector<StepRecord> rest = std::move(redo_);
      std::string report;
      try {
        report = s.loggable() ? apply(s.report.step) : applyFlip(s.flipName, s.flipHexes, false);
      } catch (...) {
        rest.push_back(std::move(s));
        redo_ = std::move(rest);
        throw;
      }
      redo_ = std::move(rest);
      return report;
    }, std::string());
  }
  int undoDepth() const { return int(history_.size()); }
  int redoDepth() const { return int(redo_.size()); }
  // The applied steps as an operation log ("v1;..."), or its URL form.
  std::string log(bool url) {
    return guarded("PRECONDITION", [&] {
      OpLog out;
      for (const StepRecord& s : history_) {
        if (!s.loggable())
          throw Error("log: the history holds a flip applied directly (flip " + s.flipName +
                      "), which the operation log cannot express; apply flips with { viaAtomic: true } to log them");
        out.steps.push_back(s.report.step);
      }
      return url ? encodeOpLogUrl(out) : formatOpLog(out);
    }, std::string());
  }
  // Steps of `op` (or of every operation when op is empty) that apply, as JSON strings; with
  // nearKind "hex", "quad" or "edge", only those whose arguments name that entity.
  std::string candidatesJson(const std::string& op, const std::string& nearKind, int hex, int local) {
    return guarded("PRECONDITION", [&] {
      std::vector<OpKind> ops;
      for (const OpInfo& info : allOps())
        if (info.candidates != CandidateSet::None && (op.empty() || op == info.name)) ops.push_back(info.kind);
      if (ops.empty()) throw Error("candidates: unknown operation '" + op + "'");
      if (!nearKind.empty()) requireNear(nearKind, hex, local);
      io::JsonWriter w;
      w.beginArray();
      for (OpKind o : ops)
        for (const OpStep& s : candidates(cx_, o))
          if (nearKind.empty() || mentions(s, nearKind, hex, local)) w.value(formatOpStep(s));
      w.endArray();
      return w.str();
    }, std::string());
  }
  // A cubical flip on the named hexes (like `hexdual flip NAME --at ...`); JSON array of reports
  // (one per atomic step with viaAtomic, else one).
  std::string flip(const std::string& name, const std::vector<int>& hexes, bool viaAtomic) {
    return guarded("PRECONDITION", [&] { return applyFlip(name, hexes, viaAtomic); }, std::string());
  }
  std::string canonicalHash() {
    return guarded("PRECONDITION", [&] { return hexString(hexdual::canonicalHash(cx_)); }, std::string());
  }
  // 1 when isomorphic (boundary kept), 0 when not, -1 on error.
  int isomorphicTo(const WasmMesh& other) {
    return guarded("PRECONDITION", [&] { return isomorphic(cx_, other.cx_) ? 1 : 0; }, -1);
  }
  // Centroid of every hex, 3 numbers per hex id (NaN for removed ids).
  val hexCenters() {
    std::vector<double> c(size_t(cx_.hexCapacity()) * 3, std::nan(""));
    for (HexId h : cx_.hexes()) {
      Vec3 p = cx_.hexCentroid(h);
      c[3 * size_t(h)] = p.x;
      c[3 * size_t(h) + 1] = p.y;
      c[3 * size_t(h) + 2] = p.z;
    }
    return copyOut("Float64Array", c);
  }
  // Extracts the dual (if stale) and returns the number of sheet and chord ids: for benchmarks.
  // Live sheets and chords (ids retired by operations are not counted; ids need not be dense).
  int numSheets() { return guarded("PRECONDITION", [&] { return countAlive(dual().sheets); }, -1); }
  int numChords() { return guarded("PRECONDITION", [&] { return countAlive(dual().chords); }, -1); }
  double memoryBytes() const { return double(cx_.memoryBytes()); }
  bool validate() {
    return guarded("INVALID_RESULT", [&] {
      cx_.validate();
      return true;
    }, false);
  }

  // Hex ids of a sheet or chord, one per slot (a hex appears twice on a self-intersecting one).
  val sheetHexes(int id) { return slotsToArray(id, true); }
  val chordHexes(int id) { return slotsToArray(id, false); }

  // Render buffers; the getters return views that wasm/index.js copies at once.
  bool buildRender(double shrink) {
    return guarded("PRECONDITION", [&] {
      rb_ = buildRenderBuffers(cx_, shrink);
      return true;
    }, false);
  }
  // For wasm/bindings_view.cpp (same module): where the complex and its current dual live.
  double complexAddress() const { return double(uintptr_t(&cx_)); }
  // Whether steps place their new and moved vertices by the local smoothing (StepOptions).
  void setSmoothing(bool on) { smooth_ = on; }
  bool smoothing() const { return smooth_; }
  // Steps are smoothed, or (smoothing off) only measured, like the CLI's apply and --no-smooth.
  StepOptions stepOptions() const { return {smooth_ ? StepGeometry::Smooth : StepGeometry::Measure}; }
  double dualAddress() { return guarded("PRECONDITION", [&] { return double(uintptr_t(&dual())); }, 0.0); }
  val positions() const { return val(typed_memory_view(rb_.positions.size(), rb_.positions.data())); }
  val normals() const { return val(typed_memory_view(rb_.normals.size(), rb_.normals.data())); }
  val indices() const { return val(typed_memory_view(rb_.indices.size(), rb_.indices.data())); }
  val triangleHex() const { return val(typed_memory_view(rb_.triangleHex.size(), rb_.triangleHex.data())); }

 private:
  std::optional<io::ReadReport> file_;  // what the reader found, for info() of a loaded file
  // The dual, kept current by a tracker so that sheet and chord ids survive operations.
  DualTracker& tracker() {
    if (!tracker_) tracker_ = std::make_unique<DualTracker>(cx_);
    return *tracker_;
  }
  const Dual& dual() { return tracker().dual(); }  // settles the chord lists changed since the last read
  int liveSheet(int id) {
    const Dual& d = dual();
    if (id >= 0 && size_t(id) < d.sheets.size() && !d.sheets[size_t(id)].alive)
      throw Error("sheet " + std::to_string(id) + " was removed by an operation");
    return id;
  }
  std::string record(StepRecord s) {
    history_.push_back(std::move(s));
    redo_.clear();
    return recordJson(history_.back(), history_.size());
  }
  // Applies one step (throws; the complex is then unchanged) and records it.
  std::string apply(const OpStep& step) {
    tracker();  // the tracker must see the state before the step
    StepRecord s;
    s.report = applyStepTracked(cx_, *tracker_, step, stepOptions());
    return record(std::move(s));
  }
  std::string applyFlip(const std::string& name, const std::vector<int>& hexes, bool viaAtomic) {
    tracker();
    flipClass(name);  // throws for an unknown name
    if (!viaAtomic) {
      StepRecord s;
      s.report.result = hexdual::flip(cx_, name, hexes);
      s.report.result.quality = placeStepGeometry(cx_, s.report.result.edits, stepOptions().geometry);
      s.flipName = name;
      s.flipHexes = hexes;
      s.report.dual = tracker_->update(cx_, s.report.result.edits, false);
      return "[" + record(std::move(s)) + "]";
    }
    const StoredDecomposition* found = nullptr;
    for (const auto& d : storedDecompositions())
      if (d.problem == name && d.found) found = &d;
    if (!found) throw Error("flip " + name + " has no stored atomic decomposition (see flips())");
    Complex trial = cx_;  // placed on a copy first: a step that cannot be placed changes nothing
    std::vector<OpStep> steps = replayInEmbedding(problemFor(name), found->steps, trial, hexes, "the mesh");
    size_t mark = history_.size();
    std::string json = "[";
    try {
      for (size_t k = 0; k < steps.size(); ++k) json += (k ? "," : "") + apply(steps[k]);
    } catch (...) {
      while (history_.size() > mark) undoOne();
      throw;
    }
    return json + "]";
  }
  void undoOne() {
    StepRecord s = std::move(history_.back());
    history_.pop_back();
    cx_.undo(s.report.result.edits);
    tracker_->update(cx_, s.report.result.edits, keepsSheetTopology(s.report.result));
    tracker_->releaseRetiredTail();
    redo_.push_back(std::move(s));
  }
  void requireNear(const std::string& kind, int hex, int local) const {
    if (kind != "hex" && kind != "quad" && kind != "edge") throw Error("candidates: near must name a hex, a quad or an edge");
    if (!cx_.isHex(hex)) throw Error("candidates: hex " + std::to_string(hex) + " does not exist");
    if ((kind == "quad" && (local < 0 || local > 5)) || (kind == "edge" && (local < 0 || local > 11)))
      throw Error("candidates: local " + kind + " " + std::to_string(local) + " is out of range");
  }
  // Whether a step's arguments name the entity: a hex (any argument in it or across its quads),
  // a quad (either side), or an edge (any incidence).
  bool mentions(const OpStep& step, const std::string& kind, int hex, int local) const {
    auto sameQuad = [&](QuadSide s) { return cx_.canonical(s) == cx_.canonical(QuadSide{hex, local}); };
    for (const OpArg& a : step.args) {
      if (kind == "hex") {
        if (a.hex == hex) return true;
        if ((a.kind == OpArg::Quad || a.kind == OpArg::Pair) && cx_.isHex(a.hex) && !cx_.isBoundary({a.hex, a.local}) &&
            cx_.gluing(a.hex, a.local).hex == hex)
          return true;
      } else if (kind == "quad") {
        if ((a.kind == OpArg::Quad || a.kind == OpArg::Pair) && sameQuad({a.hex, a.local})) return true;
        if (a.kind == OpArg::Pair && sameQuad(a.second)) return true;
      } else if (a.kind == OpArg::Edge && cx_.canonical(EdgeRef{a.hex, a.local}) == cx_.canonical(EdgeRef{hex, local})) {
        return true;
      }
    }
    return false;
  }
  val slotsToArray(int id, bool sheet) {
    const Dual& d = dual();
    size_t n = sheet ? d.sheets.size() : d.chords.size();
    bool alive = id >= 0 && size_t(id) < n && (sheet ? d.sheets[size_t(id)].alive : d.chords[size_t(id)].alive);
    if (!alive) {
      g_lastError = std::string(sheet ? "sheet " : "chord ") + std::to_string(id) + " does not exist";
      g_lastErrorCode = "PRECONDITION";
      return val::null();
    }
    const std::vector<Slot>& slots = sheet ? d.sheets[size_t(id)].slots.get() : d.chords[size_t(id)].slots;
    scratch_.clear();
    for (const Slot& s : slots) scratch_.push_back(s.hex);
    return copyOut("Int32Array", scratch_);
  }

  Complex cx_;
  std::unique_ptr<DualTracker> tracker_;
  std::vector<StepRecord> history_, redo_;
  bool smooth_ = true;
  RenderBuffers rb_;
  std::vector<int32_t> scratch_;
};

std::string lastError() { return g_lastError; }
std::string lastErrorCode() { return g_lastErrorCode; }

int isomorphicMeshes(WasmMesh& a, WasmMesh& b) { return a.isomorphicTo(b); }

std::string diagramToSvg(val d) {
  return guarded("PRECONDITION", [&] { return svgFromArrays(d); }, std::string());
}

// The flip classes and their stored decompositions, as JSON (the same facts as `hexdual flip list`).
std::string flipsJson() {
  return guarded(
      "PRECONDITION",
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
      .function("dualAddress", &WasmMesh::dualAddress);
}
