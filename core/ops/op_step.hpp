// One step of the operation log as a value: which atomic operation, on which entities. The
// text and URL forms (oplog.hpp) and the table of operations (op_table.hpp) are built on it.
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "complex/complex.hpp"

namespace hexdual {

// The atomic operations of TK03 §4 and their inverses, then the sheet operations (a separate
// family that changes the boundary quad mesh: docs/operations.md). Each has one row in op_table.cpp.
enum class OpKind : uint8_t {
  Pillow,
  Unpillow,
  ChordPush,
  ChordPull,
  HexPush,
  HexPull,
  RingCollapse,
  RingSplit,
  FaceCollapse,
  FaceSplit,
  SheetExtract,    // sheet family: log names hyphenated, URL letters lowercase
  SheetInsert,
  SheetPillow,
  ColumnCollapse,
  SheetDice,
};

// A plain number argument ("3" in `sheet-dice h4e3 3`).
struct Count {
  int value = 0;
};

// One argument: a hex "h12", a quad side "h12f3", an edge "h12e7", a quad pair "h1f2/h3f4", or a
// number "3".
struct OpArg {
  enum Kind : uint8_t { Hex, Quad, Edge, Pair, Number } kind = Hex;
  HexId hex = -1;
  int local = 0;      // face (Quad, Pair), edge (Edge) or the value (Number)
  QuadSide second{};  // the pair's second quad

  static OpArg of(HexId h) { return {Hex, h, 0, {}}; }
  static OpArg of(QuadSide q) { return {Quad, q.hex, q.face, {}}; }
  static OpArg of(EdgeRef e) { return {Edge, e.hex, e.edge, {}}; }
  static OpArg of(QuadSide f, QuadSide g) { return {Pair, f.hex, f.face, g}; }
  static OpArg of(Count n) { return {Number, -1, n.value, {}}; }
  QuadSide quad() const { return {hex, local}; }
  EdgeRef edge() const { return {hex, local}; }
  Count number() const { return {local}; }
  friend bool operator==(const OpArg& a, const OpArg& b) {
    return a.kind == b.kind && a.hex == b.hex && a.local == b.local && (a.kind != Pair || a.second == b.second);
  }
};

struct OpStep {
  OpKind op = OpKind::Pillow;
  std::vector<OpArg> args;
  size_t position = 0;  // character offset of the step in the log text it was parsed from
  friend bool operator==(const OpStep& a, const OpStep& b) { return a.op == b.op && a.args == b.args; }
};

// A step from its operation and entities: makeStep(OpKind::Pillow, QuadSide{12, 3}).
template <class... A>
OpStep makeStep(OpKind op, A... args) {
  return {op, {OpArg::of(args)...}, 0};
}

// The one spelling of entities in logs and messages: "h12", "h12f3", "h12e7", "h1f2/h3f4", "3".
std::string entityName(HexId h);
std::string entityName(QuadSide q);
std::string entityName(EdgeRef e);
std::string entityName(const OpArg& a);

}  // namespace hexdual
