// JSON and text of previews and selections (preview_json.hpp).
#include "io/preview_json.hpp"

#include "io/json.hpp"
#include "ops/op_table.hpp"
#include "ops/oplog.hpp"

namespace hexdual::io {

namespace {
const char* familyOf(const OpStep& step) { return isSheetOp(step.op) ? "sheet" : "atomic"; }
}  // namespace

std::string previewJson(const Preview& p, const OpStep& step) {
  JsonWriter w;
  w.beginObject().key("applies").value(p.applies).key("family").value(familyOf(step)).key("text").value(formatOpStep(step));
  if (p.applies) {
    w.key("hexesRemoved").value(int64_t(p.report.result.removedHexes.size()));
    w.key("hexesCreated").value(int64_t(p.report.result.createdHexes.size()));
    w.key("report");
    writeStepReport(w, p.report, 1);
  } else {
    w.key("rule");
    if (p.rule.empty()) w.raw("null");
    else w.value(p.rule);
    w.key("error").value(p.error);
  }
  w.endObject();
  return w.str();
}

// A step as the first line of a preview names it: its first 8 arguments, then how many more.
static std::string stepHeadline(const OpStep& step) {
  if (step.args.size() <= 8) return formatOpStep(step);
  OpStep head = step;
  head.args.resize(8);
  return formatOpStep(head) + " ... (" + std::to_string(step.args.size()) + " arguments)";
}

std::string previewText(const Preview& p, const OpStep& step) {
  if (!p.applies)
    return "preview: " + stepHeadline(step) + " would be refused" + (p.rule.empty() ? "" : " (rule " + p.rule + ")") + ": " +
           p.error + "\n";
  const OpResult& r = p.report.result;
  return "preview: " + stepHeadline(step) + " would remove " + std::to_string(r.removedHexes.size()) + " hexes and create " +
         std::to_string(r.createdHexes.size()) + "; nothing was changed\n" + stepReportText(p.report, 1);
}

std::string selectionJson(const Selection& s) {
  JsonWriter w;
  w.beginObject().key("kind").value(s.sheet ? "sheet" : "chord").key("id").value(int64_t(s.id)).key("through").value(s.through);
  if (s.sheet) w.key("topology").value(s.topology).key("boundaryLoops").value(int64_t(s.boundaryLoops));
  else w.key("closed").value(s.closed);
  w.key("selfIntersecting").value(s.selfIntersecting).key("hexes").raw(idList(s.hexes)).key("steps").beginArray();
  for (const std::string& st : s.steps) w.value(st);
  w.endArray().endObject();
  return w.str();
}

std::string selectionText(const Selection& s) {
  std::string what = s.sheet ? "sheet " + std::to_string(s.id) + " (" + s.topology + ", " + std::to_string(s.hexes.size()) + " hexes)"
                             : "chord " + std::to_string(s.id) + " (" + (s.closed ? "closed" : "open") + ", " +
                                   std::to_string(s.hexes.size()) + " hexes)";
  std::string text = what + " through " + s.through + ": hexes " + idList(s.hexes) + "\n  steps:";
  for (size_t k = 0; k < s.steps.size(); ++k) text += (k ? ", " : " ") + s.steps[k];
  return text + "\n";
}

}  // namespace hexdual::io
