// The operation log: a versioned text form of a sequence of operations, e.g.
//   v1;pillow h12f3;chordpush h4e7 h4f2 h9f0;hexpush h5f1
// and a compact URL-safe form of the same log. Grammar and id assignment: docs/oplog.md.
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "complex/complex.hpp"
#include "geometry/step_geometry.hpp"
#include "ops/op_step.hpp"
#include "ops/ops.hpp"

namespace hexdual {

struct OpLog {
  int version = 1;
  std::vector<OpStep> steps;
};

// Parses strictly; throws Error "oplog: position P: <reason> at 'TOKEN'".
OpLog parseOpLog(std::string_view text);
OpStep parseOpStep(std::string_view text, size_t offset = 0);
std::string formatOpLog(const OpLog& log);
std::string formatOpStep(const OpStep& step);

// URL-safe compact form ("1.P12f3.H5f1"): digits, letters, '.', '_' and '~' only.
std::string encodeOpLogUrl(const OpLog& log);
OpLog decodeOpLogUrl(std::string_view text);

// How applyStep treats geometry (geometry/step_geometry.hpp). The default, Keep, is the operation
// alone: new vertices stay at its fixed offsets and nothing is measured, for callers that only
// need topology (the flip search, `candidates`, property tests). The CLI and the package pass
// Smooth (the local untangling and smoothing; its moves join the step's edit log, so undo stays
// exact) or, with --no-smooth / mesh.smoothing = false, Measure; OpResult::quality holds the
// measurement.
struct StepOptions {
  StepGeometry geometry = StepGeometry::Keep;
};
inline constexpr StepOptions kSmoothStep{StepGeometry::Smooth};

// Applies one step (text or parsed). Throws as the operation does; the complex is then unchanged.
// A parsed step with the wrong number or kinds of arguments is rejected before anything runs.
OpResult applyStep(Complex& cx, const OpStep& step, const StepOptions& options = {});
OpResult applyStep(Complex& cx, std::string_view stepText, const StepOptions& options = {});
// The same without throwing: the result, or nullopt with `why` set to the message applyStep would
// throw (the complex unchanged). Rejections by an operation's first checks (the table's
// precheck) cost no exception: for callers that try many steps, most of them rejected.
std::optional<OpResult> tryApplyStep(Complex& cx, const OpStep& step, std::string* why = nullptr, const StepOptions& options = {});
// The message applying `step` would throw for its operation's first checks (the operation table's
// precheck), or empty: a rejection found without an exception. Empty says nothing about later checks.
std::string precheckStep(const Complex& cx, const OpStep& step);
std::optional<OpResult> tryApplyStep(Complex& cx, std::string_view stepText, std::string* why = nullptr,
                                     const StepOptions& options = {});

struct ApplyReport {
  std::vector<OpResult> results;  // one per applied step
  int failedStep = 0;             // 1-based index of the step that failed, 0 when all applied
  std::string error;
};
// Applies every step in order. On an error at step k it stops: the complex is as after step k-1,
// and the report names k and the reason. (A free function: core/complex does not depend on ops.)
ApplyReport applyLog(Complex& cx, const OpLog& log, const StepOptions& options = {});
ApplyReport applyLog(Complex& cx, std::string_view logText, const StepOptions& options = {});

}  // namespace hexdual
