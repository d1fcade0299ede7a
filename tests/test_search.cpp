// The decomposition search engine: its hash map, its region keys, its replay, its limits.
#include <doctest/doctest.h>

#include <cstdio>
#include <random>

#include "complex/builders.hpp"
#include "complex/canonical.hpp"
#include "flips/flip.hpp"
#include "flips/fourcube.hpp"
#include "flips/search.hpp"
#include "flips/search_state.hpp"
#include "ops/oplog.hpp"
#include "ops/ops.hpp"

using namespace hexdual;

TEST_CASE("FlatKeyMap: insert keeps the first value, finds every key after growth, misses absent keys") {
  const uint32_t seed = 1401;
  std::printf("FlatKeyMap seed %u\n", seed);
  std::mt19937_64 rng(seed);
  FlatKeyMap m(16);
  std::vector<Key128> keys;
  for (int i = 0; i < 5000; ++i) keys.push_back({rng(), rng()});
  for (int i = 0; i < 5000; ++i) CHECK(m.insert(keys[size_t(i)], i) == i);
  CHECK(m.size() == 5000);
  CHECK(m.slots() == 8192);  // load stays at or below 0.7
  for (int i = 0; i < 5000; ++i) CHECK(m.insert(keys[size_t(i)], -7) == i);
  CHECK(m.size() == 5000);
  for (int i = 0; i < 5000; ++i) CHECK(m.find(keys[size_t(i)]) == i);
  for (int i = 0; i < 1000; ++i) CHECK(m.find({rng(), rng()}) == -1);
  // Keys equal in their low word only are still told apart.
  FlatKeyMap n;
  CHECK(n.insert({5, 1}, 1) == 1);
  CHECK(n.insert({5, 2}, 2) == 2);
  CHECK(n.find({5, 1}) == 1);
  CHECK(n.find({5, 2}) == 2);
  CHECK(n.find({5, 3}) == -1);
}

TEST_CASE("hashWords: never the empty key; order and length matter") {
  CHECK_FALSE(hashWords({}).empty());
  CHECK(hashWords({1, 2}) != hashWords({2, 1}));
  CHECK(hashWords({0}) != hashWords({0, 0}));
  CHECK(hashWords({3, -4}) == hashWords({3, -4}));
}

namespace {
std::vector<uint8_t> hostMask(const std::vector<HexId>& host) {
  std::vector<uint8_t> m;
  for (HexId h : host) {
    if (size_t(h) >= m.size()) m.resize(size_t(h) + 1, 0);
    m[size_t(h)] = 1;
  }
  return m;
}
std::vector<HexId> regionHexes(const Complex& cx, const std::vector<uint8_t>& isHost) {
  std::vector<HexId> r;
  for (HexId h : cx.hexes())
    if (size_t(h) >= isHost.size() || !isHost[size_t(h)]) r.push_back(h);
  return r;
}
}  // namespace

TEST_CASE("RegionEncoder keys agree with canonical forms of the region (random local moves, fixed seed)") {
  const uint32_t seed = 2026;
  std::printf("RegionEncoder seed %u\n", seed);
  std::mt19937 rng(seed);
  SearchProblem pb = flipProblem("3-5e");
  auto isHost = hostMask(pb.host);
  RegionEncoder enc;
  // States reached by short random walks of hex pushes, pillows and chord pushes in the region.
  std::vector<Complex> states{pb.start, pb.goal};
  for (int walk = 0; walk < 12; ++walk) {
    Complex cx = pb.start;
    for (int step = 0; step < 3; ++step) {
      auto region = regionHexes(cx, isHost);
      HexId h = region[rng() % region.size()];
      int f = int(rng() % 6);
      try {
        if (rng() % 2)
          hexPush(cx, {h, f});
        else
          pillow(cx, {h, f});
      } catch (const Error&) {
      }
      states.push_back(cx);
    }
  }
  int equalPairs = 0;
  for (size_t i = 0; i < states.size(); ++i)
    for (size_t j = 0; j < states.size(); ++j) {
      bool sameForm = canonicalForm(subcomplex(states[i], regionHexes(states[i], isHost)), true) ==
                      canonicalForm(subcomplex(states[j], regionHexes(states[j], isHost)), true);
      CHECK((enc.key(states[i], isHost) == enc.key(states[j], isHost)) == sameForm);
      equalPairs += sameForm && i != j;
    }
  CHECK(equalPairs > 0);  // the walks revisit states, so equality is exercised too
  // The goal differs from the start; the flip done by its stored steps equals the goal.
  CHECK(enc.key(pb.start, isHost) != enc.key(pb.goal, isHost));
  Complex viaSteps = pb.start;
  for (const OpStep& st :
       parseOpLog("v1;hexpush h0f0;facecollapse h3e8 h8f2 h4f3;facesplit h7f4 h13f2;chordpull h4").steps)
    applyStep(viaSteps, st);
  CHECK(enc.key(viaSteps, isHost) == enc.key(pb.goal, isHost));
}

TEST_CASE("the search engine finds the known short decompositions again, the same with 1 and 2 threads") {
  // (2-6 and 1-7 are in test_flips.cpp.)
  SearchOptions o;
  o.maxDepth = 3;
  SearchResult r71 = searchDecomposition(flipProblem("7-1"), o);
  REQUIRE(r71.found);
  CHECK(r71.steps.size() == 2);
  verifyDecomposition(flipProblem("7-1"), r71.steps);
  o.maxDepth = 4;
  SearchProblem pb = flipProblem("3-5e");
  SearchResult plain = searchDecomposition(pb, o);
  REQUIRE(plain.found);
  CHECK(plain.steps.size() == 4);
  verifyDecomposition(pb, plain.steps);
  CHECK(plain.symmetries == 1);
  CHECK(plain.memoryBytes > 0);
  CHECK(plain.memoryBytes < size_t(plain.statesExplored) * 100 + (1u << 20));
  CHECK(plain.memoryBytes >= size_t(plain.statesExplored) * 8);
  // One state per orbit of the 12 symmetries of 3-5e: fewer states, a verified 4-step answer,
  // the same with two threads.
  o.symmetry = true;
  SearchResult one = searchDecomposition(pb, o);
  o.threads = 2;
  SearchResult two = searchDecomposition(pb, o);
  CHECK(one.symmetries == 12);
  REQUIRE(one.found);
  REQUIRE(two.found);
  CHECK(one.steps.size() == 4);
  verifyDecomposition(pb, one.steps);
  CHECK(one.statesExplored * 4 < plain.statesExplored);
  CHECK(formatOpLog({1, one.steps}) == formatOpLog({1, two.steps}));
  CHECK(one.statesExplored == two.statesExplored);
  // (moves applied may differ: a thread stops its slice at a meeting, the other finishes its own)
}

TEST_CASE("symmetry groups of the problems: 4-4 vertex flip 24, triple-chord push 6") {
  // The stabilisers of the 4-4 vertex flip's before side (the axis permutations fixing the shared
  // vertex) and of the triple-chord push in the 3x3x3 grid (the axis permutations).
  SearchOptions o;
  o.symmetry = true;
  o.maxDepth = 1;
  CHECK(searchDecomposition(flipProblem("4-4v"), o).symmetries == 24);
  CHECK(searchDecomposition(tripleChordPushProblem(), o).symmetries == 6);
}

TEST_CASE("ring splits are generated forward: the goal side undoes ring collapses, so 3-5c is found at depth 4") {
  // 3-5c = hexpush, hexpush, ringcollapse, unpillow: from the goal side the ring collapse is a
  // ring split. Without forward ring splits the 2+2 split of depth 4 cannot meet.
  SearchProblem pb = flipProblem("3-5c");
  SearchOptions o;
  o.maxDepth = 4;
  o.symmetry = true;
  SearchResult with = searchDecomposition(pb, o);
  REQUIRE(with.found);
  CHECK(with.steps.size() == 4);
  verifyDecomposition(pb, with.steps);
  o.ringSplitMax = 0;
  SearchResult without = searchDecomposition(pb, o);
  CHECK_FALSE(without.found);
  CHECK(without.stoppedBy == "depth");
}

TEST_CASE("search limits: the state cap and the memory guard stop with a message; an exhausted space says so") {
  SearchProblem pb = flipProblem("4-4v");
  SearchOptions o;
  o.maxDepth = 6;
  o.maxStates = 20;
  o.symmetry = true;
  SearchResult capped = searchDecomposition(pb, o);
  CHECK_FALSE(capped.found);
  CHECK(capped.stoppedBy == "states");
  CHECK(capped.message == "stopped at the state cap (--max-states 20) during depth 3");
  CHECK(capped.statesExplored > 20);
  o.maxStates = 1000000;
  o.maxMemoryMB = 0.01;
  SearchResult guarded = searchDecomposition(pb, o);
  CHECK(guarded.stoppedBy == "memory");
  CHECK(guarded.message.rfind("stopped by the memory guard (--max-memory 0 MB; ", 0) == 0);
  // Hex pulls alone: the 2-6 before side (two hexes) has no hex pull, so the start side is empty
  // after one level and no sequence of any length exists.
  o = SearchOptions{};
  o.maxDepth = 9;
  o.ops = {OpKind::HexPull};
  SearchResult none = searchDecomposition(flipProblem("2-6"), o);
  CHECK_FALSE(none.found);
  CHECK(none.stoppedBy == "exhausted");
  CHECK(none.depthSearched == 1);
  CHECK(none.statesExplored == 2);
}

#include "ops/candidates.hpp"

TEST_CASE("invariants behind the search bounds: each operation's change of H and of V - H") {
  // Chord push and pull change H by +2 / -2 and keep V - H; the hex push adds 4 hexes. So a
  // sequence of chord pushes and pulls doing a hex push has (pushes - pulls) = 2: its length is
  // even. Pillows and face collapses (and their inverses) are the only steps that change V - H.
  const uint32_t seed = 77;
  std::printf("invariants seed %u\n", seed);
  std::mt19937 rng(seed);
  SearchProblem pb = flipProblem("2-6");
  Complex cx = pb.start;
  const Counts goal = pb.goal.counts(), start = pb.start.counts();
  CHECK(goal.hexes - start.hexes == 4);
  CHECK(goal.vertices - goal.hexes == start.vertices - start.hexes);
  int pushes = 0, pulls = 0;
  for (int step = 0; step < 8; ++step) {
    OpKind kind = step % 3 == 2 ? OpKind::ChordPull : OpKind::ChordPush;
    auto cs = candidates(cx, kind);
    if (cs.empty()) continue;
    OpResult r = applyStep(cx, cs[rng() % cs.size()]);
    CHECK(r.dH == (kind == OpKind::ChordPush ? 2 : -2));
    CHECK(r.dV == r.dH);
    (kind == OpKind::ChordPush ? pushes : pulls) += 1;
  }
  CHECK(pushes >= 4);
  CHECK(pulls >= 1);
  Complex g = pb.start;
  auto hp = candidates(g, OpKind::HexPush);
  REQUIRE_FALSE(hp.empty());
  OpResult r = applyStep(g, hp[0]);
  CHECK(r.dH == 4);
  CHECK(r.dV - r.dH == 0);
  Complex p = pb.start;
  auto pl = candidates(p, OpKind::Pillow);
  REQUIRE_FALSE(pl.empty());
  OpResult rp = applyStep(p, pl[0]);
  CHECK(rp.dV - rp.dH == 2);
}

#include "ops/support.hpp"

namespace {
// The search with every option at its default and symmetry, then with `option` switched off.
std::pair<SearchResult, SearchResult> withAndWithout(const SearchProblem& pb, int depth, bool SearchOptions::*option) {
  SearchOptions o;
  o.maxDepth = depth;
  o.symmetry = true;
  SearchResult with = searchDecomposition(pb, o);
  o.*option = false;
  return {with, searchDecomposition(pb, o)};
}
}  // namespace

TEST_CASE("move prefilters drop only moves that are never valid and local: the same states level by level") {
  // Face collapses merging vertices of one hex or two host vertices, ring collapses through host
  // hexes or merging host vertices, hex pulls whose ring is not 4 region hexes, splits giving host
  // hexes new vertex ids, chord pushes whose quads share more than the edge: all skipped untried.
  for (const char* name : {"4-4m", "3-5e"}) {
    auto [with, without] = withAndWithout(flipProblem(name), 3, &SearchOptions::prefilter);
    INFO(name);
    CHECK(with.statesExplored == without.statesExplored);
    REQUIRE(with.levels.size() == without.levels.size());
    for (size_t i = 0; i < with.levels.size(); ++i) CHECK(with.levels[i].newStates == without.levels[i].newStates);
    CHECK(with.movesApplied <= without.movesApplied);
  }
  // Exact counts of the 4-4m search to depth 3 (a = 2, b = 1), one state per orbit of 8 symmetries:
  // 1 + 1 roots, 21 + 21 states of depth 1, and of the 1,118 of depth 2 (the last level) the 559
  // whose counts occur on the goal side.
  SearchOptions o;
  o.maxDepth = 3;
  o.symmetry = true;
  SearchResult r = searchDecomposition(flipProblem("4-4m"), o);
  CHECK(r.symmetries == 8);
  CHECK(r.statesExplored == 603);
  o.countPruning = false;
  CHECK(searchDecomposition(flipProblem("4-4m"), o).statesExplored == 1162);
}

TEST_CASE("DeferValidation: operations commit without their invariant check; undo restores the complex") {
  // Every face collapse in the closed 4-cube: those refused as "not a valid complex" commit under
  // the guard (the caller checks), and undo gives the complex back; outside it they are refused again.
  Complex cx = makeFourCubeBoundary();
  const std::vector<int64_t> form = canonicalForm(cx, true);
  int refused = 0, deferred = 0;
  for (HexId h = 0; h < 8; ++h)
    for (int e = 0; e < 12; ++e) {
      ops::EdgeStar st = ops::closedEdgeStar(cx, {h, e}, "test");
      for (size_t i = 0; i < st.inc.size(); ++i)
        for (size_t j = i + 1; j < st.inc.size(); ++j) {
          QuadSide f{st.inc[i].hex, st.exitFace[i]}, g{st.inc[j].hex, st.exitFace[j]};
          try {
            faceCollapse(cx, {h, e}, f, g);
            FAIL("a face collapse in the closed 4-cube was accepted");
          } catch (const Error& err) {
            if (std::string(err.what()).find("not be a valid complex") == std::string::npos) continue;
          }
          ++refused;
          OpResult r;
          {
            ops::DeferValidation unchecked;
            CHECK(ops::DeferValidation::active());
            r = faceCollapse(cx, {h, e}, f, g);
            ++deferred;
          }
          CHECK_FALSE(ops::DeferValidation::active());
          CHECK_THROWS(cx.validate());
          cx.undo(r.edits);
          CHECK(canonicalForm(cx, true) == form);
        }
    }
  CHECK(refused > 0);
  CHECK(deferred == refused);
  cx.validate();
}

TEST_CASE("count pruning: the same answers with fewer states; a level emptied by the bound proves the depth") {
  // Chord push and pull change (V, H) by (+2, +2) and (-2, -2); the 2-6 goal has 4 more hexes.
  // From the goal there is no chord to pull, and after one push (H + 6 from the start) three pulls
  // are needed: with 3 steps in all, nothing from the goal side survives.
  SearchProblem pb = flipProblem("2-6");
  SearchOptions o;
  o.ops = {OpKind::ChordPush, OpKind::ChordPull};
  o.symmetry = true;
  o.maxDepth = 3;
  SearchResult three = searchDecomposition(pb, o);
  CHECK_FALSE(three.found);
  CHECK(three.stoppedBy == "depth");
  CHECK(three.depthSearched == 3);
  CHECK(three.message == "no new state of depth 1 from the goal survives the count bound of --max-depth 3");
  CHECK(three.prunedByCounts > 0);
  o.maxDepth = 5;
  SearchResult pruned = searchDecomposition(pb, o);
  o.countPruning = false;
  SearchResult full = searchDecomposition(pb, o);
  CHECK_FALSE(pruned.found);
  CHECK_FALSE(full.found);
  CHECK(pruned.depthSearched == 5);
  CHECK(full.depthSearched == 5);
  CHECK(pruned.statesExplored == 114);
  CHECK(full.statesExplored == 4443);
  CHECK(full.prunedByCounts == 0);
  // All operations (ring operations make the bound on V - H unknown, and H steps up to 16): the
  // last level still meets only states with the other side's counts. 3-5e is found again.
  SearchProblem e = flipProblem("3-5e");
  auto [a, b] = withAndWithout(e, 4, &SearchOptions::countPruning);
  REQUIRE(a.found);
  REQUIRE(b.found);
  CHECK(a.steps.size() == 4);
  verifyDecomposition(e, a.steps);
  CHECK(a.statesExplored == 896);
  CHECK(b.statesExplored == 997);
}

#include <filesystem>

TEST_CASE("checkpoint and resume: a search stopped and resumed gives the uninterrupted result") {
  // 3-5e to depth 4 with chunks of 8 frontier states: checkpoints fall inside levels.
  const std::string file = (std::filesystem::temp_directory_path() / "hexdual_test_search.ckpt").string();
  SearchProblem pb = flipProblem("3-5e");
  SearchOptions o;
  o.maxDepth = 4;
  o.symmetry = true;
  o.chunk = 8;
  SearchResult whole = searchDecomposition(pb, o);
  REQUIRE(whole.found);
  CHECK(whole.checkpoints == 0);
  auto same = [&](const SearchResult& r) {
    REQUIRE(r.found);
    CHECK(formatOpLog({1, r.steps}) == formatOpLog({1, whole.steps}));
    CHECK(r.statesExplored == whole.statesExplored);
    CHECK(r.movesApplied == whole.movesApplied);
    REQUIRE(r.levels.size() == whole.levels.size());
    for (size_t i = 0; i < r.levels.size(); ++i) CHECK(r.levels[i].newStates == whole.levels[i].newStates);
  };
  // Stopped by the state cap inside depth 3 (the start side's second level), then resumed.
  o.checkpointFile = file;
  o.maxStates = 100;
  SearchResult capped = searchDecomposition(pb, o);
  CHECK(capped.stoppedBy == "states");
  CHECK(capped.checkpoints == 1);
  CHECK(capped.message == "stopped at the state cap (--max-states 100) during depth 3; checkpoint in " + file);
  o.checkpointFile.clear();
  o.maxStates = 200000;
  o.resumeFile = file;
  same(searchDecomposition(pb, o));
  // A request to stop (as SIGINT sets it) at the first chunk; a checkpoint at every chunk after.
  std::atomic<int> request{2};
  o.resumeFile.clear();
  o.checkpointFile = file;
  o.request = &request;
  SearchResult stopped = searchDecomposition(pb, o);
  CHECK(stopped.stoppedBy == "interrupted");
  CHECK(stopped.message == "stopped on request during depth 1; checkpoint in " + file);
  request = 0;
  o.resumeFile = file;
  o.checkpointEvery = 1e-9;
  SearchResult resumed = searchDecomposition(pb, o);
  same(resumed);
  CHECK(resumed.checkpoints == 5);  // one per chunk start: levels of 1, 1, 11 and 16 states in chunks of 8
  // A checkpoint belongs to one search.
  o.checkpointFile.clear();
  o.maxDepth = 5;
  CHECK_THROWS_WITH(
      searchDecomposition(pb, o),
      ("resume: " + file +
       " belongs to another search (3-5e; depth 4; ops; region 16; ring split 8; symmetry 1; prefilter 1; "
       "count pruning 1; chunk 8), not this one (3-5e; depth 5; ops; region 16; ring split 8; symmetry 1; "
       "prefilter 1; count pruning 1; chunk 8)")
          .c_str());
  std::filesystem::remove(file);
}

TEST_CASE("the hex push is a ring split: the 2-6 flip is one ring split of the 4 edges of the pushed quad") {
  // TK03 §4.4 calls face/ring collapse reversible; its inverse along the loop of the quad's edges
  // separates each of the 4 nodes of that loop and inserts the 4 ring hexes of a hex push.
  SearchProblem pb = flipProblem("2-6");
  SearchOptions o;
  o.maxDepth = 2;
  o.ops = {OpKind::RingSplit};
  SearchResult r = searchDecomposition(pb, o);
  REQUIRE(r.found);
  REQUIRE(r.steps.size() == 1);
  CHECK(r.steps[0].op == OpKind::RingSplit);
  CHECK(r.steps[0].args.size() == 4);
  CHECK(formatOpLog({1, r.steps}) == "v1;ringsplit h6f0/h2f4 h0f3/h2f3 h0f5/h2f5 h0f2/h2f2");
  verifyDecomposition(pb, r.steps);
  int places = 0;
  for (const Embedding& e : flipEmbeddings("2-6")) {
    CAPTURE(e.name);
    verifyInEmbedding(pb, r.steps, e);
    ++places;
  }
  CHECK(places == 6);  // the 4-cube as is, pillowed, hex-pushed; two 5x5x5 grid places, one O-grid place
}

TEST_CASE("last level by lookup: the same answers, the last level's children neither checked nor stored") {
  // The other side is keyed once under every symmetry; a last-level child is keyed under the
  // identity only and looked up there. Found and not found alike must agree with the stored mode.
  for (bool symmetry : {true, false}) {
    INFO("symmetry " << symmetry);
    SearchProblem pb = flipProblem("3-5e");
    SearchOptions o;
    o.maxDepth = 4;
    o.symmetry = symmetry;
    o.maxSeconds = 3600;
    SearchResult stored = searchDecomposition(pb, o);
    o.lookupLastLevel = true;
    SearchResult looked = searchDecomposition(pb, o);
    o.threads = 2;
    SearchResult two = searchDecomposition(pb, o);
    REQUIRE(stored.found);
    REQUIRE(looked.found);
    REQUIRE(two.found);
    CHECK(looked.steps.size() == 4);
    verifyDecomposition(pb, looked.steps);
    CHECK(formatOpLog({1, looked.steps}) == formatOpLog({1, two.steps}));
    CHECK(looked.statesExplored < stored.statesExplored);
    CHECK(looked.lookupKeys > 0);
    CHECK(stored.lookupKeys == 0);
  }
  // 4-4 vertex flip to depth 5: none either way; the first four levels are the same, the fifth
  // (the start side's level 3) is looked up against the goal side's 341 states in their 24 images.
  SearchProblem v = flipProblem("4-4v");
  SearchOptions o;
  o.maxDepth = 5;
  o.symmetry = true;
  o.maxStates = 1000000;
  o.maxSeconds = 3600;  // (under ASan on a loaded machine this takes minutes)
  SearchResult stored = searchDecomposition(v, o);
  o.lookupLastLevel = true;
  SearchResult looked = searchDecomposition(v, o);
  CHECK_FALSE(stored.found);
  CHECK_FALSE(looked.found);
  CHECK(stored.depthSearched == 5);
  CHECK(looked.depthSearched == 5);
  CHECK(looked.stoppedBy == "depth");
  CHECK(stored.statesExplored == 19898);
  CHECK(looked.statesExplored == 682);
  CHECK(looked.lookupKeys == 6746);
  REQUIRE(looked.levels.size() == 5);
  CHECK(looked.levels.back().lookedUp);
  CHECK_FALSE(stored.levels.back().lookedUp);
  for (size_t i = 0; i + 1 < looked.levels.size(); ++i) CHECK(looked.levels[i].newStates == stored.levels[i].newStates);
  CHECK(looked.memoryBytes > 0);
  // When the image keys (16,384 slots here) would pass the memory limit, children are keyed by
  // orbit and looked up in the other side's index: the same answer, no image keys.
  o.maxMemoryMB = 0.6;
  SearchResult byOrbit = searchDecomposition(v, o);
  CHECK_FALSE(byOrbit.found);
  CHECK(byOrbit.stoppedBy == "depth");
  CHECK(byOrbit.depthSearched == 5);
  CHECK(byOrbit.lookupKeys == 0);
  CHECK(byOrbit.statesExplored == 682);
  CHECK(byOrbit.movesApplied == looked.movesApplied);
  CHECK(byOrbit.levels.back().lookedUp);
  // Stopped at the start of the last level (a request after level 4, as SIGINT sets it) and
  // resumed: the image keys are made again and the result is the uninterrupted one.
  const std::string file = (std::filesystem::temp_directory_path() / "hexdual_test_lookup.ckpt").string();
  std::atomic<int> request{0};
  o.maxMemoryMB = 4096;
  o.chunk = 64;
  o.checkpointFile = file;
  o.request = &request;
  o.progress = [&](const SearchLevel& l) {
    if (l.side == 1 && l.depth == 2) request = 2;
  };
  SearchResult stopped = searchDecomposition(v, o);
  CHECK(stopped.stoppedBy == "interrupted");
  CHECK(stopped.message == "stopped on request during depth 5; checkpoint in " + file);
  request = 0;
  o.progress = nullptr;
  o.checkpointFile.clear();
  o.resumeFile = file;
  SearchResult resumed = searchDecomposition(v, o);
  CHECK_FALSE(resumed.found);
  CHECK(resumed.depthSearched == 5);
  CHECK(resumed.statesExplored == 682);
  CHECK(resumed.lookupKeys == 6746);
  CHECK(resumed.movesApplied == looked.movesApplied);
  std::filesystem::remove(file);
}

TEST_CASE("reversible: a step without an inverse step (a ring glued to itself) is no step of a reversible sequence") {
  // In a 3x3x3 grid: a chord push at the centre hex, then the ring collapse of its blind chord,
  // whose side quads are glued to the ring itself: that collapse reports no inverse step.
  Complex start = makeGrid(3, 3, 3);
  applyStep(start, parseOpLog("v1;chordpush h13e3 h13f3 h16f5").steps.at(0));
  Complex goal = start;
  OpResult r = applyStep(goal, parseOpLog("v1;ringcollapse h27e0").steps.at(0));
  REQUIRE_FALSE(r.inverse);
  CHECK(r.noInverse == "a side quad of the ring was glued to the ring itself");
  SearchProblem pb{"blind chord", start, goal, {}};  // no host: the whole grid is the region
  SearchOptions o;
  o.maxDepth = 1;
  o.maxRegionHexes = 40;
  o.ops = {OpKind::RingCollapse};
  SearchResult any = searchDecomposition(pb, o);
  REQUIRE(any.found);
  CHECK(formatOpLog({1, any.steps}) == "v1;ringcollapse h27e0");
  o.reversible = true;
  SearchResult reversible = searchDecomposition(pb, o);
  CHECK_FALSE(reversible.found);
  CHECK(reversible.depthSearched == 1);
}
