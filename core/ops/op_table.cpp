#include "ops/op_table.hpp"

#include "ops/sheet_ops.hpp"
#include "ops/support.hpp"

#include <type_traits>
#include <utility>

namespace hexdual {

namespace {

// How an argument of an operation's C++ signature is read from a step: the table's argument
// kinds come from the signatures, so the two cannot disagree.
template <class T>
struct ArgOf;
template <>
struct ArgOf<HexId> {
  static constexpr OpArg::Kind kind = OpArg::Hex;
  static HexId get(const OpStep& s, size_t k) { return s.args[k].hex; }
};
template <>
struct ArgOf<QuadSide> {
  static constexpr OpArg::Kind kind = OpArg::Quad;
  static QuadSide get(const OpStep& s, size_t k) { return s.args[k].quad(); }
};
template <>
struct ArgOf<EdgeRef> {
  static constexpr OpArg::Kind kind = OpArg::Edge;
  static EdgeRef get(const OpStep& s, size_t k) { return s.args[k].edge(); }
};
template <>
struct ArgOf<std::vector<std::pair<QuadSide, QuadSide>>> {  // all the step's arguments
  static constexpr OpArg::Kind kind = OpArg::Pair;
  static std::vector<std::pair<QuadSide, QuadSide>> get(const OpStep& s, size_t) {
    std::vector<std::pair<QuadSide, QuadSide>> pairs;
    for (const OpArg& a : s.args) pairs.push_back({a.quad(), a.second});
    return pairs;
  }
};

template <>
struct ArgOf<Count> {
  static constexpr OpArg::Kind kind = OpArg::Number;
  static Count get(const OpStep& s, size_t k) { return s.args[k].number(); }
};
template <>
struct ArgOf<std::vector<QuadSide>> {  // all the step's arguments
  static constexpr OpArg::Kind kind = OpArg::Quad;
  static std::vector<QuadSide> get(const OpStep& s, size_t) {
    std::vector<QuadSide> quads;
    for (const OpArg& a : s.args) quads.push_back(a.quad());
    return quads;
  }
};
template <>
struct ArgOf<std::vector<HexId>> {  // all the step's arguments
  static constexpr OpArg::Kind kind = OpArg::Hex;
  static std::vector<HexId> get(const OpStep& s, size_t) {
    std::vector<HexId> hexes;
    for (const OpArg& a : s.args) hexes.push_back(a.hex);
    return hexes;
  }
};
// A signature whose one argument is a vector takes all the step's arguments (one or more).
template <class T>
constexpr bool kIsList = false;
template <class T>
constexpr bool kIsList<std::vector<T>> = true;

template <class F>
struct Signature;
template <class... A>
struct Signature<std::string (*)(const Complex&, A...)> {  // a precheck: the operation's arguments, no edits
  template <auto F, size_t... I>
  static std::string call(const Complex& cx, const OpStep& s, std::index_sequence<I...>) {
    return F(cx, ArgOf<std::decay_t<A>>::get(s, I)...);
  }
  template <auto F>
  static std::string check(const Complex& cx, const OpStep& s) {
    return call<F>(cx, s, std::index_sequence_for<A...>{});
  }
};
template <class... A>
struct Signature<OpResult (*)(Complex&, A...)> {
  static std::vector<OpArg::Kind> kinds() { return {ArgOf<std::decay_t<A>>::kind...}; }
  static constexpr bool variadic = sizeof...(A) == 1 && (kIsList<std::decay_t<A>> && ...);
  template <auto F, size_t... I>
  static OpResult call(Complex& cx, const OpStep& s, std::index_sequence<I...>) {
    return F(cx, ArgOf<std::decay_t<A>>::get(s, I)...);
  }
  template <auto F>
  static OpResult apply(Complex& cx, const OpStep& s) {
    return call<F>(cx, s, std::index_sequence_for<A...>{});
  }
};

template <auto F, auto Precheck = nullptr>
OpInfo row(OpKind kind, const char* name, char urlCode, bool keepsSheetTopology, CandidateSet candidates, CountChange counts) {
  using S = Signature<decltype(F)>;
  std::string (*precheck)(const Complex&, const OpStep&) = nullptr;
  if constexpr (!std::is_same_v<decltype(Precheck), std::nullptr_t>)  // by type: sanitizer builds do not fold function addresses
    precheck = &Signature<decltype(Precheck)>::template check<Precheck>;
  return {kind, name, urlCode, S::kinds(), keepsSheetTopology, candidates, counts, &S::template apply<F>, precheck, S::variadic};
}
// A row of the sheet family (docs/operations.md "Sheet operations").
template <auto F>
OpInfo sheetRow(OpKind kind, const char* name, char urlCode, bool keepsSheetTopology, CandidateSet candidates) {
  OpInfo info = row<F>(kind, name, urlCode, keepsSheetTopology, candidates, {false, 0, 0});
  info.family = OpFamily::Sheet;
  return info;
}

constexpr bool kKeepsSheets = true, kReshapesSheets = false;
constexpr CountChange kByRingLength{false, 0, 0};
constexpr CountChange counts(int dV, int dH) { return {true, dV, dH}; }

std::vector<OpInfo> makeTable() {
  using K = OpKind;
  using C = CandidateSet;
  std::vector<OpInfo> t = {
      row<&pillow, &ops::pillowPrecheck>(K::Pillow, "pillow", 'P', kKeepsSheets, C::InteriorQuads, counts(4, 2)),
      row<&unpillow>(K::Unpillow, "unpillow", 'Q', kKeepsSheets, C::Hexes, counts(-4, -2)),
      row<&chordPush, &ops::chordPushPrecheck>(K::ChordPush, "chordpush", 'C', kKeepsSheets, C::EdgeStarQuadPairs, counts(2, 2)),
      row<&chordPull>(K::ChordPull, "chordpull", 'D', kKeepsSheets, C::Hexes, counts(-2, -2)),
      row<&hexPush, &ops::hexPushPrecheck>(K::HexPush, "hexpush", 'H', kKeepsSheets, C::InteriorQuads, counts(4, 4)),
      row<&hexPull>(K::HexPull, "hexpull", 'I', kKeepsSheets, C::InteriorQuadSides, counts(-4, -4)),
      row<&ringCollapse>(K::RingCollapse, "ringcollapse", 'R', kReshapesSheets, C::ClosedChordEdges, kByRingLength),
      row<&ringSplit>(K::RingSplit, "ringsplit", 'S', kReshapesSheets, C::None, kByRingLength),
      row<&faceCollapse, &ops::faceCollapsePrecheck>(K::FaceCollapse, "facecollapse", 'F', kReshapesSheets, C::EdgeStarQuadPairs, counts(-2, 0)),
      row<&faceSplit>(K::FaceSplit, "facesplit", 'G', kReshapesSheets, C::SameVertexQuadPairs, counts(2, 0)),
      // The sheet family: extraction, insertion and dicing remove, add or multiply one sheet whole
      // and leave the topology of every other sheet as it was (the tracker updates them locally);
      // column collapse cuts and re-joins the two sheets through the chord.
      sheetRow<&sheetExtract>(K::SheetExtract, "sheet-extract", 'x', kKeepsSheets, C::SheetEdges),
      sheetRow<&sheetInsert>(K::SheetInsert, "sheet-insert", 'n', kKeepsSheets, C::None),
      sheetRow<&sheetPillow>(K::SheetPillow, "sheet-pillow", 'w', kKeepsSheets, C::None),
      sheetRow<&columnCollapse>(K::ColumnCollapse, "column-collapse", 'k', kReshapesSheets, C::ChordEdges),
      sheetRow<&sheetDice>(K::SheetDice, "sheet-dice", 'u', kKeepsSheets, C::SheetEdgesByTwo),
  };
  for (size_t k = 0; k < t.size(); ++k)
    if (t[k].kind != OpKind(k)) throw Error("internal: the operation table is not in OpKind order");
  return t;
}

}  // namespace

const std::vector<OpInfo>& allOps() {
  static const std::vector<OpInfo> table = makeTable();
  return table;
}

const OpInfo& opInfo(OpKind kind) {
  const auto& t = allOps();
  if (size_t(kind) >= t.size()) throw Error("oplog: unknown operation (kind " + std::to_string(int(kind)) + ")");
  return t[size_t(kind)];
}

const OpInfo* findOp(std::string_view name) {
  for (const OpInfo& o : allOps())
    if (name == o.name) return &o;
  return nullptr;
}

const OpInfo* findOpByUrlCode(char code) {
  for (const OpInfo& o : allOps())
    if (code == o.urlCode) return &o;
  return nullptr;
}

const char* argKindName(OpArg::Kind kind) {
  switch (kind) {
    case OpArg::Hex: return "a hex (h12)";
    case OpArg::Quad: return "a quad (h12f3)";
    case OpArg::Edge: return "an edge (h12e7)";
    case OpArg::Pair: return "a quad pair (h1f2/h3f4)";
    case OpArg::Number: return "a number (3)";
  }
  return "?";
}

void checkArgs(const OpStep& step) {
  const OpInfo& info = opInfo(step.op);
  const bool list = info.variadic;
  const size_t n = step.args.size();
  if (list ? n < 1 : n != info.args.size())
    throw Error(std::string(info.name) + ": takes " + (list ? "one or more" : std::to_string(info.args.size())) +
                " argument(s), not " + std::to_string(n));
  for (size_t k = 0; k < n; ++k) {
    OpArg::Kind want = list ? info.args[0] : info.args[k];
    if (step.args[k].kind != want)
      throw Error(std::string(info.name) + ": argument " + std::to_string(k + 1) + " must be " + argKindName(want) +
                  ", not '" + entityName(step.args[k]) + "'");
  }
}

std::string entityName(HexId h) { return "h" + std::to_string(h); }
std::string entityName(QuadSide q) { return entityName(q.hex) + "f" + std::to_string(q.face); }
std::string entityName(EdgeRef e) { return entityName(e.hex) + "e" + std::to_string(e.edge); }
std::string entityName(const OpArg& a) {
  switch (a.kind) {
    case OpArg::Hex: return entityName(a.hex);
    case OpArg::Quad: return entityName(a.quad());
    case OpArg::Edge: return entityName(a.edge());
    case OpArg::Pair: return entityName(a.quad()) + "/" + entityName(a.second);
    case OpArg::Number: return std::to_string(a.local);
  }
  return "?";
}

}  // namespace hexdual
