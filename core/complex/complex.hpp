// The glued-hex complex: hexes with 8 vertex ids each and, per local face, a gluing to a
// neighbour's face (or the boundary). Quads and edges are derived from gluings, never from
// vertex sets, so every degenerate state of the dual operations is representable: two hexes
// on the same 8 vertices sharing 5 quads, two quads on the same 4 vertices, doubled edges.
// Local numbering: hex_tables.hpp.
#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "complex/hex_tables.hpp"
#include "complex/huge_pages.hpp"

namespace hexdual {

using HexId = int32_t;
using VertexId = int32_t;

struct Vec3 {
  double x = 0, y = 0, z = 0;
};
inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }

// Thrown for every user-facing error (bad input, broken invariant, rejected operation).
struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// One side of a quad: a local face of a hex.
struct QuadSide {
  HexId hex = -1;
  int face = 0;
  friend bool operator==(QuadSide a, QuadSide b) { return a.hex == b.hex && a.face == b.face; }
  friend bool operator<(QuadSide a, QuadSide b) { return a.hex != b.hex ? a.hex < b.hex : a.face < b.face; }
};
// One (hex, local edge) incidence of an edge.
struct EdgeRef {
  HexId hex = -1;
  int edge = 0;
  friend bool operator==(EdgeRef a, EdgeRef b) { return a.hex == b.hex && a.edge == b.edge; }
  friend bool operator<(EdgeRef a, EdgeRef b) { return a.hex != b.hex ? a.hex < b.hex : a.edge < b.edge; }
};
// The other side of a face: neighbour hex and face, and the orientation code of the map.
struct Gluing {
  HexId hex = -1;  // -1: boundary
  int face = 0;
  int orient = 0;
  bool boundary() const { return hex < 0; }
};

struct Counts {
  int64_t vertices = 0, edges = 0, quads = 0, hexes = 0;
  int64_t boundaryVertices = 0, boundaryEdges = 0, boundaryQuads = 0;
  friend bool operator==(const Counts& a, const Counts& b) {
    return a.vertices == b.vertices && a.edges == b.edges && a.quads == b.quads && a.hexes == b.hexes &&
           a.boundaryVertices == b.boundaryVertices && a.boundaryEdges == b.boundaryEdges &&
           a.boundaryQuads == b.boundaryQuads;
  }
};

// Iterable range of live hex ids.
class HexRange {
 public:
  class iterator {
   public:
    iterator(const HugeVector<uint8_t>* alive, HexId h) : alive_(alive), h_(h) { skip(); }
    HexId operator*() const { return h_; }
    iterator& operator++() {
      ++h_;
      skip();
      return *this;
    }
    bool operator!=(const iterator& o) const { return h_ != o.h_; }

   private:
    void skip() {
      while (h_ < (HexId)alive_->size() && !(*alive_)[h_]) ++h_;
    }
    const HugeVector<uint8_t>* alive_;
    HexId h_;
  };
  explicit HexRange(const HugeVector<uint8_t>* alive) : alive_(alive) {}
  iterator begin() const { return iterator(alive_, 0); }
  iterator end() const { return iterator(alive_, (HexId)alive_->size()); }

 private:
  const HugeVector<uint8_t>* alive_;
};

class Complex {
 public:
  Complex() = default;

  // ---- construction (builders.hpp has grids, rings and building from connectivity) ----
  // Reserves storage for this many hexes and vertices in all (avoids regrowth in builders).
  void reserve(size_t hexes, size_t vertices);
  // Hex ids fit in the 26 bits a packed gluing keeps for them.
  static constexpr int64_t kMaxHexes = int64_t(1) << 26;
  // Whether an a x b x c arrangement (each at least 1) has more than kMaxHexes hexes; a * b is
  // compared first, since the product of three ints can pass 2^63 (and wrap) before it is.
  static bool tooManyHexes(int64_t a, int64_t b, int64_t c) { return a * b > kMaxHexes || a * b * c > kMaxHexes; }
  // A structured a x b x c block at integer positions (makeGrid): the state adding its vertices
  // and hexes in order and gluing every face pair gives, written in one pass per array without
  // the per-call checks (in 40% of the time at 100^3). Refuses sizes below 1 or above kMaxHexes.
  static Complex block(int a, int b, int c);
  // Adds a vertex at a position; returns its id (ids are never reused).
  VertexId addVertex(Vec3 p);
  // Adds a hex on 8 existing vertex ids (VTK order), all faces on the boundary.
  HexId addHex(const std::array<VertexId, 8>& v);
  // Glues face fa of hex a to face fb of hex b with an orientation code (both directions).
  // Legal only when both faces are currently on the boundary.
  void glue(HexId a, int fa, HexId b, int fb, int orient);
  // Makes face f of hex h (and its partner) boundary again.
  void unglue(HexId h, int f);
  // Removes a hex: its faces must already be unglued. Leaves a tombstone.
  void removeHex(HexId h);
  // Points corner c of hex h at another vertex (reference counts follow).
  void setCorner(HexId h, int c, VertexId v);
  // Renumbers hexes and vertices densely (drops tombstones and unused vertices), keeping order.
  void compact();

  // ---- queries ----
  HexRange hexes() const { return HexRange(&alive_); }
  // Every hex id's alive flag (1: a hex), for a pass over a complex that does not change meanwhile:
  // a local span stays in registers, where HexRange reads the flags through the complex each step.
  std::span<const uint8_t> aliveFlags() const { return {alive_.data(), alive_.size()}; }
  bool isHex(HexId h) const { return h >= 0 && h < (HexId)alive_.size() && alive_[h]; }
  bool isVertex(VertexId v) const { return v >= 0 && v < (VertexId)refs_.size() && refs_[v] > 0; }
  HexId hexCapacity() const { return (HexId)alive_.size(); }
  VertexId vertexCapacity() const { return (VertexId)pos_.size(); }
  int64_t numHexes() const { return numHexes_; }
  int64_t numVertices() const { return numVertices_; }
  int64_t numBoundaryQuads() const { return numBoundarySides_; }
  int64_t numQuads() const { return (6 * numHexes_ + numBoundarySides_) / 2; }
  // Counts of every kind, including edges (a linear pass over the edge classes).
  Counts counts() const;

  VertexId vertex(HexId h, int corner) const { return verts_[h][corner]; }
  const std::array<VertexId, 8>& hexVertices(HexId h) const { return verts_[h]; }
  Gluing gluing(HexId h, int face) const {
    uint32_t g = glue_[size_t(h)][size_t(face)];
    if (g == kBoundary) return {};
    return {wordHex(g), wordFace(g), wordOrient(g)};
  }
  Gluing gluing(QuadSide s) const { return gluing(s.hex, s.face); }
  // A hex's six gluings as stored: the neighbour << 6 | its face << 3 | the orientation, or
  // kBoundaryWord on a boundary side. The low six bits are the (face, orientation) part of the
  // hex tables' step indices (hex_tables.hpp: edgeStepIndex, crossingIndex), so the extraction's
  // per-hex passes index the tables from a word without decoding it.
  static constexpr uint32_t kBoundaryWord = 0xFFFFFFFFu;
  const std::array<uint32_t, 6>& gluingWords(HexId h) const { return glue_[size_t(h)]; }
  // A packed word's parts (a gluing word, or a Glue or Unglue edit's value), and its (face,
  // orientation) bits: what a step index adds to its base (e.g. edgeStepIndex(e, x, 0, 0)).
  static HexId wordHex(uint32_t w) { return HexId(w >> 6); }
  static int wordFace(uint32_t w) { return int((w >> 3) & 7u); }
  static int wordOrient(uint32_t w) { return int(w & 7u); }
  static size_t wordFaceOrient(uint32_t w) { return size_t(w & 63u); }
  static_assert(tables::edgeStepIndex(7, 2, 5, 3) == tables::edgeStepIndex(7, 2, 0, 0) + ((5 << 3) | 3));
  static_assert(tables::crossingIndex(4, 1, 5, 3) == tables::crossingIndex(4, 1, 0, 0) + ((5 << 3) | 3));
  static_assert(tables::cornerStepIndex(5, 2, 4, 3) == tables::cornerStepIndex(5, 2, 0, 0) + ((4 << 3) | 3));
  bool isBoundary(QuadSide s) const { return glue_[s.hex][s.face] == kBoundary; }
  // The canonical side of a quad: the smaller of its two sides.
  QuadSide canonical(QuadSide s) const;
  // All quads, once each, by canonical side.
  std::vector<QuadSide> quads() const;
  // All edges, once each, by canonical (smallest) incidence.
  std::vector<EdgeRef> edges() const;
  // All vertex ids in use, ascending.
  std::vector<VertexId> vertices() const;
  // The boundary quad mesh: every boundary side with its 4 vertex ids in face-cycle order.
  struct BoundaryQuad {
    QuadSide side;
    std::array<VertexId, 4> vertices;
  };
  std::vector<BoundaryQuad> boundaryQuads() const;
  // Corner of the neighbour that corner c of face f of hex h is glued to (requires interior face).
  int mappedCorner(HexId h, int face, int corner) const {
    Gluing g = gluing(h, face);
    return tables::kFaceCorners[size_t(g.face)][size_t(tables::mapPosition(tables::positionInFace(face, corner), g.orient))];
  }
  // One step around an edge: from incidence `cur` out through `exitFace` (a face containing it) to
  // the neighbour's incidence and the face to leave that by; false at the boundary (one table lookup).
  bool stepAroundEdge(EdgeRef& cur, int& exitFace) const {
    const uint32_t g = glue_[size_t(cur.hex)][size_t(exitFace)];
    if (g == kBoundary) return false;
    const tables::EdgeStep& st = tables::kEdgeSteps[size_t(tables::edgeStepIndex(cur.edge, exitFace, 0, 0)) + wordFaceOrient(g)];
    cur = {wordHex(g), st.edge};
    exitFace = st.exit;
    return true;
  }
  // The (hex, edge) incidences of an edge, in cycle order; `closed` tells whether the cycle closes.
  std::vector<EdgeRef> edgeCycle(EdgeRef e, bool* closed = nullptr) const;
  // Its number of incidences, without listing them (validate() counts every edge's).
  size_t edgeCycleSize(EdgeRef e) const;
  // The canonical incidence (smallest) of an edge.
  EdgeRef canonical(EdgeRef e) const;
  // All (hex, corner) incidences of the vertex at corner c of hex h, found by walking gluings.
  std::vector<std::pair<HexId, int>> cornersOfVertex(HexId h, int corner) const;

  // Edge classes: a class id per (hex, local edge) slot (index 12*h+e), and the number of classes.
  std::vector<int32_t> edgeClasses(int32_t* numClasses) const;

  Vec3 position(VertexId v) const { return pos_[v]; }
  void setPosition(VertexId v, Vec3 p) {
    record({JournalEntry::SetPosition, v, 0, 0, pos_[v]});
    pos_[v] = p;
  }
  std::span<const Vec3> positions() const { return pos_; }
  Vec3 hexCentroid(HexId h) const;

  // Checks every invariant; throws Error naming the first violation.
  void validate() const;
  // Takes every vertex whose link is not a sphere or a disk as a tolerated non-manifold vertex
  // (setNonManifoldVertices), then validate(): what the file readers do, with the edge classes
  // and vertex links computed once for both.
  void validateAcceptingNonManifoldVertices();
  // Vertices whose link is neither a sphere nor a disk, accepted from an input file (ascending):
  // validate() allows exactly these, and operations refuse to touch them.
  const std::vector<VertexId>& nonManifoldVertices() const { return nonManifold_; }
  void setNonManifoldVertices(std::vector<VertexId> v) { nonManifold_ = std::move(v); }
  // Checks the invariants that an edit of these hexes can break: their gluings, their 8 distinct
  // vertices, and the links of their vertices (found by walking, so this is local); inside a
  // transaction, only the links of those vertices whose star its edits changed.
  void validateAround(const std::vector<HexId>& hexes) const;

  // ---- transactions: every edit between begin and rollback is undone exactly ----
  struct Edit {
    enum Kind : uint8_t { AddVertex, AddHex, Glue, Unglue, RemoveHex, SetCorner, SetPosition } kind;
    HexId hex;
    int face;
    uint32_t value;  // Glue, Unglue: the packed gluing of (hex, face); SetCorner: the old vertex
    Vec3 pos;
  };
  // The edits of one committed transaction, enough to undo it exactly (ids included).
  // (in whole 2 MiB pages from 1 MiB up, like the per-hex arrays: a 100³ sheet extraction's
  // journal is 4.4 MB, which in 4 KiB pages took 1,100 page faults, about 13 ms on a VM)
  struct EditLog {
    HugeVector<Edit> edits;
    uint64_t revisionBefore = 0, revisionAfter = 0;
  };
  void beginTransaction();
  // Inside a transaction: room for n more edits at once. An operation that knows its size asks
  // before it edits, so the journal does not grow by doubling (each doubling a fresh buffer: a 100³
  // sheet extraction's 110,000 edits cost 2,600 page faults that way, most of its time).
  void reserveEdits(size_t n) {
    if (journaling_) journal_.reserve(journal_.size() + n);
  }
  EditLog commitTransaction();
  void rollbackTransaction();
  bool inTransaction() const { return journaling_; }
  // Undoes a committed transaction; legal only while nothing has changed since (LIFO undo).
  void undo(const EditLog& log);
  // Modification counter: changes on every topological edit.
  uint64_t revision() const { return revision_; }
  // Bytes held by the topology and positions (for benchmarks).
  size_t memoryBytes() const;

 private:
  static constexpr uint32_t kBoundary = kBoundaryWord;
  static uint32_t pack(HexId h, int f, int o) { return (uint32_t(h) << 6) | uint32_t(f << 3) | uint32_t(o); }
  // The check inline, the message out of line: glue() runs it for every quad a grid or a file joins.
  void requireHex(HexId h, const char* what) const {
    if (!isHex(h)) [[unlikely]]
      throwNoHex(h, what);
  }
  [[noreturn]] static void throwNoHex(HexId h, const char* what);
  // Calls visit(incidence, dir) for every incidence of e's edge but e itself: round the cycle
  // (dir 0), or out along the fan through each of e's faces (dir 0, then dir 1). Returns whether
  // the cycle closes. At most 12 * hexes + 1 steps each way (a corrupt complex cannot loop it).
  template <class Visit>
  bool walkAroundEdge(EdgeRef e, Visit&& visit) const {
    const auto fs = tables::facesOfEdge(e.edge);
    const size_t limit = size_t(12) * size_t(numHexes_) + 1;
    for (int dir = 0; dir < 2; ++dir) {
      EdgeRef cur = e;
      int exitFace = fs[size_t(dir)];
      for (size_t n = 0; n < limit && stepAroundEdge(cur, exitFace); ++n) {
        if (cur == e) return true;
        visit(cur, dir);
      }
    }
    return false;
  }
  void validateLinks(const std::vector<int32_t>& edgeClass) const;
  // validate()'s checks; given `accepted`, the vertices whose link is not a sphere or a disk are
  // listed there (and tolerated) instead of failing.
  void validateImpl(std::vector<VertexId>* accepted) const;
  // counts() from edge classes already computed (edgeClasses).
  Counts countsFrom(const std::vector<int32_t>& edgeClass, int32_t numClasses) const;
  struct VertexStar {
    std::vector<std::pair<HexId, int>> corners;
    std::vector<int> link;  // union-find over 3 edge incidences per corner
    // Open-addressing index of corners (key hex << 3 | corner, value place + 1): finding a
    // neighbour corner costs O(1) instead of a scan of the star (large after many pillows).
    std::vector<uint64_t> index;
    int64_t edges = 0, boundarySides = 0;
  };
  void walkStar(HexId h, int corner, VertexStar& star) const;
  static size_t sizeStar(VertexStar& st, size_t refs);
  static void growStar(VertexStar& st, size_t& room);
  static void rehashStar(VertexStar& st, size_t n);
  std::vector<VertexId> verticesWithEditedStars() const;

  HugeVector<std::array<VertexId, 8>> verts_;
  HugeVector<std::array<uint32_t, 6>> glue_;
  HugeVector<uint8_t> alive_;
  HugeVector<Vec3> pos_;
  HugeVector<int32_t> refs_;  // number of (hex, corner) incidences per vertex
  std::vector<VertexId> nonManifold_;
  using JournalEntry = Edit;
  void revert(const HugeVector<Edit>& edits);
  void record(JournalEntry e) {
    if (journaling_) journal_.push_back(e);
  }
  HugeVector<JournalEntry> journal_;
  bool journaling_ = false;
  uint64_t revisionAtBegin_ = 0;
  int64_t numHexes_ = 0, numVertices_ = 0, numBoundarySides_ = 0;
  uint64_t revision_ = 0;
};

}  // namespace hexdual
