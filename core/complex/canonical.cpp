#include "complex/canonical.hpp"

#include <algorithm>
#include <array>

namespace hexdual {
using namespace tables;

namespace {

// The 48 symmetries of the cube as permutations of bit-corners b = x + 2y + 4z.
struct Symmetries {
  std::array<std::array<int8_t, 8>, 48> perm{};
  std::array<std::array<int8_t, 48>, 48> relative{};  // relative[g][f] = index of g^-1 o f
  Symmetries() {
    int axesPerms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    int k = 0;
    for (auto& ap : axesPerms)
      for (int flip = 0; flip < 8; ++flip, ++k)
        for (int b = 0; b < 8; ++b) {
          int out = 0;
          for (int i = 0; i < 3; ++i) out |= (((b >> i) & 1) ^ ((flip >> ap[i]) & 1)) << ap[i];
          perm[size_t(k)][size_t(b)] = int8_t(out);
        }
    for (int g = 0; g < 48; ++g)
      for (int f = 0; f < 48; ++f) {
        std::array<int8_t, 8> inv{}, comp{};
        for (int b = 0; b < 8; ++b) inv[size_t(perm[size_t(g)][size_t(b)])] = int8_t(b);
        for (int b = 0; b < 8; ++b) comp[size_t(b)] = inv[size_t(perm[size_t(f)][size_t(b)])];
        relative[size_t(g)][size_t(f)] = int8_t(find(comp));
      }
  }
  int find(const std::array<int8_t, 8>& p) const {
    for (int k = 0; k < 48; ++k)
      if (perm[size_t(k)] == p) return k;
    return -1;
  }
};
const Symmetries& symmetries() {
  static const Symmetries s;
  return s;
}

int vtkOfBits(int b) { return cornerAt(b & 1, (b >> 1) & 1, (b >> 2) & 1); }
int bitsOfVtk(int c) { return cornerBit(c, 0) | (cornerBit(c, 1) << 1) | (cornerBit(c, 2) << 2); }

// A frame: canonical bit-corner -> actual VTK corner of a hex.
using Frame = std::array<int8_t, 8>;
int frameIndex(const Frame& f) {
  std::array<int8_t, 8> p{};
  for (int b = 0; b < 8; ++b) p[size_t(b)] = int8_t(bitsOfVtk(f[size_t(b)]));
  return symmetries().find(p);
}
Frame frameOf(int index) {
  Frame f{};
  for (int b = 0; b < 8; ++b) f[size_t(b)] = int8_t(vtkOfBits(symmetries().perm[size_t(index)][size_t(b)]));
  return f;
}
// The actual face of a hex holding canonical face k (axis k/2, side k%2) under frame f.
int actualFace(const Frame& f, int k) {
  int axis = k >> 1, side = k & 1;
  int c[4], n = 0;
  for (int b = 0; b < 8; ++b)
    if (((b >> axis) & 1) == side) c[n++] = f[size_t(b)];
  for (int face = 0; face < 6; ++face) {
    int hits = 0;
    for (int p = 0; p < 4; ++p)
      for (int q = 0; q < 4; ++q) hits += kFaceCorners[size_t(face)][size_t(p)] == c[q];
    if (hits == 4) return face;
  }
  return -1;
}

std::vector<int64_t> encodeFrom(const Complex& cx, HexId start, const Frame& startFrame, const std::vector<uint8_t>& keepId,
                                std::vector<HexId>* orderOut = nullptr, std::vector<Frame>* framesOut = nullptr) {
  const auto& sym = symmetries();
  std::vector<int32_t> label(size_t(cx.hexCapacity()), -1);
  std::vector<int8_t> frameIdx(size_t(cx.hexCapacity()), -1);
  std::vector<int64_t> vlabel(size_t(cx.vertexCapacity()), -1);
  int64_t nextV = 0;
  std::vector<HexId> order{start};
  label[size_t(start)] = 0;
  frameIdx[size_t(start)] = int8_t(frameIndex(startFrame));
  std::vector<int64_t> out;
  out.reserve(size_t(cx.numHexes()) * 20 + 1);
  for (size_t i = 0; i < order.size(); ++i) {
    HexId h = order[i];
    Frame F = frameOf(frameIdx[size_t(h)]);
    for (int b = 0; b < 8; ++b) {
      VertexId v = cx.vertex(h, F[size_t(b)]);
      if (keepId[size_t(v)]) {
        out.push_back(-2 - int64_t(v));
      } else {
        if (vlabel[size_t(v)] < 0) vlabel[size_t(v)] = nextV++;
        out.push_back(vlabel[size_t(v)]);
      }
    }
    for (int k = 0; k < 6; ++k) {
      int f = actualFace(F, k);
      Gluing g = cx.gluing(h, f);
      if (g.boundary()) {
        out.push_back(-1);
        out.push_back(0);
        continue;
      }
      int axis = k >> 1, side = k & 1;
      Frame N{};
      for (int b = 0; b < 8; ++b)
        if (((b >> axis) & 1) != side) N[size_t(b)] = int8_t(cx.mappedCorner(h, f, F[size_t(b ^ (1 << axis))]));
      int na = axisOfFace(g.face);
      for (int b = 0; b < 8; ++b)
        if (((b >> axis) & 1) == side) {
          int c = N[size_t(b ^ (1 << axis))];
          int bits[3] = {cornerBit(c, 0), cornerBit(c, 1), cornerBit(c, 2)};
          bits[na] ^= 1;
          N[size_t(b)] = int8_t(cornerAt(bits[0], bits[1], bits[2]));
        }
      int ni = frameIndex(N);
      if (label[size_t(g.hex)] < 0) {
        label[size_t(g.hex)] = int32_t(order.size());
        frameIdx[size_t(g.hex)] = int8_t(ni);
        order.push_back(g.hex);
      }
      out.push_back(label[size_t(g.hex)]);
      out.push_back(sym.relative[size_t(frameIdx[size_t(g.hex)])][size_t(ni)]);
    }
  }
  out.push_back(int64_t(order.size()));
  if (orderOut) *orderOut = order;
  if (framesOut) {
    framesOut->clear();
    for (HexId h : order) framesOut->push_back(frameOf(frameIdx[size_t(h)]));
  }
  return out;
}

// Classes of hexes that every isomorphism keeps: first by the number of boundary faces, then
// refined by the neighbours' classes across the six faces (sorted), until the number of classes
// stops growing (colour refinement; a few rounds). Class ids are ranks of sorted keys, so they
// do not depend on the numbering.
std::vector<int32_t> hexClasses(const Complex& cx) {
  std::vector<int32_t> cls(size_t(cx.hexCapacity()), -1);
  for (HexId h : cx.hexes()) {
    int open = 0;
    for (int f = 0; f < 6; ++f) open += cx.gluing(h, f).boundary() ? 1 : 0;
    cls[size_t(h)] = open;
  }
  using Key = std::array<int32_t, 7>;
  std::vector<std::pair<Key, HexId>> keyed;
  size_t classes = 0;
  for (int round = 0; round < 16; ++round) {
    keyed.clear();
    for (HexId h : cx.hexes()) {
      Key k{};
      k[0] = cls[size_t(h)];
      for (int f = 0; f < 6; ++f) {
        const Gluing g = cx.gluing(h, f);
        k[size_t(f + 1)] = g.boundary() ? -1 : cls[size_t(g.hex)];
      }
      std::sort(k.begin() + 1, k.end());
      keyed.push_back({k, h});
    }
    std::sort(keyed.begin(), keyed.end());
    int32_t next = -1;
    for (size_t i = 0; i < keyed.size(); ++i) {
      if (i == 0 || keyed[i].first != keyed[i - 1].first) ++next;
      cls[size_t(keyed[i].second)] = next;
    }
    if (size_t(next + 1) == classes) break;
    classes = size_t(next + 1);
  }
  return cls;
}

// Start flags for the free form: the hexes of the smallest class (ties to the smaller class id),
// each in the frames whose neighbours' classes, read across canonical faces 0..5, are smallest.
// Every isomorphism keeps both choices, so the minimum over these flags is still canonical; a
// complex with a boundary usually tries a handful of flags instead of 48 per hex.
std::vector<std::pair<HexId, int>> startFlags(const Complex& cx) {
  const std::vector<int32_t> cls = hexClasses(cx);
  std::vector<int32_t> size;
  for (HexId h : cx.hexes()) {
    if (size.size() <= size_t(cls[size_t(h)])) size.resize(size_t(cls[size_t(h)]) + 1, 0);
    ++size[size_t(cls[size_t(h)])];
  }
  const int32_t pick = int32_t(std::min_element(size.begin(), size.end()) - size.begin());
  std::vector<std::pair<HexId, int>> flags;
  for (HexId h : cx.hexes()) {
    if (cls[size_t(h)] != pick) continue;
    std::array<int32_t, 6> best{};
    std::vector<int> frames;
    for (int k = 0; k < 48; ++k) {
      const Frame F = frameOf(k);
      std::array<int32_t, 6> t{};
      for (int j = 0; j < 6; ++j) {
        const Gluing g = cx.gluing(h, actualFace(F, j));
        t[size_t(j)] = g.boundary() ? -1 : cls[size_t(g.hex)];
      }
      if (frames.empty() || t < best) {
        best = t;
        frames.assign(1, k);
      } else if (t == best) {
        frames.push_back(k);
      }
    }
    for (int k : frames) flags.push_back({h, k});
  }
  return flags;
}

}  // namespace

std::vector<int64_t> canonicalForm(const Complex& cx, bool fixedBoundary) { return canonicalLabelling(cx, fixedBoundary).form; }

CanonicalLabelling canonicalLabelling(const Complex& cx, bool fixedBoundary, FreeStarts starts) {
  std::vector<uint8_t> keepId(size_t(cx.vertexCapacity()), 0);
  CanonicalLabelling bestL;
  std::vector<int64_t>& best = bestL.form;
  if (cx.numHexes() == 0) return bestL;
  std::vector<HexId> order;
  std::vector<Frame> frames;
  auto consider = [&](std::vector<int64_t> enc) {
    if (best.empty() || enc < best) {
      best = std::move(enc);
      bestL.order = order;
      bestL.frame = frames;
    }
  };
  auto bq = cx.boundaryQuads();
  if (fixedBoundary && !bq.empty()) {
    for (const auto& q : bq)
      for (VertexId v : q.vertices) keepId[size_t(v)] = 1;
    // Start flags: every boundary side whose vertex set is the smallest.
    auto sorted = [](std::array<VertexId, 4> v) {
      std::sort(v.begin(), v.end());
      return v;
    };
    std::array<VertexId, 4> minSet = sorted(bq[0].vertices);
    for (const auto& q : bq) minSet = std::min(minSet, sorted(q.vertices));
    for (const auto& q : bq) {
      if (sorted(q.vertices) != minSet) continue;
      // Canonical corner 0 on the smallest vertex, corner 1 toward its smaller neighbour in the face.
      int p0 = int(std::min_element(q.vertices.begin(), q.vertices.end()) - q.vertices.begin());
      int pNext = (p0 + 1) & 3, pPrev = (p0 + 3) & 3;
      int p1 = q.vertices[size_t(pNext)] < q.vertices[size_t(pPrev)] ? pNext : pPrev;
      int p2 = p1 == pNext ? pPrev : pNext;
      int f = q.side.face;
      int c0 = kFaceCorners[size_t(f)][size_t(p0)], c1 = kFaceCorners[size_t(f)][size_t(p1)],
          c2 = kFaceCorners[size_t(f)][size_t(p2)];
      // Bits: canonical x from c0 to c1, y from c0 to c2, z into the hex (off face f).
      Frame F{};
      for (int b = 0; b < 8; ++b) {
        int bits[3] = {cornerBit(c0, 0), cornerBit(c0, 1), cornerBit(c0, 2)};
        for (int a = 0; a < 3; ++a) {
          if ((b & 1) && cornerBit(c1, a) != cornerBit(c0, a)) bits[a] ^= 1;
          if ((b & 2) && cornerBit(c2, a) != cornerBit(c0, a)) bits[a] ^= 1;
        }
        if (b & 4) bits[axisOfFace(f)] ^= 1;
        F[size_t(b)] = int8_t(cornerAt(bits[0], bits[1], bits[2]));
      }
      consider(encodeFrom(cx, q.side.hex, F, keepId, &order, &frames));
    }
    return bestL;
  }
  if (starts == FreeStarts::Every) {
    for (HexId h : cx.hexes())
      for (int k = 0; k < 48; ++k) consider(encodeFrom(cx, h, frameOf(k), keepId, &order, &frames));
    return bestL;
  }
  for (const auto& [h, k] : startFlags(cx)) consider(encodeFrom(cx, h, frameOf(k), keepId, &order, &frames));
  return bestL;
}

uint64_t canonicalHash(const Complex& cx, bool fixedBoundary) {
  uint64_t h = 1469598103934665603ull;
  for (int64_t x : canonicalForm(cx, fixedBoundary))
    for (int i = 0; i < 8; ++i) {
      h ^= uint64_t(x >> (8 * i)) & 0xff;
      h *= 1099511628211ull;
    }
  return h;
}

bool isomorphic(const Complex& a, const Complex& b, bool fixedBoundary) {
  if (a.numHexes() != b.numHexes() || a.numVertices() != b.numVertices()) return false;
  return canonicalForm(a, fixedBoundary) == canonicalForm(b, fixedBoundary);
}

bool isomorphicAt(const Complex& a, HexId ha, const Complex& b, HexId hb) {
  if (a.numHexes() != b.numHexes() || a.numVertices() != b.numVertices() || !a.isHex(ha) || !b.isHex(hb)) return false;
  const Frame identity = frameOf(0);  // canonical bit-corners are the local corners
  return encodeFrom(a, ha, identity, std::vector<uint8_t>(size_t(a.vertexCapacity()), 0)) ==
         encodeFrom(b, hb, identity, std::vector<uint8_t>(size_t(b.vertexCapacity()), 0));
}

}  // namespace hexdual
