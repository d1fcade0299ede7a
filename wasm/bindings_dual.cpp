// Bindings of the dual: the tracker that keeps it current across operations (made on first use),
// counts of live sheets and chords, and the hexes of a sheet or chord.
#include "bindings_common.hpp"
#include "wasm_mesh.hpp"

namespace hexdual::wasm {

namespace {
template <class T>
int countAlive(const std::vector<T>& items) {
  int n = 0;
  for (const T& x : items) n += x.alive ? 1 : 0;
  return n;
}
}  // namespace

DualTracker& WasmMesh::tracker() {
  if (!tracker_) tracker_ = std::make_unique<DualTracker>(cx_);
  return *tracker_;
}

int WasmMesh::liveSheet(int id) {
  const Dual& d = dual();
  if (id >= 0 && size_t(id) < d.sheets.size() && !d.sheets[size_t(id)].alive)
    throw Error("sheet " + std::to_string(id) + " was removed by an operation");
  return id;
}

int WasmMesh::numSheets() {
  return guarded(
      "PRECONDITION", [&] { return countAlive(dual().sheets); }, -1);
}
int WasmMesh::numChords() {
  return guarded(
      "PRECONDITION", [&] { return countAlive(dual().chords); }, -1);
}

double WasmMesh::dualAddress() {
  return guarded(
      "PRECONDITION", [&] { return double(uintptr_t(&dual())); }, 0.0);
}

double WasmMesh::trackerAddress() {
  return guarded(
      "PRECONDITION", [&] { return double(uintptr_t(&tracker())); }, 0.0);
}

val WasmMesh::slotsToArray(int id, bool sheet) {
  const Dual& d = dual();
  size_t n = sheet ? d.sheets.size() : d.chords.size();
  bool alive = id >= 0 && size_t(id) < n && (sheet ? d.sheets[size_t(id)].alive : d.chords[size_t(id)].alive);
  if (!alive) {
    g_lastError = std::string(sheet ? "sheetHexes: sheet " : "chordHexes: chord ") + std::to_string(id) + " does not exist";
    g_lastErrorCode = "PRECONDITION";
    return val::null();
  }
  const std::span<const Slot> slots = sheet ? d.sheets[size_t(id)].slots.view() : d.chords[size_t(id)].slots.view();
  scratch_.clear();
  for (const Slot& s : slots) scratch_.push_back(s.hex);
  return copyOut("Int32Array", scratch_);
}

}  // namespace hexdual::wasm
