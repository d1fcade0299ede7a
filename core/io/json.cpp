#include "io/json.hpp"

#include <cmath>
#include <cstdio>

#include "analysis/singularity.hpp"
#include "geometry/positions_hash.hpp"
#include "io/geometry_json.hpp"
#include "ops/op_table.hpp"
#include "ops/oplog.hpp"

namespace hexdual::io {

JsonWriter& JsonWriter::value(double v) {
  if (!std::isfinite(v)) return raw("null");
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return raw(buf);
}

std::string JsonWriter::quote(const std::string& s) {
  std::string r = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') {
      r += '\\';
      r += c;
    } else if ((unsigned char)c < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      r += buf;
    } else {
      r += c;
    }
  }
  return r + "\"";
}

namespace {
void writeCounts(JsonWriter& w, const Counts& c) {
  w.key("vertices").value(c.vertices).key("edges").value(c.edges).key("quads").value(c.quads);
  w.key("hexes").value(c.hexes).key("boundaryQuads").value(c.boundaryQuads);
}
}  // namespace

std::string countsJson(const Counts& c) {
  JsonWriter w;
  w.beginObject();
  writeCounts(w, c);
  w.endObject();
  return w.str();
}

std::string infoJson(const Complex& cx, const Dual& dual, const ReadReport* file) {
  JsonWriter w;
  w.beginObject();
  writeCounts(w, cx.counts());
  w.key("sheets").beginArray();
  for (const Sheet& s : dual.sheets) {
    if (!s.alive) continue;
    w.beginObject().key("id").value(s.id).key("hexes").value(int64_t(s.slots.size()));
    w.key("topology").value(s.topology).key("boundaryLoops").value(s.boundaryLoops);
    w.key("euler").value(s.euler).key("selfIntersecting").value(s.selfIntersecting).endObject();
  }
  w.endArray().key("chords").beginArray();
  for (const Chord& ch : dual.chords) {
    if (!ch.alive) continue;
    w.beginObject().key("id").value(ch.id).key("hexes").value(int64_t(ch.slots.size()));
    w.key("closed").value(ch.closed).key("selfIntersecting").value(ch.selfIntersecting).endObject();
  }
  w.endArray().key("singularities").raw(singularityCountsJson(singularityGraph(cx).counts));
  if (file) w.key("file").raw(reportJson(*file));
  w.endObject();
  return w.str();
}

std::string infoText(const Complex& cx, const Dual& dual) {
  Counts c = cx.counts();
  std::string out;
  out += "vertices " + std::to_string(c.vertices) + "\nedges " + std::to_string(c.edges) + "\nquads " +
         std::to_string(c.quads) + " (" + std::to_string(c.boundaryQuads) + " on the boundary)\nhexes " +
         std::to_string(c.hexes) + "\n";
  out += "sheets " + std::to_string(dual.sheets.size()) + "\n";
  for (const Sheet& s : dual.sheets)
    out += "  sheet " + std::to_string(s.id) + ": " + std::to_string(s.slots.size()) + " hexes, " + s.topology + ", " +
           std::to_string(s.boundaryLoops) + " boundary loop(s), euler " + std::to_string(s.euler) +
           (s.selfIntersecting ? ", self-intersecting" : "") + "\n";
  out += "chords " + std::to_string(dual.chords.size()) + "\n";
  for (const Chord& ch : dual.chords)
    out += "  chord " + std::to_string(ch.id) + ": " + std::to_string(ch.slots.size()) + " hexes, " +
           (ch.closed ? "closed" : "open") + (ch.selfIntersecting ? ", self-intersecting" : "") + "\n";
  return out + singularityCountsText(singularityGraph(cx).counts);
}

}  // namespace hexdual::io

namespace hexdual::io {

std::string idList(const std::vector<int32_t>& v) {
  std::string s = "[";
  for (size_t i = 0; i < v.size(); ++i) s += (i ? "," : "") + std::to_string(v[i]);
  return s + "]";
}

namespace {

std::string signedNum(int64_t x) { return (x > 0 ? "+" : "") + std::to_string(x); }
std::string countsList(const Counts& c) {
  return std::to_string(c.vertices) + "," + std::to_string(c.edges) + "," + std::to_string(c.quads) + "," +
         std::to_string(c.hexes);
}
void writeIds(JsonWriter& w, const char* created, const std::vector<int32_t>& c, const char* removed,
              const std::vector<int32_t>& r) {
  w.key(created).raw(idList(c)).key(removed).raw(idList(r));
}

}  // namespace

void writeStepReport(JsonWriter& w, const StepReport& rep, size_t index) {
  const OpResult& r = rep.result;
  const DualChange& ch = rep.dual;
  w.beginObject().key("step").value(int64_t(index)).key("op").value(opName(rep.step.op)).key("text").value(formatOpStep(rep.step));
  writeIds(w, "createdHexes", r.createdHexes, "removedHexes", r.removedHexes);
  writeIds(w, "createdVertices", r.createdVertices, "removedVertices", r.removedVertices);
  w.key("delta").beginObject().key("V").value(r.dV).key("E").value(r.dE).key("F").value(r.dF).key("H").value(r.dH).endObject();
  w.key("sheets").beginObject();
  writeIds(w, "created", ch.sheetsCreated, "removed", ch.sheetsRemoved);
  w.key("changed").raw(idList(ch.sheetsChanged)).endObject();
  w.key("chords").beginObject();
  writeIds(w, "created", ch.chordsCreated, "removed", ch.chordsRemoved);
  w.key("changed").raw(idList(ch.chordsChanged)).endObject();
  w.key("inverse").value(r.inverse ? formatOpStep(*r.inverse) : std::string());
  if (!r.inverse) w.key("noInverse").value(r.noInverse);
  w.key("quality").raw(stepQualityJson(r.quality));
  w.endObject();
}

std::string stepReportJson(const StepReport& rep, size_t index) {
  JsonWriter w;
  writeStepReport(w, rep, index);
  return w.str();
}

std::string stepReportText(const StepReport& rep, size_t index) {
  const OpResult& r = rep.result;
  const DualChange& ch = rep.dual;
  std::string text = "step " + std::to_string(index) + ": " + formatOpStep(rep.step) + "\n";
  text += "  hexes created " + idList(r.createdHexes) + " removed " + idList(r.removedHexes) + "; vertices created " +
          idList(r.createdVertices) + " removed " + idList(r.removedVertices) + "\n";
  text += "  delta (V,E,F,H) = (" + signedNum(r.dV) + "," + signedNum(r.dE) + "," + signedNum(r.dF) + "," + signedNum(r.dH) + ")\n";
  text += "  sheets created " + idList(ch.sheetsCreated) + " removed " + idList(ch.sheetsRemoved) + " changed " +
          idList(ch.sheetsChanged) + "; chords created " + idList(ch.chordsCreated) + " removed " +
          idList(ch.chordsRemoved) + " changed " + idList(ch.chordsChanged) + "\n";
  std::string none = r.noInverse.empty() ? "(none; use undo)" : "(none: " + r.noInverse + "; use undo)";
  text += "  inverse: " + (r.inverse ? formatOpStep(*r.inverse) : none) + "\n";
  return text + stepQualityText(r.quality);
}

std::string applyReportJson(const std::vector<StepReport>& steps, const Complex& after,
                            const std::optional<std::string>& inverseInOutput) {
  JsonWriter w;
  w.beginObject().key("steps").beginArray();
  for (size_t k = 0; k < steps.size(); ++k) writeStepReport(w, steps[k], k + 1);
  Counts c = after.counts();
  w.endArray().key("counts").beginObject().key("vertices").value(c.vertices).key("edges").value(c.edges);
  w.key("quads").value(c.quads).key("hexes").value(c.hexes).endObject().key("positionsHash").value(positionsHash(after));
  w.key("inverseInOutput");
  if (inverseInOutput) w.value(*inverseInOutput);
  else w.raw("null");
  w.endObject();
  return w.str();
}

std::string flipListJson(const std::vector<FlipSummary>& flips) {
  JsonWriter w;
  w.beginArray();
  for (const FlipSummary& f : flips) {
    const FlipClass& fc = f.flip;
    w.beginObject().key("name").value(fc.name).key("inverse").value(fc.inverse);
    w.key("before").raw("[" + countsList(fc.interiorBefore) + "]").key("after").raw("[" + countsList(fc.interiorAfter) + "]");
    w.key("geometric").value(fc.geometric).key("decomposition");
    if (f.decomposition && f.decomposition->found) w.value(formatOpLog({1, f.decomposition->steps}));
    else w.raw("null");
    w.endObject();
  }
  w.endArray();
  return w.str();
}

std::string flipListText(const std::vector<FlipSummary>& flips) {
  std::string out;
  for (const FlipSummary& f : flips) {
    const FlipClass& fc = f.flip;
    const Counts& b = fc.interiorBefore;
    const Counts& a = fc.interiorAfter;
    Counts d{a.vertices - b.vertices, a.edges - b.edges, a.quads - b.quads, a.hexes - b.hexes, 0, 0, 0};
    out += fc.name + "  before (" + countsList(b) + ") -> after (" + countsList(a) + ")  delta (" + countsList(d) + ")  " +
           (fc.geometric ? "geometric" : "not geometric") + "  ";
    const StoredDecomposition* s = f.decomposition;
    if (s && s->found) out += std::to_string(s->steps.size()) + " atomic steps";
    else if (s) out += "no decomposition up to depth " + std::to_string(s->depthSearched) + " (" + std::to_string(s->states) + " states)";
    else out += "not searched";
    out += "\n";
  }
  return out;
}

}  // namespace hexdual::io
