// Keeps the dual current across operations. After an operation only the sheets and chords
// through the touched hexes are recomputed (cost proportional to those sheets and chords, not to
// the mesh). Surviving sheets and chords keep their ids; new ones get fresh ids; when several
// old ones merge, the result keeps the smallest id; when one splits, the piece holding its
// smallest slot keeps the id.
#pragma once
#include <vector>

#include "complex/complex.hpp"
#include "dual/dual.hpp"

namespace hexdual {

struct DualChange {
  std::vector<int> sheetsCreated, sheetsRemoved, sheetsChanged;  // changed: same id, new slots
  std::vector<int> chordsCreated, chordsRemoved, chordsChanged;
};

class DualTracker {
 public:
  explicit DualTracker(const Complex& cx);
  const Dual& dual() const { return dual_; }
  // Brings the dual up to date after an edit of cx: an operation's OpResult::edits, or the undo
  // of one. sheetsKeepTopology: the operation never cuts, merges or re-shapes a sheet (the
  // operation table's flag, keepsSheetTopology(result) in ops/op_table.hpp).
  DualChange update(const Complex& cx, const Complex::EditLog& edits, bool sheetsKeepTopology);
  // The same after an arbitrary set of edited hexes (ids of live or removed hexes). With
  // sheetsKeepTopology new slots join the sheet they touch and no sheet is re-flooded: the cost
  // is local. A merge of two sheets, if one is ever found, falls back to re-flooding the sheets involved.
  DualChange update(const Complex& cx, std::vector<HexId> touched, bool sheetsKeepTopology = false);

 private:
  bool updateSheetsLocally(const Complex& cx, const std::vector<HexId>& touched, DualChange& change);
  void updateSheetsByFlood(const Complex& cx, const std::vector<HexId>& touched, DualChange& change);
  void updateChords(const Complex& cx, const std::vector<HexId>& touched, DualChange& change);
  Dual dual_;
  std::vector<int32_t> selfHexes_;  // per sheet id: hexes with two or more slots on it
  std::vector<int8_t> sign_;
  std::vector<Slot> stack_;
};

// Hex ids whose gluings or corners an edit log changed (created, removed, re-glued, renumbered).
std::vector<HexId> touchedHexes(const Complex& cx, const Complex::EditLog& edits);

}  // namespace hexdual
