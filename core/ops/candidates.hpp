// Which entities an operation can be applied to, as operation-log steps. Each candidate is
// tried on a private copy and undone exactly, so the list holds only steps that succeed.
#pragma once
#include <vector>

#include "complex/complex.hpp"
#include "ops/op_step.hpp"

namespace hexdual {

// The steps of `op` that apply to cx. Throws Error for an operation that is not enumerated
// (ringsplit: ringcollapse reports it as its inverse).
std::vector<OpStep> candidates(const Complex& cx, OpKind op);

}  // namespace hexdual
