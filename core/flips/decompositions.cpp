#include "flips/decompositions.hpp"

#include <cstdio>
#include <string_view>

#include "ops/op_table.hpp"
#include "ops/oplog.hpp"

namespace hexdual {

extern const char* const kDecompositionsText;  // generated from core/flips/decompositions.txt

// Splits on one character, keeping empty fields between separators (not after a final one,
// like std::getline). Plain string_view splitting keeps iostreams and locales out of the wasm.
static std::vector<std::string> splitOn(std::string_view s, char sep) {
  std::vector<std::string> out;
  while (!s.empty()) {
    const size_t at = s.find(sep);
    out.emplace_back(s.substr(0, at));
    if (at == std::string_view::npos) break;
    s.remove_prefix(at + 1);
  }
  return out;
}

std::vector<StoredDecomposition> parseDecompositions(const std::string& text) {
  std::vector<StoredDecomposition> out;
  int lineNo = 0;
  bool versionSeen = false;
  for (const std::string& line : splitOn(text, '\n')) {
    ++lineNo;
    if (line.empty() || line[0] == '#') {
      if (line.rfind("# format v1", 0) == 0) versionSeen = true;
      continue;
    }
    const std::vector<std::string> f = splitOn(line, '|');
    auto bad = [&](const std::string& why) { return Error("decompositions:" + std::to_string(lineNo) + ": " + why); };
    if (!versionSeen) throw bad("missing '# format v1' header");
    if (f.size() != 8) throw bad("expected 8 fields separated by '|', found " + std::to_string(f.size()));
    StoredDecomposition d;
    d.problem = f[0];
    if (f[1] != "found" && f[1] != "none") throw bad("second field must be 'found' or 'none'");
    d.found = f[1] == "found";
    if (d.found) {
      for (OpStep& s : parseOpLog(f[2]).steps) {
        s.position = 0;
        d.steps.push_back(s);
      }
    }
    d.maxDepth = std::stoi(f[3]);
    d.depthSearched = std::stoi(f[4]);
    d.states = std::stoll(f[5]);
    d.seconds = std::stod(f[6]);
    d.ops = f[7];
    out.push_back(d);
  }
  return out;
}

const std::vector<StoredDecomposition>& storedDecompositions() {
  static const std::vector<StoredDecomposition> d = parseDecompositions(kDecompositionsText);
  return d;
}

std::string formatDecomposition(const std::string& problem, const SearchResult& r, const SearchOptions& o) {
  const std::string steps = formatOpLog({1, r.steps});
  std::string ops = "all";
  if (!o.ops.empty()) {
    ops.clear();
    for (OpKind k : o.ops) ops += (ops.empty() ? "" : ",") + std::string(opName(k));
  }
  char secs[32];
  std::snprintf(secs, sizeof secs, "%.2f", r.seconds);
  return problem + "|" + (r.found ? "found" : "none") + "|" + (r.found ? steps : "-") + "|" + std::to_string(o.maxDepth) + "|" +
         std::to_string(r.depthSearched) + "|" + std::to_string(r.statesExplored) + "|" + secs + "|" + ops;
}

const StoredDecomposition* storedFor(const std::string& problem) {
  for (const auto& d : storedDecompositions())
    if (d.problem == problem) return &d;
  return nullptr;
}

std::vector<FlipSummary> flipSummaries() {
  std::vector<FlipSummary> out;
  for (FlipClass& fc : enumerateFlipClasses()) {
    const StoredDecomposition* d = storedFor(fc.name);
    out.push_back({std::move(fc), d});
  }
  return out;
}

SearchProblem problemFor(const std::string& name) {
  if (name == "tripleChordPush") return tripleChordPushProblem();
  std::string flipName = name.substr(0, name.find('/'));
  SearchProblem p = flipProblem(flipName);
  return p;
}

}  // namespace hexdual
