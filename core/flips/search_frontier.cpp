// Frontier and hashing: expanding frontier nodes into children (every move that applies, keeps the
// host and the region cap and reaches a state not stored yet, keyed by its canonical form), pruning
// by counts, and the threads a level's chunks run on.
#include "flips/search_parts.hpp"

#include <algorithm>
#include <exception>
#include <thread>

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

// Expands nodes [begin, end) of `side`: every move that applies, keeps the host and the region
// cap, and reaches a state not yet stored there; stops at a state the other side stored. Reads
// the indexes only (workers run in parallel; the merge after them writes).
void expand(const SearchContext& ctx, const Side& side, const Side& other, bool fromGoal, const LevelPlan& plan,
            size_t begin, size_t end, std::vector<Child>& out, int64_t& applied, int64_t& pruned,
            const std::function<bool()>& stop) {
  Walker w(side, ctx.host, ctx.opt);
  RegionEncoder enc;
  FlatKeyMap foundHere(1024);  // children kept by this call (not yet in side.index)
  const int64_t hostCount = int64_t(ctx.host.size());
  const CountBounds& cb = ctx.bounds;
  auto useful = [&](uint16_t c) {
    if (!ctx.opt.countPruning) return true;
    return plan.last ? other.countSeen[c] != 0 : cb.lowerBound(c, plan.target) <= plan.remaining;
  };
  for (size_t n = begin; n < end; ++n) {
    if (stop()) return;
    w.goTo(int32_t(n));
    const auto& ms = w.movesHere();
    const int64_t V = w.cx.numVertices(), H = w.cx.numHexes();
    for (size_t i = 0; i < ms.size(); ++i) {
      const CountChange& change = opInfo(ms[i].op).counts;
      const bool exact = change.fixed;
      const int dV = change.dV, dH = change.dH;
      if (exact && CountBounds::fits(V + dV - cb.V0, H + dH - cb.H0) && !useful(cb.pack(V + dV, H + dH))) {
        ++pruned;
        continue;
      }
      // Applied without the operations' invariant check first: a result whose key is stored is
      // isomorphic (boundary fixed) to a valid state, so valid. Only a new key is applied again
      // with every check, which also gives the exact inverse step.
      OpResult r;
      try {
        ops::DeferValidation unchecked;
        r = applyStep(w.cx, ms[i]);
      } catch (const Error&) {
        continue;
      }
      if (exact && (r.dV != dV || r.dH != dH))
        throw Error("search: " + formatOpStep(ms[i]) + " changed (V, H) by (" + std::to_string(r.dV) + ", " +
                    std::to_string(r.dH) + "), not (" + std::to_string(dV) + ", " + std::to_string(dH) + ")");
      const uint16_t counts = cb.pack(V + r.dV, H + r.dH);
      if (w.cx.numHexes() - hostCount > ctx.opt.maxRegionHexes || !useful(counts)) {
        pruned += w.cx.numHexes() - hostCount <= ctx.opt.maxRegionHexes;
        w.cx.undo(r.edits);
        ++applied;
        continue;
      }
      // On a last level by lookup a child is only compared: it may meet the other side when its
      // plain key is an image of one of its states (or, without images, its orbit key is stored there).
      Key128 key{};
      bool skip = false;
      if (!plan.lookup) {
        key = ctx.key(enc, w.cx);
        skip = side.index.find(key) >= 0 || foundHere.find(key) >= 0;
      } else if (plan.images) {
        skip = plan.images->find(enc.key(w.cx, ctx.isHost)) < 0;
      } else {
        skip = other.index.find(ctx.key(enc, w.cx)) < 0;
      }
      w.cx.undo(r.edits);
      if (skip) {
        ++applied;
        continue;
      }
      try {
        r = applyStep(w.cx, ms[i]);
      } catch (const Error&) {
        continue;
      }
      ++applied;
      // From the goal side a move stands for its inverse step: a move without one (a ring collapse
      // whose side quad was glued to the ring itself) is no step of a decomposition. With
      // `reversible`, forward moves need one too.
      bool keep = (!(fromGoal || ctx.opt.reversible) || r.inverse) && localityViolation(w.cx, ctx.hs).empty();
      if (keep && plan.lookup) key = ctx.key(enc, w.cx);  // a meeting child's orbit key
      w.cx.undo(r.edits);
      if (!keep || (plan.lookup && other.index.find(key) < 0)) continue;  // (lookup: a 128-bit collision)
      out.push_back({int32_t(n), uint32_t(i), key, counts});
      if (plan.lookup) return;  // the merge stores it and meets there
      foundHere.insert(key, 0);
      if (other.index.find(key) >= 0) return;  // the two searches meet: the merge stops here
    }
  }
}

}  // namespace hexdual::flipsearch
