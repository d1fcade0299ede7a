// Previews on copies: nothing the caller holds changes, whatever the step does (preview.hpp).
#include "ops/preview.hpp"

#include "ops/sheet_ops.hpp"

namespace hexdual {

Preview previewStep(const Complex& cx, const DualTracker& tracker, const OpStep& step, const StepOptions& options) {
  Preview p;
  Complex work = cx;
  DualTracker dual = tracker;
  try {
    p.report = applyStepTracked(work, dual, step, options);
    p.applies = true;
  } catch (const Error& e) {
    p.error = e.what();
    p.rule = ruleOf(p.error);
  }
  return p;
}

}  // namespace hexdual
