#include "complex/complex.hpp"
#include "complex/huge_pages.hpp"

#include <algorithm>
#include <numeric>


namespace hexdual {
using namespace tables;

void Complex::throwNoHex(HexId h, const char* what) {
  throw Error(std::string(what) + ": hex " + std::to_string(h) + " does not exist");
}

void Complex::reserve(size_t hexes, size_t vertices) {
  reserveHuge(verts_, hexes);
  reserveHuge(glue_, hexes);
  reserveHuge(alive_, hexes);
  reserveHuge(pos_, vertices);
  reserveHuge(refs_, vertices);
}

Complex Complex::block(int a, int b, int c) {
  if (a < 1 || b < 1 || c < 1) throw Error("grid: every dimension must be at least 1");
  if (tooManyHexes(a, b, c)) throw Error("grid: more than 2^26 hexes");
  Complex cx;
  const size_t nh = size_t(a) * size_t(b) * size_t(c), nv = size_t(a + 1) * size_t(b + 1) * size_t(c + 1);
  cx.reserve(nh + nh / 8 + 64, nv + nv / 8 + 64);  // headroom for the first edits (as addHex's callers leave)
  // A vertex is a corner of one hex per side it has along each axis (two inside, one on a face).
  auto sides = [](int i, int n) { return int32_t(i > 0) + int32_t(i < n); };
  for (int k = 0; k <= c; ++k)
    for (int j = 0; j <= b; ++j)
      for (int i = 0; i <= a; ++i) {
        cx.pos_.push_back({double(i), double(j), double(k)});
        cx.refs_.push_back(sides(i, a) * sides(j, b) * sides(k, c));
      }
  const int32_t dx = 1, dy = a + 1, dz = (a + 1) * (b + 1);  // vertex id steps
  const int32_t hy = a, hz = a * b;                          // hex id steps
  HexId h = 0;
  for (int k = 0; k < c; ++k)
    for (int j = 0; j < b; ++j)
      for (int i = 0; i < a; ++i, ++h) {
        const VertexId v0 = i + dy * j + dz * k;
        std::array<VertexId, 8> v;
        for (int q = 0; q < 8; ++q) v[size_t(q)] = v0 + dx * cornerBit(q, 0) + dy * cornerBit(q, 1) + dz * cornerBit(q, 2);
        cx.verts_.push_back(v);
        // Face 2*axis meets face 2*axis+1 of the previous hex along the axis, position for position.
        cx.glue_.push_back({i > 0 ? pack(h - 1, 1, 0) : kBoundary, i + 1 < a ? pack(h + 1, 0, 0) : kBoundary,
                            j > 0 ? pack(h - hy, 3, 0) : kBoundary, j + 1 < b ? pack(h + hy, 2, 0) : kBoundary,
                            k > 0 ? pack(h - hz, 5, 0) : kBoundary, k + 1 < c ? pack(h + hz, 4, 0) : kBoundary});
      }
  cx.alive_.assign(nh, 1);
  const int64_t glued = int64_t(a - 1) * b * c + int64_t(a) * (b - 1) * c + int64_t(a) * b * (c - 1);
  cx.numHexes_ = int64_t(nh);
  cx.numVertices_ = int64_t(nv);
  cx.numBoundarySides_ = 6 * int64_t(nh) - 2 * glued;
  cx.revision_ = uint64_t(nv) + uint64_t(nh) + uint64_t(glued);  // one per vertex, hex and gluing, as one by one
  return cx;
}

VertexId Complex::addVertex(Vec3 p) {
  pos_.push_back(p);
  refs_.push_back(0);
  ++revision_;
  record({JournalEntry::AddVertex, VertexId(pos_.size() - 1), 0, 0, {}});
  return VertexId(pos_.size() - 1);
}

HexId Complex::addHex(const std::array<VertexId, 8>& v) {
  for (VertexId x : v)
    if (x < 0 || x >= (VertexId)pos_.size()) throw Error("addHex: vertex " + std::to_string(x) + " does not exist");
  if (alive_.size() >= size_t(kMaxHexes)) throw Error("addHex: more than 2^26 hexes");
  verts_.push_back(v);
  std::array<uint32_t, 6> g;
  g.fill(kBoundary);
  glue_.push_back(g);
  alive_.push_back(1);
  for (VertexId x : v)
    if (refs_[x]++ == 0) ++numVertices_;
  ++numHexes_;
  numBoundarySides_ += 6;
  ++revision_;
  record({JournalEntry::AddHex, HexId(alive_.size() - 1), 0, 0, {}});
  return HexId(alive_.size() - 1);
}

void Complex::glue(HexId a, int fa, HexId b, int fb, int orient) {
  requireHex(a, "glue");
  requireHex(b, "glue");
  if (a == b && fa == fb) throw Error("glue: a face cannot be glued to itself");
  if (glue_[a][fa] != kBoundary || glue_[b][fb] != kBoundary)
    throw Error("glue: hex " + std::to_string(a) + " face " + std::to_string(fa) + " or hex " + std::to_string(b) +
                " face " + std::to_string(fb) + " is already glued");
  glue_[a][fa] = pack(b, fb, orient);
  glue_[b][fb] = pack(a, fa, inverseOrient(orient));
  numBoundarySides_ -= 2;
  ++revision_;
  record({JournalEntry::Glue, a, fa, glue_[a][fa], {}});  // the partner too, for undo's touched hexes
}

void Complex::unglue(HexId h, int f) {
  requireHex(h, "unglue");
  Gluing g = gluing(h, f);
  if (g.boundary()) return;
  record({JournalEntry::Unglue, h, f, glue_[h][f], {}});
  glue_[h][f] = kBoundary;
  glue_[g.hex][g.face] = kBoundary;
  numBoundarySides_ += 2;
  ++revision_;
}

void Complex::removeHex(HexId h) {
  requireHex(h, "removeHex");
  for (int f = 0; f < 6; ++f)
    if (glue_[h][f] != kBoundary) throw Error("removeHex: hex " + std::to_string(h) + " is still glued");
  for (VertexId x : verts_[h])
    if (--refs_[x] == 0) --numVertices_;
  alive_[h] = 0;
  --numHexes_;
  numBoundarySides_ -= 6;
  ++revision_;
  record({JournalEntry::RemoveHex, h, 0, 0, {}});
}

void Complex::setCorner(HexId h, int c, VertexId v) {
  requireHex(h, "setCorner");
  if (v < 0 || v >= (VertexId)pos_.size()) throw Error("setCorner: vertex " + std::to_string(v) + " does not exist");
  VertexId old = verts_[h][c];
  if (old == v) return;
  if (--refs_[old] == 0) --numVertices_;
  if (refs_[v]++ == 0) ++numVertices_;
  verts_[h][c] = v;
  ++revision_;
  record({JournalEntry::SetCorner, h, c, uint32_t(old), {}});
}

void Complex::beginTransaction() {
  if (journaling_) throw Error("beginTransaction: a transaction is already open");
  journal_.clear();
  journal_.reserve(64);  // the committed journal was moved out; an operation logs a few dozen edits
  journaling_ = true;
  revisionAtBegin_ = revision_;
}

Complex::EditLog Complex::commitTransaction() {
  journaling_ = false;
  EditLog log{std::move(journal_), revisionAtBegin_, revision_};
  journal_.clear();
  return log;
}

void Complex::rollbackTransaction() {
  journaling_ = false;
  revert(journal_);
  journal_.clear();
  revision_ = revisionAtBegin_;
}

void Complex::undo(const EditLog& log) {
  if (journaling_) throw Error("undo: not allowed inside a transaction");
  if (revision_ != log.revisionAfter) throw Error("undo: the complex has changed since that operation; undo the later ones first");
  revert(log.edits);
  revision_ = log.revisionBefore;
}

void Complex::revert(const HugeVector<Edit>& edits) {
  for (auto it = edits.rbegin(); it != edits.rend(); ++it) {
    const JournalEntry& e = *it;
    switch (e.kind) {
      case JournalEntry::AddVertex:
        pos_.pop_back();
        refs_.pop_back();
        break;
      case JournalEntry::AddHex:
        for (VertexId x : verts_.back())
          if (--refs_[x] == 0) --numVertices_;
        verts_.pop_back();
        glue_.pop_back();
        alive_.pop_back();
        --numHexes_;
        numBoundarySides_ -= 6;
        break;
      case JournalEntry::Glue: {
        Gluing g = gluing(e.hex, e.face);
        glue_[e.hex][e.face] = kBoundary;
        glue_[g.hex][g.face] = kBoundary;
        numBoundarySides_ += 2;
        break;
      }
      case JournalEntry::Unglue: {
        uint32_t v = e.value;
        HexId b = wordHex(v);
        int fb = wordFace(v), o = wordOrient(v);
        glue_[e.hex][e.face] = v;
        glue_[b][fb] = pack(e.hex, e.face, inverseOrient(o));
        numBoundarySides_ -= 2;
        break;
      }
      case JournalEntry::RemoveHex:
        alive_[e.hex] = 1;
        for (VertexId x : verts_[e.hex])
          if (refs_[x]++ == 0) ++numVertices_;
        ++numHexes_;
        numBoundarySides_ += 6;
        break;
      case JournalEntry::SetCorner: {
        VertexId cur = verts_[e.hex][e.face], old = VertexId(e.value);
        if (--refs_[cur] == 0) --numVertices_;
        if (refs_[old]++ == 0) ++numVertices_;
        verts_[e.hex][e.face] = old;
        break;
      }
      case JournalEntry::SetPosition:
        pos_[e.hex] = e.pos;
        break;
    }
  }
}

void Complex::compact() {
  if (journaling_) throw Error("compact: not allowed inside a transaction");
  std::vector<HexId> newHex(alive_.size(), -1);
  HexId nh = 0;
  for (HexId h = 0; h < (HexId)alive_.size(); ++h)
    if (alive_[h]) newHex[h] = nh++;
  std::vector<VertexId> newVert(pos_.size(), -1);
  VertexId nv = 0;
  for (VertexId v = 0; v < (VertexId)pos_.size(); ++v)
    if (refs_[v] > 0) newVert[v] = nv++;
  HugeVector<std::array<VertexId, 8>> verts(nh);
  HugeVector<std::array<uint32_t, 6>> glue(nh);
  for (HexId h = 0; h < (HexId)alive_.size(); ++h) {
    if (!alive_[h]) continue;
    for (int c = 0; c < 8; ++c) verts[newHex[h]][c] = newVert[verts_[h][c]];
    for (int f = 0; f < 6; ++f) {
      uint32_t g = glue_[h][f];
      glue[newHex[h]][f] = g == kBoundary ? kBoundary : pack(newHex[wordHex(g)], wordFace(g), wordOrient(g));
    }
  }
  HugeVector<Vec3> pos(nv);
  HugeVector<int32_t> refs(nv);
  for (VertexId v = 0; v < (VertexId)pos_.size(); ++v)
    if (newVert[v] >= 0) {
      pos[newVert[v]] = pos_[v];
      refs[newVert[v]] = refs_[v];
    }
  verts_ = std::move(verts);
  glue_ = std::move(glue);
  alive_.assign(nh, 1);
  pos_ = std::move(pos);
  refs_ = std::move(refs);
  std::vector<VertexId> nonManifold;
  for (VertexId v : nonManifold_)
    if (newVert[v] >= 0) nonManifold.push_back(newVert[v]);
  nonManifold_ = std::move(nonManifold);
  ++revision_;
}

QuadSide Complex::canonical(QuadSide s) const {
  Gluing g = gluing(s);
  if (g.boundary()) return s;
  QuadSide o{g.hex, g.face};
  return o < s ? o : s;
}

std::vector<QuadSide> Complex::quads() const {
  std::vector<QuadSide> out;
  out.reserve(size_t(numQuads()));
  for (HexId h : hexes())
    for (int f = 0; f < 6; ++f) {
      QuadSide s{h, f};
      if (canonical(s) == s) out.push_back(s);
    }
  return out;
}

std::vector<EdgeRef> Complex::edgeCycle(EdgeRef e, bool* closed) const {
  std::vector<EdgeRef> fwd{e}, back;
  const bool isClosed = walkAroundEdge(e, [&](EdgeRef cur, int dir) { (dir == 0 ? fwd : back).push_back(cur); });
  if (closed) *closed = isClosed;
  if (isClosed) return fwd;
  std::reverse(back.begin(), back.end());
  back.insert(back.end(), fwd.begin(), fwd.end());
  return back;
}

size_t Complex::edgeCycleSize(EdgeRef e) const {
  size_t n = 1;
  walkAroundEdge(e, [&n](EdgeRef, int) { ++n; });
  return n;
}

EdgeRef Complex::canonical(EdgeRef e) const {
  EdgeRef best = e;
  walkAroundEdge(e, [&best](EdgeRef cur, int) {
    if (cur < best) best = cur;
  });
  return best;
}

std::vector<std::pair<HexId, int>> Complex::cornersOfVertex(HexId h, int corner) const {
  // walkStar's breadth-first walk over gluings (an open-addressing index, no allocation once warm;
  // repeated pillows grow stars to hundreds of corners) finds the corners in the order of a plain
  // walk over facesOfCorner with a linear search for repeats.
  thread_local VertexStar star;
  walkStar(h, corner, star);
  std::vector<std::pair<HexId, int>> out(star.corners.size());
  for (size_t i = 0; i < out.size(); ++i) out[i] = {star.corners[i].first, star.corners[i].second & 7};
  return out;
}

std::vector<int32_t> Complex::edgeClasses(int32_t* numClasses) const {
  // Walk each edge's cycle (or fan) once, labelling every incidence: linear, no union-find.
  std::vector<int32_t> cls(size_t(12) * alive_.size(), -1);
  int32_t n = 0;
  for (HexId h : hexes())
    for (int e = 0; e < 12; ++e) {
      if (cls[size_t(12) * h + e] >= 0) continue;
      auto fs = facesOfEdge(e);
      for (int dir = 0; dir < 2; ++dir) {
        EdgeRef cur{h, e};
        int exitFace = fs[dir];
        bool closed = false;
        while (stepAroundEdge(cur, exitFace)) {
          int32_t& c = cls[size_t(12) * cur.hex + cur.edge];
          if (c == n) {
            closed = true;
            break;
          }
          c = n;
        }
        cls[size_t(12) * h + e] = n;
        if (closed) break;
      }
      ++n;
    }
  if (numClasses) *numClasses = n;
  return cls;
}

std::vector<EdgeRef> Complex::edges() const {
  int32_t n = 0;
  auto cls = edgeClasses(&n);
  std::vector<EdgeRef> out(static_cast<size_t>(n));
  std::vector<uint8_t> seen(static_cast<size_t>(n), 0);
  for (HexId h : hexes())
    for (int e = 0; e < 12; ++e) {
      int32_t k = cls[size_t(12) * h + e];
      if (!seen[size_t(k)]) {
        seen[size_t(k)] = 1;
        out[size_t(k)] = {h, e};  // the first incidence met in (hex, edge) order is the smallest
      }
    }
  return out;
}

std::vector<VertexId> Complex::vertices() const {
  std::vector<VertexId> out;
  out.reserve(size_t(numVertices_));
  for (VertexId v = 0; v < (VertexId)refs_.size(); ++v)
    if (refs_[v] > 0) out.push_back(v);
  return out;
}

std::vector<Complex::BoundaryQuad> Complex::boundaryQuads() const {
  std::vector<BoundaryQuad> out;
  out.reserve(size_t(numBoundarySides_));
  for (HexId h : hexes())
    for (int f = 0; f < 6; ++f)
      if (glue_[h][f] == kBoundary) {
        BoundaryQuad q{{h, f}, {}};
        for (int p = 0; p < 4; ++p) q.vertices[p] = verts_[h][kFaceCorners[f][p]];
        out.push_back(q);
      }
  return out;
}

Counts Complex::counts() const {
  int32_t ne = 0;
  const auto cls = edgeClasses(&ne);
  return countsFrom(cls, ne);
}

Counts Complex::countsFrom(const std::vector<int32_t>& cls, int32_t ne) const {
  Counts c;
  c.vertices = numVertices_;
  c.edges = ne;
  c.quads = numQuads();
  c.hexes = numHexes_;
  c.boundaryQuads = numBoundarySides_;
  std::vector<uint8_t> bEdge(size_t(ne), 0), bVert(pos_.size(), 0);
  for (HexId h : hexes())
    for (int f = 0; f < 6; ++f) {
      if (glue_[h][f] != kBoundary) continue;
      for (int p = 0; p < 4; ++p) {
        bEdge[size_t(cls[size_t(12) * h + kFaceEdges[f][p]])] = 1;
        bVert[size_t(verts_[h][kFaceCorners[f][p]])] = 1;
      }
    }
  c.boundaryEdges = std::count(bEdge.begin(), bEdge.end(), 1);
  c.boundaryVertices = std::count(bVert.begin(), bVert.end(), 1);
  return c;
}

Vec3 Complex::hexCentroid(HexId h) const {
  Vec3 c;
  for (VertexId v : verts_[h]) c = c + pos_[v];
  return 0.125 * c;
}

size_t Complex::memoryBytes() const {
  return verts_.capacity() * sizeof(verts_[0]) + glue_.capacity() * sizeof(glue_[0]) + alive_.capacity() +
         pos_.capacity() * sizeof(Vec3) + refs_.capacity() * sizeof(int32_t);
}

}  // namespace hexdual
