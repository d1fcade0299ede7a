// Compact state storage for the decomposition search: 128-bit keys of a region's canonical form,
// a flat open-addressing hash set of them, and the region encoder that computes them without
// copying the complex.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <utility>
#include <vector>

#include "complex/complex.hpp"

namespace hexdual {

// 128 bits of a canonical form: two independent 64-bit hashes. The search treats equal keys as
// equal states; every sequence it returns is replayed and checked exactly (verifyDecomposition).
struct Key128 {
  uint64_t lo = 0, hi = 0;
  bool empty() const { return lo == 0 && hi == 0; }
  friend bool operator==(Key128 a, Key128 b) { return a.lo == b.lo && a.hi == b.hi; }
  friend bool operator!=(Key128 a, Key128 b) { return !(a == b); }
  friend bool operator<(Key128 a, Key128 b) { return a.hi != b.hi ? a.hi < b.hi : a.lo < b.lo; }
};

// Two independent 64-bit hashes of a word sequence (never the all-zero key, which marks empty slots).
Key128 hashWords(const std::vector<int64_t>& words);

// Open addressing, linear probing, load ≤ 0.7: 20 bytes per slot (keys and values in separate
// arrays), so 29 to 57 bytes per stored key. Maps a key to an int32 value.
class FlatKeyMap {
 public:
  explicit FlatKeyMap(size_t initialSlots = 1024);
  // The value stored for key, or -1.
  int32_t find(Key128 k) const;
  // Inserts key -> value unless present; returns the value now stored.
  int32_t insert(Key128 k, int32_t value);
  size_t size() const { return size_; }
  size_t slots() const { return keys_.size(); }
  size_t memoryBytes() const { return keys_.size() * (sizeof(Key128) + sizeof(int32_t)); }
  // The table as raw slots (a checkpoint of the search); read() replaces this map's contents and
  // throws Error on a short or inconsistent stream.
  void write(std::ostream& out) const;
  void read(std::istream& in);

 private:
  void grow();
  std::vector<Key128> keys_;
  std::vector<int32_t> values_;
  size_t size_ = 0;
};

// Canonical form of the region of cx (the hexes with inRegion[h] != 0) with its boundary vertex ids
// fixed — the same isomorphism classes as canonicalForm(subcomplex(cx, region), true) — encoded
// from table lookups into reused buffers. A quad glued to a hex outside the region counts as
// region boundary. Not thread-safe: one encoder per thread.
class RegionEncoder {
 public:
  // The canonical word sequence (valid until the next call). With `relabel`, boundary vertex v
  // is written as relabel[v] (ids past its end as themselves): the form of the image of the region
  // under a vertex map, as long as that map preserves the host.
  const std::vector<int64_t>& form(const Complex& cx, const std::vector<uint8_t>& isHost,
                                   const std::vector<VertexId>* relabel = nullptr);
  Key128 key(const Complex& cx, const std::vector<uint8_t>& isHost) { return hashWords(form(cx, isHost)); }
  // The smallest key over the identity and the given vertex maps (symmetries of the host): one
  // key for a state and all its images under the symmetries.
  Key128 key(const Complex& cx, const std::vector<uint8_t>& isHost,
             const std::vector<std::vector<VertexId>>& symmetries);

 private:
  // Encodes from a start flag into `out`; with a bound, stops early and returns false unless the
  // result is smaller than the bound.
  bool encodeFrom(const Complex& cx, const std::vector<uint8_t>& isHost, HexId start, int frame,
                  std::vector<int64_t>& out, const std::vector<int64_t>* bound);
  // The smallest encoding over the vertex maps in maps_ (nullptr: the identity) and their start flags.
  const std::vector<int64_t>& minForm(const Complex& cx, const std::vector<uint8_t>& isHost);
  // Where an encoding starts: a vertex map, a boundary side and the frame on it.
  struct Start {
    const std::vector<VertexId>* map = nullptr;
    size_t side = 0;
    int frame = 0;
  };
  void reserveStamps(const Complex& cx);
  HexId collectBoundarySides(const Complex& cx, const std::vector<uint8_t>& isHost);
  Start smallestOverMaps(const Complex& cx, const std::vector<uint8_t>& isHost);
  void appendUnreachedPieces(const Complex& cx, const std::vector<uint8_t>& isHost, const Start& best);
  struct BoundarySide {
    HexId h;
    int f;
    std::array<VertexId, 4> v;
  };
  std::vector<BoundarySide> sides_;
  std::vector<std::pair<std::array<VertexId, 4>, std::array<VertexId, 4>>> mappedSides_;  // mapped, sorted
  std::vector<const std::vector<VertexId>*> maps_;
  std::vector<uint32_t> hexStamp_, vertexStamp_, keepStamp_;
  std::vector<int32_t> hexLabel_, vertexLabel_;
  std::vector<int8_t> hexFrame_;
  std::vector<HexId> order_;
  VertexId mapped(VertexId v) const { return relabel_ && size_t(v) < relabel_->size() ? (*relabel_)[size_t(v)] : v; }
  const std::vector<VertexId>* relabel_ = nullptr;
  std::vector<int64_t> best_, cur_;
  uint32_t stamp_ = 0, keepGen_ = 0;
};

}  // namespace hexdual
