// sortUniqueIds (core/complex/sorted_ids.hpp), behind the tracker's and the sheet operations' long
// id lists: both its paths (a sort for short lists or wide ranges, a bitmap for long dense ones)
// give what std::sort + std::unique gives.
#include <algorithm>
#include <cstdio>
#include <random>
#include <vector>

#include <doctest/doctest.h>

#include "complex/sorted_ids.hpp"

using hexdual::sortUniqueIds;

namespace {
std::vector<int32_t> reference(std::vector<int32_t> ids) {
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}
}  // namespace

TEST_CASE("sortUniqueIds: ascending and once each on both paths, random lists (fixed seed)") {
  const uint32_t seed = 20261207;
  std::printf("sortUniqueIds: seed %u\n", seed);
  std::mt19937 rng(seed);
  struct Case {
    size_t size;
    uint32_t range;
    bool negative;
  };
  // Short (sorted), long and dense (bitmap: a sheet extraction's born hexes, its changed sheets),
  // long and sparse (sorted: a range over 256 ids per entry), long with a negative id (sorted).
  const Case cases[] = {{0, 10, false},       {1, 10, false},           {4095, 1000, false},  {4096, 300, false},
                        {30000, 300, false},  {60000, 1000000, false},  {5000, 10000000, false},
                        {20000, 5000, true}};
  for (const Case& c : cases) {
    std::vector<int32_t> ids(c.size);
    for (int32_t& id : ids) id = int32_t(rng() % c.range);
    if (c.negative && !ids.empty()) ids[ids.size() / 2] = -3;
    const std::vector<int32_t> want = reference(ids);
    sortUniqueIds(ids);
    CAPTURE(c.size);
    CAPTURE(c.range);
    CHECK(ids == want);
  }
}

TEST_CASE("sortUniqueIds: the largest id and id 0 survive the bitmap; repeats collapse") {
  std::vector<int32_t> ids;
  for (int i = 0; i < 5000; ++i) ids.push_back(i % 2 ? 0 : 16383);  // 5,000 entries, range 16,384: bitmap
  ids.push_back(64);
  ids.push_back(63);
  sortUniqueIds(ids);
  CHECK(ids == std::vector<int32_t>{0, 63, 64, 16383});
}
