// Decomposition search: a bidirectional breadth-first search over atomic operations (and their
// inverses) that stay local to a region, from a "before" complex to an "after" complex, states
// deduplicated by the canonical form of the region with its boundary fixed.
//
// Local: every hex removed is a region hex or one the sequence created, every new hex
// joins the region, and every host hex keeps its vertices, its gluings to other host hexes and
// its edges — only which region hex it touches across a region boundary quad may change.
#pragma once
#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include "complex/complex.hpp"
#include "ops/op_step.hpp"

namespace hexdual {

struct SearchProblem {
  std::string name;
  Complex start, goal;
  std::vector<HexId> host;  // hexes outside the region (same ids and vertices in start and goal)
};

// The before side of a flip as the region of the closed 4-cube boundary (host = the after facets),
// and the goal: the flip applied directly.
SearchProblem flipProblem(const std::string& flipName);
// The triple-chord push at the centre corner of a 3x3x3 grid (region: the 8 hexes at that vertex).
SearchProblem tripleChordPushProblem();

// One completed level of the search (for progress and growth figures).
struct SearchLevel {
  int side = 0;                                // 0: from the start, 1: from the goal
  int depth = 0;                               // that side's depth after the level
  int64_t newStates = 0;                       // states first reached at this level
  int64_t storedStates = 0, movesApplied = 0;  // totals so far
  double seconds = 0;
  bool lookedUp = false;  // a last level by lookup (SearchOptions::lookupLastLevel): children not stored
};

struct SearchOptions {
  int maxDepth = 4;            // total steps (split between the two directions)
  int64_t maxStates = 200000;  // stop when this many distinct states were stored
  double maxSeconds = 60;
  std::vector<OpKind> ops;    // operations to use; empty = all atomic operations and inverses
  int maxRegionHexes = 16;    // prune states whose region grows beyond this
  int threads = 1;            // threads over the frontier (the result does not depend on it)
  double maxMemoryMB = 4096;  // stop before the stored states could pass this
  int ringSplitMax = 8;       // ring splits generated forward: loops of at most this many edges (0: none)
  bool symmetry = false;      // store one state per orbit of the problem's symmetries
  bool prefilter = true;      // skip moves proven never valid and local without trying them
  bool countPruning = true;   // drop states whose (V, H) cannot reach the other end in the steps left
  // The last level by lookup: the other side's states are keyed once under every symmetry (the
  // identity alone without symmetry), and each child of the last level is keyed under the identity
  // only and looked up there; children are neither checked nor stored unless they meet. Same
  // answers; far less memory, and about half the time per move with symmetry. When the image keys
  // (20 bytes a hash slot, load <= 0.7) would pass maxMemoryMB, children are keyed by orbit instead.
  bool lookupLastLevel = false;
  // Every step must report its inverse step (so the sequence read backwards, step by step inverted,
  // is a decomposition of the inverse flip). Goal-side moves always must.
  bool reversible = false;
  std::function<void(const SearchLevel&)> progress;  // called after every completed level
  size_t chunk = 512;          // frontier states per chunk: merges, limits and checkpoints fall between chunks
  std::string checkpointFile;  // where checkpoints are written ("": none)
  double checkpointEvery = 0;  // seconds between checkpoints (0: only when a limit or a request stops the search)
  std::string resumeFile;      // continue the search saved there (same problem and options)
  // Set from outside (a signal handler): 1 = write a checkpoint and go on, 2 = write one and stop.
  std::atomic<int>* request = nullptr;
};

struct SearchResult {
  bool found = false;
  std::vector<OpStep> steps;   // steps from start (replay with applyStep)
  int depthSearched = 0;       // every sequence up to this length was examined (if not found)
  int64_t statesExplored = 0;  // distinct states stored (both directions)
  int64_t movesApplied = 0;    // moves that applied (before deduplication)
  int64_t prunedByCounts = 0;  // children dropped by the count bound (countPruning)
  size_t memoryBytes = 0;      // peak bytes of the stored states and their hash sets
  double seconds = 0;
  std::string stoppedBy;  // "found", "depth", "exhausted", "states", "time", "memory", "interrupted"
  std::string message;    // why the search stopped early, for the user
  std::vector<SearchLevel> levels;
  int symmetries = 1;   // the order of the symmetry group used (1: none)
  int checkpoints = 0;  // checkpoints written by this run
  int64_t lookupKeys = 0;  // keys of the other side's states and their images (lookupLastLevel)
};

SearchResult searchDecomposition(const SearchProblem& problem, const SearchOptions& options);

// Whether applying `steps` to the problem's start gives a complex isomorphic to its goal with the
// region boundary fixed, every step local. Throws Error naming the failing step otherwise.
void verifyDecomposition(const SearchProblem& problem, const std::vector<OpStep>& steps);

}  // namespace hexdual

namespace hexdual {
// A place to embed a flip's before side: a mesh and the hexes that form the before side there.
struct Embedding {
  std::string name;
  Complex mesh;
  std::vector<HexId> before;
};
// Host meshes for a flip: the closed 4-cube boundary with its host part changed in three ways
// (as is, with a pillow between two host hexes, with a hex push between two host hexes), and,
// where the before side occurs in them, places in a 5x5x5 grid and an 8x3x3 O-grid. For
// "tripleChordPush": the 8 hexes around a vertex of 4x4x4 and 5x5x5 grids and an 8x3x3 O-grid,
// and the problem's 3x3x3 grid with a host quad pillowed.
std::vector<Embedding> flipEmbeddings(const std::string& flipName);
// Replays the problem's steps inside the embedding (translated step by step through the
// canonical labellings of the two regions) and checks the result against the flip applied
// directly there (the triple-chord push: at one of the 8 hexes around the place's vertex), every step local, region boundary fixed. Throws Error naming what failed.
void verifyInEmbedding(const SearchProblem& problem, const std::vector<OpStep>& steps, const Embedding& where);
// Applies the problem's steps to `mesh`, where `beforeHexes` form the problem's before side;
// returns the steps as applied there (ids of `mesh`). Throws Error when a step cannot be placed.
std::vector<OpStep> replayInEmbedding(const SearchProblem& problem, const std::vector<OpStep>& steps, Complex& mesh,
                                      const std::vector<HexId>& beforeHexes, const std::string& placeName);
}  // namespace hexdual
