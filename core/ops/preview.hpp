// What a step would do, without doing it: the preview a user reads before applying a sheet
// operation (or any other step). The step runs on copies of the complex and of its dual tracker,
// so the ids it reports are those applying it would assign, and the mesh is untouched.
#pragma once
#include <string>

#include "dual/dual_tracker.hpp"
#include "ops/report.hpp"

namespace hexdual {

struct Preview {
  bool applies = false;
  std::string rule;   // when refused: the rule named (sheet operations; "" for other refusals)
  std::string error;  // when refused: the message applying would throw
  StepReport report;  // when it applies: hexes and vertices created and removed, Δ, sheets and chords
};

// Costs a copy of the complex and of the tracker (linear in the mesh) and the step itself; `options`
// as applying would use them (the smoothing changes the report's quality).
Preview previewStep(const Complex& cx, const DualTracker& tracker, const OpStep& step, const StepOptions& options = {});

}  // namespace hexdual
