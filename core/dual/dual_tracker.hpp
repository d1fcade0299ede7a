// Keeps the dual current across operations. Sheets through the touched hexes are updated by a
// lockstep flood from every touched slot that stops as soon as each old sheet is either wholly
// explored or continues in one unexplored remainder, so a sheet cut or re-glued in one place costs
// the explored region, and a real split its smaller pieces (a merge re-points sheet labels and
// writes no slot: see Dual::sheetLabel); Euler characteristics, loops and
// orientations of the remainder follow from per-slot shares kept between updates. At the
// boundary a group that meets a sheet whose boundary loops the edit can re-join is flooded whole;
// edits through non-orientable sheets re-flood the sheets they touch. Chords through the
// touched hexes are rebuilt from their untouched stretches and walks through the touched hexes
// that join them (TK03 §4.4: a collapse cuts two chords and re-joins them crosswise): a chord is
// listed as pieces of labelled runs (see Dual::chordLabel), so a merge or a cut writes only the
// touched slots (same ids and order as a re-walk). Surviving
// sheets and chords keep their ids; new ones get fresh ids; when sheets merge or split, the
// unexplored remainder keeps the id of its largest old sheet and explored pieces keep an old id
// only when they are all that is left of it; chords follow the smallest old id.
//
// The implementation is split by concern (docs/architecture.md draws the parts and what flows
// between them); each unit's first lines say what it owns and the invariants it keeps:
//   dual_tracker.cpp                     construction, update() choosing a strategy, retired ids
//   tracker/sheet_labels.cpp             sheet labels, orientations, merges, pair counts (self-intersection)
//   tracker/shares.cpp                   edge marks and per-slot Euler shares
//   tracker/sheets_topology_kept.cpp     sheet update when the operation keeps every sheet's topology
//   tracker/sheets_interior_lockstep.cpp sheet update for other edits on orientable sheets (lockstep flood)
//   tracker/sheets_fallback_reflood.cpp  sheet update when neither applies (twisted sheets)
//   tracker/chord_runs.cpp               chords as pieces of labelled runs: slicing, cutting, labels, settling
//   tracker/chord_update.cpp             which chords changed; the whole re-walk (reference and fallback)
//   tracker/chord_rejoin.cpp             the local chord update: stretches joined by walks through the edit
//   tracker/sheets_unmerge.cpp           exact undo of a step that kept every sheet: its memo, given back
//   tracker/id_restore.cpp               exact undo's ids: a step's ids read before it, given back after its undo
// The undo journal itself is the complex's (Complex::EditLog, cx.undo); the tracker follows an undo
// like any edit and gives the undone step's ids back with releaseRetiredTail().
#pragma once
#include <memory>
#include <span>
#include <vector>

#include "complex/complex.hpp"
#include "complex/huge_pages.hpp"
#include "dual/dual.hpp"
#include "dual/tracker/label_run.hpp"

namespace hexdual {

struct DualChange {
  std::vector<int> sheetsCreated, sheetsRemoved, sheetsChanged;  // changed: same id, new slots
  std::vector<int> chordsCreated, chordsRemoved, chordsChanged;
};

// What the update undoing a step that kept every sheet (merging some, adding new ones) needs to
// split them again without flooding them (tracker/sheets_unmerge.cpp): the sheets' labels, slot
// lists and measures before the step. Filled by update(cx, edits, keeps, memo); read by updateUndone.
struct DualUnmergeMemo;

// What undoing a step needs to give the dual its ids back: the id ranges before the step and one
// slot of each sheet and chord through the hexes it touched, with that sheet's or chord's id. Read
// by idMemo() before the step's update; restoreIds() applies it after the update undoing the step.
struct DualIdMemo {
  size_t sheets = 0, chords = 0;  // dual().sheets.size(), dual().chords.size() before the step
  std::vector<std::pair<Slot, int32_t>> sheetSlots, chordSlots;
  std::shared_ptr<const DualUnmergeMemo> unmerge;  // set by update(..., memo) when the step kept every sheet
};

class DualTracker {
 public:
  explicit DualTracker(const Complex& cx);
  // The dual; chords changed since the last read get their slot lists (and self-intersection, when
  // the update left it open) from their pieces here, so a reader pays for them, not the update.
  // Not for concurrent first reads (like SlotList, the first read after an update writes).
  const Dual& dual() const {
    if (!unsettled_.empty()) settleChords();
    return dual_;
  }
  // Brings the dual up to date after an edit of cx: an operation's OpResult::edits, or the undo
  // of one. sheetsKeepTopology: the operation never cuts, merges or re-shapes a sheet (the
  // operation table's flag, keepsSheetTopology(result) in ops/op_table.hpp).
  DualChange update(const Complex& cx, const Complex::EditLog& edits, bool sheetsKeepTopology);
  // The same after an arbitrary set of edited hexes (ids of live or removed hexes). With
  // sheetsKeepTopology new slots join the sheet they touch and no sheet is re-flooded: the cost
  // is local. A merge of two sheets, if one is ever found, falls back to re-flooding the sheets involved.
  DualChange update(const Complex& cx, std::vector<HexId> touched, bool sheetsKeepTopology = false);

  // The same, for a step whose exact undo may follow: when the step kept every sheet (a face or
  // ring collapse joining two layers), memo (idMemo's, taken before) also keeps what the undo's
  // update needs to split them again in time proportional to the step, not to the sheets.
  DualChange update(const Complex& cx, const Complex::EditLog& edits, bool sheetsKeepTopology, DualIdMemo& memo);
  // The update after cx.undo(edits), edits being the log of the step memo was taken for (the last
  // step the tracker followed, or one whose later steps were undone through updateUndone too): the
  // merged sheets are given back from memo when nothing else changed the sheets since (else, and
  // for every other step, it is update(cx, edits, sheetsKeepTopology)). restoreIds(memo) follows.
  DualChange updateUndone(const Complex& cx, const Complex::EditLog& edits, bool sheetsKeepTopology,
                          const DualIdMemo& memo);
  // Whether the last update gave merged sheets back from a memo (updateUndone) instead of flooding.
  bool lastUpdateUnmerged() const { return unmerged_; }

  // Drops retired ids at the end of the id ranges, so that after an exact undo (LIFO) the ids the
  // undone step created are handed out again when it is redone.
  void releaseRetiredTail();

  // Exact undo, ids included (tracker/id_restore.cpp). Before a step's update: idMemo of its edits.
  // After the update that undoes it (cx.undo(edits), then update): restoreIds gives each sheet and
  // chord the step changed the id it had before (the update names a restored sheet afresh), and
  // drops the ids the step and its undo handed out. The dual is then the one before the step, ids
  // and id ranges included, so a redo or another step hands out the same ids as a replay would.
  DualIdMemo idMemo(const Complex& cx, const Complex::EditLog& edits) const;
  void restoreIds(const DualIdMemo& memo);

  // Slots the last update visited (walked, flooded or re-labelled): its cost, independent of time.
  size_t slotsTouched() const { return slotsTouched_; }
  // The same for sheets and chords apart; and whether the last update's sheets were re-flooded.
  size_t sheetSlotsTouched() const { return sheetSlotsTouched_; }
  size_t chordSlotsTouched() const { return slotsTouched_ - sheetSlotsTouched_; }
  // Sheet labels re-pointed because two old sheets merged (a merge writes no slot: see Dual::sheetLabel).
  size_t mergedLabels() const { return mergedLabels_; }
  bool lastUpdateReflooded() const { return reflooded_; }
  // Test knob: false re-walks every changed chord (the reference the local chord update must equal).
  void setLocalChords(bool on) { localChords_ = on; }
  // How many pieces of labelled runs chord id is listed as (one after extraction or a re-walk).
  size_t chordPieces(int32_t id) const { return pieces_[size_t(id)].size(); }
  // Whether the last update re-walked its changed chords whole (the local rejoin was not sure).
  bool lastChordsRewalked() const { return chordsRewalked_; }

  // Checks the tracker's own state against cx: each unit's invariants (stated in its first lines,
  // listed in docs/architecture.md: labels and their counts, orientations, shares and edge marks,
  // pair counts, chord pieces and label cuts, scratch marks cleared). Throws Error naming the
  // first one broken. Linear in the mesh; the debug build (HEXDUAL_CHECK_INVARIANTS) runs it after
  // every update. validateDual checks the dual itself against the complex.
  void checkInvariants(const Complex& cx) const;

 private:
  DualChange updateFromLog(const Complex& cx, const Complex::EditLog& edits, bool sheetsKeepTopology,
                           const DualUnmergeMemo* unmerge);
  DualChange updateSorted(const Complex& cx, const std::vector<HexId>& touched, bool sheetsKeepTopology,
                          const DualUnmergeMemo* unmerge = nullptr);

  // ---- exact undo of a step that kept every sheet (tracker/sheets_unmerge.cpp) ----
  // The lockstep, before it commits a plan that keeps every old sheet, records them when asked to
  // (recordUnmerge_ set by update(..., memo)); unmergeSheets gives them back after the undo.
  void recordUnmerge(const std::vector<HexId>& touched, const std::vector<int32_t>& old,
                     const std::vector<std::pair<int32_t, int32_t>>& merges, size_t pieces);
  bool unmergeSheets(const Complex& cx, const std::vector<HexId>& touched, const DualUnmergeMemo& u, DualChange& change);
  void retirePieces(const DualUnmergeMemo& u, DualChange& change);
  void relistByLabels(const std::vector<HexId>& touched, const DualUnmergeMemo& u, int32_t keep);
  void newSheetState();  // a number no tracker in the process had: a memo never fits another tracker
  friend struct DualTrackerTestAccess;  // tests break the state on purpose to see checkInvariants fail

  // ---- sheet update strategies, one unit each; update() runs the first that accepts the edit ----
  struct TopologyKept;  // state and steps of the topology-kept update (tracker/sheets_topology_kept.cpp)
  struct Lockstep;      // state and steps of the lockstep flood (tracker/sheets_interior_lockstep.cpp)
  bool updateSheetsLocally(const Complex& cx, const std::vector<HexId>& touched, DualChange& change);
  bool updateSheetsLockstep(const Complex& cx, const std::vector<HexId>& touched, DualChange& change);
  void updateSheetsByFlood(const Complex& cx, const std::vector<HexId>& touched, DualChange& change);

  // ---- chord updates (tracker/chord_update.cpp, tracker/chord_rejoin.cpp) ----
  struct ChordRejoin;  // state and steps of the local chord update
  void updateChords(const Complex& cx, const std::vector<HexId>& touched, DualChange& change);
  std::vector<int32_t> changedChords(const Complex& cx, const std::vector<HexId>& touched);
  bool chordUnchanged(const Complex& cx, int32_t id, const std::vector<Slot>& own) const;
  bool rejoinChords(const Complex& cx, const std::vector<HexId>& touched, const std::vector<int32_t>& ids,
                    DualChange& change);
  void rewalkChords(const Complex& cx, const std::vector<HexId>& touched, const std::vector<int32_t>& ids,
                    DualChange& change);

  // ---- chord runs (tracker/chord_runs.cpp) ----
  // Chord pieces: places [lo, hi) of a label's run, listed forward or reversed.
  struct Piece {
    int32_t label, lo, hi;
    bool reversed;
  };
  int32_t chordLength(int32_t id) const;
  const Piece* pieceOf(int32_t id, Slot s, int32_t* k, int32_t* q) const;
  int32_t placeInChord(int32_t id, Slot s) const;  // -1 when s is not listed in chord id
  // placeInChord, and the slots before and after s along chord id where there are (a closed chord
  // wraps round): *hasPrev / *hasNext false where the chord ends.
  int32_t chordNeighbours(int32_t id, Slot s, Slot* prev, bool* hasPrev, Slot* next, bool* hasNext) const;
  void appendSlots(std::span<const Piece> pieces, std::vector<Slot>& out) const;
  void dropPieces(const std::vector<int32_t>& ids);
  Slot chordSlotAt(int32_t id, int32_t p) const;
  void sliceChord(int32_t id, int32_t a, int32_t b, std::vector<Piece>& out) const;  // places a..b, b < length
  int32_t newChordLabel(std::span<const Slot> run);
  void cutLabel(int32_t label, int32_t lo, int32_t hi, int32_t chord, bool add);
  void releaseLabels();
  void setChordPieces(int32_t id, const std::vector<Piece>& pieces);
  void growChordIds(size_t n);  // room for chord ids below n in the per-chord arrays
  void settleChords() const;
  bool chordSelfIntersects(int32_t id) const;
  void checkChordRuns(const Complex& cx) const;
  void checkLabelCuts() const;

  // ---- shares (tracker/shares.cpp) ----
  // Recomputes the smallest-incidence marks of the edges through the live touched hexes and the
  // mid-surface share of every slot whose share the edit changed, listing the changes when asked.
  struct ShareChange {
    Slot slot;
    int before, after;
  };
  void refreshShares(const Complex& cx, const std::vector<HexId>& touched, std::vector<ShareChange>* changes);
  void checkShares(const Complex& cx) const;

  // ---- sheet labels, orientations and pair counts (tracker/sheet_labels.cpp) ----
  void propagateSigns(const Complex& cx, std::span<const Slot> unsigned_);
  void countSelfHexes(const std::vector<HexId>& hexes, int sign);
  void countSelfHex(HexId h, int sign);
  void countPair(int32_t la, int32_t lb, int32_t n);
  // Sheet labels: a new one for sheet id; writing one on a slot (counted per label); the
  // orientation of a slot's mid-quad (stored relative to its label, which may be flipped).
  int32_t newLabel(int32_t id);
  void setLabel(Slot t, int32_t label);
  int signOf(Slot t) const;
  void setSign(Slot t, int sign);
  void pruneLabels(int32_t id);  // drops the sheet's labels no slot carries any more
  void mergeSheet(int32_t x, int32_t keep, bool flip);
  void checkSheetLabels(const Complex& cx) const;
  void checkLabelsOf(const Complex& cx) const;
  void checkOrientations(const Complex& cx) const;
  void checkPairCounts(const Complex& cx) const;

  // ---- ids (tracker/id_restore.cpp): exchange everything two sheet (chord) ids name; either may be retired ----
  void swapSheetIds(int32_t a, int32_t b);
  void swapChordIds(int32_t a, int32_t b);
  void dropRetiredAbove(size_t sheets, size_t chords);  // retired ids at the end, keeping at least these

  // ---- the frame (dual_tracker.cpp) ----
  void growPerHexArrays(size_t cap);
  void checkScratchCleared() const;

  // ---- state (each unit's first lines say which it owns) ----
  mutable Dual dual_;                         // dual() settles chord lists
  std::vector<std::vector<int32_t>> labels_;  // per sheet id: the labels naming it
  std::vector<int32_t> labelSlots_;           // per label: slots carrying it
  std::vector<uint8_t> labelFlip_;            // per label: its slots' stored orientations are flipped
  std::vector<int32_t> freeLabels_;           // labels no slot carries, handed out again
  // Per sheet id: (hex, pair of its axes) with both slots on the sheet; a sheet self-intersects when
  // it has one. The same pairs across two sheets are counted per pair of labels (a merge reads them).
  std::vector<int32_t> selfPairs_;
  class PairCounts {
   public:
    void add(int32_t a, int32_t b, int32_t n);
    int32_t take(int32_t a, int32_t b);                   // the count, zeroed
    int32_t count(int32_t a, int32_t b) const;            // the count (checkInvariants)
    std::vector<std::array<int32_t, 3>> entries() const;  // (a, b, count) of the non-zero counts
   private:
    // A key and its count side by side: a probe reads one cache line, not one in each of two arrays.
    struct Entry {
      uint64_t key;
      int32_t count;
    };
    size_t find(uint64_t key) const;
    HugeVector<Entry> table_;  // rehashed into fresh storage: MBs at 1M hexes
    size_t used_ = 0;
    int shift_ = 58;
  } pairs_;
  SheetFlooder flooder_;  // its signs() persist: one orientation per orientable sheet
  // Per hex: bit e set when (h, e) is its edge's smallest incidence; kNearBoundary when any of its
  // 12 edges reaches the boundary.
  HugeVector<uint16_t> edgeMarks_;
  // Per slot: twice its share of its sheet's Euler characteristic (2 - sides - boundary sides +
  // 2 x primal edges it holds the smallest incidence of); a sheet's Euler characteristic is half the sum.
  HugeVector<int8_t> share_;
  HugeVector<int32_t> front_;    // per slot: lockstep front + 1 that reached it (0 outside an update)
  HugeVector<uint16_t> walked_;  // per hex: edges walked by the current refreshShares (0 outside it)
  // Parallel to the current update's touched hexes: the edges whose cycles its edits can have
  // changed and the chord-axis bits (edgesChangedBy); empty when not known (every edge of a live
  // touched hex is walked, every slot of it checked against its chord).
  std::vector<uint16_t> edgesToWalk_;
  // Chords: per label its run of slots (by place); per chord id its pieces; labels no slot carries.
  HugeVector<tracker::LabelRun> runs_;  // MBs at 1M hexes, grown by edits
  HugeVector<SmallVector<Piece, 4>> pieces_;  // per chord: up to four pieces in place
  std::vector<int32_t> freeChordLabels_;
  std::vector<int32_t> dropped_;            // labels that lost places in this update (released after it)
  mutable std::vector<uint8_t> chordSelf_;  // per chord id: 0/1 self-intersecting, 2 not known until read
  mutable std::vector<int32_t> unsettled_;  // chord ids whose Chord::slots wait for the next dual()
  mutable std::vector<uint8_t> unsettledMark_;
  bool localChords_ = true, chordsRewalked_ = false;
  std::vector<int64_t> delta_;  // per sheet id: change of twice its Euler characteristic (0 outside an update)
  size_t slotsTouched_ = 0, sheetSlotsTouched_ = 0, mergedLabels_ = 0;
  bool reflooded_ = false, unmerged_ = false;
  // Names the sheet side's state (labels, lists, measures): a fresh number after every change but
  // an unmerge, which gives back the number the merge's memo was taken at.
  uint64_t sheetState_ = 0;
  bool recordUnmerge_ = false;                  // the current update is asked to record its sheets
  std::shared_ptr<DualUnmergeMemo> recorded_;  // what it recorded
};

// Hex ids whose gluings or corners an edit log changed (created, removed, re-glued, renumbered).
std::vector<HexId> touchedHexes(const Complex& cx, const Complex::EditLog& edits);
// Per hex of `touched` (touchedHexes of the same log): bit e set when the cycle of its edge e can
// have changed, i.e. the hex was added or removed or a face through e was glued or unglued (an
// edge cycle is the gluings of the faces through it); bit 12 + a (chordAxisChanged(a)) set when
// the hex was added or removed or one of its two faces across axis a was glued or unglued, i.e.
// when its slot along a can have other neighbours along its chord. The same for the log and its undo.
constexpr uint16_t chordAxisChanged(int axis) { return uint16_t(1u << (12 + axis)); }
constexpr uint16_t kChordAxesChanged = uint16_t(7u << 12);
std::vector<uint16_t> edgesChangedBy(const Complex::EditLog& edits, const std::vector<HexId>& touched);
// Both at once (what update() uses): touched = touchedHexes, edges =
// edgesChangedBy(edits, touched). `scratch` holds a word per hex id, 0 before and after the call
// (grown to the log's largest id).
void touchedHexesWithEdges(const Complex::EditLog& edits, std::vector<HexId>& touched, std::vector<uint16_t>& edges,
                           HugeVector<uint16_t>& scratch);

}  // namespace hexdual
