// Ids ascending, once each: the one helper behind every "sort and unique" of hex, vertex, sheet or
// chord ids whose lists can be long (a sheet operation lists tens of thousands of hexes, and its
// dual update names a few hundred sheets thirty thousand times).
#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace hexdual {

// A long list against a range at most 256 ids per entry is put in order by a bitmap over the
// range, in linear time; a short one (or one with a negative id) is sorted.
inline void sortUniqueIds(std::vector<int32_t>& ids) {
  size_t words = 0;  // of the bitmap, when it pays
  if (ids.size() >= 4096) {
    const auto [lo, hi] = std::minmax_element(ids.begin(), ids.end());
    if (*lo >= 0 && size_t(*hi) / 64 + 1 <= 4 * ids.size()) words = size_t(*hi) / 64 + 1;
  }
  if (!words) {
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    return;
  }
  std::vector<uint64_t> bits(words, 0);
  for (int32_t id : ids) bits[size_t(id) / 64] |= uint64_t(1) << (size_t(id) % 64);
  ids.clear();
  for (size_t w = 0; w < words; ++w)
    for (uint64_t b = bits[w]; b; b &= b - 1) ids.push_back(int32_t(64 * w + size_t(__builtin_ctzll(b))));
}

}  // namespace hexdual
