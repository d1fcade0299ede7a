// The search's problems (a flip's before side in the 4-cube boundary, the triple-chord push in a
// grid), the search driver (levels, chunks, limits, joining the two paths where they meet) and the
// check of a found decomposition. The other jobs live in search_*.cpp (search_parts.hpp lists them).
#include "flips/search.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>

#include "complex/builders.hpp"
#include "complex/canonical.hpp"
#include "flips/flip.hpp"
#include "flips/fourcube.hpp"
#include "flips/search_parts.hpp"
#include "flips/search_state.hpp"
#include "ops/oplog.hpp"

namespace hexdual {
using namespace tables;
using namespace flipsearch;

SearchProblem flipProblem(const std::string& name) {
  const FlipClass& fc = flipClass(name);
  SearchProblem p;
  p.name = name;
  p.start = makeFourCubeBoundary();
  p.host = facetsOf(uint8_t(~fc.before));
  p.goal = p.start;
  flip(p.goal, name, facetsOf(fc.before));
  return p;
}

SearchProblem tripleChordPushProblem() {
  SearchProblem p;
  p.name = "tripleChordPush";
  p.start = makeGrid(3, 3, 3);
  // The 8 hexes around vertex (1,1,1): i, j, k in {0, 1}.
  std::vector<HexId> region;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) region.push_back(HexId(i + 3 * j + 9 * k));
  for (HexId h : p.start.hexes())
    if (std::find(region.begin(), region.end(), h) == region.end()) p.host.push_back(h);
  p.goal = p.start;
  tripleChordPush(p.goal, 13, 0, {13, 0}, {13, 2}, {13, 4});
  return p;
}

namespace {

// One run of the bidirectional search: the context, the two sides, the result so far, the clock
// and the requests. run() searches level by level, always on the side with the smaller frontier;
// a level is searched in chunks of its frontier (expanded on the threads, merged in frontier
// order), with checkpoints and limits checked between chunks.
class Search {
 public:
  Search(const SearchProblem& problem, const SearchOptions& options);
  SearchResult run();

 private:
  // A level in progress: its side, its first new node, the children the count bound dropped, its plan.
  struct Level {
    int s;
    size_t start;
    int64_t pruned;
    LevelPlan plan;
  };
  // What the threads found in one chunk: children, moves applied, children pruned (per thread).
  struct Chunk {
    std::vector<std::vector<Child>> found;
    std::vector<int64_t> applied, pruned;
  };
  double elapsed() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); }
  bool stop();
  void save(int s, size_t next, size_t levelStart, int64_t prunedThisLevel);
  int64_t stored() const { return int64_t(side[0].parent.size() + side[1].parent.size()); }
  size_t memory() const { return side[0].memoryBytes() + side[1].memoryBytes() + images.memoryBytes(); }
  SearchResult finishStats();
  bool searchLevel(int s);
  LevelPlan planLevel(int s);
  void checkpointIfDue(const Level& lv, size_t next);
  bool searchChunk(Level& lv, size_t b, size_t e);
  Chunk expandChunk(const Level& lv, size_t b, size_t e);
  bool storeChildren(int s, const std::vector<std::vector<Child>>& found);
  bool stoppedByLimit(const Level& lv, size_t e);
  bool endLevel(const Level& lv);
  void joinPaths(int32_t fi, int32_t bi);
  OpStep stepTowards(Complex& cur, const Complex& prev, const OpStep& back);

  const SearchProblem& pb;
  const SearchOptions& opt;
  const std::chrono::steady_clock::time_point t0;
  double secondsBefore = 0;  // of the runs before a resume
  HostSnapshot hs;
  const std::vector<HexId>& host;
  SearchContext ctx;
  SearchResult res;
  Side side[2];
  RegionEncoder enc;
  const std::string fingerprint;
  Resume resume;
  double lastSave = 0;
  FlatKeyMap images{1};  // the other side's image keys, for a last level by lookup
  const int threads;
  std::atomic<bool> timeUp{false}, interrupted{false};
};

// The context (host, symmetries, count bounds), the two roots, and a checkpoint to resume from.
Search::Search(const SearchProblem& problem, const SearchOptions& options)
    : pb(problem),
      opt(options),
      t0(std::chrono::steady_clock::now()),
      hs(snapshot(pb.start, pb.host)),
      host(hs.host),
      ctx{host, {}, hs, opt, {}, {}},
      fingerprint(searchFingerprint(pb, opt)),
      threads(std::max(1, opt.threads)) {
  for (HexId h : host) {
    if (size_t(h) >= ctx.isHost.size()) ctx.isHost.resize(size_t(h) + 1, 0);
    ctx.isHost[size_t(h)] = 1;
  }
  if (opt.symmetry) ctx.symmetries = problemSymmetries(pb, ctx.isHost);
  res.symmetries = int(ctx.symmetries.size()) + 1;
  ctx.bounds = countBounds(pb.start, opt);
  for (int s = 0; s < 2; ++s) {
    side[s].root = s == 0 ? pb.start : pb.goal;
    side[s].add(-1, 0, ctx.bounds.pack(side[s].root.numVertices(), side[s].root.numHexes()));
    side[s].index.insert(ctx.key(enc, side[s].root), 0);
  }
  if (!opt.resumeFile.empty()) resume = readCheckpoint(opt.resumeFile, fingerprint, side, res, secondsBefore);
}

// The time limit or a request to stop (read by the workers between nodes).
bool Search::stop() {
  if (!timeUp && elapsed() > opt.maxSeconds) timeUp = true;
  if (!interrupted && opt.request && opt.request->load() == 2) interrupted = true;
  return timeUp || interrupted;
}

void Search::save(int s, size_t next, size_t levelStart, int64_t prunedThisLevel) {
  writeCheckpoint(opt.checkpointFile, fingerprint, side, res, secondsBefore + elapsed(),
                  {int32_t(s), uint64_t(next), uint64_t(levelStart), prunedThisLevel});
  lastSave = elapsed();
  ++res.checkpoints;
}

SearchResult Search::finishStats() {
  res.statesExplored = stored();
  res.memoryBytes = std::max(res.memoryBytes, memory());
  if (res.found) res.depthSearched = int(res.steps.size());
  res.seconds = secondsBefore + elapsed();
  return res;
}

// Levels on the side with the smaller frontier, until the sides meet, a limit stops the search,
// a side is exhausted, or the depths add up to maxDepth.
SearchResult Search::run() {
  if (side[1].index.find(ctx.key(enc, side[0].root)) >= 0) {
    res.found = true;
    res.stoppedBy = "found";
    return finishStats();
  }
  while (side[0].depth + side[1].depth < opt.maxDepth) {
    const int s = side[0].levelEnd - side[0].levelBegin <= side[1].levelEnd - side[1].levelBegin ? 0 : 1;
    if (!searchLevel(s)) return finishStats();
  }
  res.stoppedBy = "depth";
  return finishStats();
}

// One level of side s (resumed where a checkpoint left it): chunks of the frontier, split between
// the threads; children merge in frontier order, so node ids and the result do not depend on the
// thread count. False when the search ends in it (res says why).
bool Search::searchLevel(int s) {
  Side& me = side[s];
  if (resume.side >= 0 && resume.side != s) throw Error("resume: the checkpoint's level does not match its frontiers");
  const bool resuming = resume.side >= 0;
  const size_t levelStart = resuming ? size_t(resume.levelStart) : me.parent.size();
  const size_t chunk = std::max<size_t>(1, opt.chunk);
  const int64_t prunedBefore = resuming ? resume.prunedThisLevel : 0;
  const size_t firstChunk = resuming ? size_t(resume.next) : me.levelBegin;
  resume.side = -1;
  Level lv{s, levelStart, prunedBefore, planLevel(s)};
  for (size_t b = firstChunk; b < me.levelEnd; b += chunk) {
    const size_t e = std::min(me.levelEnd, b + chunk);
    checkpointIfDue(lv, b);
    if (!searchChunk(lv, b, e)) return false;
  }
  return endLevel(lv);
}

// What expand needs to know of the level; on a last level by lookup, the other side's image keys
// (beyond the memory limit, children are keyed by orbit and looked up in the other side's index).
LevelPlan Search::planLevel(int s) {
  const Side& me = side[s];
  const Side& other = side[1 - s];
  LevelPlan plan;
  plan.remaining = opt.maxDepth - (me.depth + 1);  // steps left for a child of this level to reach the other root
  plan.last = side[0].depth + side[1].depth + 1 == opt.maxDepth;
  plan.target = other.counts[0];
  if (plan.last && opt.lookupLastLevel) {
    plan.lookup = true;
    const double imageBytes = double(imageSlots(ctx, other) * (sizeof(Key128) + sizeof(int32_t)));
    if (double(memory()) + imageBytes <= opt.maxMemoryMB * 1048576.0) {
      images = imageKeys(ctx, other, threads);
      res.lookupKeys = int64_t(images.size());
      plan.images = &images;
    }
  }
  return plan;
}

// A checkpoint before the chunk starting at `next`, when one is due or requested.
void Search::checkpointIfDue(const Level& lv, size_t next) {
  if (!opt.checkpointFile.empty() && ((opt.checkpointEvery > 0 && elapsed() - lastSave >= opt.checkpointEvery) ||
                                      (opt.request && opt.request->load() == 1))) {
    if (opt.request && opt.request->load() == 1) opt.request->store(0);
    save(lv.s, next, lv.start, lv.pruned);
  }
}

// Nodes [b, e) of the level expanded, their children stored; false when the search ends here.
bool Search::searchChunk(Level& lv, size_t b, size_t e) {
  const Chunk chunk = expandChunk(lv, b, e);
  // Stopped inside this chunk: the checkpoint is the state before it (the chunk is redone).
  if ((timeUp || interrupted) && !opt.checkpointFile.empty()) save(lv.s, b, lv.start, lv.pruned);
  for (int64_t a : chunk.applied) res.movesApplied += a;
  for (int64_t a : chunk.pruned) res.prunedByCounts += a, lv.pruned += a;
  if (storeChildren(lv.s, chunk.found)) return false;
  res.memoryBytes = std::max(res.memoryBytes, memory());
  return !stoppedByLimit(lv, e);
}

Search::Chunk Search::expandChunk(const Level& lv, size_t b, size_t e) {
  Chunk c{std::vector<std::vector<Child>>(static_cast<size_t>(threads)),
          std::vector<int64_t>(static_cast<size_t>(threads), 0), std::vector<int64_t>(static_cast<size_t>(threads), 0)};
  onThreads(threads, [&](int t) {
    size_t per = (e - b + size_t(threads) - 1) / size_t(threads);
    size_t lo = std::min(e, b + per * size_t(t)), hi = std::min(e, lo + per);
    expand(ctx, side[lv.s], side[1 - lv.s], lv.s == 1, lv.plan, lo, hi, c.found[size_t(t)], c.applied[size_t(t)],
           c.pruned[size_t(t)], [this] { return stop(); });
  });
  return c;
}

// The children in frontier order, each stored unless its key is; true when one meets the other
// side (the paths are joined: res holds the steps).
bool Search::storeChildren(int s, const std::vector<std::vector<Child>>& found) {
  Side& me = side[s];
  Side& other = side[1 - s];
  for (const auto& list : found)
    for (const Child& c : list) {
      int32_t id = int32_t(me.parent.size());
      if (me.index.insert(c.key, id) != id) continue;
      me.add(c.parent, c.move, c.counts);
      int32_t there = other.index.find(c.key);
      if (there >= 0) {
        if (s == 0)
          joinPaths(id, there);
        else
          joinPaths(there, id);
        return true;
      }
    }
  return false;
}

// A stop request, the time limit, the state cap or the memory guard, each with its message (and a
// checkpoint of where the level goes on, when one is kept).
bool Search::stoppedByLimit(const Level& lv, size_t e) {
  const std::string saved = opt.checkpointFile.empty() ? "" : "; checkpoint in " + opt.checkpointFile;
  const std::string during = " during depth " + std::to_string(side[0].depth + side[1].depth + 1) + saved;
  if (interrupted) {
    res.stoppedBy = "interrupted";
    res.message = "stopped on request" + during;
    return true;
  }
  if (timeUp) {
    res.stoppedBy = "time";
    char secs[32];
    std::snprintf(secs, sizeof secs, "%g", opt.maxSeconds);
    res.message = "stopped by the time limit (--max-seconds " + std::string(secs) + ")" + during;
    return true;
  }
  if (stored() > opt.maxStates) {
    if (!opt.checkpointFile.empty()) save(lv.s, e, lv.start, lv.pruned);
    res.stoppedBy = "states";
    res.message = "stopped at the state cap (--max-states " + std::to_string(opt.maxStates) + ")" + during;
    return true;
  }
  // A hash set grows by doubling: stop before the next growth could pass the memory limit.
  // (A last level by lookup adds no states.)
  const Side& me = side[lv.s];
  if (double(memory()) + (lv.plan.lookup ? 0.0 : double(me.index.memoryBytes()) * 2) > opt.maxMemoryMB * 1048576.0) {
    if (!opt.checkpointFile.empty()) save(lv.s, e, lv.start, lv.pruned);
    res.stoppedBy = "memory";
    res.message = "stopped by the memory guard (--max-memory " + std::to_string(int64_t(opt.maxMemoryMB)) + " MB; " +
                  std::to_string(memory() >> 20) + " MB in use)" + during;
    return true;
  }
  return false;
}

// The level's new nodes become the side's frontier; false when the search ends after it (a last
// level by lookup, every new state dropped by the count bound, or no new state at all).
bool Search::endLevel(const Level& lv) {
  Side& me = side[lv.s];
  me.levelBegin = lv.start;
  me.levelEnd = me.parent.size();
  ++me.depth;
  res.depthSearched = side[0].depth + side[1].depth;
  res.levels.push_back({lv.s, me.depth, int64_t(me.levelEnd - me.levelBegin), stored(), res.movesApplied,
                        secondsBefore + elapsed(), lv.plan.lookup});
  if (opt.progress) opt.progress(res.levels.back());
  if (lv.plan.lookup) {  // the last level, by lookup: its children were not stored
    res.stoppedBy = "depth";
    return false;
  }
  if (me.levelBegin == me.levelEnd && lv.pruned > 0) {
    // Every new state was dropped by the count bound: no sequence of at most maxDepth steps.
    res.depthSearched = opt.maxDepth;
    res.stoppedBy = "depth";
    res.message = "no new state of depth " + std::to_string(me.depth) + " from the " + (lv.s ? "goal" : "start") +
                  " survives the count bound of --max-depth " + std::to_string(opt.maxDepth);
    return false;
  }
  if (me.levelBegin == me.levelEnd) {
    // No new state on this side: every sequence of any length (within the region cap) was seen.
    res.stoppedBy = "exhausted";
    return false;
  }
  return true;
}

// Joins the forward path to node fi with the backward path from the goal to node bi (same key).
void Search::joinPaths(int32_t fi, int32_t bi) {
  Walker wf(side[0], host, opt), wb(side[1], host, opt);
  wf.goTo(fi);
  wb.goTo(bi);
  std::vector<OpStep> steps = wf.steps(), back = wb.steps();
  // The backward chain's states: goal = chain[0], ..., chain[k] = the meeting state.
  std::vector<Complex> chain{pb.goal};
  for (const OpStep& st : back) {
    chain.push_back(chain.back());
    applyStep(chain.back(), st);
  }
  Complex cur = wf.cx;
  for (size_t k = back.size(); k > 0; --k) {
    const OpStep chosen = stepTowards(cur, chain[k - 1], back[k - 1]);
    applyStep(cur, chosen);
    steps.push_back(chosen);
  }
  res.found = true;
  res.steps = steps;
  res.stoppedBy = "found";
}

// A local move from cur reaching `prev` (the backward chain's state before `back`): first among the
// generated moves (this also picks the side that keeps host vertex ids for splits), else the
// inverse of `back`, translated.
OpStep Search::stepTowards(Complex& cur, const Complex& prev, const OpStep& back) {
  Key128 want = ctx.key(enc, prev);
  for (const OpStep& m : moves(cur, host, {}, opt.ringSplitMax, opt.prefilter)) {
    OpResult r;
    try {
      r = applyStep(cur, m);
    } catch (const Error&) {
      continue;
    }
    bool hit = ctx.key(enc, cur) == want && (!opt.reversible || r.inverse) && localityViolation(cur, hs).empty();
    cur.undo(r.edits);
    if (hit) return m;
  }
  Complex tmp = prev;
  OpResult r = applyStep(tmp, back);
  if (!r.inverse) throw Error("search: " + formatOpStep(back) + " has no inverse step (" + r.noInverse + ")");
  CanonicalLabelling from = regionLabelling(tmp, host), to = regionLabelling(cur, host);
  if (from.form != to.form)
    throw Error(
        "search: the paths meet only up to a symmetry where a generated move is missing; search again without "
        "symmetry");
  return translateStep(*r.inverse, from, to, host);
}

}  // namespace

SearchResult searchDecomposition(const SearchProblem& pb, const SearchOptions& opt) {
  Search search(pb, opt);
  return search.run();
}

void verifyDecomposition(const SearchProblem& pb, const std::vector<OpStep>& steps) {
  HostSnapshot hs = snapshot(pb.start, pb.host);
  Complex cx = pb.start;
  for (size_t k = 0; k < steps.size(); ++k) {
    try {
      applyStep(cx, steps[k]);
    } catch (const Error& e) {
      throw Error("verify " + pb.name + ": step " + std::to_string(k + 1) + " (" + formatOpStep(steps[k]) +
                  "): " + e.what());
    }
    std::string why = localityViolation(cx, hs);
    if (!why.empty()) throw Error("verify " + pb.name + ": step " + std::to_string(k + 1) + " is not local: " + why);
  }
  cx.validate();
  if (regionLabelling(cx, hs.host).form != regionLabelling(pb.goal, hs.host).form)
    throw Error("verify " + pb.name + ": the result is not isomorphic to the flip's after side");
}

}  // namespace hexdual
