// The scaled-Jacobian distribution of a whole mesh, as HexaLab reports it: minimum, maximum, mean,
// how many hexes are inverted or degenerate (<= 0), and a histogram (`hexdual quality`).
#pragma once
#include <array>
#include <cstdint>

#include "complex/complex.hpp"

namespace hexdual {

struct QualityStats {
  static constexpr int kBuckets =
      20;  // of width 0.1 over [-1, 1]; bucket k holds [-1+k/10, -1+(k+1)/10), the last includes 1
  int64_t hexes = 0;
  double min = 1, max = -1, mean = 0;  // min 1, max -1, mean 0 when there are no hexes
  int64_t nonPositive = 0;             // hexes with scaled Jacobian <= 0 (inverted or degenerate)
  std::array<int64_t, kBuckets> buckets{};
};

// Bucket of a scaled-Jacobian value (clamped to [-1, 1]).
int qualityBucket(double sj);
QualityStats qualityStats(const Complex& cx);

}  // namespace hexdual
