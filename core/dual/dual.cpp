#include "dual/dual.hpp"

#include <algorithm>
#include <numeric>

#include "complex/huge_pages.hpp"


namespace hexdual {
using namespace tables;

namespace {

constexpr std::array<std::array<int, 2>, 3> kParallelAxes = {{{1, 2}, {0, 2}, {0, 1}}};
// Bit of boundary mid-edge (face f, slot axis a) in a hex's loop marks.
constexpr int loopBit(int f, int a) { return 2 * f + (a == (axisOfFace(f) + 1) % 3 ? 0 : 1); }

int axisAcrossGluing(int f, int a, const Gluing& g) { return kCrossings[size_t(crossingIndex(f, a, g.face, g.orient))].axis; }

// facesOfEdge(e) as a table, and as a bit mask of faces.
constexpr auto kEdgeFaces = [] {
  std::array<std::array<int, 2>, 12> t{};
  for (int e = 0; e < 12; ++e) t[size_t(e)] = facesOfEdge(e);
  return t;
}();
constexpr auto kEdgeFaceMask = [] {
  std::array<unsigned, 12> t{};
  for (int e = 0; e < 12; ++e) t[size_t(e)] = (1u << facesOfEdge(e)[0]) | (1u << facesOfEdge(e)[1]);
  return t;
}();

// Per mask of faces: the edges on none of them (a 12-bit mask). The set bits of a nibble, and its
// lowest, by table: baseline x86-64 has no popcnt instruction, and __builtin_popcount there is a
// call into libgcc (0.8% of a random sequence's instructions).
constexpr auto kEdgesOffFaces = [] {
  std::array<uint16_t, 64> t{};
  for (unsigned m = 0; m < 64; ++m)
    for (int e = 0; e < 12; ++e)
      if (!(kEdgeFaceMask[size_t(e)] & m)) t[m] = uint16_t(t[m] | (1u << e));
  return t;
}();
constexpr std::array<uint8_t, 16> kNibbleBits{0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 4};
constexpr std::array<uint8_t, 16> kLowestBit{0, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0};
// The faces parallel to each axis (kParallelFaces) as masks.
constexpr std::array<unsigned, 3> kParallelFaceMask{0b111100u, 0b110011u, 0b001111u};

size_t slotIndex(HexId h, int a) { return size_t(3) * size_t(h) + size_t(a); }

// The parts of a packed gluing word (Complex::gluingWords): the step tables are indexed from the
// word without decoding it.
HexId hexOf(uint32_t w) { return Complex::wordHex(w); }
int faceOf(uint32_t w) { return Complex::wordFace(w); }
size_t faceOrient(uint32_t w) { return Complex::wordFaceOrient(w); }
// A per-hex array of 3 values read as one flat per-slot array (slotIndex).
int32_t* flat(HugeVector<std::array<int32_t, 3>>& v) { return v.empty() ? nullptr : v[0].data(); }

}  // namespace

void SheetFlooder::reserve(size_t hexCapacity) {
  growHuge(sign_, 3 * hexCapacity, int8_t(0));
  growHuge(edgeSeen_, hexCapacity, uint16_t(0));
  growHuge(loopSeen_, hexCapacity, uint16_t(0));
}

void SheetFlooder::clear(const std::vector<Slot>& slots) {
  for (Slot t : slots) {
    edgeSeen_[size_t(t.hex)] &= uint16_t(~(0xFu << (4 * t.axis)));
    for (int f : kParallelFaces[t.axis]) loopSeen_[size_t(t.hex)] &= uint16_t(~(1u << loopBit(f, t.axis)));
  }
}

// Marks every incidence of the edge at (h, e) (its cycle, or its fan both ways to the boundary).
bool SheetFlooder::walkEdge(const Complex& cx, HexId h, int e) {
  edgeSeen_[size_t(h)] |= uint16_t(1u << e);
  auto fs = facesOfEdge(e);
  for (int dir = 0; dir < 2; ++dir) {
    EdgeRef cur{h, e};
    int exit = fs[size_t(dir)];
    while (cx.stepAroundEdge(cur, exit)) {
      if (cur.hex == h && cur.edge == e) return true;  // round the cycle
      edgeSeen_[size_t(cur.hex)] |= uint16_t(1u << cur.edge);
    }
  }
  return false;
}

namespace {
// Walks one boundary loop of a sheet's mid-surface from a boundary mid-edge (the side of slot
// (h, a) on boundary face f): mid-edge, fan of the primal edge it ends at, next mid-edge, ...;
// marks each mid-edge in `loopSeen` (per hex, loopBit).
void walkBoundaryLoop(const Complex& cx, HexId h, int f, int a, uint16_t* loopSeen) {
  HexId ch = h;
  int cf = f, ca = a;
  int leave = kMidSides[size_t(f * 3 + a)].secondEdge;
  const size_t limit = 12 * size_t(cx.hexCapacity()) + 1;  // a valid complex never gets near it
  for (size_t steps = 0; steps < limit; ++steps) {
    loopSeen[size_t(ch)] |= uint16_t(1u << loopBit(cf, ca));
    // Around the primal edge `leave` from face cf to the fan's other boundary face.
    auto fs = facesOfEdge(leave);
    int exit = fs[0] == cf ? fs[1] : fs[0];
    EdgeRef cur{ch, leave};
    while (cx.stepAroundEdge(cur, exit)) continue;  // to the fan's far end
    ch = cur.hex;
    const int ce = cur.edge;
    cf = exit;
    ca = axisOfEdge(ce);
    if (ch == h && cf == f && ca == a) return;
    const MidSide& m = kMidSides[size_t(cf * 3 + ca)];
    leave = m.firstEdge == ce ? m.secondEdge : m.firstEdge;
  }
}
}  // namespace

void SheetFlooder::walkLoop(const Complex& cx, HexId h, int f, int a) { walkBoundaryLoop(cx, h, f, a, loopSeen_.data()); }

// Adds one slot's share of its sheet's mid-surface: the quad, its sides, and the primal edges and
// boundary loops it is the first to meet (each is walked whole and marked).
void SheetFlooder::measure(const Complex& cx, HexId h, int a, SheetStats& st) {
  ++st.slots;
  const unsigned unseen = ~unsigned(edgeSeen_[size_t(h)] >> (4 * a)) & 0xFu;
  if (unseen)
    for (int k = 0; k < 4; ++k)
      if ((unseen >> k) & 1u && !((edgeSeen_[size_t(h)] >> (4 * a + k)) & 1u)) {  // the walk may mark a sibling
        const bool closed = walkEdge(cx, h, 4 * a + k);
        ++st.vertices;
        if (edgeMarks) markEdge(cx, h, 4 * a + k, closed);
      }
  for (int f : kParallelFaces[a]) {
    if (!cx.isBoundary({h, f})) {
      ++st.interiorSides;
    } else {
      ++st.boundarySides;
      if (!((loopSeen_[size_t(h)] >> loopBit(f, a)) & 1u)) {
        walkLoop(cx, h, f, a);
        ++st.loops;
      }
    }
  }
}

namespace {
// Marks every hex of the fan of boundary edge (h, e) as near the boundary, along the edge's axis
// there (DualExtras::edgeMarks).
void markFan(const Complex& cx, HexId h, int e, uint16_t* marks) {
  marks[size_t(h)] |= kEdgeNearBoundary | kEdgeAxisNearBoundary(axisOfEdge(e));
  const auto fs = facesOfEdge(e);
  for (int dir = 0; dir < 2; ++dir) {
    EdgeRef cur{h, e};
    int exit = fs[size_t(dir)];
    while (cx.stepAroundEdge(cur, exit))
      marks[size_t(cur.hex)] |= kEdgeNearBoundary | kEdgeAxisNearBoundary(axisOfEdge(cur.edge));
  }
}

}  // namespace

// In a whole extraction (hexes in id order) the first incidence of an edge measured is its
// smallest; a fan's hexes all reach the boundary.
void SheetFlooder::markEdge(const Complex& cx, HexId h, int e, bool closed) {
  (*edgeMarks)[size_t(h)] |= uint16_t(1u << e);
  if (!closed) markFan(cx, h, e, edgeMarks->data());
}

int8_t slotShare(const Complex& cx, HexId h, int a, uint16_t marks) {
  int s = 2 + 2 * kNibbleBits[(marks >> (4 * a)) & 0xFu];
  for (int f : kParallelFaces[size_t(a)]) s -= cx.isBoundary({h, f}) ? 2 : 1;
  return int8_t(s);
}

int SheetFlooder::walkNewLoops(const Complex& cx, HexId h, int a) {
  int loops = 0;
  for (int f : kParallelFaces[a])
    if (cx.isBoundary({h, f}) && !((loopSeen_[size_t(h)] >> loopBit(f, a)) & 1u)) {
      walkLoop(cx, h, f, a);
      ++loops;
    }
  return loops;
}

SheetStats SheetFlooder::flood(const Complex& cx, Slot start, int32_t id, int32_t* sheetOf, std::vector<Slot>* out,
                               std::vector<int32_t>* previous) {
  SheetStats st;
  if (previous) previous->push_back(sheetOf[slotIndex(start.hex, start.axis)]);
  sheetOf[slotIndex(start.hex, start.axis)] = id;
  sign_[slotIndex(start.hex, start.axis)] = 1;
  stack_.assign(1, start);
  while (!stack_.empty()) {
    Slot cur = stack_.back();
    stack_.pop_back();
    if (out) out->push_back(cur);
    const int a = cur.axis;
    measure(cx, cur.hex, a, st);
    const int sc = sign_[slotIndex(cur.hex, a)];
    for (int f : kParallelFaces[a]) {
      Gluing g = cx.gluing(cur.hex, f);
      if (g.boundary()) continue;
      const Crossing& c = kCrossings[size_t(crossingIndex(f, a, g.face, g.orient))];
      const size_t k = slotIndex(g.hex, c.axis);
      const int want = sc * c.sign;
      if (sheetOf[k] < 0) {
        if (previous) previous->push_back(sheetOf[k]);
        sheetOf[k] = id;
        sign_[k] = int8_t(want);
        stack_.push_back({g.hex, c.axis});
      } else if (sign_[k] != want) {
        st.orientable = false;
      }
    }
  }
  return st;
}

void SheetStats::classify(Sheet& sh) const {
  sh.orientable = orientable;
  sh.boundaryLoops = loops;
  sh.euler = vertices - (interiorSides / 2 + boundarySides) + slots;
  sh.topology = classifySurface(sh.euler, sh.boundaryLoops, sh.orientable);
}

namespace {
// Where a chord's list starts when walked from slot `start`: back through low faces to a boundary
// end, or `start` itself once round. Sets `back` (the face the list's first slot is entered by)
// and `closed` (a twisted return leaves the chord open-ended at start).
Slot chordListStart(const Complex& cx, Slot start, int& back, bool& closed) {
  Slot cur = start;
  back = 2 * cur.axis;  // leaving backwards through the low face
  closed = false;
  for (;;) {
    Gluing g = cx.gluing(cur.hex, back);
    if (g.boundary()) break;
    cur = {g.hex, axisOfFace(g.face)};
    back = oppositeFace(g.face);
    if (cur == start) {
      closed = back == 2 * start.axis;
      break;
    }
  }
  if (closed) {
    cur = start;
    back = 2 * start.axis;
  }
  return cur;
}
}  // namespace

// Walks one chord from a slot: back to a boundary end (or once round), then forward, labelling.
void walkChord(const Complex& cx, Slot start, Chord& ch, int32_t* chordOf, std::vector<int32_t>* previous) {
  int back;
  bool closed;
  const Slot from = chordListStart(cx, start, back, closed);
  walkChordForward(cx, from, oppositeFace(back), ch, chordOf, previous);
  ch.closed = closed;
}

ChordWalk walkChordForward(const Complex& cx, Slot cur, int exitFace, Chord& ch, int32_t* chordOf,
                           std::vector<int32_t>* previous) {
  ChordWalk w;
  w.smallest = slotIndex(cur.hex, cur.axis);
  w.smallestEnteredLow = (oppositeFace(exitFace) & 1) == 0;
  for (;;) {
    ch.slots.push_back(cur);
    if (previous) previous->push_back(chordOf[slotIndex(cur.hex, cur.axis)]);
    chordOf[slotIndex(cur.hex, cur.axis)] = ch.id;
    Gluing g = cx.gluing(cur.hex, exitFace);
    if (g.boundary()) break;
    cur = {g.hex, axisOfFace(g.face)};
    exitFace = oppositeFace(g.face);
    const size_t k = slotIndex(cur.hex, cur.axis);
    if (chordOf[k] == ch.id) break;
    if (k < w.smallest) {
      w.smallest = k;
      w.smallestEnteredLow = (g.face & 1) == 0;
    }
  }
  ch.closed = false;
  return w;
}

namespace {
// A chord with no boundary end, listed from slot `first` as walkChord lists it (round once, forward
// through the high face; a twisted return is listed the other way). Returns whether it closes.
bool walkClosedChord(const Complex& cx, Slot first, std::vector<Slot>& out) {
  int back;
  bool closed;
  const Slot from = chordListStart(cx, first, back, closed);
  Slot cur = from;
  int exit = oppositeFace(back);
  const size_t limit = 3 * size_t(cx.hexCapacity());
  for (;;) {
    out.push_back(cur);
    Gluing g = cx.gluing(cur.hex, exit);
    if (g.boundary() || out.size() > limit) break;
    cur = {g.hex, axisOfFace(g.face)};
    exit = oppositeFace(g.face);
    if (cur == from) break;
  }
  return closed;
}
}  // namespace

int mapAxisAcross(const Complex& cx, HexId h, int face, int axis) { return axisAcrossGluing(face, axis, cx.gluing(h, face)); }

std::string classifySurface(int64_t euler, int loops, bool orientable) {
  if (!orientable) return "other";
  if (loops == 0 && euler == 2) return "sphere";
  if (loops == 0 && euler == 0) return "torus";
  if (loops == 1 && euler == 1) return "disk";
  if (loops == 2 && euler == 0) return "annulus";
  return "other";
}

namespace {

// Union-find over slots kept in the sheet-label array itself (one uint32 per slot: parent << 1,
// low bit the slot's orientation relative to its parent; a root's low bit marks its sheet
// twisted), so one sequential pass over glued quads finds the sheets and their orientability, as
// the floor finds the sheets alone. The smaller root wins, so every parent is a smaller slot and a
// sheet's root is its smallest slot.
class SheetUnionFind {
 public:
  explicit SheetUnionFind(uint32_t* link) : link_(link) {}
  uint32_t find(uint32_t x, uint32_t& parity) {
    parity = 0;
    for (;;) {
      const uint32_t l = link_[x], p = l >> 1;
      if (p == x) return x;
      const uint32_t lp = link_[p], gp = lp >> 1;
      if (gp == p) {  // p is the root: its low bit is not a parity
        parity ^= l & 1u;
        return p;
      }
      const uint32_t par = (l ^ lp) & 1u;
      link_[x] = (gp << 1) | par;  // path halving, parity composed
      parity ^= par;
      x = gp;
    }
  }
  // Joins two slots whose orientations differ by `flip`; a conflict marks the sheet twisted.
  void unite(uint32_t a, uint32_t b, uint32_t flip) {
    if (a < b && link_[b] == b << 1) {  // b an untwisted root: its tree hangs under a, no find
      link_[b] = (a << 1) | flip;
      return;
    }
    uint32_t pa, pb;
    uint32_t ra = find(a, pa), rb = find(b, pb);
    if (ra == rb) {
      if ((pa ^ pb) != flip) link_[ra] |= 1u;
      return;
    }
    if (rb < ra) std::swap(ra, rb);
    const uint32_t twisted = link_[rb] & 1u;
    link_[rb] = (ra << 1) | (pa ^ pb ^ flip);
    link_[ra] |= twisted;
  }

 private:
  uint32_t* link_;
};

// Chord union-find: plain parent links kept in the chord-label array (the smaller root wins, so
// every parent is a smaller slot, as for sheets).
uint32_t findChordRoot(uint32_t* link, uint32_t x) {
  while (link[x] != x) x = link[x] = link[link[x]];  // path halving
  return x;
}
void uniteChordSlots(uint32_t* link, uint32_t a, uint32_t b) {
  if (a < b && link[b] == b) {  // b a root: its tree hangs under a, no find
    link[b] = a;
    return;
  }
  a = findChordRoot(link, a);
  b = findChordRoot(link, b);
  if (a < b) link[b] = a;
  else if (b < a) link[a] = b;
}

// Unites the sheet slots and the chord slots across every glued quad (each once).
[[gnu::noinline]] void uniteSlots(const Complex& cx, Dual& d) {
  const size_t n = size_t(cx.hexCapacity());
  reserveHuge(d.sheetLabel, withHeadroom(n));  // written once each (no zero-fill first)
  reserveHuge(d.chordLabel, withHeadroom(n));
  const std::span<const uint8_t> alive = cx.aliveFlags();
  for (size_t h = 0; h < n; ++h) {
    const int32_t i = int32_t(3 * h);
    if (alive[h]) {
      d.sheetLabel.push_back({i << 1, (i + 1) << 1, (i + 2) << 1});
      d.chordLabel.push_back({i, i + 1, i + 2});
    } else {
      d.sheetLabel.push_back({-1, -1, -1});
      d.chordLabel.push_back({-1, -1, -1});
    }
  }
  uint32_t* link = reinterpret_cast<uint32_t*>(flat(d.sheetLabel));
  uint32_t* chordLink = reinterpret_cast<uint32_t*>(flat(d.chordLabel));
  SheetUnionFind uf(link);
  for (HexId h = 0; h < HexId(alive.size()); ++h) {
    if (!alive[size_t(h)]) continue;
    const std::array<uint32_t, 6>& words = cx.gluingWords(h);
    for (int f = 0; f < 6; ++f) {
      const uint32_t w = words[size_t(f)];
      const HexId g = hexOf(w);
      if (w == Complex::kBoundaryWord || g < h || (g == h && faceOf(w) < f)) continue;  // each glued quad once
      for (int a : kParallelAxes[axisOfFace(f)]) {
        const Crossing& c = kCrossings[size_t(crossingIndex(f, a, 0, 0)) + faceOrient(w)];
        uf.unite(uint32_t(slotIndex(h, a)), uint32_t(slotIndex(g, c.axis)), c.sign < 0 ? 1u : 0u);
      }
      uniteChordSlots(chordLink, uint32_t(slotIndex(h, axisOfFace(f))), uint32_t(slotIndex(g, axisOfFace(faceOf(w)))));
    }
  }
}

// What the slot pass learns of the chords: per chord id (in the order of its smallest slot) that
// slot and whether a boundary start was claimed for it, and the starts: each open chord's boundary
// face met first in (hex, face) order.
struct ChordPlan {
  std::vector<uint32_t> root, size;  // size: the chord's slots, counted as they are labelled
  std::vector<uint8_t> claimed, selfIntersecting;
  std::vector<QuadSide> starts;
};

// True when (h, e) is the smallest incidence of its primal edge; `closed` then tells whether the
// edge's incidences form a cycle (false for a fan ending on the boundary). Two fronts walk round
// the edge from (h, e), one through each of its faces, a step each in turn (independent loads),
// and stop at the first smaller incidence: in a structured block a neighbour decides every
// incidence but the smallest at once, and the smallest one's 4-cycle closes after a step each.
bool smallestIncidence(const Complex& cx, HexId h, int e, bool& closed) {
  // An incidence as one comparable key: hex * 16 + edge.
  const int64_t start = int64_t(h) * 16 + e;
  int64_t a = start, b = start;
  int exitA = kEdgeFaces[size_t(e)][0], exitB = kEdgeFaces[size_t(e)][1];
  auto step = [&cx](int64_t& k, int& exit) {
    const Gluing g = cx.gluing(HexId(k >> 4), exit);
    if (g.boundary()) return false;
    const EdgeStep& st = kEdgeSteps[size_t(edgeStepIndex(int(k & 15), exit, g.face, g.orient))];
    k = int64_t(g.hex) * 16 + st.edge;
    exit = st.exit;
    return true;
  };
  bool openA = true, openB = true;  // fronts not yet at the boundary
  for (;;) {
    if (openA && (openA = step(a, exitA))) {
      if (a < start) return false;
      if (a == b) break;  // the fronts met: every incidence seen
    }
    if (openB && (openB = step(b, exitB))) {
      if (b < start) return false;
      if (a == b) break;
    }
    if (!openA && !openB) {
      closed = false;
      return true;
    }
  }
  closed = true;
  return true;
}

// smallestIncidence for an edge of h whose two faces are glued to larger hexes (`words`: h's
// packed gluings): one step from each neighbour, and when both land on the same incidence the edge
// is a 4-cycle (a structured block's interior edge) decided by that incidence alone (unless it is
// (h, e): a 2-cycle); else the walk. Read from the packed words, so no gluing is decoded whole.
[[gnu::always_inline]] inline bool closesAsSmallest(const Complex& cx, HexId h, int e, const std::array<uint32_t, 6>& words, bool& closed) {
  const auto& fs = kEdgeFaces[size_t(e)];
  const uint32_t w0 = words[size_t(fs[0])], w1 = words[size_t(fs[1])];
  const EdgeStep& s0 = kEdgeSteps[size_t(edgeStepIndex(e, fs[0], 0, 0)) + faceOrient(w0)];
  const EdgeStep& s1 = kEdgeSteps[size_t(edgeStepIndex(e, fs[1], 0, 0)) + faceOrient(w1)];
  const uint32_t wa = cx.gluingWords(hexOf(w0))[size_t(s0.exit)], wb = cx.gluingWords(hexOf(w1))[size_t(s1.exit)];
  if (wa != Complex::kBoundaryWord && wb != Complex::kBoundaryWord && hexOf(wa) == hexOf(wb)) {
    const int ea = kEdgeSteps[size_t(edgeStepIndex(s0.edge, s0.exit, 0, 0)) + faceOrient(wa)].edge;
    const int eb = kEdgeSteps[size_t(edgeStepIndex(s1.edge, s1.exit, 0, 0)) + faceOrient(wb)].edge;
    const HexId a = hexOf(wa);
    if (ea == eb && !(a == h && ea == e)) {
      closed = true;
      return h < a || (h == a && e < ea);
    }
  }
  return smallestIncidence(cx, h, e, closed);
}

// Labels hex h's chord slots (read off their parents, smaller slots already labelled) and claims
// a boundary start for each open chord first met here (`boundary`: h's boundary faces).
[[gnu::always_inline]] inline void labelChords(HexId h, unsigned boundary, int32_t* chordOf, ChordPlan& plan) {
  for (int a = 0; a < 3; ++a) {
    const size_t i = slotIndex(h, a);
    const uint32_t parent = uint32_t(chordOf[i]);
    if (parent == i) {
      chordOf[i] = int32_t(plan.root.size());
      plan.root.push_back(uint32_t(i));
      plan.size.push_back(0);
      plan.claimed.push_back(0);
      plan.selfIntersecting.push_back(0);
    } else {
      chordOf[i] = chordOf[parent];
    }
  }
  const int32_t* c = chordOf + slotIndex(h, 0);
  for (int a = 0; a < 3; ++a) ++plan.size[size_t(c[a])];
  if (c[0] == c[1] || c[0] == c[2]) plan.selfIntersecting[size_t(c[0])] = 1;
  if (c[1] == c[2]) plan.selfIntersecting[size_t(c[1])] = 1;
  for (int f = 0; f < 6; ++f)
    if ((boundary >> f) & 1u) {
      uint8_t& claimed = plan.claimed[size_t(c[axisOfFace(f)])];
      if (!claimed) plan.starts.push_back({h, f});
      claimed = 1;
    }
}

// One pass over the slots in order: each slot's label read off the union-find (its parent, a
// smaller slot, is already labelled: O(1) per slot, no find), its orientation, and its share of
// its sheet's mid-surface: quad, sides, boundary loops first met, and the primal edges it holds
// the smallest incidence of. The labels overwrite the links in place.
template <bool kExtras>
[[gnu::noinline]] std::vector<SheetStats> labelAndMeasureSheets(const Complex& cx, Dual& d, DualExtras* x, ChordPlan& plan) {
  const uint32_t* link = reinterpret_cast<const uint32_t*>(flat(d.sheetLabel));
  int32_t* label = flat(d.sheetLabel);
  int32_t* chordOf = flat(d.chordLabel);
  int8_t* sign = kExtras ? x->slotSigns.data() : nullptr;
  uint16_t* marks = kExtras ? x->edgeMarks.data() : nullptr;
  int8_t* shares = kExtras ? x->slotShares.data() : nullptr;
  HugeVector<uint16_t> loopSeen(size_t(cx.hexCapacity()), 0);  // (2 MB at 1M hexes: one huge page, not 500 small ones)
  std::vector<SheetStats> stats;
  const std::span<const uint8_t> alive = cx.aliveFlags();
  for (HexId h = 0; h < HexId(alive.size()); ++h) {
    if (!alive[size_t(h)]) continue;
    // Faces glued to a smaller hex: an edge on one of them is not its edge's smallest incidence.
    // Also the faces glued to h itself.
    const std::array<uint32_t, 6>& words = cx.gluingWords(h);
    unsigned boundary = 0, smaller = 0, self = 0;
    for (int f = 0; f < 6; ++f) {
      const uint32_t w = words[size_t(f)];
      const bool onBoundary = w == Complex::kBoundaryWord;
      boundary |= unsigned(onBoundary) << f;
      smaller |= unsigned(!onBoundary && hexOf(w) <= h) << f;  // itself: decided by the walk
      self |= unsigned(!onBoundary && hexOf(w) == h) << f;
    }
    labelChords(h, boundary, chordOf, plan);
    // An edge on no face glued to a smaller hex, or on one glued to h itself (decided by the walk).
    const unsigned candidates = kEdgesOffFaces[smaller] | (self & smaller ? 0xFFFu & ~kEdgesOffFaces[self & smaller] : 0u);
    for (int a = 0; a < 3; ++a) {
      const size_t i = slotIndex(h, a);
      const uint32_t l = link[i], p = l >> 1;
      int32_t id;
      if (p == i) {
        id = int32_t(stats.size());
        stats.emplace_back().orientable = (l & 1u) == 0;
        if constexpr (kExtras) sign[i] = 1;
      } else {
        id = label[p];
        if constexpr (kExtras) sign[i] = int8_t((l & 1u) ? -sign[p] : sign[p]);
      }
      label[i] = id;
      SheetStats& st = stats[size_t(id)];
      // The quad's four sides, on the faces parallel to the axis (the interior ones are counted
      // after the pass); boundary loops first met here.
      const unsigned onBoundary = boundary & kParallelFaceMask[size_t(a)];
      const int sidesOnBoundary = kNibbleBits[onBoundary & 0xFu] + kNibbleBits[onBoundary >> 4];
      ++st.slots;
      int share = -2 - sidesOnBoundary;
      if (onBoundary) {
        st.boundarySides += sidesOnBoundary;
        for (int f : kParallelFaces[size_t(a)])
          if (((onBoundary >> f) & 1u) && !((loopSeen[size_t(h)] >> loopBit(f, a)) & 1u)) {
            walkBoundaryLoop(cx, h, f, a, loopSeen.data());
            ++st.loops;
          }
      }
      // The primal edges along the axis that this incidence may be the smallest of (`candidates`).
      for (unsigned todo = (candidates >> 4 * a) & 0xFu; todo; todo &= todo - 1) {
        const int e = 4 * a + kLowestBit[todo];
        bool closed;
        const unsigned faces = kEdgeFaceMask[size_t(e)];
        if (((smaller | boundary) & faces) ? !smallestIncidence(cx, h, e, closed) : !closesAsSmallest(cx, h, e, words, closed))
          continue;
        ++st.vertices;
        if constexpr (kExtras) {
          marks[size_t(h)] |= uint16_t(1u << e);
          share += 2;
          if (!closed) markFan(cx, h, e, marks);
        }
      }
      if constexpr (kExtras) shares[i] = int8_t(share);
    }
  }
  for (SheetStats& st : stats) st.interiorSides = 4 * st.slots - st.boundarySides;  // a quad has four sides
  return stats;
}

// Sheets numbered in the order of their smallest slot: labelled by one oriented union-find pass
// over the glued quads, then labelled and measured in one pass over the slots.
void extractSheets(const Complex& cx, Dual& d, DualExtras* extras, ChordPlan& plan) {
  std::vector<SheetStats> stats =
      extras ? labelAndMeasureSheets<true>(cx, d, extras, plan) : labelAndMeasureSheets<false>(cx, d, extras, plan);
  d.sheets.resize(stats.size());
  d.labelSheet.resize(stats.size());
  for (size_t s = 0; s < stats.size(); ++s) {
    d.labelSheet[s] = int32_t(s);
    d.sheets[s].id = int32_t(s);
    stats[s].classify(d.sheets[s]);
  }
  // Slot lists, one range each of one pool (PooledSlots), sorted: one pass over the labels.
  std::vector<size_t> at(stats.size() + 1, 0);
  for (size_t s = 0; s < stats.size(); ++s) at[s + 1] = at[s] + size_t(stats[s].slots);
  const auto pool = std::make_shared<SlotPool>(at.back());
  Slot* slots = pool->data();
  std::vector<size_t> next(at.begin(), at.end() - 1);
  const std::span<const uint8_t> alive = cx.aliveFlags();
  for (HexId h = 0; h < HexId(alive.size()); ++h) {
    if (!alive[size_t(h)]) continue;
    const auto& l = d.sheetLabel[size_t(h)];
    if (l[0] == l[1] || l[0] == l[2]) d.sheets[size_t(l[0])].selfIntersecting = true;
    if (l[1] == l[2]) d.sheets[size_t(l[1])].selfIntersecting = true;
    for (int a = 0; a < 3; ++a) slots[next[size_t(l[size_t(a)])]++] = {h, a};
  }
  for (size_t s = 0; s < stats.size(); ++s) d.sheets[s].slots = SlotList(PooledSlots(pool, at[s], at[s + 1] - at[s]));
}

// Chord slot lists. Ids and labels are known (the chord union-find); each open chord is walked
// once, forward from its claimed boundary start, several chords in turn so that their cache misses
// overlap, and listed from the end its smallest slot's low face leads to (as a walk from that slot
// would list it). Closed chords after: from their smallest slot, round once.
[[gnu::noinline]] void extractChords(const Complex& cx, Dual& d, DualExtras* extras, const ChordPlan& plan) {
  const int32_t* chordOf = flat(d.chordLabel);
  int32_t* places = extras ? extras->chordPlaces.data() : nullptr;
  reserveRoom(d.chords, plan.root.size());  // edits add chords (huge_pages.hpp)
  d.chords.resize(plan.root.size());
  for (size_t c = 0; c < d.chords.size(); ++c) {
    d.chords[c].id = int32_t(c);
    d.chords[c].selfIntersecting = plan.selfIntersecting[c] != 0;
  }
  // Each chord's slots, one range of one pool (PooledSlots), in chord id order: the sizes are
  // counted by the label pass, so each walk writes its slots in place.
  std::vector<size_t> at(d.chords.size() + 1, 0);
  for (size_t c = 0; c < d.chords.size(); ++c) at[c + 1] = at[c] + plan.size[c];
  const auto pool = std::make_shared<SlotPool>(at.back());
  // A walked chord's range, reversed when its smallest slot was entered through its high face (a
  // walk from that slot lists it from the other end), and its places.
  auto keep = [&](int32_t id, bool reversed) {
    Slot* first = pool->data() + at[size_t(id)];
    const size_t n = plan.size[size_t(id)];
    if (reversed) std::reverse(first, first + n);
    if (places)
      for (size_t i = 0; i < n; ++i) places[slotIndex(first[i].hex, first[i].axis)] = int32_t(i);
  };
  struct Lane {
    int32_t chord = -1;
    Slot cur;
    int exit = 0;
    bool rootEnteredLow = true;
    Slot* out = nullptr;  // the chord's range in the pool
    size_t walked = 0, size = 0, root = 0;
  };
  constexpr int kLanes = 16;
  std::array<Lane, kLanes> lanes;
  size_t next = 0;
  auto start = [&](Lane& l) {
    if (next == plan.starts.size()) return false;
    const QuadSide s = plan.starts[next++];
    l.cur = {s.hex, axisOfFace(s.face)};
    l.chord = chordOf[slotIndex(l.cur.hex, l.cur.axis)];
    l.exit = oppositeFace(s.face);
    l.rootEnteredLow = (s.face & 1) == 0;
    l.out = pool->data() + at[size_t(l.chord)];
    l.walked = 0;
    l.size = plan.size[size_t(l.chord)];
    l.root = plan.root[size_t(l.chord)];
    return true;
  };
  int active = 0;
  for (Lane& l : lanes) active += start(l);
  // An open chord is a path from one boundary face to another: the walk from its claimed end
  // meets exactly the slots its label counted (the size check only guards a corrupt complex).
  while (active > 0)
    for (Lane& l : lanes) {
      if (l.chord < 0) continue;
      l.out[l.walked++] = l.cur;
      const uint32_t w = cx.gluingWords(l.cur.hex)[size_t(l.exit)];
      if (w == Complex::kBoundaryWord || l.walked == l.size) {
        std::fill(l.out + l.walked, l.out + l.size, Slot{});  // (a corrupt complex's short walk: no unwritten slot)
        keep(l.chord, !l.rootEnteredLow);
        l.chord = -1;
        if (!start(l)) --active;
        continue;
      }
      const int face = faceOf(w);
      l.cur = {hexOf(w), axisOfFace(face)};
      l.exit = oppositeFace(face);
      if (slotIndex(l.cur.hex, l.cur.axis) == l.root) l.rootEnteredLow = (face & 1) == 0;
    }
  std::vector<Slot> walked;
  for (size_t c = 0; c < d.chords.size(); ++c)
    if (!plan.claimed[c]) {
      const Slot first{HexId(plan.root[c] / 3), int(plan.root[c] % 3)};
      walked.clear();
      d.chords[c].closed = walkClosedChord(cx, first, walked);
      walked.resize(plan.size[c]);  // the label's count (equal in a valid complex)
      std::copy(walked.begin(), walked.end(), pool->data() + at[c]);
      keep(int32_t(c), false);
    }
  for (size_t c = 0; c < d.chords.size(); ++c) d.chords[c].slots = PooledSlots(pool, at[c], at[c + 1] - at[c]);
}

// Every chord one label, equal to its id (DualTracker cuts and joins them later).
void labelChordsById(Dual& d) {
  reserveRoom(d.labelChord, d.chords.size());
  d.labelChord.resize(d.chords.size());
  std::iota(d.labelChord.begin(), d.labelChord.end(), 0);
}

}  // namespace

Dual extractDual(const Complex& cx, DualExtras* extras) {
  const size_t n = size_t(cx.hexCapacity());
  Dual d;
  if (extras) {
    assignHuge(extras->slotSigns, 3 * n, int8_t(0));
    assignHuge(extras->edgeMarks, n, uint16_t(0));
    assignHuge(extras->slotShares, 3 * n, int8_t(0));
    assignHuge(extras->chordPlaces, 3 * n, int32_t(0));
  }
  uniteSlots(cx, d);
  ChordPlan plan;
  plan.starts.reserve(size_t(cx.numBoundaryQuads() / 2 + 1));  // an open chord claims one of its two ends
  extractSheets(cx, d, extras, plan);
  extractChords(cx, d, extras, plan);
  labelChordsById(d);
  return d;
}

}  // namespace hexdual
