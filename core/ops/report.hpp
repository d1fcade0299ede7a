// What an applied step did: the facts `hexdual apply` prints and the wasm module returns
// (io/json.hpp writes them as JSON and text).
#pragma once
#include "dual/dual_tracker.hpp"
#include "ops/op_step.hpp"
#include "ops/oplog.hpp"
#include "ops/ops.hpp"

namespace hexdual {

struct StepReport {
  OpStep step;
  OpResult result;  // hexes and vertices created and removed, (dV,dE,dF,dH), inverse or why none, edits
  DualChange dual;  // sheets and chords created, removed and changed (ids of the tracker)
};

// Applies `step` to cx and brings `tracker` (which follows cx) up to date. Throws as applyStep
// does; the complex and the tracker are then unchanged.
StepReport applyStepTracked(Complex& cx, DualTracker& tracker, const OpStep& step, const StepOptions& options = {});

}  // namespace hexdual
