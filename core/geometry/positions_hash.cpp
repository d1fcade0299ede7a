#include "geometry/positions_hash.hpp"

#include <bit>
#include <cstdint>
#include <cstdio>

namespace hexdual {

std::string positionsHash(const Complex& cx) {
  uint64_t h = 14695981039346656037ull;
  auto mix = [&](uint64_t word) {
    for (int b = 0; b < 8; ++b) h = (h ^ ((word >> (8 * b)) & 0xff)) * 1099511628211ull;
  };
  for (VertexId v : cx.vertices()) {
    const Vec3 p = cx.position(v);
    mix(uint64_t(v));
    mix(std::bit_cast<uint64_t>(p.x));
    mix(std::bit_cast<uint64_t>(p.y));
    mix(std::bit_cast<uint64_t>(p.z));
  }
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", (unsigned long long)h);
  return buf;
}

}  // namespace hexdual
