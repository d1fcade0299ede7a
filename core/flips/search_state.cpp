#include "flips/search_state.hpp"

#include <algorithm>
#include <array>
#include <istream>
#include <ostream>

namespace hexdual {
using namespace tables;

Key128 hashWords(const std::vector<int64_t>& words) {
  // Two multiply-xorshift streams with different seeds and multipliers.
  uint64_t a = 0x9E3779B97F4A7C15ull ^ words.size(), b = 0xC2B2AE3D27D4EB4Full + words.size();
  for (int64_t w : words) {
    uint64_t x = uint64_t(w);
    a = (a ^ x) * 0xBF58476D1CE4E5B9ull;
    a ^= a >> 31;
    b = (b + x) * 0x94D049BB133111EBull;
    b ^= b >> 29;
  }
  a ^= a >> 33;
  a *= 0xFF51AFD7ED558CCDull;
  a ^= a >> 33;
  b ^= b >> 32;
  b *= 0xC4CEB9FE1A85EC53ull;
  b ^= b >> 29;
  if (a == 0 && b == 0) b = 1;
  return {a, b};
}

FlatKeyMap::FlatKeyMap(size_t initialSlots) {
  size_t n = 16;
  while (n < initialSlots) n <<= 1;
  keys_.resize(n);
  values_.resize(n, -1);
}

int32_t FlatKeyMap::find(Key128 k) const {
  size_t mask = keys_.size() - 1;
  for (size_t i = size_t(k.lo) & mask;; i = (i + 1) & mask) {
    if (keys_[i].empty()) return -1;
    if (keys_[i] == k) return values_[i];
  }
}

int32_t FlatKeyMap::insert(Key128 k, int32_t value) {
  if (10 * (size_ + 1) > 7 * keys_.size()) grow();
  size_t mask = keys_.size() - 1;
  for (size_t i = size_t(k.lo) & mask;; i = (i + 1) & mask) {
    if (keys_[i].empty()) {
      keys_[i] = k;
      values_[i] = value;
      ++size_;
      return value;
    }
    if (keys_[i] == k) return values_[i];
  }
}

void FlatKeyMap::grow() {
  std::vector<Key128> oldKeys(keys_.size() * 2);
  std::vector<int32_t> oldValues(values_.size() * 2, -1);
  oldKeys.swap(keys_);
  oldValues.swap(values_);
  size_ = 0;
  for (size_t i = 0; i < oldKeys.size(); ++i)
    if (!oldKeys[i].empty()) insert(oldKeys[i], oldValues[i]);
}

void FlatKeyMap::write(std::ostream& out) const {
  const uint64_t n = keys_.size(), used = size_;
  out.write(reinterpret_cast<const char*>(&n), sizeof n);
  out.write(reinterpret_cast<const char*>(&used), sizeof used);
  out.write(reinterpret_cast<const char*>(keys_.data()), std::streamsize(n * sizeof(Key128)));
  out.write(reinterpret_cast<const char*>(values_.data()), std::streamsize(n * sizeof(int32_t)));
}

void FlatKeyMap::read(std::istream& in) {
  uint64_t n = 0, used = 0;
  in.read(reinterpret_cast<char*>(&n), sizeof n);
  in.read(reinterpret_cast<char*>(&used), sizeof used);
  if (!in || n < 16 || (n & (n - 1)) != 0 || used > n || n > (uint64_t(1) << 40))
    throw Error("checkpoint: the hash table header is damaged");
  keys_.assign(size_t(n), Key128{});
  values_.assign(size_t(n), -1);
  in.read(reinterpret_cast<char*>(keys_.data()), std::streamsize(n * sizeof(Key128)));
  in.read(reinterpret_cast<char*>(values_.data()), std::streamsize(n * sizeof(int32_t)));
  if (!in) throw Error("checkpoint: the hash table is cut short");
  size_ = 0;
  for (const Key128& k : keys_) size_ += !k.empty();
  if (size_ != used) throw Error("checkpoint: the hash table does not hold the keys it says");
}

namespace {

// The 48 frames of a cube: frame k maps canonical bit-corners (x + 2y + 4z) to VTK corners.
// All steps of the encoding are lookups in these tables, computed once.
struct FrameTables {
  std::array<std::array<int8_t, 8>, 48> corner{};
  std::array<std::array<int8_t, 6>, 48> face{};                      // canonical face k -> actual face
  std::array<std::array<int8_t, 48>, 48> relative{};                 // index of a^-1 o b
  std::vector<int8_t> across = std::vector<int8_t>(48 * 6 * 6 * 8);  // neighbour's frame across canonical face k

  static int bitsOf(int vtk) { return cornerBit(vtk, 0) | (cornerBit(vtk, 1) << 1) | (cornerBit(vtk, 2) << 2); }
  int indexOf(const std::array<int8_t, 8>& vtkCorners) const {
    for (int k = 0; k < 48; ++k)
      if (corner[size_t(k)] == vtkCorners) return k;
    return -1;
  }
  FrameTables() {
    const int axes[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    std::array<std::array<int8_t, 8>, 48> perm{};
    for (int k = 0; k < 48; ++k)
      for (int b = 0; b < 8; ++b) {
        const int* ap = axes[k / 8];
        int out = 0;
        for (int i = 0; i < 3; ++i) out |= (((b >> i) & 1) ^ (((k % 8) >> ap[i]) & 1)) << ap[i];
        perm[size_t(k)][size_t(b)] = int8_t(out);
        corner[size_t(k)][size_t(b)] = int8_t(cornerAt(out & 1, (out >> 1) & 1, (out >> 2) & 1));
      }
    for (int k = 0; k < 48; ++k)
      for (int cf = 0; cf < 6; ++cf) {
        int mask = 0;
        for (int b = 0; b < 8; ++b)
          if (((b >> (cf >> 1)) & 1) == (cf & 1)) mask |= 1 << corner[size_t(k)][size_t(b)];
        for (int f = 0; f < 6; ++f) {
          int m = 0;
          for (int p = 0; p < 4; ++p) m |= 1 << kFaceCorners[size_t(f)][size_t(p)];
          if (m == mask) face[size_t(k)][size_t(cf)] = int8_t(f);
        }
      }
    for (int a = 0; a < 48; ++a)
      for (int b = 0; b < 48; ++b) {
        std::array<int8_t, 8> inv{}, comp{};
        for (int x = 0; x < 8; ++x) inv[size_t(perm[size_t(a)][size_t(x)])] = int8_t(x);
        for (int x = 0; x < 8; ++x) comp[size_t(x)] = inv[size_t(perm[size_t(b)][size_t(x)])];
        for (int k = 0; k < 48; ++k)
          if (perm[size_t(k)] == comp) relative[size_t(a)][size_t(b)] = int8_t(k);
      }
    // Across canonical face cf (actual face f) glued to face g with orientation o: the neighbour's
    // corners on the shared quad are the mapped ones, its far corners lie across its own axis.
    for (int k = 0; k < 48; ++k)
      for (int cf = 0; cf < 6; ++cf)
        for (int g = 0; g < 6; ++g)
          for (int o = 0; o < 8; ++o) {
            int axis = cf >> 1, side = cf & 1, f = face[size_t(k)][size_t(cf)];
            std::array<int8_t, 8> n{};
            for (int b = 0; b < 8; ++b)
              if (((b >> axis) & 1) != side) {
                int c = corner[size_t(k)][size_t(b ^ (1 << axis))];
                n[size_t(b)] = int8_t(kFaceCorners[size_t(g)][size_t(mapPosition(positionInFace(f, c), o))]);
              }
            for (int b = 0; b < 8; ++b)
              if (((b >> axis) & 1) == side) {
                int c = n[size_t(b ^ (1 << axis))];
                int bits[3] = {cornerBit(c, 0), cornerBit(c, 1), cornerBit(c, 2)};
                bits[axisOfFace(g)] ^= 1;
                n[size_t(b)] = int8_t(cornerAt(bits[0], bits[1], bits[2]));
              }
            across[size_t(((k * 6 + cf) * 6 + g) * 8 + o)] = int8_t(indexOf(n));
          }
  }
};

const FrameTables& frameTables() {
  static const FrameTables t;
  return t;
}

bool outside(const std::vector<uint8_t>& isHost, HexId h) { return size_t(h) < isHost.size() && isHost[size_t(h)]; }

}  // namespace

bool RegionEncoder::encodeFrom(const Complex& cx, const std::vector<uint8_t>& isHost, HexId start, int frame,
                               std::vector<int64_t>& out, const std::vector<int64_t>* bound) {
  const FrameTables& T = frameTables();
  ++stamp_;
  if (stamp_ == 0) {  // wrapped: clear the stamps once
    std::fill(hexStamp_.begin(), hexStamp_.end(), 0);
    std::fill(vertexStamp_.begin(), vertexStamp_.end(), 0);
    stamp_ = 1;
  }
  int32_t nextVertex = 0;
  order_.clear();
  auto label = [&](HexId h, int fr) {
    hexStamp_[size_t(h)] = stamp_;
    hexLabel_[size_t(h)] = int32_t(order_.size());
    hexFrame_[size_t(h)] = int8_t(fr);
    order_.push_back(h);
  };
  // Words go out compared with `bound` as they come: the encoding stops as soon as it is larger.
  bool tied = bound != nullptr;
  auto emit = [&](int64_t w) {
    if (tied) {
      size_t i = out.size();
      if (i >= bound->size() || w > (*bound)[i]) return false;
      if (w < (*bound)[i]) tied = false;
    }
    out.push_back(w);
    return true;
  };
  label(start, frame);
  out.clear();
  for (size_t i = 0; i < order_.size(); ++i) {
    HexId h = order_[i];
    int fr = hexFrame_[size_t(h)];
    for (int b = 0; b < 8; ++b) {
      VertexId v = cx.vertex(h, T.corner[size_t(fr)][size_t(b)]);
      int64_t w;
      if (keepStamp_[size_t(v)] == keepGen_) {
        w = -2 - int64_t(mapped(v));
      } else {
        if (vertexStamp_[size_t(v)] != stamp_) {
          vertexStamp_[size_t(v)] = stamp_;
          vertexLabel_[size_t(v)] = nextVertex++;
        }
        w = vertexLabel_[size_t(v)];
      }
      if (!emit(w)) return false;
    }
    for (int cf = 0; cf < 6; ++cf) {
      Gluing g = cx.gluing(h, T.face[size_t(fr)][size_t(cf)]);
      if (g.boundary() || outside(isHost, g.hex)) {
        if (!emit(-1) || !emit(0)) return false;
        continue;
      }
      int nf = T.across[size_t(((fr * 6 + cf) * 6 + g.face) * 8 + g.orient)];
      if (hexStamp_[size_t(g.hex)] != stamp_) label(g.hex, nf);
      if (!emit(hexLabel_[size_t(g.hex)]) || !emit(T.relative[size_t(hexFrame_[size_t(g.hex)])][size_t(nf)]))
        return false;
    }
  }
  if (!emit(int64_t(order_.size()))) return false;
  return !tied || out.size() < bound->size();  // equal to the bound is no improvement
}

const std::vector<int64_t>& RegionEncoder::form(const Complex& cx, const std::vector<uint8_t>& isHost,
                                                const std::vector<VertexId>* relabel) {
  maps_.assign(1, relabel);
  return minForm(cx, isHost);
}

Key128 RegionEncoder::key(const Complex& cx, const std::vector<uint8_t>& isHost,
                          const std::vector<std::vector<VertexId>>& symmetries) {
  maps_.assign(1, nullptr);
  for (const auto& m : symmetries) maps_.push_back(&m);
  return hashWords(minForm(cx, isHost));
}

namespace {

// The frame of a start flag on boundary side f whose (mapped) corner vertices are v: canonical
// corner 0 on the smallest vertex, x toward its smaller neighbour, z inward.
int frameOf(const FrameTables& T, int f, const std::array<VertexId, 4>& v) {
  int p0 = int(std::min_element(v.begin(), v.end()) - v.begin());
  int pn = (p0 + 1) & 3, pp = (p0 + 3) & 3;
  int p1 = v[size_t(pn)] < v[size_t(pp)] ? pn : pp, p2 = p1 == pn ? pp : pn;
  int c0 = kFaceCorners[size_t(f)][size_t(p0)], c1 = kFaceCorners[size_t(f)][size_t(p1)],
      c2 = kFaceCorners[size_t(f)][size_t(p2)];
  std::array<int8_t, 8> F{};
  for (int b = 0; b < 8; ++b) {
    int bits[3] = {cornerBit(c0, 0), cornerBit(c0, 1), cornerBit(c0, 2)};
    for (int x = 0; x < 3; ++x) {
      if ((b & 1) && cornerBit(c1, x) != cornerBit(c0, x)) bits[x] ^= 1;
      if ((b & 2) && cornerBit(c2, x) != cornerBit(c0, x)) bits[x] ^= 1;
    }
    if (b & 4) bits[axisOfFace(f)] ^= 1;
    F[size_t(b)] = int8_t(cornerAt(bits[0], bits[1], bits[2]));
  }
  return T.indexOf(F);
}

// Four ids sorted by a 5-comparator network (this runs for every side under every map).
std::array<VertexId, 4> sorted4(std::array<VertexId, 4> a) {
  auto cs = [&](int i, int j) {
    if (a[size_t(j)] < a[size_t(i)]) std::swap(a[size_t(i)], a[size_t(j)]);
  };
  cs(0, 1), cs(2, 3), cs(0, 2), cs(1, 3), cs(1, 2);
  return a;
}

}  // namespace

const std::vector<int64_t>& RegionEncoder::minForm(const Complex& cx, const std::vector<uint8_t>& isHost) {
  relabel_ = nullptr;
  reserveStamps(cx);
  const HexId regionSize = collectBoundarySides(cx, isHost);
  best_.clear();
  if (regionSize == 0) return best_;
  if (sides_.empty()) {
    // A region without boundary (cut off from the host: never a local state): any encoding will do.
    for (HexId h : cx.hexes())
      if (!outside(isHost, h)) {
        encodeFrom(cx, isHost, h, 0, best_, nullptr);
        best_.push_back(-4);
        return best_;
      }
  }
  const Start best = smallestOverMaps(cx, isHost);
  // A region in several pieces: the pieces not reached are appended.
  if (best_.back() < int64_t(regionSize)) appendUnreachedPieces(cx, isHost, best);
  return best_;
}

// The per-hex and per-vertex stamps sized for cx; a new generation of vertex keep-stamps.
void RegionEncoder::reserveStamps(const Complex& cx) {
  size_t nh = size_t(cx.hexCapacity()), nv = size_t(cx.vertexCapacity());
  if (hexStamp_.size() < nh) {
    hexStamp_.resize(nh, 0);
    hexLabel_.resize(nh);
    hexFrame_.resize(nh);
  }
  if (vertexStamp_.size() < nv) {
    vertexStamp_.resize(nv, 0);
    vertexLabel_.resize(nv);
    keepStamp_.resize(nv, 0);
  }
  if (++keepGen_ == 0) {
    std::fill(keepStamp_.begin(), keepStamp_.end(), 0);
    keepGen_ = 1;
  }
}

// Region boundary sides (mesh boundary or glued outside the region): their vertices keep their
// ids; under each vertex map, the start flags are the sides with the smallest vertex set.
// Returns the region's hex count.
HexId RegionEncoder::collectBoundarySides(const Complex& cx, const std::vector<uint8_t>& isHost) {
  sides_.clear();
  HexId regionSize = 0;
  for (HexId h : cx.hexes()) {
    if (outside(isHost, h)) continue;
    ++regionSize;
    for (int f = 0; f < 6; ++f) {
      Gluing g = cx.gluing(h, f);
      if (!g.boundary() && !outside(isHost, g.hex)) continue;
      BoundarySide bs{h, f, {}};
      for (int p = 0; p < 4; ++p) {
        bs.v[size_t(p)] = cx.vertex(h, kFaceCorners[size_t(f)][size_t(p)]);
        keepStamp_[size_t(bs.v[size_t(p)])] = keepGen_;
      }
      sides_.push_back(bs);
    }
  }
  return regionSize;
}

// The smallest encoding (into best_) over the vertex maps and, under each, the start flags on the
// sides with the smallest mapped vertex set; returns where it starts.
RegionEncoder::Start RegionEncoder::smallestOverMaps(const Complex& cx, const std::vector<uint8_t>& isHost) {
  const FrameTables& T = frameTables();
  Start best;
  mappedSides_.resize(sides_.size());
  for (const std::vector<VertexId>* m : maps_) {
    relabel_ = m;
    std::array<VertexId, 4> minSet{};
    for (size_t i = 0; i < sides_.size(); ++i) {
      auto& [v, s] = mappedSides_[i];
      for (int p = 0; p < 4; ++p) v[size_t(p)] = mapped(sides_[i].v[size_t(p)]);
      s = sorted4(v);
      if (i == 0 || s < minSet) minSet = s;
    }
    for (size_t i = 0; i < sides_.size(); ++i) {
      if (mappedSides_[i].second != minSet) continue;
      int fr = frameOf(T, sides_[i].f, mappedSides_[i].first);
      if (encodeFrom(cx, isHost, sides_[i].h, fr, cur_, best_.empty() ? nullptr : &best_)) {
        best_.swap(cur_);
        best = {m, i, fr};
      }
    }
  }
  return best;
}

// The pieces of the region the best encoding did not reach, appended from their first hex (not
// canonical, so such states may be stored twice, never merged wrongly).
void RegionEncoder::appendUnreachedPieces(const Complex& cx, const std::vector<uint8_t>& isHost, const Start& best) {
  relabel_ = best.map;
  std::vector<uint8_t> reached(size_t(cx.hexCapacity()), 0);
  encodeFrom(cx, isHost, sides_[best.side].h, best.frame, cur_, nullptr);  // marks what it reached
  for (HexId h : cx.hexes())
    if (!outside(isHost, h) && hexStamp_[size_t(h)] == stamp_) reached[size_t(h)] = 1;
  for (HexId h : cx.hexes()) {
    if (outside(isHost, h) || reached[size_t(h)]) continue;
    encodeFrom(cx, isHost, h, 0, cur_, nullptr);
    best_.push_back(-3);
    for (int64_t w : cur_) best_.push_back(w);
    for (HexId x : order_) reached[size_t(x)] = 1;
  }
}

}  // namespace hexdual
