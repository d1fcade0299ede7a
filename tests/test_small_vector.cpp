// SmallVector (core/complex/small_vector.hpp), the tracker's per-chord pieces and per-label cuts:
// the same contents as std::vector through every operation the tracker uses, in place and on the
// heap, and copies and moves that keep their contents and leave the source empty (moves) or as it
// was (copies).
#include <cstdio>
#include <random>
#include <utility>
#include <vector>

#include <doctest/doctest.h>

#include "complex/small_vector.hpp"

using hexdual::SmallVector;

namespace {
struct Cut {
  int32_t lo, hi, chord;
  bool operator==(const Cut&) const = default;
};
template <class V>
std::vector<Cut> contents(const V& v) {
  return std::vector<Cut>(v.begin(), v.end());
}
}  // namespace

TEST_CASE("SmallVector: in place up to N, on the heap beyond, the same contents as std::vector") {
  SmallVector<Cut, 3> v;
  CHECK(v.empty());
  CHECK(v.capacity() == 3);
  for (int32_t i = 0; i < 3; ++i) v.push_back({i, i + 1, 7});
  CHECK(v.capacity() == 3);  // still in place
  v.push_back({3, 4, 7});
  CHECK(v.size() == 4);
  CHECK(v.capacity() == 6);  // moved to the heap, doubled
  CHECK(v[0] == Cut{0, 1, 7});
  CHECK(v.back() == Cut{3, 4, 7});
  v.erase(v.begin() + 1);
  CHECK(contents(v) == std::vector<Cut>{{0, 1, 7}, {2, 3, 7}, {3, 4, 7}});
  v.clear();
  CHECK(v.empty());
  CHECK(v.capacity() == 6);  // clear keeps the room
  v.assign(5, Cut{1, 2, 3});
  CHECK(contents(v) == std::vector<Cut>(5, Cut{1, 2, 3}));
}

TEST_CASE("SmallVector: an entry of the list pushed onto it as it grows, and assigned from its own range") {
  SmallVector<Cut, 2> v;
  v.push_back({1, 2, 3});
  v.push_back(v[0]);
  v.push_back(v[1]);  // full in place: moves to the heap while reading v[1]
  CHECK(contents(v) == std::vector<Cut>(3, Cut{1, 2, 3}));
  v.push_back({4, 5, 6});
  v.push_back(v[3]);  // full on the heap: regrows while reading v[3]
  CHECK(v.size() == 5);
  CHECK(v[4] == Cut{4, 5, 6});
  v.assign(v.begin() + 2, v.end());  // its own last three entries, overlapping where they go
  CHECK(contents(v) == std::vector<Cut>{{1, 2, 3}, {4, 5, 6}, {4, 5, 6}});
}

TEST_CASE("SmallVector: copies and moves, in place and on the heap") {
  for (size_t n : {size_t(0), size_t(1), size_t(2), size_t(3), size_t(9)}) {
    CAPTURE(n);
    SmallVector<Cut, 2> a;
    std::vector<Cut> ref;
    for (size_t i = 0; i < n; ++i) {
      a.push_back({int32_t(i), int32_t(2 * i), -1});
      ref.push_back({int32_t(i), int32_t(2 * i), -1});
    }
    SmallVector<Cut, 2> copy(a);
    CHECK(contents(copy) == ref);
    CHECK(contents(a) == ref);
    SmallVector<Cut, 2> moved(std::move(copy));
    CHECK(contents(moved) == ref);
    CHECK(copy.empty());  // NOLINT(bugprone-use-after-move): a moved-from list is empty
    SmallVector<Cut, 2> assigned;
    assigned.push_back({9, 9, 9});
    assigned.push_back({9, 9, 9});
    assigned.push_back({9, 9, 9});  // on the heap before the assignment
    assigned = moved;
    CHECK(contents(assigned) == ref);
    SmallVector<Cut, 2> moveAssigned;
    moveAssigned = std::move(moved);
    CHECK(contents(moveAssigned) == ref);
    SmallVector<Cut, 2> other;
    other.push_back({5, 6, 7});
    std::swap(other, moveAssigned);
    CHECK(contents(other) == ref);
    CHECK(contents(moveAssigned) == std::vector<Cut>{{5, 6, 7}});
  }
}

TEST_CASE("SmallVector: random pushes, erases, clears against std::vector (fixed seed)") {
  const uint32_t seed = 2026120607;
  std::printf("SmallVector: seed %u\n", seed);
  std::mt19937 rng(seed);
  std::vector<SmallVector<Cut, 3>> lists(40);  // grown and moved by std::vector as the tracker's arrays are
  std::vector<std::vector<Cut>> refs(40);
  for (int step = 0; step < 20000; ++step) {
    const size_t k = rng() % lists.size();
    const uint32_t what = rng() % 10;
    if (what < 6) {
      const Cut c{int32_t(rng() % 100), int32_t(rng() % 100), int32_t(step)};
      lists[k].push_back(c);
      refs[k].push_back(c);
    } else if (what < 9 && !refs[k].empty()) {
      const size_t i = rng() % refs[k].size();
      lists[k].erase(lists[k].begin() + std::ptrdiff_t(i));
      refs[k].erase(refs[k].begin() + std::ptrdiff_t(i));
    } else if (what == 9) {
      lists[k].clear();
      refs[k].clear();
    }
    if (step % 1000 == 999) {  // a full outer array grows: every list moves
      lists.shrink_to_fit();
      lists.emplace_back();
      refs.emplace_back();
    }
  }
  for (size_t k = 0; k < lists.size(); ++k) {
    CAPTURE(k);
    CHECK(contents(lists[k]) == refs[k]);
  }
}
