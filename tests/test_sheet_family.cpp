// The sheet operations as a family apart from the atomic ones: their rows in the operation table,
// their log names and URL letters, the number argument, and the v1 log that old texts and URLs
// still read exactly as before.
#include <doctest/doctest.h>

#include <cctype>

#include "complex/builders.hpp"
#include "helpers.hpp"
#include "ops/candidates.hpp"
#include "ops/op_table.hpp"
#include "ops/oplog.hpp"
#include "ops/sheet_ops.hpp"

using namespace hexdual;
using namespace hexdual::test;

TEST_CASE("sheet family: hyphenated log names and lower-case URL letters no atomic operation uses in either case") {
  int atomic = 0, sheet = 0;
  for (const OpInfo& op : allOps()) {
    const bool isSheet = op.family == OpFamily::Sheet;
    CAPTURE(op.name);
    CHECK(isSheet == (std::string(op.name).find('-') != std::string::npos));
    CHECK(isSheet == (std::islower(op.urlCode) != 0));
    if (isSheet) {
      CHECK(findOpByUrlCode(char(std::toupper(op.urlCode))) == nullptr);  // 'x' never reads as an atomic 'X'
      CHECK_FALSE(op.counts.fixed);  // the flip search's count bounds read atomic operations only
    }
    (isSheet ? sheet : atomic) += 1;
  }
  CHECK(atomic == 10);
  CHECK(sheet == 5);
  CHECK(isSheetOp(OpKind::SheetExtract));
  CHECK_FALSE(isSheetOp(OpKind::RingCollapse));
}

TEST_CASE("op log v1: old texts and URLs read exactly as before the sheet family") {
  // Logs written before the sheet operations existed: the same steps, the same text, the same URL.
  const std::string text =
      "v1;pillow h12f3;unpillow h27;chordpush h4e7 h4f2 h9f0;chordpull h30;hexpush h5f1;hexpull h40f5;"
      "ringcollapse h3e4;ringsplit h1f2/h3f4 h5f0/h6f1;facecollapse h21e11 h21f1 h25f1;facesplit h1f1 h2f0";
  const std::string url = "1.P12f3.Q27.C4e7_4f2_9f0.D30.H5f1.I40f5.R3e4.S1f2~3f4_5f0~6f1.F21e11_21f1_25f1.G1f1_2f0";
  const OpLog fromText = parseOpLog(text), fromUrl = decodeOpLogUrl(url);
  CHECK(formatOpLog(fromText) == text);
  CHECK(formatOpLog(fromUrl) == text);
  CHECK(encodeOpLogUrl(fromText) == url);
  REQUIRE(fromText.steps.size() == 10);
  for (size_t k = 0; k < 10; ++k) {
    CHECK(fromText.steps[k] == fromUrl.steps[k]);
    CHECK(fromText.steps[k].op == OpKind(k));
  }
  CHECK(formatOpLog(decodeOpLogUrl("1.P13f5.H13f5")) == "v1;pillow h13f5;hexpush h13f5");
  // Their errors read as before.
  CHECK(errorOf([] { decodeOpLogUrl("1.Z1"); }) == "oplog: position 2: unknown operation code at 'Z'");
  CHECK(errorOf([] { parseOpLog("v1;pillow h1e1"); }) == "oplog: position 10: expected a quad (h12f3) at 'h1e1'");
}

TEST_CASE("op log: the sheet steps round trip as text and URL; a number argument keeps its digits") {
  const std::string text =
      "v1;sheet-extract h4e3;sheet-insert h1f2 h3f4;sheet-pillow h5 h6;column-collapse h7e0;sheet-dice h4e3 3;pillow h12f3";
  const OpLog log = parseOpLog(text);
  CHECK(formatOpLog(log) == text);
  const std::string url = encodeOpLogUrl(log);
  CHECK(url == "1.x4e3.n1f2_3f4.w5_6.k7e0.u4e3_3.P12f3");
  CHECK(formatOpLog(decodeOpLogUrl(url)) == text);
  CHECK(log.steps[4] == makeStep(OpKind::SheetDice, EdgeRef{4, 3}, Count{3}));
  CHECK(errorOf([] { parseOpLog("v1;sheet-dice h4e3 h3"); }) == "oplog: position 19: expected a number (3) at 'h3'");
  CHECK(errorOf([] { parseOpLog("v1;sheet-dice h4e3"); }) == "oplog: position 3: sheet-dice takes 2 argument(s), not 1 at 'sheet-dice h4e3'");
  CHECK(errorOf([] { parseOpLog("v1;sheet-insert"); }) ==
        "oplog: position 3: sheet-insert takes one or more argument(s), not 0 at 'sheet-insert'");
  CHECK(errorOf([] { parseOpLog("v1;sheet-pillow h1 h2f0"); }) == "oplog: position 19: expected a hex (h12) at 'h2f0'");
  Complex cx = makeGrid(2, 2, 2);
  CHECK(errorOf([&] { applyStep(cx, makeStep(OpKind::SheetDice, EdgeRef{0, 0}, QuadSide{0, 1})); }) ==
        "sheet-dice: argument 2 must be a number (3), not 'h0f1'");
}

TEST_CASE("ruleOf reads the rule of a sheet operation's refusal, and nothing from other messages") {
  CHECK(ruleOf("sheet-extract: self-touching: the sheet touches itself at vertex 5") == "self-touching");
  CHECK(ruleOf("column-collapse: non-manifold-result: the result would not be a valid complex (x)") == "non-manifold-result");
  CHECK(ruleOf("hexpush: quad h0f0 is on the boundary; hex push needs an interior quad") == "");
  CHECK(ruleOf("oplog: position 3: unknown operation at 'pilow'") == "");
  CHECK(ruleOf("") == "");
}

TEST_CASE("candidates: every sheet once for sheet-extract and sheet-dice, both diagonals of every chord for column-collapse") {
  Complex cx = makeGrid(2, 2, 3);
  const auto extract = candidates(cx, OpKind::SheetExtract);
  CHECK(extract.size() == 7);  // every sheet of a 2x2x3 grid can be extracted
  CHECK(formatOpStep(extract[0]) == "sheet-extract h0e0");
  const auto dice = candidates(cx, OpKind::SheetDice);
  CHECK(dice.size() == 7);
  CHECK(formatOpStep(dice[0]) == "sheet-dice h0e0 2");
  CHECK(candidates(cx, OpKind::ColumnCollapse).size() == 2 * 16);
  CHECK(errorOf([&] { candidates(cx, OpKind::SheetInsert); }) ==
        "candidates: sheet-insert steps are not enumerated; they take a surface or set you choose (sheet-extract prints the "
        "one that undoes it)");
}

// Each sheet operation reserves its journal once for the edits it will make (Transaction's
// reservation), instead of doubling it from a few dozen entries: at 100³ the doubling cost a
// sheet extraction 2,600 page faults, most of its time (bench/README.md). Without the reservation
// the capacities here are powers of two times 64: 1.7-1.9 times the sizes, 1.29 for the dicing.
TEST_CASE("sheet operations reserve their journal once: its capacity is within a quarter of its edits") {
  const int n = 20, c = n / 2;
  Complex cx = makeGrid(n, n, n);
  const std::string mid = std::to_string(c + n * (c + n * c));
  OpResult extracted = applyStep(cx, "sheet-extract h" + mid + "e0");
  const std::string insert = formatOpStep(*extracted.inverse);
  auto check = [](const OpResult& r, size_t edits) {
    CHECK(r.edits.edits.size() == edits);
    CHECK(r.edits.edits.capacity() >= edits);
    CHECK(r.edits.edits.capacity() <= edits + edits / 4);
  };
  check(extracted, 4401);
  const OpResult inserted = applyStep(cx, insert);
  check(inserted, 4401);
  cx.undo(inserted.edits);
  cx.undo(extracted.edits);
  const std::pair<std::string, size_t> steps[] = {
      {"sheet-dice h" + mid + "e0 5", 12724}, {"column-collapse h" + mid + "e0", 300}};
  for (const auto& [step, edits] : steps) {
    CAPTURE(step);
    const OpResult r = applyStep(cx, step);
    check(r, edits);
    cx.undo(r.edits);
  }
}
