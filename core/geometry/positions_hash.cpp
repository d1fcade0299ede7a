#include "geometry/positions_hash.hpp"

#include <cstdint>
#include <cstdio>
#include <cstring>

namespace hexdual {

std::string positionsHash(const Complex& cx) {
  uint64_t h = 14695981039346656037ull;
  auto mix = [&](uint64_t word) {
    for (int b = 0; b < 8; ++b) h = (h ^ ((word >> (8 * b)) & 0xff)) * 1099511628211ull;
  };
  auto bits = [](double d) {  // std::bit_cast is missing from Emscripten 3.1.6's libc++
    uint64_t u;
    std::memcpy(&u, &d, sizeof u);
    return u;
  };
  for (VertexId v : cx.vertices()) {
    const Vec3 p = cx.position(v);
    mix(uint64_t(v));
    mix(bits(p.x));
    mix(bits(p.y));
    mix(bits(p.z));
  }
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", (unsigned long long)h);
  return buf;
}

}  // namespace hexdual
