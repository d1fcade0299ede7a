// Minimal JSON writing, and the reports shared by the CLI and the wasm module: `info`, the
// per-step report of `apply`, and the flips list.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "complex/complex.hpp"
#include "dual/dual.hpp"
#include "flips/decompositions.hpp"
#include "ops/report.hpp"
#include "io/io.hpp"

namespace hexdual::io {

class JsonWriter {
 public:
  JsonWriter& beginObject() { return open('{'); }
  JsonWriter& endObject() { return close('}'); }
  JsonWriter& beginArray() { return open('['); }
  JsonWriter& endArray() { return close(']'); }
  JsonWriter& key(const std::string& k) {
    comma();
    out_ += quote(k) + ":";
    afterKey_ = true;
    return *this;
  }
  JsonWriter& value(const std::string& s) { return raw(quote(s)); }
  JsonWriter& value(const char* s) { return raw(quote(s)); }
  JsonWriter& value(bool b) { return raw(b ? "true" : "false"); }
  JsonWriter& value(int64_t v) { return raw(std::to_string(v)); }
  JsonWriter& value(int v) { return raw(std::to_string(v)); }
  JsonWriter& value(double v);
  JsonWriter& raw(const std::string& text) {
    comma();
    out_ += text;
    return *this;
  }
  const std::string& str() const { return out_; }
  static std::string quote(const std::string& s);

 private:
  JsonWriter& open(char c) {
    comma();
    out_ += c;
    first_ = true;
    return *this;
  }
  JsonWriter& close(char c) {
    out_ += c;
    first_ = false;
    return *this;
  }
  void comma() {
    if (afterKey_) {
      afterKey_ = false;
      return;
    }
    if (!first_) out_ += ",";
    first_ = false;
  }
  std::string out_;
  bool first_ = true, afterKey_ = false;
};

// "[1,2,3]": ids as a JSON array (also the text reports' spelling).
std::string idList(const std::vector<int32_t>& ids);

// {"vertices":..,"edges":..,"quads":..,"hexes":..,"boundaryQuads":..}: the counts info() starts with.
std::string countsJson(const Counts& c);

// {"vertices":..,"edges":..,"quads":..,"hexes":..,"boundaryQuads":..,"sheets":[..],"chords":[..]},
// and "file": {...} last (what the reader found, see ReadReport) when a report is given.
std::string infoJson(const Complex& cx, const Dual& dual, const ReadReport* file = nullptr);
// The same facts as readable text.
std::string infoText(const Complex& cx, const Dual& dual);

// One applied step (number `index`, from 1) as a JSON object: {"step","op","text","createdHexes",
// "removedHexes","createdVertices","removedVertices","delta":{V,E,F,H},"sheets":{created,removed,
// changed},"chords":{..},"inverse": step text or null, "noInverse": why (only when null)}.
void writeStepReport(JsonWriter& w, const StepReport& r, size_t index);
std::string stepReportJson(const StepReport& r, size_t index);
// The same as four lines of text ("step 1: pillow h13f5\n  hexes created ...").
std::string stepReportText(const StepReport& r, size_t index);
// {"steps":[..],"counts":{"vertices","edges","quads","hexes"},"positionsHash"}: the report of a whole log.
// inverseInOutput: the last step's inverse in the written file's hex numbering (null: none, or nothing written).
std::string applyReportJson(const std::vector<StepReport>& steps, const Complex& after,
                            const std::optional<std::string>& inverseInOutput = std::nullopt);

// The flips list: [{"name","inverse","before":[V,E,F,H],"after":[..],"geometric","decomposition":
// op log or null}], and one line of text per flip.
std::string flipListJson(const std::vector<FlipSummary>& flips);
std::string flipListText(const std::vector<FlipSummary>& flips);

}  // namespace hexdual::io
