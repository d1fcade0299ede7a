// Bindings of operations: applying steps and operation logs with their reports, undo and redo
// (the engine's exact edit journal, the tracker following), the log of what was applied, the
// candidate steps, cubical flips (directly or through their stored atomic decompositions), and
// the flip classes.
#include "bindings_common.hpp"
#include "flips/decompositions.hpp"
#include "flips/flip.hpp"
#include "flips/fourcube.hpp"
#include "io/json.hpp"
#include "ops/candidates.hpp"
#include "ops/op_table.hpp"
#include "wasm_mesh.hpp"

namespace hexdual::wasm {

namespace {
// {"flip": "NAME [h,..]" or null, "report": the core's step report (as `hexdual apply --json`)}.
std::string recordJson(const StepRecord& s, size_t index) {
  std::string flip = s.loggable() ? "null" : io::JsonWriter::quote(s.flipName + " " + io::idList(s.flipHexes));
  return "{\"flip\":" + flip + ",\"report\":" + io::stepReportJson(s.report, index) + "}";
}
}  // namespace

std::string WasmMesh::applyStep(const std::string& step) {
  return guarded(
      "PRECONDITION",
      [&] {
        apply(parseOpStep(step));
        const OpResult& r = history_.back().report.result;
        return r.inverse ? formatOpStep(*r.inverse) : std::string("-");
      },
      std::string());
}

// A step its operation's first checks reject (most rejected steps: a boundary quad, an edge that
// is not interior, ...) is reported without a C++ exception: the same message and code as a throw.
std::string WasmMesh::applyReport(const std::string& text) {
  std::string refused;
  std::string out = guarded(
      "PRECONDITION",
      [&] {
        const OpStep step = parseOpStep(text);
        refused = precheckStep(cx_, step);
        return refused.empty() ? apply(step) : std::string();
      },
      std::string());
  if (!refused.empty()) {
    g_lastError = refused;
    g_lastErrorCode = classify(refused, "PRECONDITION");
  }
  return out;
}

std::string WasmMesh::applyLog(const std::string& logText, int stopAt) {
  size_t mark = history_.size();
  std::vector<StepRecord> redoKept = redo_;
  std::string out = guarded(
      "PRECONDITION",
      [&] {
        OpLog log =
            !logText.empty() && logText[0] >= '0' && logText[0] <= '9' ? decodeOpLogUrl(logText) : parseOpLog(logText);
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
      },
      std::string());
  if (out.empty()) {
    std::string message = g_lastError, code = g_lastErrorCode;
    while (history_.size() > mark) undoOne();
    redo_ = std::move(redoKept);
    g_lastError = message;
    g_lastErrorCode = code;
  }
  return out;
}

std::string WasmMesh::undo() {
  return guarded(
      "PRECONDITION",
      [&] {
        if (history_.empty()) throw Error("undo: nothing to undo");
        const StepRecord& last = history_.back();
        std::string text = last.loggable() ? formatOpStep(last.report.step)
                                           : "flip " + last.flipName + " " + io::idList(last.flipHexes);
        undoOne();
        return text;
      },
      std::string());
}

std::string WasmMesh::redo() {
  return guarded(
      "PRECONDITION",
      [&] {
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
      },
      std::string());
}

std::string WasmMesh::log(bool url) {
  return guarded(
      "PRECONDITION",
      [&] {
        OpLog out;
        for (const StepRecord& s : history_) {
          if (!s.loggable())
            throw Error("log: the history holds a flip applied directly (flip " + s.flipName +
                        "), which the operation log cannot express; apply flips with { viaAtomic: true } to log them");
          out.steps.push_back(s.report.step);
        }
        return url ? encodeOpLogUrl(out) : formatOpLog(out);
      },
      std::string());
}

std::string WasmMesh::candidatesJson(const std::string& op, const std::string& nearKind, int hex, int local) {
  return guarded(
      "PRECONDITION",
      [&] {
        std::vector<OpKind> ops;
        for (const OpInfo& info : allOps())
          if (info.candidates != CandidateSet::None && (op.empty() ? info.family == OpFamily::Atomic : op == info.name))
            ops.push_back(info.kind);  // without a name: the atomic family (the sheet operations are listed by name)
        if (ops.empty()) throw Error("candidates: unknown operation '" + op + "'");
        if (!nearKind.empty()) requireNear(nearKind, hex, local);
        io::JsonWriter w;
        w.beginArray();
        for (OpKind o : ops)
          for (const OpStep& s : candidates(cx_, o))
            if (nearKind.empty() || mentions(s, nearKind, hex, local)) w.value(formatOpStep(s));
        w.endArray();
        return w.str();
      },
      std::string());
}

std::string WasmMesh::flip(const std::string& name, const std::vector<int>& hexes, bool viaAtomic) {
  return guarded(
      "PRECONDITION", [&] { return applyFlip(name, hexes, viaAtomic); }, std::string());
}

// Records a step that applied; a new step clears the redo list.
std::string WasmMesh::record(StepRecord s) {
  history_.push_back(std::move(s));
  redo_.clear();
  return recordJson(history_.back(), history_.size());
}

// Applies one step (throws; the complex is then unchanged) and records it.
std::string WasmMesh::apply(const OpStep& step) {
  tracker();  // the tracker must see the state before the step
  StepRecord s;
  s.report = applyStepTracked(cx_, *tracker_, step, stepOptions(), &s.ids);
  return record(std::move(s));
}

std::string WasmMesh::applyFlip(const std::string& name, const std::vector<int>& hexes, bool viaAtomic) {
  tracker();
  flipClass(name);  // throws for an unknown name
  if (!viaAtomic) {
    StepRecord s;
    s.report.result = hexdual::flip(cx_, name, hexes);
    s.report.result.quality = placeStepGeometry(cx_, s.report.result.edits, stepOptions().geometry);
    s.flipName = name;
    s.flipHexes = hexes;
    s.ids = tracker_->idMemo(cx_, s.report.result.edits);
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

void WasmMesh::undoOne() {
  StepRecord s = std::move(history_.back());
  history_.pop_back();
  undoStepTracked(cx_, *tracker_, s.report, s.ids);  // exact, sheet and chord ids included
  redo_.push_back(std::move(s));
}

void WasmMesh::requireNear(const std::string& kind, int hex, int local) const {
  if (kind != "hex" && kind != "quad" && kind != "edge")
    throw Error("candidates: near must name a hex, a quad or an edge");
  if (!cx_.isHex(hex)) throw Error("candidates: hex " + std::to_string(hex) + " does not exist");
  if ((kind == "quad" && (local < 0 || local > 5)) || (kind == "edge" && (local < 0 || local > 11)))
    throw Error("candidates: local " + kind + " " + std::to_string(local) + " is out of range");
}

// Whether a step's arguments name the entity: a hex (any argument in it or across its quads),
// a quad (either side), or an edge (any incidence).
bool WasmMesh::mentions(const OpStep& step, const std::string& kind, int hex, int local) const {
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

// The flip classes and their stored decompositions, as JSON (the same facts as `hexdual flip list`).
std::string flipsJson() {
  return guarded(
      "PRECONDITION",
      [] {
        io::JsonWriter w;
        w.beginArray();
        for (const FlipClass& fc : enumerateFlipClasses()) {
          w.beginObject()
              .key("name")
              .value(fc.name)
              .key("inverse")
              .value(fc.inverse)
              .key("geometric")
              .value(fc.geometric);
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

}  // namespace hexdual::wasm
