// The table of atomic operations: one row per OpKind with everything the log, the URL form, the
// candidates list, the dual tracker and applyStep need to know. Adding an operation is one enum
// value (op_step.hpp), one row here (op_table.cpp) and one file in core/ops.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "ops/op_step.hpp"
#include "ops/ops.hpp"

namespace hexdual {

// Which steps `candidates` tries for an operation.
enum class CandidateSet : uint8_t {
  None,                 // not enumerated (ringsplit: ringcollapse reports it as its inverse)
  InteriorQuads,        // every interior quad, once
  InteriorQuadSides,    // every side of every interior quad
  Hexes,                // every hex
  EdgeStarQuadPairs,    // every closed interior edge with two quads of its cycle
  ClosedChordEdges,     // two edges along each closed chord (the two diagonals)
  SameVertexQuadPairs,  // every two interior quads on the same 4 vertices, both sides of the second
  SheetEdges,           // one edge per sheet (of its smallest slot)
  SheetEdgesByTwo,      // one edge per sheet, with the number 2 (sheet-dice)
  ChordEdges,           // two edges along every chord (the two diagonals)
};

// The atomic operations keep the boundary quad mesh; the sheet operations change it (they remove,
// insert, collapse or split whole sheets and chords, including where they meet the boundary).
enum class OpFamily : uint8_t { Atomic, Sheet };

// How an operation changes the vertex and hex counts: the same for every application (OPERATIONS.md),
// or, for ring collapse and ring split, by the ring's length.
struct CountChange {
  bool fixed;
  int dV, dH;
};

struct OpInfo {
  OpKind kind;
  const char* name;  // the log name, e.g. "chordpush"; also the prefix of the operation's errors
  char urlCode;      // the letter of the URL form, e.g. 'C'
  std::vector<OpArg::Kind> args;  // with `variadic`, one kind repeated one or more times
  bool keepsSheetTopology;        // never cuts, merges or re-shapes an existing sheet (DualTracker)
  CandidateSet candidates;
  CountChange counts;
  OpResult (*apply)(Complex&, const OpStep&);  // called with arguments already checked
  // The operation's first checks without throwing (arguments checked): the message `apply` would
  // throw for them, or empty when they pass (apply may still reject later). Null: none.
  std::string (*precheck)(const Complex&, const OpStep&);
  bool variadic = false;              // the operation takes a list (ringsplit's pairs, sheet-insert's quads)
  OpFamily family = OpFamily::Atomic;
};

// Every operation, in OpKind order.
const std::vector<OpInfo>& allOps();
// The row of an operation; throws Error for a value outside the enum.
const OpInfo& opInfo(OpKind kind);
inline const char* opName(OpKind kind) { return opInfo(kind).name; }
// The row with this log name or URL letter, or nullptr.
const OpInfo* findOp(std::string_view name);
const OpInfo* findOpByUrlCode(char code);
// "a quad (h12f3)" and the like, for messages.
const char* argKindName(OpArg::Kind kind);
// Throws Error "<op>: ..." when the step's argument count or kinds do not match the table.
void checkArgs(const OpStep& step);
// Whether the dual tracker may update sheets locally after this result (false for composites).
inline bool keepsSheetTopology(const OpResult& r) { return r.op && opInfo(*r.op).keepsSheetTopology; }
inline bool isSheetOp(OpKind kind) { return opInfo(kind).family == OpFamily::Sheet; }

}  // namespace hexdual
