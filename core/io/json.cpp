#include "io/json.hpp"

#include <cmath>
#include <cstdio>

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

std::string infoJson(const Complex& cx, const Dual& dual, const ReadReport* file) {
  Counts c = cx.counts();
  JsonWriter w;
  w.beginObject();
  w.key("vertices").value(c.vertices).key("edges").value(c.edges).key("quads").value(c.quads);
  w.key("hexes").value(c.hexes).key("boundaryQuads").value(c.boundaryQuads);
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
  w.endArray();
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
  return out;
}

}  // namespace hexdual::io
