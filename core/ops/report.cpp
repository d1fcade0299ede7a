#include "ops/report.hpp"

#include "ops/op_table.hpp"
#include "ops/oplog.hpp"

namespace hexdual {

StepReport applyStepTracked(Complex& cx, DualTracker& tracker, const OpStep& step, const StepOptions& options) {
  StepReport rep;
  rep.step = step;
  rep.result = applyStep(cx, step, options);
  rep.dual = tracker.update(cx, rep.result.edits, keepsSheetTopology(rep.result));
  return rep;
}

}  // namespace hexdual
