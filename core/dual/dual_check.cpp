// Checks of a dual against its complex: validateDual (every slot listed once, in the sheet and
// chord its labels name, neighbours across quads in the same sheet or chord, chords walking glued
// slots) and compareDuals (two duals equal up to renaming of ids). Used by the tests and debug builds.
#include <string>
#include <unordered_map>

#include "dual/dual.hpp"

namespace hexdual {
using namespace tables;

void validateDual(const Complex& cx, const Dual& d) {
  auto fail = [](const std::string& m) { throw Error("validateDual: " + m); };
  auto slotName = [](Slot s) { return "slot (hex " + std::to_string(s.hex) + ", axis " + std::to_string(s.axis) + ")"; };
  if (d.sheetLabel.size() < size_t(cx.hexCapacity()) || d.chordLabel.size() < size_t(cx.hexCapacity()))
    fail("per-hex arrays are shorter than the hex capacity");
  std::vector<uint8_t> seenSheet(size_t(3) * size_t(cx.hexCapacity()), 0), seenChord(seenSheet.size(), 0);
  auto mark = [&](std::vector<uint8_t>& seen, Slot s, const char* what, int id) {
    if (!cx.isHex(s.hex)) fail(std::string(what) + " " + std::to_string(id) + " lists dead hex " + std::to_string(s.hex));
    uint8_t& m = seen[size_t(3) * size_t(s.hex) + size_t(s.axis)];
    if (m) fail(slotName(s) + " is listed twice among " + what + "s");
    m = 1;
  };
  for (size_t i = 0; i < d.sheets.size(); ++i)
    for (Slot s : d.sheets[i].slots) {
      mark(seenSheet, s, "sheet", d.sheets[i].id);
      if (d.sheetAt(s.hex, s.axis) != d.sheets[i].id) fail(slotName(s) + " is in sheet " + std::to_string(d.sheets[i].id) + " but its label names another");
    }
  for (size_t i = 0; i < d.chords.size(); ++i) {
    const Chord& ch = d.chords[i];
    for (size_t k = 0; k < ch.slots.size(); ++k) {
      Slot s = ch.slots[k];
      mark(seenChord, s, "chord", ch.id);
      if (d.chordAt(s.hex, s.axis) != ch.id) fail(slotName(s) + " is in chord " + std::to_string(ch.id) + " but its label names another");
      bool last = k + 1 == ch.slots.size();
      if (last && !ch.closed) continue;
      Slot next = ch.slots[last ? 0 : k + 1];
      Gluing a = cx.gluing(s.hex, 2 * s.axis), b = cx.gluing(s.hex, 2 * s.axis + 1);
      bool adjacent = (!a.boundary() && a.hex == next.hex && axisOfFace(a.face) == next.axis) ||
                      (!b.boundary() && b.hex == next.hex && axisOfFace(b.face) == next.axis);
      if (!adjacent) fail("chord " + std::to_string(ch.id) + ": " + slotName(s) + " is not glued to the next " + slotName(next));
    }
  }
  for (HexId h : cx.hexes())
    for (int a = 0; a < 3; ++a) {
      Slot s{h, a};
      if (!seenSheet[size_t(3) * size_t(h) + size_t(a)]) fail(slotName(s) + " is in no sheet");
      if (!seenChord[size_t(3) * size_t(h) + size_t(a)]) fail(slotName(s) + " is in no chord");
      for (int f = 0; f < 6; ++f) {
        Gluing g = cx.gluing(h, f);
        if (g.boundary()) continue;
        int a2 = mapAxisAcross(cx, h, f, a);
        if (axisOfFace(f) == a) {
          if (d.chordAt(h, a) != d.chordAt(g.hex, a2)) fail(slotName(s) + " and its neighbour across face " + std::to_string(f) + " are in different chords");
        } else if (d.sheetAt(h, a) != d.sheetAt(g.hex, a2)) {
          fail(slotName(s) + " and its neighbour across face " + std::to_string(f) + " are in different sheets");
        }
      }
    }
}

void compareDuals(const Complex& cx, const Dual& a, const Dual& b) {
  auto fail = [](const std::string& m) { throw Error("compareDuals: " + m); };
  std::unordered_map<int32_t, int32_t> sheetMap, chordMap, sheetBack, chordBack;
  auto link = [&](std::unordered_map<int32_t, int32_t>& fwd, std::unordered_map<int32_t, int32_t>& back, int32_t x,
                  int32_t y, const char* what, Slot s) {
    auto [it, ins] = fwd.try_emplace(x, y);
    auto [jt, jns] = back.try_emplace(y, x);
    if (it->second != y || jt->second != x)
      fail(std::string(what) + "s differ at slot (hex " + std::to_string(s.hex) + ", axis " + std::to_string(s.axis) + ")");
  };
  for (HexId h : cx.hexes())
    for (int ax = 0; ax < 3; ++ax) {
      link(sheetMap, sheetBack, a.sheetAt(h, ax), b.sheetAt(h, ax), "sheet", {h, ax});
      link(chordMap, chordBack, a.chordAt(h, ax), b.chordAt(h, ax), "chord", {h, ax});
    }
  size_t liveA = 0, liveB = 0;
  for (const Sheet& s : a.sheets) liveA += s.alive;
  for (const Sheet& s : b.sheets) liveB += s.alive;
  if (liveA != liveB || liveA != sheetMap.size()) fail("different numbers of sheets");
  for (auto [x, y] : sheetMap) {
    const Sheet &p = a.sheets[size_t(x)], &q = b.sheets[size_t(y)];
    if (p.slots.size() != q.slots.size() || p.euler != q.euler || p.boundaryLoops != q.boundaryLoops ||
        p.topology != q.topology || p.selfIntersecting != q.selfIntersecting || p.orientable != q.orientable)
      fail("sheet " + std::to_string(x) + " and sheet " + std::to_string(y) + " are classified differently (" +
           p.topology + " euler " + std::to_string(p.euler) + " vs " + q.topology + " euler " + std::to_string(q.euler) + ")");
    if (!(p.slots == q.slots))  // (reads the lists: their pending edits are merged)
      fail("sheet " + std::to_string(x) + " lists other slots than sheet " + std::to_string(y));
  }
  liveA = liveB = 0;
  for (const Chord& c : a.chords) liveA += c.alive;
  for (const Chord& c : b.chords) liveB += c.alive;
  if (liveA != liveB || liveA != chordMap.size()) fail("different numbers of chords");
  for (auto [x, y] : chordMap) {
    const Chord &p = a.chords[size_t(x)], &q = b.chords[size_t(y)];
    if (p.slots.size() != q.slots.size() || p.closed != q.closed || p.selfIntersecting != q.selfIntersecting)
      fail("chord " + std::to_string(x) + " and chord " + std::to_string(y) + " are classified differently");
  }
}

}  // namespace hexdual
