// The decomposition search's parts, shared between its units (core/flips/search*.cpp); not part of
// the public interface (flips/search.hpp). The units, by job:
//   search.cpp             the problems, the search driver (levels, chunks, limits), joining the paths
//   search_locality.cpp    the host snapshot and the locality check; the region of a state
//   search_moves.cpp       the candidate moves of a state, with the prefilters that skip hopeless ones
//   search_frontier.cpp    expanding frontier nodes into children, keyed (hashed) by canonical form;
//                          pruning by counts; threads
//   search_symmetry.cpp    the problem's symmetries (one state stored per orbit)
//   search_lookup.cpp      the last level by lookup: the other side's stored states keyed under every symmetry
//   search_checkpoint.cpp  writing and reading checkpoints
//   search_replay.cpp      steps translated between isomorphic regions; replay in a host mesh
//   search_embeddings.cpp  the host meshes a found decomposition is replayed in
#pragma once
#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include "complex/canonical.hpp"
#include "flips/search.hpp"
#include "flips/search_state.hpp"
#include "ops/oplog.hpp"

namespace hexdual::flipsearch {

// ---- host and locality (search_locality.cpp) ----

struct HostSnapshot {
  std::vector<HexId> host;
  std::vector<std::array<VertexId, 8>> verts;
  std::vector<std::array<Gluing, 6>> hostGlue;           // gluings to host hexes (else boundary/region marker)
  std::vector<std::vector<std::vector<EdgeRef>>> edges;  // per host hex, per edge: host incidences on its cycle
};

inline bool isHost(const std::vector<HexId>& host, HexId h) { return std::binary_search(host.begin(), host.end(), h); }

HostSnapshot snapshot(const Complex& cx, std::vector<HexId> host);
// Why a state is not local, or "" when it is.
std::string localityViolation(const Complex& cx, const HostSnapshot& s);
std::vector<HexId> regionOf(const Complex& cx, const std::vector<HexId>& host);
CanonicalLabelling regionLabelling(const Complex& cx, const std::vector<HexId>& host);

// ---- moves (search_moves.cpp) ----

// Candidate steps on region hexes (cheap exact preconditions checked, most rejections cost no exception).
std::vector<OpStep> moves(const Complex& cx, const std::vector<HexId>& host, const std::vector<OpKind>& ops,
                          int ringSplitMax, bool prefilter = true);

// ---- replay (search_replay.cpp) ----

// Rewrites a step's hex ids and local indices from complex `from` to the isomorphic `to`.
OpStep translateStep(OpStep st, const CanonicalLabelling& from, const CanonicalLabelling& to,
                     const std::vector<HexId>& host);

// ---- frontier and hashing (search_frontier.cpp) ----

// One side of the bidirectional search: nodes stored as (parent, index of the move in the
// parent's move list), 8 bytes each; the state itself is replayed from the root on demand.
struct Side {
  Complex root;
  std::vector<int32_t> parent;
  std::vector<uint32_t> move;
  std::vector<uint16_t> counts;                                       // packed (V, H) of each node (CountBounds::pack)
  std::vector<uint8_t> countSeen = std::vector<uint8_t>(1 << 16, 0);  // which packed counts occur
  FlatKeyMap index{1 << 12};
  size_t levelBegin = 0, levelEnd = 1;  // the frontier: nodes [levelBegin, levelEnd)
  int depth = 0;
  size_t memoryBytes() const {
    return parent.capacity() * 4 + move.capacity() * 4 + counts.capacity() * 2 + countSeen.size() + index.memoryBytes();
  }
  void add(int32_t par, uint32_t mv, uint16_t c) {
    parent.push_back(par);
    move.push_back(mv);
    counts.push_back(c);
    countSeen[c] = 1;
  }
};

// Replays nodes of one side in frontier order. Frontier nodes are stored in the order of their
// parents, so consecutive nodes share most of their path: the walker undoes back to the common
// ancestor and applies forward from there, keeping each ancestor's move list.
class Walker {
 public:
  Walker(const Side& side, const std::vector<HexId>& host, const SearchOptions& opt)
      : side_(side), host_(host), ops_(opt.ops), prefilter_(opt.prefilter), cx(side.root) {
    ringMax_ = [&opt, this] {
      return std::min(opt.ringSplitMax, opt.maxRegionHexes - int(cx.numHexes() - int64_t(host_.size())));
    };
    path_ = {0};
    movesAt_.emplace_back();
    ready_.push_back(false);
  }
  void goTo(int32_t node) {
    chain_.clear();
    for (int32_t n = node; n >= 0; n = side_.parent[size_t(n)]) chain_.push_back(n);
    std::reverse(chain_.begin(), chain_.end());
    size_t common = 0;
    while (common < chain_.size() && common < path_.size() && chain_[common] == path_[common]) ++common;
    while (path_.size() > common) {
      cx.undo(logs_.back());
      logs_.pop_back();
      movesAt_.pop_back();
      ready_.pop_back();
      path_.pop_back();
    }
    for (size_t i = common; i < chain_.size(); ++i) {
      const OpStep& m = movesHere()[side_.move[size_t(chain_[i])]];
      logs_.push_back(applyStep(cx, m).edits);
      path_.push_back(chain_[i]);
      movesAt_.emplace_back();
      ready_.push_back(false);
    }
  }
  // The current node's move list (generated on first use: a node only replayed needs none).
  const std::vector<OpStep>& movesHere() {
    if (!ready_.back()) {
      movesAt_.back() = moves(cx, host_, ops_, ringMax_(), prefilter_);
      ready_.back() = true;
    }
    return movesAt_.back();
  }
  // The steps from the root to the current node.
  std::vector<OpStep> steps() const {
    std::vector<OpStep> out;
    for (size_t i = 1; i < path_.size(); ++i) out.push_back(movesAt_[i - 1][side_.move[size_t(path_[i])]]);
    return out;
  }

 private:
  const Side& side_;
  const std::vector<HexId>& host_;
  const std::vector<OpKind>& ops_;
  bool prefilter_;
  std::vector<int32_t> path_, chain_;
  std::vector<Complex::EditLog> logs_;
  std::vector<std::vector<OpStep>> movesAt_;
  std::vector<bool> ready_;  // whether movesAt_ of that path node was generated
  std::function<int()> ringMax_;  // ring splits: loops up to the region cap's headroom

 public:
  Complex cx;
};

// A child found by a worker: not yet in its side's index when the worker saw it.
struct Child {
  int32_t parent;
  uint32_t move;
  Key128 key;
  uint16_t counts;
};

// Pruning by counts (TK03 §4: every atomic operation changes V, E, F, H by fixed amounts).
// Every interior quad has two hex sides and every boundary quad one, so 6H = 2F - F_boundary;
// the boundary quads are fixed, so F - 3H never changes, and neither does V - E + F - H: a state's
// counts are determined by (V, H). One step changes H by at most upH (at least -downH) and
// X = V - H by at most upX (at least -downX), so a state whose H is δ > 0 below the target's needs
// at least ceil(δ / upH) more steps, and likewise for the other three cases; a state first reached
// at depth d is dropped when that bound exceeds maxDepth - d. No state of a sequence of at most
// maxDepth steps is dropped: its place p in the sequence is at least d, and the rest of the
// sequence, at most maxDepth - p <= maxDepth - d steps, reaches the target. On the last level a
// child can only meet a state of the other side, whose counts are known: any other count is dropped.
struct CountBounds {
  int64_t V0 = 0, H0 = 0;  // the start's counts: packed counts are relative to them
  int upH = 0, downH = 0, upX = 0, downX = 0;
  bool boundX = true;  // false when a ring operation is used (its change of X is not fixed)
  static bool fits(int64_t dV, int64_t dH) { return dV >= -128 && dV < 128 && dH >= -128 && dH < 128; }
  uint16_t pack(int64_t V, int64_t H) const {
    int64_t dV = V - V0, dH = H - H0;
    if (!fits(dV, dH))
      throw Error("search: the counts moved more than 127 from the start's; the count table cannot hold them");
    return uint16_t(uint16_t(dV + 128) << 8 | uint16_t(dH + 128));
  }
  static int64_t dV(uint16_t c) { return int64_t(c >> 8) - 128; }
  static int64_t dH(uint16_t c) { return int64_t(c & 255) - 128; }
  // Fewest steps from counts a to counts b.
  int lowerBound(uint16_t a, uint16_t b) const {
    auto need = [](int64_t delta, int up, int down) -> int {
      if (delta > 0) return up > 0 ? int((delta + up - 1) / up) : 1 << 20;
      if (delta < 0) return down > 0 ? int((-delta + down - 1) / down) : 1 << 20;
      return 0;
    };
    int64_t h = dH(b) - dH(a), x = (dV(b) - dH(b)) - (dV(a) - dH(a));
    return std::max(need(h, upH, downH), boundX ? need(x, upX, downX) : 0);
  }
};

CountBounds countBounds(const Complex& start, const SearchOptions& opt);

struct SearchContext {
  const std::vector<HexId>& host;
  std::vector<uint8_t> isHost;  // by hex id; ids past the end are region hexes
  const HostSnapshot& hs;
  const SearchOptions& opt;
  std::vector<std::vector<VertexId>> symmetries;  // vertex maps fixing host, start and goal (not the identity)
  CountBounds bounds;
  Key128 key(RegionEncoder& enc, const Complex& cx) const {
    return symmetries.empty() ? enc.key(cx, isHost) : enc.key(cx, isHost, symmetries);
  }
};

// What expand needs to know of the level: whether it is the last (children must meet the other
// side), how many steps remain after it, and the counts of the other side's root.
struct LevelPlan {
  bool last = false;
  int remaining = 0;
  uint16_t target = 0;
  bool lookup = false;                 // a last level by lookup: children only compared, never stored
  const FlatKeyMap* images = nullptr;  // the other side's image keys (null: children keyed by orbit)
};

// Runs work(0..threads-1) on that many threads (the calling one when 1); rethrows the first error.
void onThreads(int threads, const std::function<void(int)>& work);
// Expands nodes [begin, end) of `side` into children not stored there yet (see search_frontier.cpp).
void expand(const SearchContext& ctx, const Side& side, const Side& other, bool fromGoal, const LevelPlan& plan,
            size_t begin, size_t end, std::vector<Child>& out, int64_t& applied, int64_t& pruned,
            const std::function<bool()>& stop);

// ---- symmetry (search_symmetry.cpp) ----

// Vertex maps that carry the host onto itself and fix the canonical forms of start and goal.
std::vector<std::vector<VertexId>> problemSymmetries(const SearchProblem& pb, const std::vector<uint8_t>& isHost);

// ---- the last level by lookup (search_lookup.cpp) ----

// Hash slots for the image keys of `side`, and the keys: every state's plain key and its images'.
size_t imageSlots(const SearchContext& ctx, const Side& side);
FlatKeyMap imageKeys(const SearchContext& ctx, const Side& side, int threads);

// ---- checkpoints (search_checkpoint.cpp) ----


// A checkpoint: the two sides' nodes, counts and hash tables, the statistics, and where the level
// in progress goes on (its side, the next chunk, its first new node). Binary, this machine's byte
// order; the first lines name the format and the search it belongs to.
struct Resume {
  int32_t side = -1;  // -1: at a level boundary
  uint64_t next = 0, levelStart = 0;
  int64_t prunedThisLevel = 0;
};

std::string searchFingerprint(const SearchProblem& pb, const SearchOptions& o);
void writeCheckpoint(const std::string& path, const std::string& fingerprint, const Side side[2],
                     const SearchResult& res, double seconds, const Resume& at);
Resume readCheckpoint(const std::string& path, const std::string& fingerprint, Side side[2], SearchResult& res,
                      double& seconds);

}  // namespace hexdual::flipsearch
