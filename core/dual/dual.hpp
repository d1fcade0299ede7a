// The dual of a hex complex: sheets (dual surfaces, layers of hexes) and chords (dual curves,
// columns of hexes). Every hex lies on 3 sheet slots and 3 chord slots, one per local axis:
// sheet slot (h, a) is the layer crossed by h's edges along axis a; chord slot (h, a) is the
// column through h's two faces normal to a. TK03 §1.1.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "complex/complex.hpp"

namespace hexdual {

struct Slot {
  HexId hex = -1;
  int axis = 0;
  friend bool operator==(Slot a, Slot b) { return a.hex == b.hex && a.axis == b.axis; }
  friend bool operator<(Slot a, Slot b) { return a.hex != b.hex ? a.hex < b.hex : a.axis < b.axis; }
};

struct Sheet {
  int id = -1;
  bool alive = true;        // false for an id retired by an operation (DualTracker)
  std::vector<Slot> slots;  // sorted; a self-intersecting sheet has a hex twice
  int64_t euler = 0;        // of the sheet's mid-surface
  int boundaryLoops = 0;
  bool orientable = true;
  bool selfIntersecting = false;
  std::string topology;  // disk, annulus, sphere, torus, other
};

struct Chord {
  int id = -1;
  bool alive = true;
  std::vector<Slot> slots;  // in order along the chord (from a boundary end when open)
  bool closed = false;      // a ring that never reaches the boundary
  bool selfIntersecting = false;
};

struct Dual {
  std::vector<Sheet> sheets;
  std::vector<Chord> chords;
  std::vector<std::array<int32_t, 3>> sheetOf;  // per hex id (capacity), per axis; -1 for tombstones
  std::vector<std::array<int32_t, 3>> chordOf;
};

// Axis of the neighbour's hex that continues axis `a` of hex h across face f (f must be interior).
int mapAxisAcross(const Complex& cx, HexId h, int face, int axis);

// Extracts sheets and chords in linear time. Ids are deterministic: sheets and chords are
// numbered in the order of their smallest slot (hex id, then axis).
Dual extractDual(const Complex& cx);

// Names a sheet's topology from its Euler characteristic, boundary loops and orientability.
std::string classifySurface(int64_t euler, int loops, bool orientable);

// Recomputes a sheet's Euler characteristic, boundary loops, self-intersection and topology from
// its slots alone (local: cost proportional to the sheet). `orientable` must already be set.
void classifySheet(const Complex& cx, Sheet& sheet);

// Floods the sheet through a slot, labelling unlabelled slots (-1 in the flat per-slot array
// `sheetOf`, 3 per hex) with `id`; `sign` (same layout) receives an orientation per slot.
// Returns false when the sheet is not orientable; appends the slots to `out`.
bool floodSheet(const Complex& cx, Slot start, int32_t id, int32_t* sheetOf, int8_t* sign, std::vector<Slot>& stack,
                std::vector<Slot>* out);
// Walks the chord through a slot, labelling its slots with `chord.id` in `chordOf` (flat array).
void walkChord(const Complex& cx, Slot start, Chord& chord, int32_t* chordOf);

// Compares two duals of the same complex up to renaming of ids: same partition of slots into
// sheets and chords, same classification. Throws Error naming the first difference.
void compareDuals(const Complex& cx, const Dual& a, const Dual& b);

}  // namespace hexdual

namespace hexdual {
// Checks that a Dual describes the complex: every live slot is listed exactly once in the sheet
// and chord named by sheetOf/chordOf, slots glued across parallel (sheet) or normal (chord) quads
// share a sheet or chord, and chords list consecutive glued slots. Throws Error naming the first
// inconsistency. Used after incremental updates in debug builds and tests.
void validateDual(const Complex& cx, const Dual& dual);
}  // namespace hexdual
