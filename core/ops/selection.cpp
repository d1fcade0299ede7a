// Sheets and chords through picked entities (selection.hpp): one slot lookup each.
#include "ops/selection.hpp"

#include "ops/op_step.hpp"

namespace hexdual {
using namespace tables;

int32_t sheetThroughEdge(const Complex& cx, const Dual& dual, EdgeRef e) {
  if (!cx.isHex(e.hex)) throw Error("select: hex " + std::to_string(e.hex) + " does not exist");
  if (e.edge < 0 || e.edge > 11) throw Error("select: local edge " + std::to_string(e.edge) + " is not 0..11");
  return dual.sheetAt(e.hex, axisOfEdge(e.edge));
}

int32_t chordThroughQuad(const Complex& cx, const Dual& dual, QuadSide q) {
  if (!cx.isHex(q.hex)) throw Error("select: hex " + std::to_string(q.hex) + " does not exist");
  if (q.face < 0 || q.face > 5) throw Error("select: local face " + std::to_string(q.face) + " is not 0..5");
  return dual.chordAt(q.hex, axisOfFace(q.face));
}

Selection selectSheet(const Complex& cx, const Dual& dual, EdgeRef e) {
  Selection s;
  s.id = sheetThroughEdge(cx, dual, e);
  s.through = entityName(e);
  const Sheet& sh = dual.sheets[size_t(s.id)];
  s.topology = sh.topology;
  s.boundaryLoops = sh.boundaryLoops;
  s.selfIntersecting = sh.selfIntersecting;
  for (const Slot& t : sh.slots) s.hexes.push_back(t.hex);
  s.steps = {"sheet-extract " + s.through, "sheet-dice " + s.through + " 2"};
  return s;
}

Selection selectChord(const Complex& cx, const Dual& dual, QuadSide q) {
  Selection s;
  s.sheet = false;
  s.id = chordThroughQuad(cx, dual, q);
  s.through = entityName(q);
  const Chord& ch = dual.chords[size_t(s.id)];
  s.closed = ch.closed;
  s.selfIntersecting = ch.selfIntersecting;
  for (const Slot& t : ch.slots) s.hexes.push_back(t.hex);
  // Column collapse along either diagonal of the chord's cross-section (an edge of the picked hex along it).
  const int a = axisOfFace(q.face);
  for (int k : {0, 1}) s.steps.push_back("column-collapse " + entityName(EdgeRef{q.hex, 4 * a + k}));
  return s;
}

}  // namespace hexdual
