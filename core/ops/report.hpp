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
// With `memo`, also keeps what undoStepTracked needs to give the dual its ids back.
StepReport applyStepTracked(Complex& cx, DualTracker& tracker, const OpStep& step, const StepOptions& options = {},
                            DualIdMemo* memo = nullptr);

// Undoes the step `rep` reports, applied last (LIFO), with the memo kept when it was applied: the
// complex and the dual are exactly as before it, sheet and chord ids (and id ranges) included, so
// the ids that follow are those a replay of the log without the step gives.
void undoStepTracked(Complex& cx, DualTracker& tracker, const StepReport& rep, const DualIdMemo& memo);

}  // namespace hexdual
