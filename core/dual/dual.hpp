// The dual of a hex complex: sheets (dual surfaces, layers of hexes) and chords (dual curves,
// columns of hexes). Every hex lies on 3 sheet slots and 3 chord slots, one per local axis:
// sheet slot (h, a) is the layer crossed by h's edges along axis a; chord slot (h, a) is the
// column through h's two faces normal to a. TK03 §1.1.
#pragma once
#include <array>
#include <memory>
#include <string>
#include <span>
#include <vector>

#include "complex/complex.hpp"
#include "complex/small_vector.hpp"

namespace hexdual {

struct Slot {
  HexId hex = -1;
  int axis = 0;
  friend bool operator==(Slot a, Slot b) { return a.hex == b.hex && a.axis == b.axis; }
  friend bool operator<(Slot a, Slot b) { return a.hex != b.hex ? a.hex < b.hex : a.axis < b.axis; }
};

// The storage of one extraction's slot lists: n slots in one allocation (whole huge pages where the
// OS gives them, HugePageAllocator), written by the extraction before any list reads them. Not a
// vector: a vector fills its n slots on creation and the extraction then writes every one again
// (two 24 MB fills per 1M-hex extraction natively, and two element-by-element loops in wasm).
class SlotPool {
 public:
  explicit SlotPool(size_t n);
  ~SlotPool();
  SlotPool(const SlotPool&) = delete;
  SlotPool& operator=(const SlotPool&) = delete;
  Slot* data() { return data_; }
  const Slot* data() const { return data_; }
  size_t size() const { return size_; }
  const Slot* begin() const { return data_; }
  const Slot* end() const { return data_ + size_; }
  const Slot& operator[](size_t i) const { return data_[i]; }

 private:
  Slot* data_;
  size_t size_;
};

// A list of slots that either views a range of a pool or owns a vector. Extraction lists every
// sheet's slots in one pool and every chord's in another (each one allocation, in huge pages where
// the OS gives them: a 1M-hex mesh's 30,300 lists cost a few dozen page faults, not 11,600); a list
// that is written (an update's new slots) copies its range out first. Copies share the pool, which
// lives while any list views it. Read like a const std::vector<Slot>.
class PooledSlots {
 public:
  using Pool = std::shared_ptr<const SlotPool>;
  PooledSlots() = default;
  PooledSlots(std::vector<Slot> own);
  PooledSlots(Pool pool, size_t begin, size_t size);
  // Out of line, like the writers below: every copy, move and destruction of a Sheet, Chord or
  // Dual would otherwise inline the pool's reference counting (and crowd out hotter inlining).
  PooledSlots(const PooledSlots&);
  PooledSlots(PooledSlots&&) noexcept;
  PooledSlots& operator=(const PooledSlots&);
  PooledSlots& operator=(PooledSlots&&) noexcept;
  ~PooledSlots();
  PooledSlots& operator=(std::vector<Slot> own);
  std::span<const Slot> view() const {
    return pool_ ? std::span<const Slot>(pool_->data() + begin_, size_) : std::span<const Slot>(own_);
  }
  const Slot* begin() const { return view().data(); }
  const Slot* end() const {
    const std::span<const Slot> v = view();
    return v.data() + v.size();
  }
  size_t size() const { return pool_ ? size_ : own_.size(); }
  bool empty() const { return size() == 0; }
  const Slot& operator[](size_t i) const { return view()[i]; }
  const Slot& front() const { return view().front(); }
  const Slot& back() const { return view().back(); }
  bool pooled() const { return pool_ != nullptr; }
  const Pool& pool() const { return pool_; }  // null unless pooled
  size_t poolBegin() const { return begin_; }
  size_t capacity() const { return own_.capacity(); }  // of its own vector (0 while pooled)
  // Writing: a pooled list's slots are copied into its own vector first.
  std::vector<Slot>& own() {
    if (pool_) copyOut();
    return own_;
  }
  void clear();
  void reserve(size_t n) { own().reserve(n); }
  void push_back(Slot s) { own().push_back(s); }
  // (The pool is let go after the copy: [first, last) may lie in it.)
  template <class It>
  void assign(It first, It last) {
    own_.assign(first, last);
    pool_.reset();
  }
  friend bool operator==(const PooledSlots& a, const PooledSlots& b) { return equal(a.view(), b.view()); }
  friend bool operator==(const PooledSlots& a, const std::vector<Slot>& b) { return equal(a.view(), b); }

 private:
  void copyOut();
  static bool equal(std::span<const Slot> a, std::span<const Slot> b);
  Pool pool_;
  size_t begin_ = 0, size_ = 0;
  std::vector<Slot> own_;
};

// A sheet's slots, sorted, read like a const std::vector<Slot>. DualTracker merges two sheets by
// handing one list to the other as a pending run and drops slots as pending removals; the first
// read merges them (linear in the list), so an update that merges two large sheets stays local.
// Not for concurrent reads of a list with pending edits (the first read writes the merged list).
class SlotList {
 public:
  SlotList() = default;
  SlotList(std::vector<Slot> sorted) : list_(std::move(sorted)), size_(list_.size()) {}
  SlotList(PooledSlots sorted) : list_(std::move(sorted)), size_(list_.size()) {}
  SlotList& operator=(std::vector<Slot> sorted);
  const PooledSlots& get() const {
    if (!runs_.empty() || !adds_.empty() || !gone_.empty()) settle();
    return list_;
  }
  std::span<const Slot> view() const { return get().view(); }
  size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  const Slot* begin() const { return get().begin(); }
  const Slot* end() const { return get().end(); }
  const Slot& operator[](size_t i) const { return get()[i]; }
  const Slot& front() const { return get().front(); }
  const Slot& back() const { return get().back(); }
  void reserve(size_t n) { list_.reserve(n); }
  void push_back(Slot s) {  // s after every slot listed (extraction lists slots in order)
    get();
    ++version_;
    list_.push_back(s);
    ++size_;
  }
  void clear();
  // Edits that wait for the next read: slots not listed join (in any order); `other`'s slots
  // (disjoint from these) join; listed slots leave.
  void add(std::span<const Slot> slots);
  void absorb(SlotList&& other);
  void remove(std::span<const Slot> listed);
  friend bool operator==(const SlotList& a, const SlotList& b) { return a.get() == b.get(); }

  // For an exact undo (DualTracker::updateUndone): the pending edits at a moment, and the list
  // rolled back to them. version() changes whenever the pending edits are merged or the list is
  // replaced; in between, edits only append to the pending runs, additions and removals.
  struct Mark {
    uint64_t version = 0;
    size_t size = 0, runs = 0, adds = 0, gone = 0;
  };
  Mark mark() const { return {version_, size_, runs_.size(), adds_.size(), gone_.size()}; }
  uint64_t version() const { return version_; }
  size_t listedSize() const { return list_.size(); }  // the merged part, without the pending runs
  size_t pendingRuns() const { return runs_.size(); }
  size_t runSize(size_t i) const { return runs_[i].size(); }
  const std::vector<Slot>& pendingAdds() const { return adds_; }
  const std::vector<Slot>& pendingGone() const { return gone_; }
  // Back to mark m, taken at this version (nothing merged since): the runs absorbed since are
  // handed back, in the order they came; the additions and removals made since are dropped.
  std::vector<std::vector<Slot>> rollBack(const Mark& m);
  // The list as a mark recorded it: its merged part, pending runs, additions and removals.
  void reset(std::vector<Slot> listed, std::vector<std::vector<Slot>> runs, std::vector<Slot> adds,
             std::vector<Slot> gone, const Mark& m);

 private:
  void settle() const;
  mutable uint64_t version_ = 0;
  mutable PooledSlots list_;
  mutable std::vector<std::vector<Slot>> runs_;  // sorted runs (merged lists) waiting to join
  mutable std::vector<Slot> adds_;               // slots waiting to join (a few per edit), in no order
  mutable std::vector<Slot> gone_;               // listed slots waiting to leave
  size_t size_ = 0;
};

struct Sheet {
  int id = -1;
  bool alive = true;  // false for an id retired by an operation (DualTracker)
  SlotList slots;     // sorted; a self-intersecting sheet has a hex twice
  int64_t euler = 0;  // of the sheet's mid-surface
  int boundaryLoops = 0;
  bool orientable = true;
  bool selfIntersecting = false;
  std::string topology;  // disk, annulus, sphere, torus, other
};

struct Chord {
  int id = -1;
  bool alive = true;
  PooledSlots slots;        // in order along the chord (from a boundary end when open)
  bool closed = false;      // a ring that never reaches the boundary
  bool selfIntersecting = false;
};

struct Dual {
  // In whole huge pages from 1 MiB up, like the per-hex arrays: a 1M-hex mesh has 30,000 chords, and
  // an edit session grows both lists (DualTracker reserves room for new ones at construction).
  HugeVector<Sheet> sheets;
  HugeVector<Chord> chords;
  // Per hex id (capacity), per axis: a sheet label, -1 for tombstones; labelSheet names each label's
  // sheet. Extraction gives every sheet one label equal to its id; DualTracker merges two sheets by
  // re-pointing the labels of one instead of re-writing its slots. Read sheet ids with sheetAt().
  HugeVector<std::array<int32_t, 3>> sheetLabel;
  HugeVector<int32_t> labelSheet;
  // Per hex id (capacity), per axis: a chord LABEL, -1 for tombstones.
  // Extraction gives every chord one label equal to its id. DualTracker lists a chord as pieces of
  // labels' runs (the slots a label was made with, by place: chordPlace), so joining or cutting
  // chords writes no slot outside the edit; a label's slots can then lie in several chords:
  // labelChord names the chord of a label lying in one, else (-1) labelCuts lists its ranges of
  // places per chord. Read chord ids with chordAt().
  HugeVector<std::array<int32_t, 3>> chordLabel;
  HugeVector<int32_t> labelChord;
  struct ChordCut {
    int32_t lo, hi, chord;  // places [lo, hi) of a label's run lie in this chord
  };
  HugeVector<SmallVector<ChordCut, 3>> labelCuts;  // per label (DualTracker only): up to three cuts in place
  HugeVector<int32_t> chordPlace;               // per slot: its place in its label's run (DualTracker only)

  // The sheet id of slot (h, a), -1 for a tombstone.
  int32_t sheetAt(HexId h, int a) const {
    const int32_t l = sheetLabel[size_t(h)][size_t(a)];
    return l < 0 ? -1 : labelSheet[size_t(l)];
  }
  std::array<int32_t, 3> sheetsAt(HexId h) const { return {sheetAt(h, 0), sheetAt(h, 1), sheetAt(h, 2)}; }
  // The chord id of slot (h, a), -1 for a tombstone.
  int32_t chordAt(HexId h, int a) const {
    const int32_t l = chordLabel[size_t(h)][size_t(a)];
    if (l < 0) return -1;
    const int32_t c = labelChord[size_t(l)];
    if (c >= 0) return c;
    const int32_t i = chordPlace[3 * size_t(h) + size_t(a)];
    for (const ChordCut& k : labelCuts[size_t(l)])
      if (i >= k.lo && i < k.hi) return k.chord;
    return -1;
  }
  std::array<int32_t, 3> chordsAt(HexId h) const { return {chordAt(h, 0), chordAt(h, 1), chordAt(h, 2)}; }
};

// Axis of the neighbour's hex that continues axis `a` of hex h across face f (f must be interior).
int mapAxisAcross(const Complex& cx, HexId h, int face, int axis);

// What extraction can report on the way, for DualTracker: an orientation (+1/-1) of every slot's
// mid-quad (3 per hex), consistent across each orientable sheet; and per hex, bit e set when (h, e)
// is its primal edge's smallest incidence, bit kEdgeNearBoundary when one of its edges reaches the boundary,
// and bit kEdgeAxisNearBoundary(a) when one of its 4 edges along axis a does.
struct DualExtras {
  HugeVector<int8_t> slotSigns;
  HugeVector<uint16_t> edgeMarks;
  HugeVector<int8_t> slotShares;    // per slot: slotShare() below
  HugeVector<int32_t> chordPlaces;  // per slot: its place in its chord's slot list
};
constexpr uint16_t kEdgeNearBoundary = uint16_t(1u << 15);
constexpr uint16_t kEdgeAxisNearBoundary(int a) { return uint16_t(1u << (12 + a)); }

// Twice slot (h, a)'s share of its sheet's Euler characteristic V - E + F: its quad, minus its
// sides (interior ones are shared by two slots), plus the primal edges it holds the smallest
// incidence of (`marks`: the hex's DualExtras::edgeMarks). A sheet's Euler characteristic is half the sum.
int8_t slotShare(const Complex& cx, HexId h, int a, uint16_t marks);

// Extracts sheets and chords in linear time. Ids are deterministic: sheets and chords are
// numbered in the order of their smallest slot (hex id, then axis).
Dual extractDual(const Complex& cx, DualExtras* extras = nullptr);

// The 4 faces of a hex parallel to axis a: the sides of sheet slot (h, a). TK03 §1.1.
constexpr std::array<std::array<int, 4>, 3> kParallelFaces = {{{2, 3, 4, 5}, {0, 1, 4, 5}, {0, 1, 2, 3}}};

// Names a sheet's topology from its Euler characteristic, boundary loops and orientability.
std::string classifySurface(int64_t euler, int loops, bool orientable);

// What one flood measures of a sheet's mid-surface (faces = slots, edges = slot sides parallel to
// the sheet, vertices = primal edges crossing it). TK03 §1.1.
struct SheetStats {
  int64_t slots = 0, interiorSides = 0, boundarySides = 0, vertices = 0;
  int loops = 0;
  bool orientable = true;
  // Sets the sheet's Euler characteristic, loops, orientability and topology name.
  void classify(Sheet& sheet) const;
};

// Floods sheets: labels slots, orients them and measures the mid-surface in the same pass (each
// primal edge walked once, each boundary loop once). Its marks persist between floods so a whole
// extraction pays once; clear() resets the marks of a flooded sheet for the next local flood.
class SheetFlooder {
 public:
  void reserve(size_t hexCapacity);
  // Floods the sheet through `start`, labelling unlabelled slots (negative in the flat per-slot
  // label array `sheetOf`, 3 per hex: Dual::sheetLabel) with `id`; appends the slots to `out` and
  // the labels they had (all negative) to `previous` when given.
  SheetStats flood(const Complex& cx, Slot start, int32_t id, int32_t* sheetOf, std::vector<Slot>* out,
                   std::vector<int32_t>* previous = nullptr);
  // Resets the edge and loop marks of these slots (their orientations stay: they persist).
  void clear(const std::vector<Slot>& slots);
  // Adds slot (h, a)'s share of its sheet's mid-surface to `stats` (not its orientation).
  void measure(const Complex& cx, HexId h, int a, SheetStats& stats);
  // Walks the boundary loops of a sheet that slot (h, a)'s boundary sides are first to meet; returns how many.
  int walkNewLoops(const Complex& cx, HexId h, int a);
  // Orientation of each slot's mid-quad (+1/-1, 0 unknown), 3 per hex: written by every flood.
  HugeVector<int8_t>& signs() { return sign_; }
  const HugeVector<int8_t>& signs() const { return sign_; }

 private:
  bool walkEdge(const Complex& cx, HexId h, int e);  // false for a fan (a boundary edge)
  void markEdge(const Complex& cx, HexId h, int e, bool closed);

 public:
  HugeVector<uint16_t>* edgeMarks = nullptr;  // when set, measure() records DualExtras::edgeMarks

 private:
  void walkLoop(const Complex& cx, HexId h, int f, int a);
  HugeVector<int8_t> sign_;        // per slot: orientation of its mid-quad
  HugeVector<uint16_t> edgeSeen_;  // per hex: bit e set once edge incidence (h, e) is counted
  HugeVector<uint16_t> loopSeen_;  // per hex: bit per boundary mid-edge (face, slot axis) walked
  std::vector<Slot> stack_;
};

// Walks the chord through a slot (back to a boundary end or once round, then forward), labelling
// its slots with `chord.id` in `chordOf` (flat array); the labels overwritten go to `previous`.
void walkChord(const Complex& cx, Slot start, Chord& chord, int32_t* chordOf, std::vector<int32_t>* previous = nullptr);
// Walks a chord forward from slot `start` leaving through `exitFace`, until the boundary or back
// at a slot already labelled with chord.id; reports the smallest slot index met and its entry side.
struct ChordWalk {
  size_t smallest = 0;
  bool smallestEnteredLow = true;
};
ChordWalk walkChordForward(const Complex& cx, Slot start, int exitFace, Chord& chord, int32_t* chordOf,
                           std::vector<int32_t>* previous = nullptr);

// Compares two duals of the same complex up to renaming of ids: same partition of slots into
// sheets and chords, same classification, each sheet listing the same slots (read: a list's pending
// edits are merged). Throws Error naming the first difference.
void compareDuals(const Complex& cx, const Dual& a, const Dual& b);

}  // namespace hexdual

namespace hexdual {
// Checks that a Dual describes the complex: every live slot is listed exactly once in the sheet
// and chord named by sheetAt/chordAt, slots glued across parallel (sheet) or normal (chord) quads
// share a sheet or chord, and chords list consecutive glued slots. Throws Error naming the first
// inconsistency. Used after incremental updates in debug builds and tests.
void validateDual(const Complex& cx, const Dual& dual);
}  // namespace hexdual
