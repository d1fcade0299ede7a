// Canonical form of a complex up to isomorphism: relabel hexes by a breadth-first traversal from a
// start flag (hex + one of the cube's 48 frames), recording each hex's vertices and, per face,
// its neighbour and the relative frame across the gluing.
// With a fixed boundary (the default) the isomorphism must keep every boundary vertex id, hence
// every boundary quad: the start flag is read off the smallest boundary quad. A complex without
// boundary (or fixedBoundary = false: any isomorphism, vertex ids free) starts from the hexes of
// the smallest class of a colour refinement (boundary faces, then the neighbours' classes), in
// the frames that read their neighbours' classes smallest: a handful of flags on most meshes,
// every hex (quadratic) only when all hexes look alike.
// Assumes a connected complex.
#pragma once
#include <cstdint>
#include <vector>

#include "complex/complex.hpp"

namespace hexdual {

std::vector<int64_t> canonicalForm(const Complex& cx, bool fixedBoundary = true);
// 64-bit FNV-1a hash of the canonical form.
uint64_t canonicalHash(const Complex& cx, bool fixedBoundary = true);
bool isomorphic(const Complex& a, const Complex& b, bool fixedBoundary = true);
// Whether a and b are isomorphic by a map sending hex ha of a to hex hb of b, local corner to the
// same local corner (vertex ids free): one traversal each, linear. For a complex compared with
// itself after steps that renumber boundary vertices (the sheet operations) around a hex they
// left in place.
bool isomorphicAt(const Complex& a, HexId ha, const Complex& b, HexId hb);

// The labelling behind the canonical form: hexes in canonical order, and for each a frame mapping
// canonical bit-corners (x + 2y + 4z) to its actual local corners. Two isomorphic complexes have
// labellings that line up: hex order[i] of one corresponds to order[i] of the other, corner by corner.
struct CanonicalLabelling {
  std::vector<int64_t> form;
  std::vector<HexId> order;
  std::vector<std::array<int8_t, 8>> frame;  // per order index: canonical bit-corner -> local corner
};
// Where a free form starts: from the refined start flags (canonicalForm, canonicalHash and
// isomorphic use these), or from all 48 frames of every hex (quadratic). Both are canonical, but
// for a complex with symmetries they can pick different labellings: the flip replay
// (flips/search_replay.cpp) matches a stored region with a host's by the labelling of every start,
// which its stored decompositions were replayed and verified with.
enum class FreeStarts { Refined, Every };
CanonicalLabelling canonicalLabelling(const Complex& cx, bool fixedBoundary = true, FreeStarts starts = FreeStarts::Refined);

}  // namespace hexdual
