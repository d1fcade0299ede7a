// Ring splits through an edge (TK03 §4.4, the inverse of a ring collapse), for pickers: the
// operation's candidates are not enumerated by candidates() (a split needs a whole loop of
// edges and two strips of quads along it), so this walks the loops through one picked edge.
#pragma once
#include <vector>

#include "complex/complex.hpp"
#include "ops/op_step.hpp"

namespace hexdual {

// The ring splits whose loop passes through edge `e`, loops of at most `maxEdges` edges, each
// one that applies to cx (tried on a copy and undone). Steps are written as the decomposition
// search writes them (the loop started at its smallest canonical edge, walked from that edge's
// smaller vertex, the strips ordered by that edge's star), so a stored decomposition's ring
// split appears here verbatim. Throws Error when e is not an edge of a live hex.
std::vector<OpStep> ringSplitsThrough(const Complex& cx, EdgeRef e, int maxEdges = 8);

}  // namespace hexdual
