#include "layout/diagram_spread.hpp"

#include <algorithm>
#include <cmath>
#include <set>

namespace hexdual {

double diagramSpread(const SheetDiagram& d) {
  const size_t n = d.crossings.size();
  if (n < 2) return 1e9;
  // The closest pair by a sweep in x, keeping the points within the best distance so far ordered
  // by y: O(n log n) however crowded the drawing is.
  std::vector<Point2> p;
  p.reserve(n);
  for (const auto& c : d.crossings) p.push_back(c.p);
  std::sort(p.begin(), p.end(), [](Point2 a, Point2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  double best = 1e300;
  std::set<std::pair<double, size_t>> window;
  size_t left = 0;
  for (size_t i = 0; i < n; ++i) {
    const double r = std::sqrt(best);
    while (left < i && p[i].x - p[left].x > r) window.erase({p[left].y, left}), ++left;
    for (auto it = window.lower_bound({p[i].y - r, 0}); it != window.end() && it->first <= p[i].y + r; ++it) {
      double dx = p[i].x - p[it->second].x, dy = p[i].y - p[it->second].y;
      best = std::min(best, dx * dx + dy * dy);
    }
    window.insert({p[i].y, i});
  }
  const double pi = std::acos(-1.0), even = std::sqrt(pi / double(n));
  return std::sqrt(best) / even;
}

}  // namespace hexdual
