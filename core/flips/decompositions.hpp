// The stored results of the decomposition search (core/flips/decompositions.txt, compiled in).
#pragma once
#include <string>
#include <vector>

#include "flips/fourcube.hpp"
#include "flips/search.hpp"

namespace hexdual {

struct StoredDecomposition {
  std::string problem;             // a flip name, "tripleChordPush", or "2-6/chord-only"
  bool found = false;
  std::vector<OpStep> steps;       // steps in the problem's complex (flipProblem / tripleChordPushProblem)
  int maxDepth = 0, depthSearched = 0;
  int64_t states = 0;
  double seconds = 0;
  std::string ops;  // "all" or the op names the search used
};

// Parses the text of a decompositions file (format v1, documented in it). Throws Error with the line.
std::vector<StoredDecomposition> parseDecompositions(const std::string& text);
// The decompositions compiled into this build.
const std::vector<StoredDecomposition>& storedDecompositions();
// One record line for a search result.
std::string formatDecomposition(const std::string& problem, const SearchResult& r, const SearchOptions& o);
// The search problem behind a stored record's name.
SearchProblem problemFor(const std::string& name);
// The stored record for a problem name, or nullptr.
const StoredDecomposition* storedFor(const std::string& problem);

// One flip class with its stored decomposition: the flips list of `hexdual flip list` and the
// wasm module (io/json.hpp writes it).
struct FlipSummary {
  FlipClass flip;
  const StoredDecomposition* decomposition = nullptr;  // nullptr when the flip was not searched
};
std::vector<FlipSummary> flipSummaries();

}  // namespace hexdual
