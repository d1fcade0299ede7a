// Shared checks for the sheet-operation suites (test_sheet_*.cpp, test_column_collapse.cpp): one
// step applied with the dual tracker and checked every way, and random steps with fixed seeds.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <functional>
#include <cstdio>
#include <map>
#include <random>
#include <string>

#include "complex/builders.hpp"
#include "complex/canonical.hpp"
#include "dual/dual_tracker.hpp"
#include "helpers.hpp"
#include "ops/candidates.hpp"
#include "ops/op_table.hpp"
#include "ops/oplog.hpp"
#include "ops/report.hpp"
#include "ops/sheet_ops.hpp"

namespace hexdual::test {

// Whether a refusal is `prefix` followed by a non-manifold link in either wording: the release
// build's local check (validateAround) says "its link is not connected", the debug build's full
// validate() counts the link's components ("its link has 2 components").
inline bool nonManifoldLink(const std::string& message, const std::string& prefix) {
  return message == prefix + "its link is not connected)" || message == prefix + "its link has 2 components)";
}

// The smallest hex alive in both: the anchor of isomorphicAt after steps that renumber vertices.
inline HexId commonHex(const Complex& a, const Complex& b) {
  for (HexId h : a.hexes())
    if (b.isHex(h)) return h;
  return -1;
}

// What a checked step did: applied (its report) or refused (its rule and message).
struct Checked {
  bool applied = false;
  std::string rule, error;
  StepReport report;
};

// Applies `step` to cx with the tracker. A refusal must name a rule and leave cx byte for byte as
// it was. Otherwise: validate() passes; Δ(V,E,F,H) is the change of counts(); the tracked dual
// equals a fresh extraction; a reported inverse applies (on a copy) and gives back a complex
// isomorphic to the start; undo (when asked) restores the state exactly, and the dual with it.
inline Checked checkSheetStep(Complex& cx, DualTracker& tracker, const OpStep& step, bool undo) {
  Checked out;
  const std::string dump = stateDump(cx);
  const Complex before = cx;
  const Counts c0 = cx.counts();
  try {
    out.report = applyStepTracked(cx, tracker, step);
  } catch (const Error& e) {
    out.error = e.what();
    out.rule = ruleOf(out.error);
    REQUIRE(stateDump(cx) == dump);
    return out;
  }
  out.applied = true;
  const OpResult& r = out.report.result;
  cx.validate();
  const Counts c1 = cx.counts();
  CHECK(r.dV == c1.vertices - c0.vertices);
  CHECK(r.dE == c1.edges - c0.edges);
  CHECK(r.dF == c1.quads - c0.quads);
  CHECK(r.dH == c1.hexes - c0.hexes);
  validateDual(cx, tracker.dual());
  compareDuals(cx, tracker.dual(), extractDual(cx));
  CHECK((r.inverse || !r.noInverse.empty()));
  if (r.inverse) {
    CAPTURE(formatOpStep(*r.inverse).substr(0, 200));
    Complex back = cx;
    OpResult inv = applyStep(back, *r.inverse);
    back.validate();
    CHECK(isomorphicAt(back, commonHex(back, before), before, commonHex(back, before)));
  }
  if (undo) {
    cx.undo(r.edits);
    tracker.update(cx, r.edits, keepsSheetTopology(r));
    tracker.releaseRetiredTail();
    REQUIRE(stateDump(cx) == dump);  // the same ids, gluings and positions: the same complex
    compareDuals(cx, tracker.dual(), extractDual(cx));
  }
  return out;
}

// A ring of `around` x 2 hexes (2 radial, 1 axial) whose cross-section turns half round before the
// ring closes: the sheet crossed by the radial edges, and the surface of quads between the two
// radial layers, are Moebius bands (one-sided). Hex (i, r) has id 2i + r; local x around, y radial.
inline Complex makeMobiusRing(int around) {
  std::vector<Vec3> p;
  for (int i = 0; i < around; ++i)
    for (int r = 0; r < 3; ++r)
      for (int z = 0; z < 2; ++z) p.push_back({double(i), double(r), double(z)});
  auto id = [&](int i, int r, int z) {
    if (i == around) i = 0, r = 2 - r, z = 1 - z;  // the half turn
    return VertexId(6 * i + 2 * r + z);
  };
  std::vector<std::array<VertexId, 8>> hexes;
  for (int i = 0; i < around; ++i)
    for (int r = 0; r < 2; ++r) {
      std::array<VertexId, 8> v;
      for (int c = 0; c < 8; ++c) v[size_t(c)] = id(i + tables::cornerBit(c, 0), r + tables::cornerBit(c, 1), tables::cornerBit(c, 2));
      hexes.push_back(v);
    }
  return fromConnectivity(p, hexes);
}

// " rule=count ..." of a tally.
inline std::string tallyLine(const std::map<std::string, int>& tally) {
  std::string line;
  for (auto& [k, v] : tally) line += " " + k + "=" + std::to_string(v);
  return line;
}

// What the dual tracker's update visited for a step at the centre of an n^3 grid (`step` makes
// its text from the centre hex id), after checking the tracked dual against a fresh extraction.
struct UpdateCost {
  size_t sheetSlots, chordSlots;
  bool reflooded;
};
inline UpdateCost costAtCentre(int n, const std::function<std::string(const std::string& centre)>& step) {
  Complex cx = makeGrid(n, n, n);
  DualTracker tracker(cx);
  const int c = n / 2;
  applyStepTracked(cx, tracker, parseOpStep(step(std::to_string(c + n * (c + n * c)))));
  compareDuals(cx, tracker.dual(), extractDual(cx));
  return {tracker.sheetSlotsTouched(), tracker.chordSlotsTouched(), tracker.lastUpdateReflooded()};
}
// costAtCentre at two grid sizes, printed: the cost tests assert how each count grows with n.
inline std::pair<UpdateCost, UpdateCost> costsAtCentre(int small, int big,
                                                       const std::function<std::string(const std::string& centre)>& step) {
  const UpdateCost a = costAtCentre(small, step), b = costAtCentre(big, step);
  MESSAGE("sheet slots " << small << "^3 / " << big << "^3: " << a.sheetSlots << " / " << b.sheetSlots << ", chord slots "
                         << a.chordSlots << " / " << b.chordSlots << (a.reflooded || b.reflooded ? " (re-flooded)" : ""));
  return {a, b};
}

// A random step of a sheet operation on live entities: the sheet or chord through a random edge,
// or a random hex with up to three neighbours (sheet-pillow).
inline OpStep randomSheetStep(const Complex& cx, std::mt19937& rng, OpKind op) {
  std::vector<HexId> live;
  for (HexId h : cx.hexes()) live.push_back(h);
  const HexId h = live[rng() % live.size()];
  const EdgeRef e{h, int(rng() % 12)};
  switch (op) {
    case OpKind::SheetDice: return makeStep(op, e, Count{2 + int(rng() % 2)});
    case OpKind::SheetPillow: {
      OpStep st{op, {OpArg::of(h)}, 0};
      for (int i = int(rng() % 4); i > 0; --i)
        if (Gluing g = cx.gluing(h, int(rng() % 6)); !g.boundary()) st.args.push_back(OpArg::of(g.hex));
      return st;
    }
    default: return makeStep(op, e);
  }
}

// A 3x3x3 grid (or, one seed in three, a 6x2x2 O-grid) after three random atomic steps, chosen
// among the candidates of pillow, hex push, chord push, face collapse and ring collapse: the
// steps that make sheets and chords touch themselves, fold, pinch and reach the boundary twice.
inline Complex randomAtomicMesh(uint32_t seed) {
  const OpKind kinds[] = {OpKind::Pillow, OpKind::HexPush, OpKind::ChordPush, OpKind::FaceCollapse, OpKind::RingCollapse};
  std::mt19937 rng(seed);
  Complex cx = seed % 3 ? makeGrid(3, 3, 3) : makeRing(6, 2, 2);
  for (int k = 0; k < 3; ++k) {
    const auto c = candidates(cx, kinds[rng() % 5]);
    if (!c.empty()) applyStep(cx, c[rng() % c.size()]);
  }
  return cx;
}

// Every step `stepsOf` lists for randomAtomicMesh(seed), for `count` seeds from `first` (printed),
// checked with checkSheetStep and undone. The tally: "<op> applied" (", no inverse" when it has
// none) and "<op> <rule>" for refusals.
inline std::map<std::string, int> everyStepAfterRandomAtomic(uint32_t first, uint32_t count,
                                                            const std::function<std::vector<OpStep>(const Complex&)>& stepsOf) {
  std::map<std::string, int> tally;
  for (uint32_t seed = first; seed < first + count; ++seed) {
    CAPTURE(seed);
    Complex cx = randomAtomicMesh(seed);
    DualTracker tracker(cx);
    for (const OpStep& step : stepsOf(cx)) {
      Checked c = checkSheetStep(cx, tracker, step, true);
      const std::string op = opName(step.op);
      ++tally[c.applied ? op + " applied" + (c.report.result.inverse ? "" : ", no inverse") : op + " " + c.rule];
    }
  }
  MESSAGE("seeds " << first << ".." << first + count - 1 << ":" << tallyLine(tally));
  return tally;
}
// One edge per sheet (of its smallest slot), and both diagonals of every chord.
inline std::vector<EdgeRef> sheetEdges(const Complex& cx) {
  std::vector<EdgeRef> out;
  for (const Sheet& s : extractDual(cx).sheets) out.push_back({s.slots[0].hex, 4 * s.slots[0].axis});
  return out;
}
inline std::vector<EdgeRef> chordEdges(const Complex& cx) {
  std::vector<EdgeRef> out;
  for (const Chord& ch : extractDual(cx).chords)
    for (int k : {0, 1}) out.push_back({ch.slots[0].hex, 4 * ch.slots[0].axis + k});
  return out;
}
// One step per edge: everyStepAfterRandomAtomic's lists of every sheet's or every chord's step.
inline std::vector<OpStep> stepsOn(const std::vector<EdgeRef>& edges, const std::function<OpStep(EdgeRef)>& make) {
  std::vector<OpStep> out;
  for (EdgeRef e : edges) out.push_back(make(e));
  return out;
}
// Δ(V, E, F, H) of a result.
inline void checkDelta(const OpResult& r, int64_t dV, int64_t dE, int64_t dF, int64_t dH) {
  CHECK(r.dV == dV);
  CHECK(r.dE == dE);
  CHECK(r.dF == dF);
  CHECK(r.dH == dH);
}

// Random sequences (seeds printed): each step an atomic candidate or a random sheet step of `op`;
// every sheet step checked with checkSheetStep; the whole sequence undone exactly at the end.
// Returns how many steps of `op` applied, per rule refused (key "applied" for the applied).
inline std::map<std::string, int> randomSheetRuns(const Complex& start, uint32_t firstSeed, int sequences, OpKind op) {
  std::map<std::string, int> tally;
  for (int s = 0; s < sequences; ++s) {
    const uint32_t seed = firstSeed + uint32_t(s);
    CAPTURE(seed);
    std::mt19937 rng(seed);
    Complex cx = start;
    DualTracker tracker(cx);
    std::vector<OpResult> done;
    for (int k = 0, n = 2 + int(rng() % 5); k < n; ++k) {
      OpStep step = randomSheetStep(cx, rng, op);
      if (rng() % 3 == 0) {  // an atomic step in between: pillows and hex pushes make the sheets less regular
        const HexId h = step.args[0].hex;
        step = rng() % 2 ? makeStep(OpKind::Pillow, QuadSide{h, int(rng() % 6)}) : makeStep(OpKind::HexPush, QuadSide{h, int(rng() % 6)});
      }
      CAPTURE(formatOpStep(step).substr(0, 200));
      Checked c = checkSheetStep(cx, tracker, step, false);
      if (step.op == op) ++tally[c.applied ? "applied" : c.rule.empty() ? c.error : c.rule];
      if (c.applied) done.push_back(c.report.result);
    }
    for (auto it = done.rbegin(); it != done.rend(); ++it) {
      cx.undo(it->edits);
      tracker.update(cx, it->edits, keepsSheetTopology(*it));
    }
    REQUIRE(stateDump(cx) == stateDump(start));
    compareDuals(cx, tracker.dual(), extractDual(cx));
  }
  MESSAGE(std::string(opName(op)) << " random runs, seeds " << firstSeed << ".." << firstSeed + uint32_t(sequences) - 1 << ":"
                                  << tallyLine(tally));
  return tally;
}

}  // namespace hexdual::test
