#include "flips/search.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <thread>

#include "complex/builders.hpp"
#include "complex/canonical.hpp"
#include "flips/flip.hpp"
#include "flips/fourcube.hpp"
#include "flips/search_parts.hpp"
#include "flips/search_state.hpp"
#include "ops/op_table.hpp"
#include "ops/oplog.hpp"
#include "ops/support.hpp"

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


SearchResult searchDecomposition(const SearchProblem& pb, const SearchOptions& opt) {
  auto t0 = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  double secondsBefore = 0;  // of the runs before a resume
  HostSnapshot hs = snapshot(pb.start, pb.host);
  const std::vector<HexId>& host = hs.host;
  SearchContext ctx{host, {}, hs, opt, {}, {}};
  for (HexId h : host) {
    if (size_t(h) >= ctx.isHost.size()) ctx.isHost.resize(size_t(h) + 1, 0);
    ctx.isHost[size_t(h)] = 1;
  }
  if (opt.symmetry) ctx.symmetries = problemSymmetries(pb, ctx.isHost);
  SearchResult res;
  res.symmetries = int(ctx.symmetries.size()) + 1;
  Side side[2];
  RegionEncoder enc;
  ctx.bounds = countBounds(pb.start, opt);
  for (int s = 0; s < 2; ++s) {
    side[s].root = s == 0 ? pb.start : pb.goal;
    side[s].add(-1, 0, ctx.bounds.pack(side[s].root.numVertices(), side[s].root.numHexes()));
    side[s].index.insert(ctx.key(enc, side[s].root), 0);
  }
  const std::string fingerprint = searchFingerprint(pb, opt);
  Resume resume;
  if (!opt.resumeFile.empty()) resume = readCheckpoint(opt.resumeFile, fingerprint, side, res, secondsBefore);
  double lastSave = 0;
  auto save = [&](int s, size_t next, size_t levelStart, int64_t prunedThisLevel) {
    writeCheckpoint(opt.checkpointFile, fingerprint, side, res, secondsBefore + elapsed(),
                    {int32_t(s), uint64_t(next), uint64_t(levelStart), prunedThisLevel});
    lastSave = elapsed();
    ++res.checkpoints;
  };
  auto stored = [&] { return int64_t(side[0].parent.size() + side[1].parent.size()); };
  FlatKeyMap images{1};  // the other side's image keys, for a last level by lookup
  auto memory = [&] { return side[0].memoryBytes() + side[1].memoryBytes() + images.memoryBytes(); };
  auto finishStats = [&] {
    res.statesExplored = stored();
    res.memoryBytes = std::max(res.memoryBytes, memory());
    if (res.found) res.depthSearched = int(res.steps.size());
    res.seconds = secondsBefore + elapsed();
    return res;
  };
  if (side[1].index.find(ctx.key(enc, side[0].root)) >= 0) {
    res.found = true;
    res.stoppedBy = "found";
    return finishStats();
  }
  // Joins the forward path to node fi with the backward path from the goal to node bi (same key).
  auto finish = [&](int32_t fi, int32_t bi) {
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
      Key128 want = ctx.key(enc, chain[k - 1]);
      // A local move from cur reaching the previous state: first among the generated moves (this
      // also picks the side that keeps host vertex ids for splits), else the translated inverse.
      std::optional<OpStep> chosen;
      for (const OpStep& m : moves(cur, host, {}, opt.ringSplitMax, opt.prefilter)) {
        OpResult r;
        try {
          r = applyStep(cur, m);
        } catch (const Error&) {
          continue;
        }
        bool hit = ctx.key(enc, cur) == want && (!opt.reversible || r.inverse) && localityViolation(cur, hs).empty();
        cur.undo(r.edits);
        if (hit) {
          chosen = m;
          break;
        }
      }
      if (!chosen) {
        Complex tmp = chain[k - 1];
        OpResult r = applyStep(tmp, back[k - 1]);
        if (!r.inverse)
          throw Error("search: " + formatOpStep(back[k - 1]) + " has no inverse step (" + r.noInverse + ")");
        CanonicalLabelling from = regionLabelling(tmp, host), to = regionLabelling(cur, host);
        if (from.form != to.form)
          throw Error(
              "search: the paths meet only up to a symmetry where a generated move is missing; search again without "
              "symmetry");
        chosen = translateStep(*r.inverse, from, to, host);
      }
      applyStep(cur, *chosen);
      steps.push_back(*chosen);
    }
    res.found = true;
    res.steps = steps;
    res.stoppedBy = "found";
  };
  const int threads = std::max(1, opt.threads);
  std::atomic<bool> timeUp{false}, interrupted{false};
  auto stop = [&] {
    if (!timeUp && elapsed() > opt.maxSeconds) timeUp = true;
    if (!interrupted && opt.request && opt.request->load() == 2) interrupted = true;
    return timeUp || interrupted;
  };
  while (side[0].depth + side[1].depth < opt.maxDepth) {
    int s = side[0].levelEnd - side[0].levelBegin <= side[1].levelEnd - side[1].levelBegin ? 0 : 1;
    Side& me = side[s];
    Side& other = side[1 - s];
    if (resume.side >= 0 && resume.side != s)
      throw Error("resume: the checkpoint's level does not match its frontiers");
    const bool resuming = resume.side >= 0;
    const size_t levelStart = resuming ? size_t(resume.levelStart) : me.parent.size();
    // Chunks of the frontier, split between the threads; children merge in frontier order, so
    // node ids and the result do not depend on the thread count.
    const size_t chunk = std::max<size_t>(1, opt.chunk);
    int64_t prunedThisLevel = resuming ? resume.prunedThisLevel : 0;
    const size_t firstChunk = resuming ? size_t(resume.next) : me.levelBegin;
    resume.side = -1;
    LevelPlan plan;
    plan.remaining = opt.maxDepth - (me.depth + 1);  // steps left for a child of this level to reach the other root
    plan.last = side[0].depth + side[1].depth + 1 == opt.maxDepth;
    plan.target = other.counts[0];
    if (plan.last && opt.lookupLastLevel) {
      plan.lookup = true;
      // Beyond the memory limit, children are keyed by orbit and looked up in the other side's index.
      const double imageBytes = double(imageSlots(ctx, other) * (sizeof(Key128) + sizeof(int32_t)));
      if (double(memory()) + imageBytes <= opt.maxMemoryMB * 1048576.0) {
        images = imageKeys(ctx, other, threads);
        res.lookupKeys = int64_t(images.size());
        plan.images = &images;
      }
    }
    for (size_t b = firstChunk; b < me.levelEnd; b += chunk) {
      size_t e = std::min(me.levelEnd, b + chunk);
      if (!opt.checkpointFile.empty() && ((opt.checkpointEvery > 0 && elapsed() - lastSave >= opt.checkpointEvery) ||
                                          (opt.request && opt.request->load() == 1))) {
        if (opt.request && opt.request->load() == 1) opt.request->store(0);
        save(s, b, levelStart, prunedThisLevel);
      }
      std::vector<std::vector<Child>> found(static_cast<size_t>(threads));
      std::vector<int64_t> applied(static_cast<size_t>(threads), 0), pruned(static_cast<size_t>(threads), 0);
      onThreads(threads, [&](int t) {
        size_t per = (e - b + size_t(threads) - 1) / size_t(threads);
        size_t lo = std::min(e, b + per * size_t(t)), hi = std::min(e, lo + per);
        expand(ctx, me, other, s == 1, plan, lo, hi, found[size_t(t)], applied[size_t(t)], pruned[size_t(t)], stop);
      });
      // Stopped inside this chunk: the checkpoint is the state before it (the chunk is redone).
      if ((timeUp || interrupted) && !opt.checkpointFile.empty()) save(s, b, levelStart, prunedThisLevel);
      for (int64_t a : applied) res.movesApplied += a;
      for (int64_t a : pruned) res.prunedByCounts += a, prunedThisLevel += a;
      for (const auto& list : found)
        for (const Child& c : list) {
          int32_t id = int32_t(me.parent.size());
          if (me.index.insert(c.key, id) != id) continue;
          me.add(c.parent, c.move, c.counts);
          int32_t there = other.index.find(c.key);
          if (there >= 0) {
            if (s == 0)
              finish(id, there);
            else
              finish(there, id);
            return finishStats();
          }
        }
      res.memoryBytes = std::max(res.memoryBytes, memory());
      const std::string saved = opt.checkpointFile.empty() ? "" : "; checkpoint in " + opt.checkpointFile;
      if (interrupted) {
        res.stoppedBy = "interrupted";
        res.message = "stopped on request during depth " + std::to_string(side[0].depth + side[1].depth + 1) + saved;
        return finishStats();
      }
      if (timeUp) {
        res.stoppedBy = "time";
        char secs[32];
        std::snprintf(secs, sizeof secs, "%g", opt.maxSeconds);
        res.message = "stopped by the time limit (--max-seconds " + std::string(secs) + ") during depth " +
                      std::to_string(side[0].depth + side[1].depth + 1) + saved;
        return finishStats();
      }
      if (stored() > opt.maxStates) {
        if (!opt.checkpointFile.empty()) save(s, e, levelStart, prunedThisLevel);
        res.stoppedBy = "states";
        res.message = "stopped at the state cap (--max-states " + std::to_string(opt.maxStates) + ") during depth " +
                      std::to_string(side[0].depth + side[1].depth + 1) + saved;
        return finishStats();
      }
      // A hash set grows by doubling: stop before the next growth could pass the memory limit.
      // (A last level by lookup adds no states.)
      if (double(memory()) + (plan.lookup ? 0.0 : double(me.index.memoryBytes()) * 2) > opt.maxMemoryMB * 1048576.0) {
        if (!opt.checkpointFile.empty()) save(s, e, levelStart, prunedThisLevel);
        res.stoppedBy = "memory";
        res.message = "stopped by the memory guard (--max-memory " + std::to_string(int64_t(opt.maxMemoryMB)) +
                      " MB; " + std::to_string(memory() >> 20) + " MB in use) during depth " +
                      std::to_string(side[0].depth + side[1].depth + 1) + saved;
        return finishStats();
      }
    }
    me.levelBegin = levelStart;
    me.levelEnd = me.parent.size();
    ++me.depth;
    res.depthSearched = side[0].depth + side[1].depth;
    res.levels.push_back({s, me.depth, int64_t(me.levelEnd - me.levelBegin), stored(), res.movesApplied,
                          secondsBefore + elapsed(), plan.lookup});
    if (opt.progress) opt.progress(res.levels.back());
    if (plan.lookup) break;  // the last level, by lookup: its children were not stored
    if (me.levelBegin == me.levelEnd && prunedThisLevel > 0) {
      // Every new state was dropped by the count bound: no sequence of at most maxDepth steps.
      res.depthSearched = opt.maxDepth;
      res.stoppedBy = "depth";
      res.message = "no new state of depth " + std::to_string(me.depth) + " from the " + (s ? "goal" : "start") +
                    " survives the count bound of --max-depth " + std::to_string(opt.maxDepth);
      return finishStats();
    }
    if (me.levelBegin == me.levelEnd) {
      // No new state on this side: every sequence of any length (within the region cap) was seen.
      res.stoppedBy = "exhausted";
      return finishStats();
    }
  }
  res.stoppedBy = "depth";
  return finishStats();
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
