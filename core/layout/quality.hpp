// Element quality: the scaled Jacobian of each hex (HexaLab, Verdict): at each corner the
// determinant of its three unit edge vectors; the hex's value is the minimum over its 8 corners.
#pragma once
#include <vector>

#include "complex/complex.hpp"
#include "geometry/scaled_jacobian.hpp"

namespace hexdual {

struct QualityReport {
  std::vector<float> scaledJacobian;  // per hex id (capacity); tombstones hold 1
  std::vector<int32_t> inverted;      // ids of hexes with scaled Jacobian <= 0, ascending
  double min = 1, max = -1;           // over live hexes (min 1, max -1 when there are none)
};

QualityReport measureQuality(const Complex& cx);

}  // namespace hexdual
