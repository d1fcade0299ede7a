// Previews and selections (core/ops/preview.hpp, core/ops/selection.hpp) and the CLI commands over
// them (hexdual preview, select, apply --dry-run): what a step would change, or its refusal with the
// rule, without changing the mesh or its dual; the sheet through an edge, the chord through a quad.
#include "sheet_helpers.hpp"

#include "complex/builders.hpp"
#include "io/json.hpp"
#include "io/preview_json.hpp"
#include "ops/preview.hpp"
#include "ops/selection.hpp"

using namespace hexdual;
using namespace hexdual::test;

TEST_CASE("preview: what the step would do, the same as applying it, and nothing changed") {
  Complex cx = makeGrid(3, 3, 3);
  DualTracker tracker(cx);
  applyStepTracked(cx, tracker, parseOpStep("pillow h13f5"));  // the tracker has ids an extraction would not give
  const std::string dump = stateDump(cx);
  const Dual dual = tracker.dual();
  for (std::string text : {"sheet-extract h0e0", "sheet-dice h4e0 3", "sheet-pillow h0", "column-collapse h4e0", "hexpush h4f1"}) {
    CAPTURE(text);
    const OpStep step = parseOpStep(text);
    const Preview p = previewStep(cx, tracker, step);
    REQUIRE(p.applies);
    CHECK(stateDump(cx) == dump);
    compareDuals(cx, tracker.dual(), dual);
    CHECK(tracker.dual().sheetLabel == dual.sheetLabel);
    // Applying it gives the same report: ids, Δ, sheets and chords.
    Complex copy = cx;
    DualTracker t2 = tracker;
    const StepReport r = applyStepTracked(copy, t2, step);
    CHECK(io::stepReportJson(p.report, 1) == io::stepReportJson(r, 1));
  }
  const Preview refused = previewStep(cx, tracker, parseOpStep("sheet-extract h27e0"));
  CHECK_FALSE(refused.applies);
  CHECK(refused.rule == "no-sides");
  CHECK(refused.error == "sheet-extract: no-sides: the chord through hex 27 is closed and lies in the sheet; nothing is on either side of it");
  const Preview atomic = previewStep(cx, tracker, parseOpStep("hexpush h0f0"));
  CHECK_FALSE(atomic.applies);
  CHECK(atomic.rule.empty());
  CHECK(io::previewJson(atomic, parseOpStep("hexpush h0f0")) ==
        "{\"applies\":false,\"family\":\"atomic\",\"text\":\"hexpush h0f0\",\"rule\":null,\"error\":\"hexpush: quad h0f0 is on the "
        "boundary; hex push needs an interior quad\"}");
  CHECK(stateDump(cx) == dump);
}

TEST_CASE("select: the sheet through an edge, the chord through a quad, and the steps that act on them") {
  Complex cx = makeGrid(3, 3, 3);
  const Dual d = extractDual(cx);
  const Selection s = selectSheet(cx, d, {13, 0});
  CHECK(s.id == d.sheetAt(13, 0));
  CHECK(s.hexes == std::vector<HexId>{1, 4, 7, 10, 13, 16, 19, 22, 25});
  CHECK(s.topology == "disk");
  CHECK(s.steps == std::vector<std::string>{"sheet-extract h13e0", "sheet-dice h13e0 2"});
  const Selection c = selectChord(cx, d, {13, 1});
  CHECK(c.id == d.chordAt(13, 0));
  CHECK(c.hexes == std::vector<HexId>{12, 13, 14});
  CHECK(c.steps == std::vector<std::string>{"column-collapse h13e0", "column-collapse h13e1"});
  CHECK(io::selectionJson(c) ==
        "{\"kind\":\"chord\",\"id\":" + std::to_string(c.id) +
            ",\"through\":\"h13f1\",\"closed\":false,\"selfIntersecting\":false,\"hexes\":[12,13,14],\"steps\":[\"column-collapse "
            "h13e0\",\"column-collapse h13e1\"]}");
  CHECK(errorOf([&] { selectSheet(cx, d, {27, 0}); }) == "select: hex 27 does not exist");
  CHECK(errorOf([&] { selectChord(cx, d, {0, 6}); }) == "select: local face 6 is not 0..5");
}

TEST_CASE("cli: select, preview (exit 1 when refused, with the rule), apply --dry-run writes nothing") {
  REQUIRE(runCli("grid 3x3x3 -o /tmp/hexdual_cli_sheetops.hxd").status == 0);
  CliRun sel = runCli("select /tmp/hexdual_cli_sheetops.hxd h13e0");
  CHECK(sel.status == 0);
  CHECK(sel.out == "sheet 3 (disk, 9 hexes) through h13e0: hexes [1,4,7,10,13,16,19,22,25]\n  steps: sheet-extract h13e0, sheet-dice h13e0 2\n");
  CHECK(runCli("select /tmp/hexdual_cli_sheetops.hxd h13x0").out == "hexdual: select takes an edge (h12e3) or a quad (h12f5), not 'h13x0'\n");
  CliRun ok = runCli("preview /tmp/hexdual_cli_sheetops.hxd --ops 'v1;sheet-extract h13e0' --json");
  CHECK(ok.status == 0);
  CHECK(contains(ok.out, "{\"applies\":true,\"family\":\"sheet\",\"text\":\"sheet-extract h13e0\",\"hexesRemoved\":9,\"hexesCreated\":0,"));
  CHECK(contains(ok.out, "\"delta\":{\"V\":-16,\"E\":-40,\"F\":-33,\"H\":-9}"));
  CliRun refused = runCli("preview /tmp/hexdual_cli_sheetops.hxd --ops '1.F1e3_1f3_13f2.x0e0'");
  CHECK(refused.status == 1);
  CHECK(refused.out == "preview: sheet-extract h0e0 would be refused (rule self-touching): sheet-extract: self-touching: the sheet "
                       "touches itself at vertex 5: its edges to 4 and to 36 would merge three vertices into one\n");
  std::remove("/tmp/hexdual_cli_sheetops_out.hxd");
  CliRun dry = runCli("apply /tmp/hexdual_cli_sheetops.hxd --ops 'v1;sheet-dice h13e0 2' --dry-run");
  CHECK(dry.status == 0);
  CHECK(contains(dry.out, "step 1: sheet-dice h13e0 2\n  hexes created [27,28,29,30,31,32,33,34,35] removed []"));
  CHECK(runCli("apply /tmp/hexdual_cli_sheetops.hxd --ops 'v1;sheet-dice h13e0 2'").out == "hexdual: apply needs -o OUT (or --dry-run)\n");
  CliRun real = runCli("apply /tmp/hexdual_cli_sheetops.hxd --ops 'v1;sheet-dice h13e0 2' -o /tmp/hexdual_cli_sheetops_out.hxd");
  CHECK(real.status == 0);
  CHECK(contains(runCli("info /tmp/hexdual_cli_sheetops_out.hxd").out, "hexes 36"));
}
