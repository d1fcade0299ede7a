#include "ops/report.hpp"

#include "ops/op_table.hpp"
#include "ops/oplog.hpp"

namespace hexdual {

StepReport applyStepTracked(Complex& cx, DualTracker& tracker, const OpStep& step, const StepOptions& options,
                            DualIdMemo* memo) {
  StepReport rep;
  rep.step = step;
  rep.result = applyStep(cx, step, options);
  if (memo) {
    *memo = tracker.idMemo(cx, rep.result.edits);  // the tracker still holds the dual before the step
    rep.dual = tracker.update(cx, rep.result.edits, keepsSheetTopology(rep.result), *memo);
  } else {
    rep.dual = tracker.update(cx, rep.result.edits, keepsSheetTopology(rep.result));
  }
  return rep;
}

void undoStepTracked(Complex& cx, DualTracker& tracker, const StepReport& rep, const DualIdMemo& memo) {
  cx.undo(rep.result.edits);
  tracker.updateUndone(cx, rep.result.edits, keepsSheetTopology(rep.result), memo);
  tracker.restoreIds(memo);
}

}  // namespace hexdual
