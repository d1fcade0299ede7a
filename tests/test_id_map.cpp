// IdMap (core/complex/id_map.hpp), the flat map of the sheet operations' per-sheet tables: it
// keeps every entry across its growth, reports whether an emplace inserted, and finds no absent id.
#include <cstdio>
#include <map>
#include <random>

#include <doctest/doctest.h>

#include "complex/id_map.hpp"

using hexdual::IdMap;

TEST_CASE("IdMap: the same entries as std::map across growth, random ids (fixed seed)") {
  const uint32_t seed = 20261203;
  std::printf("IdMap: seed %u\n", seed);
  std::mt19937 rng(seed);
  IdMap<int32_t> m;
  std::map<int32_t, int32_t> ref;
  CHECK(m.empty());
  CHECK(m.find(7) == nullptr);
  for (int i = 0; i < 5000; ++i) {
    const int32_t id = int32_t(rng() % 20000), v = int32_t(rng() % 1000);
    auto [at, fresh] = m.emplace(id, v);
    auto [it, refFresh] = ref.emplace(id, v);
    CHECK(fresh == refFresh);
    CHECK(*at == it->second);  // an id already there keeps its first value
  }
  CHECK(m.size() == ref.size());
  for (int32_t id = 0; id < 20000; ++id) {
    auto it = ref.find(id);
    CHECK(m.count(id) == (it != ref.end()));
    CHECK(m.get(id, -1) == (it != ref.end() ? it->second : -1));
  }
}

TEST_CASE("IdMap: reserved up front, ids that collide in the low bits, id 0") {
  IdMap<int8_t> m(3);
  for (int32_t k = 0; k < 64; ++k) CHECK(m.emplace(k << 20, int8_t(k % 3)).second);
  CHECK(m.size() == 64);
  for (int32_t k = 0; k < 64; ++k) CHECK(m.at(k << 20) == k % 3);
  CHECK_FALSE(m.count(1));
  CHECK_FALSE(m.emplace(0, 5).second);
  CHECK(m.at(0) == 0);
}
