// The correctness checks of a sheet diagram, in time near-linear in its size.
#pragma once
#include <cstddef>

#include "layout/diagram.hpp"

namespace hexdual {

// Every slot appears exactly once; every crossing joins exactly two chord passes; chords meet
// only at crossings; interior crossings lie inside the outer loop (and outside the inner one);
// a fundamental polygon's sides close up into its outer loop and each seam is drawn on exactly
// two sides with matching labels. Throws Error naming the first violation.
void checkDiagram(const SheetDiagram& d, size_t expectedSlots);

}  // namespace hexdual
