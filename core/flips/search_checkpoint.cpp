// Checkpoints of the search (SearchOptions::checkpointFile, resumeFile): the two sides' nodes,
// counts and hash tables, the statistics and where the level in progress goes on, in a binary
// format (v1) whose first lines name it and the search it belongs to.
#include "flips/search_parts.hpp"

#include <cstdio>
#include <fstream>

#include "ops/op_table.hpp"

namespace hexdual::flipsearch {
using namespace tables;

std::string searchFingerprint(const SearchProblem& pb, const SearchOptions& o) {
  std::string f = pb.name + "; depth " + std::to_string(o.maxDepth) + "; ops";
  for (OpKind k : o.ops) f += " " + std::string(opName(k));
  f += "; region " + std::to_string(o.maxRegionHexes) + "; ring split " + std::to_string(o.ringSplitMax) +
       "; symmetry " + std::to_string(o.symmetry) + "; prefilter " + std::to_string(o.prefilter) + "; count pruning " +
       std::to_string(o.countPruning) + "; chunk " + std::to_string(o.chunk) +
       (o.lookupLastLevel ? "; last level by lookup" : "") + (o.reversible ? "; reversible" : "");
  return f;
}

template <class T>
void put(std::ostream& out, const T& v) {
  out.write(reinterpret_cast<const char*>(&v), sizeof v);
}
template <class T>
void putVector(std::ostream& out, const std::vector<T>& v) {
  put(out, uint64_t(v.size()));
  out.write(reinterpret_cast<const char*>(v.data()), std::streamsize(v.size() * sizeof(T)));
}
template <class T>
void get(std::istream& in, T& v) {
  in.read(reinterpret_cast<char*>(&v), sizeof v);
  if (!in) throw Error("checkpoint: the file is cut short");
}
template <class T>
void getVector(std::istream& in, std::vector<T>& v) {
  uint64_t n = 0;
  get(in, n);
  if (n > (uint64_t(1) << 36)) throw Error("checkpoint: a list length is damaged");
  v.resize(size_t(n));
  in.read(reinterpret_cast<char*>(v.data()), std::streamsize(n * sizeof(T)));
  if (!in) throw Error("checkpoint: the file is cut short");
}

const char* const kCheckpointMagic = "hexdual search checkpoint v1";

// A completed level as format v1 stores it (40 bytes; a level by lookup is always the last one and
// never saved, so SearchLevel::lookedUp needs no field).
struct LevelRecord {
  int32_t side, depth;
  int64_t newStates, storedStates, movesApplied;
  double seconds;
};
static_assert(sizeof(LevelRecord) == 40, "the v1 checkpoint layout");

std::vector<LevelRecord> levelRecords(const std::vector<SearchLevel>& levels) {
  std::vector<LevelRecord> out;
  for (const SearchLevel& l : levels)
    out.push_back({l.side, l.depth, l.newStates, l.storedStates, l.movesApplied, l.seconds});
  return out;
}

void writeCheckpoint(const std::string& path, const std::string& fingerprint, const Side side[2],
                     const SearchResult& res, double seconds, const Resume& at) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw Error("checkpoint: cannot write " + tmp);
    out << kCheckpointMagic << "\n" << fingerprint << "\n";
    put(out, at);
    put(out, res.movesApplied);
    put(out, res.prunedByCounts);
    put(out, seconds);
    putVector(out, levelRecords(res.levels));
    for (int s = 0; s < 2; ++s) {
      const Side& d = side[s];
      put(out, int64_t(d.depth));
      put(out, uint64_t(d.levelBegin));
      put(out, uint64_t(d.levelEnd));
      putVector(out, d.parent);
      putVector(out, d.move);
      putVector(out, d.counts);
      d.index.write(out);
    }
    if (!out.flush()) throw Error("checkpoint: writing " + tmp + " failed");
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) throw Error("checkpoint: cannot rename " + tmp + " to " + path);
}

Resume readCheckpoint(const std::string& path, const std::string& fingerprint, Side side[2], SearchResult& res,
                      double& seconds) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("resume: cannot read " + path);
  std::string magic, fp;
  std::getline(in, magic);
  std::getline(in, fp);
  if (magic != kCheckpointMagic) throw Error("resume: " + path + " is not a search checkpoint");
  if (fp != fingerprint)
    throw Error("resume: " + path + " belongs to another search (" + fp + "), not this one (" + fingerprint + ")");
  Resume at;
  get(in, at);
  get(in, res.movesApplied);
  get(in, res.prunedByCounts);
  get(in, seconds);
  std::vector<LevelRecord> levels;
  getVector(in, levels);
  res.levels.clear();
  for (const LevelRecord& l : levels)
    res.levels.push_back({l.side, l.depth, l.newStates, l.storedStates, l.movesApplied, l.seconds, false});
  for (int s = 0; s < 2; ++s) {
    Side& d = side[s];
    int64_t depth = 0;
    uint64_t begin = 0, end = 0;
    get(in, depth);
    get(in, begin);
    get(in, end);
    getVector(in, d.parent);
    getVector(in, d.move);
    getVector(in, d.counts);
    d.index.read(in);
    d.depth = int(depth);
    d.levelBegin = size_t(begin);
    d.levelEnd = size_t(end);
    if (d.move.size() != d.parent.size() || d.counts.size() != d.parent.size() || d.index.size() != d.parent.size() ||
        end > d.parent.size() || begin > end)
      throw Error("resume: " + path + " is inconsistent (side " + std::to_string(s) + ")");
    std::fill(d.countSeen.begin(), d.countSeen.end(), 0);
    for (uint16_t c : d.counts) d.countSeen[c] = 1;
  }
  res.depthSearched = side[0].depth + side[1].depth;
  return at;
}

}  // namespace hexdual::flipsearch
