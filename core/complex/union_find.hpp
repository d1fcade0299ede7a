// Union-find with path halving and union by index (smaller root wins, so results are deterministic).
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace hexdual {

class UnionFind {
 public:
  explicit UnionFind(size_t n = 0) { reset(n); }
  // n singletons again, keeping the storage (one union-find reused for many small sets).
  void reset(size_t n) {
    parent_.resize(n);
    for (size_t i = 0; i < n; ++i) parent_[i] = uint32_t(i);
  }
  size_t find(size_t x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }
  // Joins two classes; the smaller root becomes the representative.
  void unite(size_t a, size_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (a < b) parent_[b] = uint32_t(a);
    else parent_[a] = uint32_t(b);
  }

 private:
  std::vector<uint32_t> parent_;
};

}  // namespace hexdual
