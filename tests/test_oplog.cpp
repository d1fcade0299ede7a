#include <doctest/doctest.h>

#include "complex/builders.hpp"
#include "complex/canonical.hpp"
#include "helpers.hpp"
#include "ops/op_table.hpp"
#include "ops/oplog.hpp"

using namespace hexdual;
using namespace hexdual::test;

TEST_CASE("op log: parse and format round trip exactly; the h12.f3 spelling is accepted") {
  const std::string text =
      "v1;pillow h12f3;unpillow h27;chordpush h4e7 h4f2 h9f0;chordpull h30;hexpush h5f1;hexpull h40f5;"
      "ringcollapse h3e4;ringsplit h1f2/h3f4 h5f0/h6f1;facecollapse h21e11 h21f1 h25f1;facesplit h1f1 h2f0";
  OpLog log = parseOpLog(text);
  CHECK(log.steps.size() == 10);
  CHECK(formatOpLog(log) == text);
  CHECK(formatOpLog(parseOpLog("v1;pillow h12.f3")) == "v1;pillow h12f3");
  CHECK(formatOpLog(parseOpLog("v1")) == "v1");
  // The URL form is URL-safe and decodes to the same log.
  std::string url = encodeOpLogUrl(log);
  CHECK(url == "1.P12f3.Q27.C4e7_4f2_9f0.D30.H5f1.I40f5.R3e4.S1f2~3f4_5f0~6f1.F21e11_21f1_25f1.G1f1_2f0");
  CHECK(formatOpLog(decodeOpLogUrl(url)) == text);
}

TEST_CASE("op log: parse errors name the position and the token") {
  CHECK(errorOf([] { parseOpLog("v2;pillow h1f1"); }) == "oplog: position 0: a log starts with its version 'v1' at 'v2'");
  CHECK(errorOf([] { parseOpLog("v1;pilow h1f1"); }) == "oplog: position 3: unknown operation at 'pilow'");
  CHECK(errorOf([] { parseOpLog("v1;pillow h1e1"); }) == "oplog: position 10: expected a quad (h12f3) at 'h1e1'");
  CHECK(errorOf([] { parseOpLog("v1;hexpush h1f1;pillow"); }) ==
        "oplog: position 16: pillow takes 1 argument(s), not 0 at 'pillow'");
  CHECK(errorOf([] { parseOpLog("v1;pillow  h1f1"); }) == "oplog: position 9: stray space at 'pillow  h1f1'");
  CHECK(errorOf([] { parseOpLog("v1;chordpush h1e1 h1f1 hxf2"); }) == "oplog: position 23: expected a quad (h12f3) at 'hxf2'");
  CHECK(errorOf([] { parseOpLog("v1;;pillow h1f1"); }) == "oplog: position 3: empty step at ''");
  CHECK(errorOf([] { decodeOpLogUrl("1.P1f1%20"); }) == "oplog: position 6: character not allowed in a URL-encoded log at '%'");
  CHECK(errorOf([] { decodeOpLogUrl("1.Z1"); }) == "oplog: position 2: unknown operation code at 'Z'");
}

TEST_CASE("apply: all steps, or stop at step k with the complex as after k-1") {
  Complex cx = makeGrid(3, 3, 3);
  ApplyReport ok = applyLog(cx, "v1;pillow h13f5;hexpush h13f5");
  CHECK(ok.failedStep == 0);
  CHECK(ok.results.size() == 2);
  CHECK(cx.numHexes() == 33);
  Complex before = cx;
  std::string dumpAfterStep1;
  Complex probe = cx;
  applyStep(probe, "pillow h0f1");
  dumpAfterStep1 = stateDump(probe);
  ApplyReport bad = applyLog(cx, "v1;pillow h0f1;hexpush h0f0;pillow h1f1");
  CHECK(bad.failedStep == 2);
  CHECK(bad.error == "hexpush: quad h0f0 is on the boundary; hex push needs an interior quad");
  CHECK(bad.results.size() == 1);
  CHECK(stateDump(cx) == dumpAfterStep1);
  ApplyReport parse = applyLog(cx, "v1;pillow h0");
  CHECK(parse.failedStep == -1);
  CHECK(parse.error == "oplog: position 10: expected a quad (h12f3) at 'h0'");
}

TEST_CASE("replaying a log is deterministic: same ids, same canonical hash, every time") {
  const std::string log = "v1;pillow h13f5;hexpush h13f5;chordpush h21e11 h21f1 h25f1";
  uint64_t hash = 0;
  std::string dump;
  for (int run = 0; run < 3; ++run) {
    Complex cx = makeGrid(4, 4, 4);
    ApplyReport r = applyLog(cx, log);
    REQUIRE(r.failedStep == 0);
    if (run == 0) {
      hash = canonicalHash(cx);
      dump = stateDump(cx);
    }
    CHECK(canonicalHash(cx) == hash);
    CHECK(stateDump(cx) == dump);
  }
  // Undo in reverse order restores the grid exactly, ids and revision included.
  Complex cx = makeGrid(4, 4, 4);
  std::string grid = stateDump(cx);
  ApplyReport r = applyLog(cx, log);
  CHECK(errorOf([&] { cx.undo(r.results[0].edits); }) ==
        "undo: the complex has changed since that operation; undo the later ones first");
  for (auto it = r.results.rbegin(); it != r.results.rend(); ++it) cx.undo(it->edits);
  CHECK(stateDump(cx) == grid);
}

TEST_CASE("op table: one row per operation; typed steps with a wrong argument count or kind are errors, not UB") {
  // The table is in OpKind order and every name and URL letter maps back to its row.
  for (size_t k = 0; k < allOps().size(); ++k) {
    const OpInfo& op = allOps()[k];
    CHECK(op.kind == OpKind(k));
    CHECK(findOp(op.name) == &op);
    CHECK(findOpByUrlCode(op.urlCode) == &op);
  }
  CHECK(allOps().size() == 15);  // 10 atomic operations and inverses, 5 sheet operations (test_sheet_family.cpp)
  Complex cx = makeGrid(3, 3, 3);
  const std::string grid = stateDump(cx);
  CHECK(errorOf([&] { applyStep(cx, OpStep{OpKind::Pillow, {}}); }) == "pillow: takes 1 argument(s), not 0");
  CHECK(errorOf([&] { applyStep(cx, makeStep(OpKind::ChordPush, EdgeRef{13, 11}, QuadSide{13, 1})); }) ==
        "chordpush: takes 3 argument(s), not 2");
  CHECK(errorOf([&] { applyStep(cx, makeStep(OpKind::Unpillow, QuadSide{13, 1})); }) ==
        "unpillow: argument 1 must be a hex (h12), not 'h13f1'");
  CHECK(errorOf([&] { applyStep(cx, OpStep{OpKind::RingSplit, {}}); }) == "ringsplit: takes one or more argument(s), not 0");
  CHECK(errorOf([&] { applyStep(cx, makeStep(OpKind::RingSplit, QuadSide{13, 1})); }) ==
        "ringsplit: argument 1 must be a quad pair (h1f2/h3f4), not 'h13f1'");
  CHECK(errorOf([&] { applyStep(cx, OpStep{OpKind(200), {}}); }) == "oplog: unknown operation (kind 200)");
  CHECK(stateDump(cx) == grid);
  // An unknown operation in a typed log is an error in the URL encoder too.
  CHECK(errorOf([] { encodeOpLogUrl({1, {OpStep{OpKind(99), {}}}}); }) == "oplog: unknown operation (kind 99)");
  // Typed steps format with the one entity spelling.
  CHECK(formatOpStep(makeStep(OpKind::ChordPush, EdgeRef{4, 7}, QuadSide{4, 2}, QuadSide{9, 0})) == "chordpush h4e7 h4f2 h9f0");
  CHECK(parseOpStep("ringsplit h1f2/h3f4") == OpStep{OpKind::RingSplit, {OpArg::of(QuadSide{1, 2}, QuadSide{3, 4})}});
}
