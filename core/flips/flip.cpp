#include "flips/flip.hpp"

#include <algorithm>
#include <map>

#include "flips/fourcube.hpp"
#include "ops/support.hpp"

namespace hexdual {
using namespace tables;
using namespace ops;

namespace {

// A map of the region onto the pattern: hex -> pattern hex, and per hex local corner -> pattern corner.
struct Match {
  std::map<HexId, HexId> hex;
  std::map<HexId, std::array<int, 8>> corner;
  std::map<VertexId, VertexId> vertex;  // region vertex -> pattern vertex
};

// Tries to extend r0 -> (p0, corner map) to the whole region by walking gluings.
bool extend(const Complex& cx, const std::vector<HexId>& region, const Complex& pat, const std::vector<HexId>& patHexes,
            HexId r0, HexId p0, std::array<int, 8> sigma0, Match& m) {
  auto inRegion = [&](HexId h) { return std::find(region.begin(), region.end(), h) != region.end(); };
  auto inPat = [&](HexId h) { return std::find(patHexes.begin(), patHexes.end(), h) != patHexes.end(); };
  m = {};
  std::vector<HexId> queue{r0};
  m.hex[r0] = p0;
  m.corner[r0] = sigma0;
  std::map<HexId, HexId> patUsed{{p0, r0}};
  for (size_t i = 0; i < queue.size(); ++i) {
    HexId r = queue[i], p = m.hex[r];
    const auto& s = m.corner[r];
    for (int c = 0; c < 8; ++c) {
      VertexId vr = cx.vertex(r, c), vp = pat.vertex(p, s[size_t(c)]);
      auto [it, ins] = m.vertex.try_emplace(vr, vp);
      if (it->second != vp) return false;
    }
    for (int f = 0; f < 6; ++f) {
      // The pattern face holding the images of f's corners.
      int pf = -1;
      for (int g = 0; g < 6 && pf < 0; ++g) {
        int hits = 0;
        for (int q = 0; q < 4; ++q) hits += positionInFace(g, s[size_t(kFaceCorners[size_t(f)][size_t(q)])]) >= 0;
        if (hits == 4) pf = g;
      }
      Gluing gr = cx.gluing(r, f), gp = pat.gluing(p, pf);
      bool rInside = !gr.boundary() && inRegion(gr.hex), pInside = !gp.boundary() && inPat(gp.hex);
      if (rInside != pInside) return false;
      if (!rInside) continue;
      std::array<int, 8> s2{};
      for (int q = 0; q < 4; ++q) {
        int c = kFaceCorners[size_t(f)][size_t(q)];
        int cr = cx.mappedCorner(r, f, c), cp = pat.mappedCorner(p, pf, s[size_t(c)]);
        s2[size_t(cr)] = cp;
        s2[size_t(flipAxis(cr, axisOfFace(gr.face)))] = flipAxis(cp, axisOfFace(gp.face));
      }
      auto known = m.hex.find(gr.hex);
      if (known != m.hex.end()) {
        if (known->second != gp.hex || m.corner[gr.hex] != s2) return false;
        continue;
      }
      if (patUsed.count(gp.hex)) return false;
      patUsed[gp.hex] = gr.hex;
      m.hex[gr.hex] = gp.hex;
      m.corner[gr.hex] = s2;
      queue.push_back(gr.hex);
    }
  }
  if (queue.size() != region.size()) return false;
  std::map<VertexId, VertexId> back;
  for (auto [a, b] : m.vertex)
    if (!back.try_emplace(b, a).second) return false;  // two region vertices on one pattern vertex
  return true;
}

// All 48 corner permutations of a hex that are cube symmetries.
std::vector<std::array<int, 8>> cubeSymmetries() {
  std::vector<std::array<int, 8>> out;
  int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (auto& p : perms)
    for (int flip = 0; flip < 8; ++flip) {
      std::array<int, 8> s{};
      for (int c = 0; c < 8; ++c) {
        int b[3];
        for (int a = 0; a < 3; ++a) b[p[a]] = cornerBit(c, a) ^ ((flip >> a) & 1);
        s[size_t(c)] = cornerAt(b[0], b[1], b[2]);
      }
      out.push_back(s);
    }
  return out;
}

}  // namespace

OpResult flip(Complex& cx, const std::string& name, const std::vector<HexId>& hexes) {
  const std::string op = "flip " + name;
  const FlipClass& fc = flipClass(name);
  std::vector<HexId> region = hexes;
  std::sort(region.begin(), region.end());
  region.erase(std::unique(region.begin(), region.end()), region.end());
  for (HexId h : region)
    if (!cx.isHex(h)) reject(op, hexName(h) + " does not exist");
  auto before = facetsOf(fc.before), after = facetsOf(uint8_t(~fc.before));
  if (region.size() != before.size())
    reject(op, "the " + name + " flip replaces " + std::to_string(before.size()) + " hexes, not " +
                   std::to_string(region.size()));
  static const Complex pattern = makeFourCubeBoundary();
  static const auto syms = cubeSymmetries();
  Match m;
  bool found = false;
  for (HexId p0 : before) {
    for (const auto& s : syms)
      if (extend(cx, region, pattern, before, region[0], p0, s, m)) {
        found = true;
        break;
      }
    if (found) break;
  }
  if (!found) reject(op, "the hexes do not form the " + name + " flip's before side");
  // Vertices of the after side: boundary ones are the region's, interior ones are new.
  std::map<VertexId, VertexId> toMesh;  // pattern vertex -> mesh vertex
  for (auto [r, p] : m.vertex) toMesh[p] = r;
  Vec3 centre;
  for (HexId h : region) centre = centre + (1.0 / double(region.size())) * cx.hexCentroid(h);
  Transaction tx(cx);
  OpResult res;
  std::vector<VertexId> newPattern;
  for (HexId p : after)
    for (VertexId v : pattern.hexVertices(p))
      if (!toMesh.count(v) && std::find(newPattern.begin(), newPattern.end(), v) == newPattern.end())
        newPattern.push_back(v);
  std::sort(newPattern.begin(), newPattern.end());
  for (VertexId v : newPattern) {
    // Halfway from the region's centre toward the boundary vertices it shares an edge with.
    Vec3 sum;
    int n = 0;
    for (HexId p : after)
      for (int e = 0; e < 12; ++e) {
        VertexId a = pattern.vertex(p, kEdgeCorners[size_t(e)][0]), b = pattern.vertex(p, kEdgeCorners[size_t(e)][1]);
        VertexId other = a == v ? b : b == v ? a : -1;
        if (other >= 0 && toMesh.count(other)) {
          sum = sum + cx.position(toMesh[other]);
          ++n;
        }
      }
    Vec3 target = n ? (1.0 / n) * sum : centre;
    toMesh[v] = cx.addVertex(centre + 0.5 * (target - centre));
    res.createdVertices.push_back(toMesh[v]);
  }
  std::vector<std::array<VertexId, 8>> added;
  for (HexId p : after) {
    std::array<VertexId, 8> v;
    for (int c = 0; c < 8; ++c) v[size_t(c)] = toMesh.at(pattern.vertex(p, c));
    added.push_back(v);
  }
  std::vector<VertexId> oldInterior;  // the region's vertices: those no hex uses afterwards were removed
  for (const auto& entry : m.vertex) oldInterior.push_back(entry.first);
  res.createdHexes = replaceHexes(cx, op, region, added);
  res.removedHexes = region;
  for (VertexId v : oldInterior)
    if (!cx.isVertex(v)) res.removedVertices.push_back(v);
  res.noInverse = "a flip, not an atomic step: its inverse is the " + fc.inverse + " flip of the created hexes";
  tx.commit(res, withNeighbours(cx, res.createdHexes));
  return res;
}

std::vector<OpResult> traditionalPillow(Complex& cx, HexId hex, int face) {
  std::vector<OpResult> out;
  out.push_back(pillow(cx, {hex, face}));
  try {
    out.push_back(hexPush(cx, {hex, face}));
  } catch (...) {
    cx.undo(out[0].edits);
    throw;
  }
  return out;
}

OpResult pillowRegion(Complex& cx, const std::vector<HexId>& hexes) {
  const std::string op = "pillowRegion";
  std::vector<HexId> S = hexes;
  std::sort(S.begin(), S.end());
  S.erase(std::unique(S.begin(), S.end()), S.end());
  if (S.empty()) reject(op, "needs at least one hex");
  auto inS = [&](HexId h) { return std::binary_search(S.begin(), S.end(), h); };
  std::vector<QuadSide> surface;
  for (HexId h : S) {
    if (!cx.isHex(h)) reject(op, hexName(h) + " does not exist");
    for (int f = 0; f < 6; ++f) {
      Gluing g = cx.gluing(h, f);
      if (g.boundary()) reject(op, "quad " + entityName(QuadSide{h, f}) + " of the set is on the mesh boundary");
      if (!inS(g.hex)) surface.push_back({h, f});
    }
  }
  if (surface.empty()) reject(op, "the set has no outer surface");
  Transaction tx(cx);
  OpResult res;
  std::map<VertexId, VertexId> inner;
  Vec3 centre;
  for (HexId h : S) centre = centre + (1.0 / double(S.size())) * cx.hexCentroid(h);
  for (QuadSide s : surface)
    for (int q = 0; q < 4; ++q) {
      VertexId v = cx.vertex(s.hex, kFaceCorners[size_t(s.face)][size_t(q)]);
      if (!inner.count(v)) {
        Vec3 p = cx.position(v);
        inner[v] = cx.addVertex(p + 0.25 * (centre - p));
        res.createdVertices.push_back(inner[v]);
      }
    }
  std::vector<std::array<VertexId, 8>> added;
  for (HexId h : S) {  // S's hexes move onto the inner copies
    std::array<VertexId, 8> v = cx.hexVertices(h);
    for (auto& x : v)
      if (inner.count(x)) x = inner[x];
    added.push_back(v);
  }
  for (QuadSide s : surface) {  // one layer hex per outer quad: outer quad + its inner copy
    std::array<VertexId, 8> v = cx.hexVertices(s.hex);
    for (int q = 0; q < 4; ++q) {
      int c = kFaceCorners[size_t(s.face)][size_t(q)];
      v[size_t(flipAxis(c, axisOfFace(s.face)))] = inner[v[size_t(c)]];
    }
    added.push_back(v);
  }
  res.removedHexes = S;
  res.createdHexes = replaceHexes(cx, op, S, added);
  std::vector<HexId> touched = withNeighbours(cx, res.createdHexes);
  tx.commitIfValid(res, touched, op, "the set's outer surface is not a manifold");
  return res;
}

namespace {

// A triple-chord push worked out before anything is edited (TK03 §4.5.1): vertex v at `corner` of
// `hex` is split along three quads through it; two new hexes X (outside) and Y (inside) fill the
// gap, corner 0 on v (X) or its copy (Y), their x, y, z edges along the quads' shared edges.
class TripleChordPush {
 public:
  TripleChordPush(const Complex& cx, HexId hex, int corner, QuadSide q1, QuadSide q2, QuadSide q3);
  OpResult apply(Complex& cx) const;

 private:
  void readQuads();
  void findCorners();
  void splitSides();
  std::array<VertexId, 8> hexAt(VertexId origin, VertexId w) const;

  const std::string op_ = "tripleChordPush";
  const Complex& cx_;
  VertexId v_ = -1;
  std::array<QuadSide, 3> q_;
  std::array<std::array<VertexId, 4>, 3> qv_;
  VertexId p12_ = -1, p13_ = -1, p23_ = -1;      // the other end of the edge q_i and q_j share at v
  VertexId d1_ = -1, d2_ = -1, d3_ = -1;         // the corner of q_i opposite v
  std::vector<std::pair<HexId, int>> in_, all_;  // v's corners on q1's named side, and all of them
  std::array<QuadSide, 3> inSide_, outSide_;
};

TripleChordPush::TripleChordPush(const Complex& cx, HexId hex, int corner, QuadSide q1, QuadSide q2, QuadSide q3)
    : cx_(cx), q_{q1, q2, q3} {
  if (!cx.isHex(hex)) reject(op_, hexName(hex) + " does not exist");
  if (corner < 0 || corner > 7) reject(op_, "corner " + std::to_string(corner) + " is not 0..7");
  v_ = cx.vertex(hex, corner);
  readQuads();
  findCorners();
  splitSides();
}

// Three distinct interior quads through v.
void TripleChordPush::readQuads() {
  for (int i = 0; i < 3; ++i) {
    const QuadSide qi = q_[size_t(i)];
    if (!cx_.isHex(qi.hex) || qi.face < 0 || qi.face > 5) reject(op_, "quad " + entityName(qi) + " does not exist");
    if (cx_.isBoundary(qi)) reject(op_, "quad " + entityName(qi) + " is on the boundary");
    qv_[size_t(i)] = faceVertexSet(cx_, qi.hex, qi.face);
    if (!std::binary_search(qv_[size_t(i)].begin(), qv_[size_t(i)].end(), v_))
      reject(op_, "quad " + entityName(qi) + " does not contain vertex " + std::to_string(v_));
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < i; ++j)
      if (cx_.canonical(q_[size_t(i)]) == cx_.canonical(q_[size_t(j)])) reject(op_, "the three quads must be distinct");
}

// p_ij: the other end of the edge q_i and q_j share at v; d_i: the corner of q_i opposite v.
void TripleChordPush::findCorners() {
  auto common = [&](int i, int j) {
    std::vector<VertexId> c;
    for (VertexId x : qv_[size_t(i)])
      if (x != v_ && std::binary_search(qv_[size_t(j)].begin(), qv_[size_t(j)].end(), x)) c.push_back(x);
    if (c.size() != 1)
      reject(op_, "quads " + entityName(q_[size_t(i)]) + " and " + entityName(q_[size_t(j)]) +
                      " must share exactly one edge at v");
    return c[0];
  };
  p12_ = common(0, 1), p13_ = common(0, 2), p23_ = common(1, 2);
  auto opposite = [&](int i, VertexId a, VertexId b) {
    for (VertexId x : qv_[size_t(i)])
      if (x != v_ && x != a && x != b) return x;
    return VertexId(-1);
  };
  d1_ = opposite(0, p12_, p13_), d2_ = opposite(1, p12_, p23_), d3_ = opposite(2, p13_, p23_);
}

// Split v along the three quads: the side of q1's named side gets a new vertex. v must be
// interior and cut into exactly two sides, each quad with one side on each.
void TripleChordPush::splitSides() {
  std::vector<QuadSide> walls;
  for (QuadSide s : q_) {
    walls.push_back(s);
    walls.push_back({cx_.gluing(s).hex, cx_.gluing(s).face});
  }
  int c1 = -1;
  for (int c = 0; c < 8; ++c)
    if (cx_.vertex(q_[0].hex, c) == v_) c1 = c;
  in_ = cornersOnSide(cx_, {q_[0].hex, c1}, walls);
  all_ = cx_.cornersOfVertex(q_[0].hex, c1);
  for (auto [h, c] : all_)
    for (int f : facesOfCorner(c))
      if (cx_.gluing(h, f).boundary()) reject(op_, "vertex " + std::to_string(v_) + " is on the boundary");
  if (in_.size() == all_.size())
    reject(op_, "the three quads do not cut vertex " + std::to_string(v_) + " into two sides");
  std::vector<std::pair<HexId, int>> out;
  for (auto k : all_)
    if (std::find(in_.begin(), in_.end(), k) == in_.end()) out.push_back(k);
  if (cornersOnSide(cx_, out[0], walls).size() != out.size())
    reject(op_, "the three quads cut vertex " + std::to_string(v_) + " into more than two sides");
  auto onIn = [&](QuadSide s) {
    for (int c = 0; c < 8; ++c)
      if (cx_.vertex(s.hex, c) == v_)
        return std::find(in_.begin(), in_.end(), std::pair<HexId, int>{s.hex, c}) != in_.end();
    return false;
  };
  for (int i = 0; i < 3; ++i) {
    QuadSide s = q_[size_t(i)], t{cx_.gluing(s).hex, cx_.gluing(s).face};
    inSide_[size_t(i)] = onIn(s) ? s : t;
    outSide_[size_t(i)] = onIn(s) ? t : s;
    if (onIn(outSide_[size_t(i)]) || !onIn(inSide_[size_t(i)]))
      reject(op_, "the quads do not separate vertex " + std::to_string(v_));
  }
}

// X (outside): corner 0 = v, x -> p23, y -> p13, z -> p12; faces x=0,y=0,z=0 are q1,q2,q3. Y likewise on vIn.
std::array<VertexId, 8> TripleChordPush::hexAt(VertexId origin, VertexId w) const {
  std::array<VertexId, 8> a;
  a[size_t(cornerAt(0, 0, 0))] = origin;
  a[size_t(cornerAt(1, 0, 0))] = p23_;
  a[size_t(cornerAt(0, 1, 0))] = p13_;
  a[size_t(cornerAt(0, 0, 1))] = p12_;
  a[size_t(cornerAt(0, 1, 1))] = d1_;
  a[size_t(cornerAt(1, 0, 1))] = d2_;
  a[size_t(cornerAt(1, 1, 0))] = d3_;
  a[size_t(cornerAt(1, 1, 1))] = w;
  return a;
}

// The inside corners take v's copy; X and Y are glued to the quads' two sides and to each other.
OpResult TripleChordPush::apply(Complex& cx) const {
  Transaction tx(cx);
  OpResult res;
  Vec3 cIn;
  for (auto [h, c] : in_) cIn = cIn + (1.0 / double(in_.size())) * cx.hexCentroid(h);
  Vec3 pv = cx.position(v_);
  VertexId vIn = cx.addVertex(pv + 0.2 * (cIn - pv));
  Vec3 mid = (1.0 / 3.0) * (cx.position(d1_) + cx.position(d2_) + cx.position(d3_));
  VertexId w = cx.addVertex(pv + 0.3 * (mid - pv) + 0.1 * (cIn - pv));
  res.createdVertices = {vIn, w};
  for (QuadSide s : q_) cx.unglue(s.hex, s.face);
  for (auto [h, c] : in_) cx.setCorner(h, c, vIn);
  HexId X = cx.addHex(hexAt(v_, w)), Y = cx.addHex(hexAt(vIn, w));
  res.createdHexes = {X, Y};
  for (int i = 0; i < 3; ++i) {
    int face = 2 * i;  // q1 on x=0 (p12, p13, d1), q2 on y=0, q3 on z=0
    glueByVertices(cx, X, face, outSide_[size_t(i)].hex, outSide_[size_t(i)].face);
    glueByVertices(cx, Y, face, inSide_[size_t(i)].hex, inSide_[size_t(i)].face);
    glueByVertices(cx, X, face + 1, Y, face + 1);
  }
  std::vector<HexId> touched{X, Y};
  for (int i = 0; i < 3; ++i) touched.insert(touched.end(), {inSide_[size_t(i)].hex, outSide_[size_t(i)].hex});
  for (auto [h, c] : all_) touched.push_back(h);
  tx.commitIfValid(res, touched, op_, "the result would not be a valid complex");
  return res;
}

}  // namespace

OpResult tripleChordPush(Complex& cx, HexId hex, int corner, QuadSide q1, QuadSide q2, QuadSide q3) {
  return TripleChordPush(cx, hex, corner, q1, q2, q3).apply(cx);
}

}  // namespace hexdual
