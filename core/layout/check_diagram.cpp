#include "layout/check_diagram.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <unordered_map>

#include "layout/cut_graph.hpp"

namespace hexdual {

namespace {

bool segmentsMeet(Point2 a, Point2 b, Point2 c, Point2 d, Point2* at) {
  double d1x = b.x - a.x, d1y = b.y - a.y, d2x = d.x - c.x, d2y = d.y - c.y;
  double den = d1x * d2y - d1y * d2x;
  if (std::fabs(den) < 1e-12) return false;  // parallel (collinear overlaps are not produced here)
  double t = ((c.x - a.x) * d2y - (c.y - a.y) * d2x) / den, u = ((c.x - a.x) * d1y - (c.y - a.y) * d1x) / den;
  const double eps = 1e-9;
  if (t < -eps || t > 1 + eps || u < -eps || u > 1 + eps) return false;
  *at = {a.x + t * d1x, a.y + t * d1y};
  return true;
}
bool near(Point2 a, Point2 b) {
  return (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) < 1e-14;
}  // closer than 1e-7
bool insidePolygon(Point2 p, const std::vector<Point2>& poly) {
  bool in = false;
  for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
    if ((poly[i].y > p.y) != (poly[j].y > p.y) &&
        p.x < (poly[j].x - poly[i].x) * (p.y - poly[i].y) / (poly[j].y - poly[i].y) + poly[i].x)
      in = !in;
  return in;
}

// Crossings by rounded coordinates, so that "which crossing is at p" is a hash lookup.
class CrossingIndex {
 public:
  explicit CrossingIndex(const SheetDiagram& d) : d_(d) {
    for (size_t k = 0; k < d.crossings.size(); ++k) at_[key(d.crossings[k].p, 0, 0)].push_back(k);
  }
  template <class F>
  void forEachNear(Point2 p, F f) const {
    for (int ox = -1; ox <= 1; ++ox)
      for (int oy = -1; oy <= 1; ++oy) {
        auto it = at_.find(key(p, ox, oy));
        if (it == at_.end()) continue;
        for (size_t k : it->second)
          if (near(p, d_.crossings[k].p)) f(k);
      }
  }

 private:
  static std::pair<long long, long long> cell(Point2 p) { return {std::llround(p.x * 1e6), std::llround(p.y * 1e6)}; }
  static uint64_t key(Point2 p, int ox, int oy) {
    auto [x, y] = cell(p);
    return uint64_t(x + ox) * 0x9E3779B97F4A7C15ull ^ uint64_t(y + oy);
  }
  const SheetDiagram& d_;
  std::unordered_map<uint64_t, std::vector<size_t>> at_;
};

struct Seg {
  Point2 a, b;
  size_t chord, index;
};

// Pairs of chord segments that meet away from a crossing, found with a uniform grid over the
// segments' bounding boxes; each pair is tested in the one cell holding the corner of the
// intersection of their boxes.
void checkChordsMeetAtCrossings(const SheetDiagram& d, const CrossingIndex& crossings,
                                void (*fail)(const SheetDiagram&, const std::string&)) {
  std::vector<Seg> segs;
  for (size_t k = 0; k < d.chords.size(); ++k)
    for (size_t i = 0; i + 1 < d.chords[k].points.size(); ++i)
      segs.push_back({d.chords[k].points[i], d.chords[k].points[i + 1], k, i});
  if (segs.empty()) return;
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (const Seg& g : segs) {
    x0 = std::min({x0, g.a.x, g.b.x});
    y0 = std::min({y0, g.a.y, g.b.y});
    x1 = std::max({x1, g.a.x, g.b.x});
    y1 = std::max({y1, g.a.y, g.b.y});
  }
  const int G = std::max(1, int(std::sqrt(double(segs.size()))));
  const double cw = std::max((x1 - x0) / G, 1e-12), ch = std::max((y1 - y0) / G, 1e-12);
  auto cellOf = [&](double v, double lo, double w) { return std::clamp(int((v - lo) / w), 0, G - 1); };
  auto lox = [](const Seg& g) { return std::min(g.a.x, g.b.x) - 1e-9; };
  auto loy = [](const Seg& g) { return std::min(g.a.y, g.b.y) - 1e-9; };
  std::vector<std::vector<size_t>> grid(size_t(G) * size_t(G));
  for (size_t i = 0; i < segs.size(); ++i) {
    const Seg& g = segs[i];
    int cx0 = cellOf(lox(g), x0, cw), cx1 = cellOf(std::max(g.a.x, g.b.x) + 1e-9, x0, cw);
    int cy0 = cellOf(loy(g), y0, ch), cy1 = cellOf(std::max(g.a.y, g.b.y) + 1e-9, y0, ch);
    for (int cxx = cx0; cxx <= cx1; ++cxx)
      for (int cyy = cy0; cyy <= cy1; ++cyy) grid[size_t(cxx) * size_t(G) + size_t(cyy)].push_back(i);
  }
  for (size_t cell = 0; cell < grid.size(); ++cell) {
    const auto& list = grid[cell];
    for (size_t p = 0; p < list.size(); ++p)
      for (size_t q = p + 1; q < list.size(); ++q) {
        const Seg &s = segs[list[p]], &t = segs[list[q]];
        size_t home = size_t(cellOf(std::max(lox(s), lox(t)), x0, cw)) * size_t(G) +
                      size_t(cellOf(std::max(loy(s), loy(t)), y0, ch));
        if (home != cell) continue;  // tested in another cell
        bool consecutive = s.chord == t.chord && (s.index + 1 == t.index || t.index + 1 == s.index ||
                                                  (d.chords[s.chord].closed && (s.index == 0 || t.index == 0)));
        Point2 at;
        if (!segmentsMeet(s.a, s.b, t.a, t.b, &at)) continue;
        if (consecutive && (near(at, s.a) || near(at, s.b))) continue;
        bool atCrossing = false;
        crossings.forEachNear(at, [&](size_t) { atCrossing = true; });
        if (!atCrossing) {
          char buf[160];
          std::snprintf(buf, sizeof buf, "chords %d and %d meet at (%.4f, %.4f), which is not a hex crossing",
                        d.chords[s.chord].chord, d.chords[t.chord].chord, at.x, at.y);
          fail(d, buf);
        }
      }
  }
}

// The sides of a fundamental polygon run round its outer loop, and each seam is drawn twice.
void checkPolygonSides(const SheetDiagram& d, void (*fail)(const SheetDiagram&, const std::string&)) {
  if (d.arcs.empty()) return;
  for (size_t k = 0; k < d.arcs.size(); ++k) {
    const auto& a = d.arcs[k];
    const auto& b = d.arcs[(k + 1) % d.arcs.size()];
    if (a.points.size() < 2 || !near(a.points.back(), b.points.front()))
      fail(d, "polygon side " + a.label + " does not end where the next begins");
  }
  size_t points = 0;
  for (const auto& a : d.arcs) points += a.points.size() - 1;
  if (d.loops.empty() || d.loops[0].size() != points)
    fail(d, "the polygon's sides do not run round its outer loop");
  std::unordered_map<int, std::vector<const SheetDiagram::Arc*>> byPair;
  for (const auto& a : d.arcs)
    if (a.pair >= 0) byPair[a.pair].push_back(&a);
  for (const auto& [pair, sides] : byPair) {
    if (sides.size() != 2)
      fail(d, "seam " + seamLabel(pair, 1) + " is drawn on " + std::to_string(sides.size()) + " sides, not 2");
    if (sides[0]->label != seamLabel(pair, sides[0]->sign) || sides[1]->label != seamLabel(pair, sides[1]->sign))
      fail(d, "seam " + seamLabel(pair, 1) + " has a wrong label");
  }
}

[[noreturn]] void failWith(const SheetDiagram& d, const std::string& m) {
  throw Error("sheet diagram " + std::to_string(d.sheet) + ": " + m);
}

}  // namespace

void checkDiagram(const SheetDiagram& d, size_t expectedSlots) {
  auto fail = [&](const std::string& m) { failWith(d, m); };
  // Every slot exactly once.
  std::vector<std::pair<HexId, int>> seen;
  for (const auto& c : d.crossings) seen.push_back({c.hex, c.axis});
  std::sort(seen.begin(), seen.end());
  if (std::adjacent_find(seen.begin(), seen.end()) != seen.end()) fail("a slot appears twice");
  if (seen.size() != expectedSlots)
    fail(std::to_string(seen.size()) + " crossings for " + std::to_string(expectedSlots) + " slots");
  // Every crossing joins exactly two chord passes (failing at the third, so that a collapsed
  // layout with thousands of points in one place fails fast).
  CrossingIndex index(d);
  std::vector<int> passes(d.crossings.size(), 0);
  auto tooMany = [&](size_t k) {
    fail("crossing of hex " + std::to_string(d.crossings[k].hex) + " joins more than 2 chord passes");
  };
  for (const auto& ch : d.chords)
    for (Point2 p : ch.points)
      index.forEachNear(p, [&](size_t k) {
        if (++passes[k] > 2) tooMany(k);
      });
  for (size_t k = 0; k < d.crossings.size(); ++k)
    if (passes[k] != 2)
      fail("crossing of hex " + std::to_string(d.crossings[k].hex) + " joins " + std::to_string(passes[k]) +
           " chord passes, not 2");
  // Chords meet only at crossings (or where consecutive segments join).
  checkChordsMeetAtCrossings(d, index, failWith);
  checkPolygonSides(d, failWith);
  // Interior points inside the outer loop (and outside the inner one).
  if (d.loops.empty()) return;
  for (const auto& c : d.crossings) {
    if (c.outside) continue;
    if (!insidePolygon(c.p, d.loops[0]))
      fail("crossing of hex " + std::to_string(c.hex) + " lies outside the outer loop");
    if (d.loops.size() > 1 && insidePolygon(c.p, d.loops[1]))
      fail("crossing of hex " + std::to_string(c.hex) + " lies inside the inner loop");
  }
}

}  // namespace hexdual
