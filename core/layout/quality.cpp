#include "layout/quality.hpp"

#include <algorithm>

namespace hexdual {

QualityReport measureQuality(const Complex& cx) {
  QualityReport q;
  q.scaledJacobian.assign(size_t(cx.hexCapacity()), 1.0f);
  for (HexId h : cx.hexes()) {
    double sj = scaledJacobian(cx, h);
    q.scaledJacobian[size_t(h)] = float(sj);
    if (sj <= 0) q.inverted.push_back(h);
    q.min = std::min(q.min, sj);
    q.max = std::max(q.max, sj);
  }
  return q;
}

}  // namespace hexdual
