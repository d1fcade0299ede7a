// A map from ids (hexes or vertices: non-negative) to small values: open addressing in two flat
// arrays, so n ids cost two allocations, not one node per id as std::unordered_map did. Used by
// the sheet operations' per-sheet tables and by the dual tracker's index of a long edit's hexes
// (issue 22: sheet operations' cost).
// Owns its arrays; keeps: keys_ has a power-of-two size, at most half of it used, -1 marking a free slot.
#pragma once
#include <algorithm>
#include <cassert>
#include <cstdint>
#include <utility>
#include <vector>

namespace hexdual {

template <class V>
class IdMap {
 public:
  IdMap() = default;
  explicit IdMap(size_t expected) { reserve(expected); }
  void reserve(size_t expected) {
    size_t cap = 16;
    while (cap < 2 * expected) cap *= 2;
    if (cap > keys_.size()) rehash(cap);
  }
  // The value at id, set to v when id was absent (the pointer holds until the next emplace);
  // second: whether it was absent.
  std::pair<V*, bool> emplace(int32_t id, V v) {
    if (2 * (used_ + 1) > keys_.size()) rehash(keys_.empty() ? 16 : 2 * keys_.size());
    size_t i = slotOf(id);
    while (keys_[i] >= 0 && keys_[i] != id) i = (i + 1) & (keys_.size() - 1);
    if (keys_[i] == id) return {&vals_[i], false};
    keys_[i] = id;
    vals_[i] = v;
    ++used_;
    return {&vals_[i], true};
  }
  const V* find(int32_t id) const {
    if (keys_.empty()) return nullptr;
    for (size_t i = slotOf(id);; i = (i + 1) & (keys_.size() - 1)) {
      if (keys_[i] == id) return &vals_[i];
      if (keys_[i] < 0) return nullptr;
    }
  }
  bool count(int32_t id) const { return find(id) != nullptr; }
  V get(int32_t id, V absent) const {
    const V* v = find(id);
    return v ? *v : absent;
  }
  V at(int32_t id) const {  // id must be present (checked in debug builds; std::unordered_map::at threw)
    const V* v = find(id);
    assert(v && "IdMap::at: id absent");
    return *v;
  }
  bool empty() const { return used_ == 0; }
  // Empties the map. Its arrays are kept for the next use unless they are far larger than what it
  // held (a map reused after one long edit does not sweep a large array on every later clear).
  void clear() {
    if (keys_.size() > 4096 && 8 * used_ < keys_.size()) {
      keys_ = {};
      vals_ = {};
    } else {
      std::fill(keys_.begin(), keys_.end(), -1);
    }
    used_ = 0;
  }
  size_t size() const { return used_; }

 private:
  size_t slotOf(int32_t id) const { return size_t((uint64_t(uint32_t(id)) * 0x9E3779B97F4A7C15ull) >> 32) & (keys_.size() - 1); }
  void rehash(size_t cap) {
    std::vector<int32_t> keys(cap, -1);
    std::vector<V> vals(cap);
    keys.swap(keys_);
    vals.swap(vals_);
    used_ = 0;
    for (size_t i = 0; i < keys.size(); ++i)
      if (keys[i] >= 0) emplace(keys[i], vals[i]);
  }
  std::vector<int32_t> keys_;
  std::vector<V> vals_;
  size_t used_ = 0;
};

}  // namespace hexdual
