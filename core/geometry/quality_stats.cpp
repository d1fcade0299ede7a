#include "geometry/quality_stats.hpp"

#include <algorithm>

#include "geometry/scaled_jacobian.hpp"

namespace hexdual {

int qualityBucket(double sj) {
  const int k = int((std::clamp(sj, -1.0, 1.0) + 1.0) * 10.0);  // exact for the bucket edges k/10 up to rounding
  return std::clamp(k, 0, QualityStats::kBuckets - 1);
}

QualityStats qualityStats(const Complex& cx) {
  QualityStats s;
  double sum = 0;
  for (HexId h : cx.hexes()) {
    const double sj = scaledJacobian(cx, h);
    ++s.hexes;
    sum += sj;
    s.min = std::min(s.min, sj);
    s.max = std::max(s.max, sj);
    s.nonPositive += sj <= 0;
    ++s.buckets[size_t(qualityBucket(sj))];
  }
  if (s.hexes > 0) s.mean = sum / double(s.hexes);
  return s;
}

}  // namespace hexdual
