// Frontier and hashing: expanding frontier nodes into children (every move that applies, keeps the
// host and the region cap and reaches a state not stored yet, keyed by its canonical form), pruning
// by counts, and the threads a level's chunks run on.
#include <algorithm>
#include <exception>
#include <thread>

#include "flips/search_parts.hpp"
#include "ops/op_table.hpp"
#include "ops/support.hpp"

namespace hexdual::flipsearch {
using namespace tables;

CountBounds countBounds(const Complex& start, const SearchOptions& opt) {
  CountBounds b;
  b.V0 = start.numVertices();
  b.H0 = start.numHexes();
  auto use = [&](OpKind k) { return opt.ops.empty() || std::find(opt.ops.begin(), opt.ops.end(), k) != opt.ops.end(); };
  for (const OpInfo& op : allOps()) {
    if (!use(op.kind) || !op.counts.fixed) continue;
    const int dV = op.counts.dV, dH = op.counts.dH;
    b.upH = std::max(b.upH, dH), b.downH = std::max(b.downH, -dH);
    b.upX = std::max(b.upX, dV - dH), b.downX = std::max(b.downX, dH - dV);
  }
  if (use(OpKind::RingSplit)) b.upH = std::max(b.upH, opt.ringSplitMax), b.boundX = false;
  if (use(OpKind::RingCollapse)) b.downH = std::max(b.downH, opt.maxRegionHexes), b.boundX = false;
  // The goal side applies the listed moves as inverse steps: bound both directions alike.
  b.upH = b.downH = std::max(b.upH, b.downH);
  b.upX = b.downX = std::max(b.upX, b.downX);
  return b;
}

// Runs work(0..threads-1) on that many threads (the calling one when 1); rethrows the first error.
void onThreads(int threads, const std::function<void(int)>& work) {
  std::vector<std::exception_ptr> errors(static_cast<size_t>(threads));
  auto guarded = [&](int t) {
    try {
      work(t);
    } catch (...) {
      errors[size_t(t)] = std::current_exception();
    }
  };
  if (threads == 1) {
    guarded(0);
  } else {
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t) pool.emplace_back(guarded, t);
    for (auto& th : pool) th.join();
  }
  for (auto& err : errors)
    if (err) std::rethrow_exception(err);
}

namespace {

// One worker's expansion of frontier nodes: each node replayed (Walker), each of its moves tried
// cheaply first (counts, then applied unchecked and keyed), and only a child with a new key
// applied again with every check. Reads the indexes only (workers run in parallel; the merge
// after them writes).
class Expander {
 public:
  Expander(const SearchContext& ctx, const Side& side, const Side& other, bool fromGoal, const LevelPlan& plan,
           std::vector<Child>& out, int64_t& applied, int64_t& pruned)
      : ctx_(ctx),
        side_(side),
        other_(other),
        fromGoal_(fromGoal),
        plan_(plan),
        out_(out),
        applied_(applied),
        pruned_(pruned),
        w_(side, ctx.host, ctx.opt),
        cb_(ctx.bounds),
        hostCount_(int64_t(ctx.host.size())) {}
  void run(size_t begin, size_t end, const std::function<bool()>& stop);

 private:
  bool useful(uint16_t c) const {
    if (!ctx_.opt.countPruning) return true;
    return plan_.last ? other_.countSeen[c] != 0 : cb_.lowerBound(c, plan_.target) <= plan_.remaining;
  }
  bool tryMove(size_t n, size_t i, const OpStep& m, int64_t V, int64_t H);
  bool skipKey(Key128& key);
  bool keepChild(size_t n, size_t i, const OpStep& m, Key128 key, uint16_t counts);

  const SearchContext& ctx_;
  const Side& side_;
  const Side& other_;
  const bool fromGoal_;
  const LevelPlan& plan_;
  std::vector<Child>& out_;
  int64_t& applied_;
  int64_t& pruned_;
  Walker w_;
  RegionEncoder enc_;
  FlatKeyMap foundHere_{1024};  // children kept by this call (not yet in side.index)
  const CountBounds& cb_;
  const int64_t hostCount_;
};

void Expander::run(size_t begin, size_t end, const std::function<bool()>& stop) {
  for (size_t n = begin; n < end; ++n) {
    if (stop()) return;
    w_.goTo(int32_t(n));
    const auto& ms = w_.movesHere();
    const int64_t V = w_.cx.numVertices(), H = w_.cx.numHexes();
    for (size_t i = 0; i < ms.size(); ++i)
      if (!tryMove(n, i, ms[i], V, H)) return;
  }
}

// Move i of node n (whose counts are V, H); false when this worker stops (a child meets the other side).
bool Expander::tryMove(size_t n, size_t i, const OpStep& m, int64_t V, int64_t H) {
  const CountChange& change = opInfo(m.op).counts;
  const bool exact = change.fixed;
  const int dV = change.dV, dH = change.dH;
  if (exact && CountBounds::fits(V + dV - cb_.V0, H + dH - cb_.H0) && !useful(cb_.pack(V + dV, H + dH))) {
    ++pruned_;
    return true;
  }
  // Applied without the operations' invariant check first: a result whose key is stored is
  // isomorphic (boundary fixed) to a valid state, so valid. Only a new key is applied again
  // with every check, which also gives the exact inverse step.
  OpResult r;
  try {
    ops::DeferValidation unchecked;
    r = applyStep(w_.cx, m);
  } catch (const Error&) {
    return true;
  }
  if (exact && (r.dV != dV || r.dH != dH))
    throw Error("search: " + formatOpStep(m) + " changed (V, H) by (" + std::to_string(r.dV) + ", " +
                std::to_string(r.dH) + "), not (" + std::to_string(dV) + ", " + std::to_string(dH) + ")");
  const uint16_t counts = cb_.pack(V + r.dV, H + r.dH);
  if (w_.cx.numHexes() - hostCount_ > ctx_.opt.maxRegionHexes || !useful(counts)) {
    pruned_ += w_.cx.numHexes() - hostCount_ <= ctx_.opt.maxRegionHexes;
    w_.cx.undo(r.edits);
    ++applied_;
    return true;
  }
  Key128 key{};
  const bool skip = skipKey(key);
  w_.cx.undo(r.edits);
  if (skip) {
    ++applied_;
    return true;
  }
  return keepChild(n, i, m, key, counts);
}

// Whether the child in w_.cx is no new state (its key, when computed, in `key`). On a last level by
// lookup a child is only compared: it may meet the other side when its plain key is an image of
// one of its states (or, without images, its orbit key is stored there).
bool Expander::skipKey(Key128& key) {
  if (!plan_.lookup) {
    key = ctx_.key(enc_, w_.cx);
    return side_.index.find(key) >= 0 || foundHere_.find(key) >= 0;
  }
  if (plan_.images) return plan_.images->find(enc_.key(w_.cx, ctx_.isHost)) < 0;
  return other_.index.find(ctx_.key(enc_, w_.cx)) < 0;
}

// The move applied again with every check: kept when it has the inverse step it needs and stays
// local. False when this worker stops (a last level by lookup, or the sides meet).
bool Expander::keepChild(size_t n, size_t i, const OpStep& m, Key128 key, uint16_t counts) {
  OpResult r;
  try {
    r = applyStep(w_.cx, m);
  } catch (const Error&) {
    return true;
  }
  ++applied_;
  // From the goal side a move stands for its inverse step: a move without one (a ring collapse
  // whose side quad was glued to the ring itself) is no step of a decomposition. With
  // `reversible`, forward moves need one too.
  bool keep = (!(fromGoal_ || ctx_.opt.reversible) || r.inverse) && localityViolation(w_.cx, ctx_.hs).empty();
  if (keep && plan_.lookup) key = ctx_.key(enc_, w_.cx);  // a meeting child's orbit key
  w_.cx.undo(r.edits);
  if (!keep || (plan_.lookup && other_.index.find(key) < 0)) return true;  // (lookup: a 128-bit collision)
  out_.push_back({int32_t(n), uint32_t(i), key, counts});
  if (plan_.lookup) return false;  // the merge stores it and meets there
  foundHere_.insert(key, 0);
  return other_.index.find(key) < 0;  // the two searches meet: the merge stops here
}

}  // namespace

// Expands nodes [begin, end) of `side`: every move that applies, keeps the host and the region
// cap, and reaches a state not yet stored there; stops at a state the other side stored.
void expand(const SearchContext& ctx, const Side& side, const Side& other, bool fromGoal, const LevelPlan& plan,
            size_t begin, size_t end, std::vector<Child>& out, int64_t& applied, int64_t& pruned,
            const std::function<bool()>& stop) {
  Expander(ctx, side, other, fromGoal, plan, out, applied, pruned).run(begin, end, stop);
}

}  // namespace hexdual::flipsearch
