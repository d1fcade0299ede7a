#include "io/diagram_svg.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <unordered_map>
#include <vector>

#include "layout/palette.hpp"

namespace hexdual {

namespace {

std::string escapeXml(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '&')
      out += "&amp;";
    else
      out += c;
  }
  return out;
}

struct Canvas {
  double S = 200, M = 1.2;  // scale; margin in diagram units
  double cx = 0, cy = 0;    // the drawing's centre
  double hx = 0, hy = 0;    // half its width and height with the margin, in diagram units
  double X(double x) const { return S * (x - cx + hx); }
  double Y(double y) const { return S * (cy - y + hy); }
  std::string points(const std::vector<Point2>& ps) const {
    std::string out;
    char buf[64];
    for (Point2 p : ps) {
      std::snprintf(buf, sizeof buf, "%.1f,%.1f ", X(p.x), Y(p.y));
      out += buf;
    }
    return out;
  }
};

// A seam side: thick, in its pair's colour, an arrow along the gluing direction at its middle,
// and its label just outside the circle.
std::string seamSvg(const Canvas& cv, const SheetDiagram::Arc& a) {
  if (a.pair < 0 || a.points.size() < 2) return "";
  std::string colour = palette::seamColor(a.pair);
  std::string out = "<polyline points=\"" + cv.points(a.points) + "\" fill=\"none\" stroke=\"" + colour +
                    "\" stroke-width=\"4\" stroke-opacity=\"0.7\"><title>seam " + a.label + "</title></polyline>\n";
  size_t k = (a.points.size() - 1) / 2;
  Point2 p = a.points[k], q = a.points[k + 1];
  if (a.sign < 0) std::swap(p, q);
  double dx = cv.X(q.x) - cv.X(p.x), dy = cv.Y(q.y) - cv.Y(p.y), len = std::hypot(dx, dy);
  Point2 m{0.5 * (p.x + q.x), 0.5 * (p.y + q.y)};
  char buf[320];
  if (len > 1e-9) {
    dx /= len;
    dy /= len;
    double mx = cv.X(m.x), my = cv.Y(m.y);
    std::snprintf(buf, sizeof buf, "<polygon points=\"%.1f,%.1f %.1f,%.1f %.1f,%.1f\" fill=\"%s\"/>\n", mx + 7 * dx,
                  my + 7 * dy, mx - 5 * dx + 5 * dy, my - 5 * dy - 5 * dx, mx - 5 * dx - 5 * dy, my - 5 * dy + 5 * dx,
                  colour.c_str());
    out += buf;
  }
  double r = std::hypot(m.x, m.y), lx = r > 1e-9 ? m.x / r * 1.09 : m.x, ly = r > 1e-9 ? m.y / r * 1.09 : m.y;
  std::snprintf(buf, sizeof buf,
                "<text x=\"%.1f\" y=\"%.1f\" font-size=\"14\" font-weight=\"bold\" text-anchor=\"middle\" "
                "fill=\"%s\">%s</text>\n",
                cv.X(lx), cv.Y(ly) + 5, colour.c_str(), a.label.c_str());
  return out + buf;
}

// Per crossing: the distance to its nearest other crossing (diagram units; 1e9 alone), from a
// grid of cells `cell` wide (farther neighbours count as `cell` away: far enough for a label).
std::vector<double> nearestCrossing(const SheetDiagram& d, double cell) {
  std::unordered_map<uint64_t, std::vector<size_t>> grid;
  auto key = [](long long x, long long y) { return uint64_t(x) * 0x9E3779B97F4A7C15ull ^ uint64_t(y); };
  auto at = [&](Point2 p) { return std::pair{(long long)std::floor(p.x / cell), (long long)std::floor(p.y / cell)}; };
  for (size_t k = 0; k < d.crossings.size(); ++k) {
    auto [x, y] = at(d.crossings[k].p);
    grid[key(x, y)].push_back(k);
  }
  std::vector<double> near(d.crossings.size(), cell);
  for (size_t k = 0; k < d.crossings.size(); ++k) {
    auto [x, y] = at(d.crossings[k].p);
    for (long long ox = -1; ox <= 1; ++ox)
      for (long long oy = -1; oy <= 1; ++oy) {
        auto it = grid.find(key(x + ox, y + oy));
        if (it == grid.end()) continue;
        for (size_t j : it->second)
          if (j != k)
            near[k] = std::min(near[k], std::hypot(d.crossings[j].p.x - d.crossings[k].p.x,
                                                   d.crossings[j].p.y - d.crossings[k].p.y));
      }
  }
  return near;
}

}  // namespace

std::string diagramSvg(const SheetDiagram& d) {
  Canvas cv;
  cv.M = d.openedHex >= 0 ? 1.65 : 1.2;
  cv.hx = cv.hy = cv.M;
  // A disk drawn in the shape its quads give (a long rectangle, a square) is framed by its box and
  // drawn as large as the circle would be; local views and opened spheres keep the circle's frame.
  // The outer loop's box and area (the unit circle's when there is none).
  double x0 = -1, x1 = 1, y0 = -1, y1 = 1, twice = 2 * std::acos(-1.0);
  if (!d.loops.empty() && d.loops[0].size() >= 3) {
    const std::vector<Point2>& loop = d.loops[0];
    x0 = y0 = 1e300, x1 = y1 = -1e300, twice = 0;
    for (size_t k = 0; k < loop.size(); ++k) {
      const Point2 p = loop[k], q = loop[(k + 1) % loop.size()];
      x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
      twice += p.x * q.y - q.x * p.y;
    }
  }
  double grow = 1, area = std::acos(-1.0);  // what the crossings spread over: the unit disk, or the loop
  const bool framed = !d.local && d.openedHex < 0 && !d.loops.empty() && d.loops[0].size() >= 3;
  if (framed) {
    grow = 2 / std::max({x1 - x0, y1 - y0, 0.2});
    area = std::max(std::abs(twice) / 2, 1e-3);
    cv.cx = (x0 + x1) / 2, cv.cy = (y0 + y1) / 2;
    cv.hx = (x1 - x0) / 2, cv.hy = (y1 - y0) / 2;  // the margin is added below, once the scale is known
  }
  // Readable at scale: the canvas grows with the number of crossings so that evenly spread ones
  // (over the unit disk, or over a shaped disk's own loop) are 24 px apart, room for their labels;
  // markers and strokes shrink where crossings are closer; a crossing is labelled only when its
  // label fits before its nearest neighbour (every crossing has its id as a tooltip).
  const double even = std::sqrt(area / double(std::max<size_t>(d.crossings.size(), 1)));
  size_t digits = 1;  // the longest hex id: evenly spread crossings get room for it
  for (const auto& c : d.crossings) digits = std::max(digits, std::to_string(c.hex).size());
  cv.S = std::clamp(std::max(24.0, 12 + 6.2 * double(digits)) / even, 200.0 * grow, 2400.0 * grow);
  if (framed) cv.hx += 36 / cv.S, cv.hy += 36 / cv.S;  // a margin of 36 px: the boundary marks and labels
  const double px = even * cv.S, marker = std::clamp(0.3 * px, 1.5, 4.5), stroke = std::clamp(0.15 * px, 0.6, 2.2);
  const std::vector<double> near = nearestCrossing(d, 24 / cv.S);
  char sw[16];
  std::snprintf(sw, sizeof sw, "%.3g", stroke);
  const std::string strokeWidth = sw;
  const double S = cv.S;
  char buf[256];
  std::string out;
  // The title under the drawing, and the note under it in lines that fit the width (about 6.2 px a character).
  std::vector<std::string> noteLines;
  {
    const size_t perLine = size_t(std::max(20.0, (2 * S * cv.hx - 16) / 6.2));
    std::string line;
    for (size_t at = 0; at < d.note.size();) {
      size_t end = d.note.find(' ', at);
      if (end == std::string::npos) end = d.note.size();
      const std::string word = d.note.substr(at, end - at);
      if (!line.empty() && line.size() + 1 + word.size() > perLine) noteLines.push_back(line), line.clear();
      line += (line.empty() ? "" : " ") + word;
      at = end + 1;
    }
    if (!line.empty()) noteLines.push_back(line);
  }
  const double foot = 24 + 15 * double(noteLines.size());
  std::snprintf(
      buf, sizeof buf,
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\" "
      "font-family=\"sans-serif\" font-size=\"11\">\n<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n",
      2 * S * cv.hx, 2 * S * cv.hy + foot, 2 * S * cv.hx, 2 * S * cv.hy + foot);
  out += buf;
  // "sheet 6 · annulus", or "sheet 6 · annulus · polygon" when drawn another way (as the explorer's title).
  const std::string how = d.method == d.topology ? "" : " · " + d.method;
  std::snprintf(buf, sizeof buf, "<text x=\"8\" y=\"%.0f\" font-size=\"13\">sheet %d · %s%s</text>\n",
                2 * S * cv.hy + 16, d.sheet, d.topology.c_str(), how.c_str());
  out += buf;
  if (!d.note.empty()) {  // which face was opened, the polygon's word, why a disk is drawn as it is
    out += "<title>" + escapeXml(d.note) + "</title>\n";
    for (size_t k = 0; k < noteLines.size(); ++k) {
      std::snprintf(buf, sizeof buf, "<text x=\"8\" y=\"%.0f\" fill=\"#555\">", 2 * S * cv.hy + 33 + 15 * double(k));
      out += buf + escapeXml(noteLines[k]) + "</text>\n";
    }
  }
  if (d.local) {
    std::snprintf(
        buf, sizeof buf,
        "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"%.1f\" fill=\"none\" stroke=\"#555\" stroke-dasharray=\"6 5\"/>\n",
        cv.X(0), cv.Y(0), S);
    out += buf;
  }
  for (size_t k = 0; k < d.loops.size(); ++k)
    out += "<polygon points=\"" + cv.points(d.loops[k]) + "\" fill=\"" + std::string(k == 0 ? "#f4f6fa" : "white") +
           "\" stroke=\"#222\" stroke-width=\"" + (d.local ? "0.8" : "1.6") + "\"" +
           (d.local ? " stroke-dasharray=\"2 3\"" : "") + "/>\n";
  for (const auto& a : d.arcs) out += seamSvg(cv, a);
  for (const auto& c : d.chords)
    out += "<polyline points=\"" + cv.points(c.points) + "\" fill=\"none\" stroke=\"" + palette::chordColor(c.chord) +
           "\" stroke-width=\"" + strokeWidth + "\"><title>chord " + std::to_string(c.chord) + " (with sheet " +
           std::to_string(c.otherSheet) + ")</title></polyline>\n";
  for (const auto& b : d.boundary) {
    std::snprintf(buf, sizeof buf, "<rect x=\"%.1f\" y=\"%.1f\" width=\"5\" height=\"5\" fill=\"#222\"/>\n",
                  cv.X(b.p.x) - 2.5, cv.Y(b.p.y) - 2.5);
    out += buf;
  }
  for (size_t k = 0; k < d.crossings.size(); ++k) {
    const auto& c = d.crossings[k];
    std::snprintf(buf, sizeof buf,
                  "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"%.1f\" fill=\"%s\" stroke=\"#111\"><title>hex %d</title></circle>",
                  cv.X(c.p.x), cv.Y(c.p.y), marker, c.outside ? "#fc6" : "#fff", c.hex);
    out += buf;
    if (near[k] * cv.S >= std::max(22.0, 8 + 6.2 * double(std::to_string(c.hex).size()))) {  // room for its digits
      // Up and right of its crossing, but under-left of it where it would not fit before the loop's
      // right side (under, as the next column's labels sit up-right, above the same row line).
      const bool left = (x1 - c.p.x) * cv.S < 11 + 6.2 * double(std::to_string(c.hex).size()), under = left;
      std::snprintf(buf, sizeof buf, "<text x=\"%.1f\" y=\"%.1f\"%s>%d</text>", cv.X(c.p.x) + (left ? -6 : 6),
                    cv.Y(c.p.y) + (under ? 15 : -6), left ? " text-anchor=\"end\"" : "", c.hex);
      out += buf;
    }
    out += "\n";
  }
  return out + "</svg>\n";
}

}  // namespace hexdual
