#include "io/geometry_json.hpp"

#include <cstdio>

#include "io/json.hpp"

namespace hexdual::io {

namespace {

void writeByValence(JsonWriter& w, const char* key, const std::map<int, int64_t>& m) {
  w.key(key).beginObject();
  for (auto [valence, n] : m) w.key(std::to_string(valence)).value(n);
  w.endObject();
}

std::string byValenceText(const std::map<int, int64_t>& m) {
  std::string out;
  for (auto [valence, n] : m) out += (out.empty() ? "" : ", ") + std::string("valence ") + std::to_string(valence) + ": " + std::to_string(n);
  return out.empty() ? "" : " (" + out + ")";
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

}  // namespace

std::string singularityCountsJson(const SingularityCounts& c) {
  JsonWriter w;
  w.beginObject().key("interiorEdges").value(c.interiorEdges).key("boundaryEdges").value(c.boundaryEdges);
  writeByValence(w, "interiorByValence", c.interiorByValence);
  writeByValence(w, "boundaryByValence", c.boundaryByValence);
  w.key("vertices").value(c.vertices).key("boundaryVertices").value(c.boundaryVertices).key("curves").value(c.curves);
  return w.endObject().str();
}

std::string singularityGraphJson(const SingularityGraph& g) {
  JsonWriter w;
  w.beginObject().key("counts").raw(singularityCountsJson(g.counts)).key("edges").beginArray();
  for (const SingularEdge& e : g.edges) {
    w.beginObject().key("hex").value(e.ref.hex).key("edge").value(e.ref.edge);
    w.key("vertices").raw(idList({e.vertices[0], e.vertices[1]})).key("valence").value(e.valence);
    w.key("boundary").value(e.boundary).key("curve").value(e.curve).endObject();
  }
  w.endArray().key("vertices").beginArray();
  for (const SingularVertex& v : g.vertices)
    w.beginObject().key("vertex").value(v.vertex).key("boundary").value(v.boundary).key("degree").value(v.degree).endObject();
  w.endArray().key("curves").beginArray();
  for (const SingularCurve& c : g.curves) {
    w.beginObject().key("edges").raw(idList(c.edges)).key("valence").value(c.valence).key("boundary").value(c.boundary);
    w.key("closed").value(c.closed).key("ends").raw(c.closed ? "[]" : idList({c.ends[0], c.ends[1]})).endObject();
  }
  return w.endArray().endObject().str();
}

std::string singularityCountsText(const SingularityCounts& c) {
  return "singular edges: interior " + std::to_string(c.interiorEdges) + byValenceText(c.interiorByValence) + ", boundary " +
         std::to_string(c.boundaryEdges) + byValenceText(c.boundaryByValence) + "; irregular vertices " +
         std::to_string(c.vertices) + " (" + std::to_string(c.boundaryVertices) + " on the boundary); curves " +
         std::to_string(c.curves) + "\n";
}

std::string edgeDualJson(const EdgeDual& d) {
  JsonWriter w;
  w.beginObject().key("hex").value(d.ref.hex).key("edge").value(d.ref.edge).key("valence").value(d.valence);
  w.key("boundary").value(d.boundary).key("sheet").value(d.sheet).key("hexes").raw(idList(d.hexes)).key("quads").beginArray();
  for (const EdgeDual::Quad& q : d.quads)
    w.beginObject().key("hex").value(q.quad.hex).key("face").value(q.quad.face).key("chord").value(q.chord).key("sheet").value(q.sheet).endObject();
  w.endArray().key("chords").raw(idList(d.chords)).key("sheets").raw(idList(d.sheets));
  return w.endObject().str();
}

std::string qualityStatsJson(const QualityStats& s) {
  JsonWriter w;
  w.beginObject().key("hexes").value(s.hexes).key("min").value(s.min).key("max").value(s.max).key("mean").value(s.mean);
  w.key("nonPositive").value(s.nonPositive).key("buckets").beginArray();
  for (int64_t n : s.buckets) w.value(n);
  return w.endArray().endObject().str();
}

std::string qualityStatsText(const QualityStats& s) {
  std::string out = "hexes " + std::to_string(s.hexes) + "\nscaled Jacobian: min " + number(s.min) + ", max " + number(s.max) +
                    ", mean " + number(s.mean) + "; " + std::to_string(s.nonPositive) + " <= 0\n";
  for (int k = 0; k < QualityStats::kBuckets; ++k) {
    if (s.buckets[size_t(k)] == 0) continue;
    char row[96];
    std::snprintf(row, sizeof row, "  [%5.2f, %5.2f%c %lld\n", -1 + k / 10.0, -1 + (k + 1) / 10.0,
                  k + 1 == QualityStats::kBuckets ? ']' : ')', (long long)s.buckets[size_t(k)]);
    out += row;
  }
  return out;
}

std::string stepQualityJson(const StepQuality& q) {
  if (!q.measured) return "null";
  JsonWriter w;
  w.beginObject().key("smoothed").value(q.smoothed).key("before").value(q.before).key("after").value(q.after);
  w.key("afterRegular").value(q.afterRegular).key("inverted").raw(idList(q.inverted)).key("pinned").raw(idList(q.pinned));
  w.key("degenerate").raw(idList(q.degenerate)).key("moved").raw(idList(q.moved)).key("rings").value(int64_t(q.rings));
  w.key("kept").value(q.kept);
  w.key("evaluations").value(q.evaluations);
  return w.endObject().str();
}

std::string stepQualityText(const StepQuality& q) {
  if (!q.measured) return "";
  std::string text = "  quality: min scaled Jacobian " + number(q.before) + " -> " + number(q.after);
  if (q.kept)
    text += " (smoothing kept the operation's placement: it left fewer hexes newly inverted)";
  else if (q.smoothed)
    text += " (smoothed, " + std::to_string(q.moved.size()) + " vertices moved" +
            (q.rings ? ", region widened " + std::to_string(q.rings) + (q.rings == 1 ? " ring" : " rings") : "") + ")";
  else
    text += " (not smoothed)";
  if (!q.inverted.empty()) text += "; inverted " + idList(q.inverted);
  if (!q.pinned.empty())
    text += " (pinned by the boundary: " + idList(q.pinned) + ", proved: no placement with the boundary fixed makes every hex here valid)";
  if (!q.degenerate.empty()) text += "; degenerate by construction " + idList(q.degenerate) + ", min of the others " + number(q.afterRegular);
  return text + "\n";
}

}  // namespace hexdual::io
