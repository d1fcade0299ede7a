#include "geometry/step_geometry.hpp"

#include <algorithm>
#include <map>

#include "dual/dual_tracker.hpp"
#include "geometry/degenerate.hpp"
#include "geometry/pinned.hpp"
#include "geometry/scaled_jacobian.hpp"
#include "geometry/smoothing.hpp"
#include "geometry/step_before.hpp"

namespace hexdual {

namespace {

// The movable vertices at the corners of `hexes`, each once (ascending), with a corner.
std::vector<FreeVertex> interiorCorners(const Complex& cx, const std::vector<HexId>& hexes) {
  std::map<VertexId, std::pair<HexId, int>> seen;
  for (HexId h : hexes)
    for (int c = 0; c < 8; ++c) seen.emplace(cx.vertex(h, c), std::pair{h, c});
  std::vector<FreeVertex> out;
  for (auto [v, hc] : seen)
    if (!pinnedVertex(cx, hc.first, hc.second)) out.push_back({v, hc.first, hc.second});
  return out;
}

// The hexes holding one of the vertices, ascending.
std::vector<HexId> hexesAround(const Complex& cx, const std::vector<FreeVertex>& vertices) {
  std::vector<HexId> out;
  for (const FreeVertex& f : vertices)
    for (auto [h, c] : cx.cornersOfVertex(f.hex, f.corner)) out.push_back(h);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<HexId> merged(std::vector<HexId> a, const std::vector<HexId>& b) {
  a.insert(a.end(), b.begin(), b.end());
  std::sort(a.begin(), a.end());
  a.erase(std::unique(a.begin(), a.end()), a.end());
  return a;
}

std::vector<HexId> invertedRegular(const Complex& cx, const std::vector<HexId>& hexes) {
  std::vector<HexId> out;
  for (HexId h : hexes)
    if (cx.isHex(h) && scaledJacobian(cx, h) <= 0 && !degenerateByConstruction(cx, h)) out.push_back(h);
  return out;
}

// The live hexes whose corners the step placed: created or re-cornered (re-glued neighbours keep
// their shape).
std::vector<HexId> reshapedByStep(const Complex& cx, const Complex::EditLog& log) {
  std::vector<HexId> out;
  for (const Complex::Edit& e : log.edits)
    if ((e.kind == Complex::Edit::AddHex || e.kind == Complex::Edit::SetCorner) && cx.isHex(e.hex))
      out.push_back(e.hex);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// The positions one ring of the smoothing reached, and what it left newly inverted.
struct RingResult {
  int ring = -1;  // -1: the operation's own placement (no moves)
  std::vector<std::pair<VertexId, Vec3>> moves;
  std::vector<HexId> around;    // the hexes around its free vertices, and the step's
  std::vector<HexId> inverted;  // regular hexes among `around` left inverted (and not inverted before the step)
};

// Every hex with a vertex of one of `hexes` (ascending): beyond them, the step changed neither
// the positions nor whether a hex is degenerate by construction (its edges' cycles and its
// vertices' stars are as they were).
std::vector<HexId> nearHexes(const Complex& cx, const std::vector<HexId>& hexes) {
  std::vector<FreeVertex> corners;
  for (HexId h : hexes)
    for (int c = 0; c < 8; ++c) corners.push_back({cx.vertex(h, c), h, c});
  return merged(hexesAround(cx, corners), hexes);
}

// Smooths the interior vertices of `hexes` (undone by cx.undo(edits)); `alive`: the live hexes
// the step touched; `near`: nearHexes(alive) (hexes not near that are inverted now were inverted
// and regular before the step: the smoothing keeps their corners from getting lower).
RingResult smoothRing(Complex& cx, const std::vector<HexId>& hexes, const std::vector<HexId>& alive,
                      const std::vector<HexId>& near, const StepBefore& before, Complex::EditLog& edits,
                      StepQuality& q) {
  RingResult res;
  const std::vector<FreeVertex> free = interiorCorners(cx, hexes);
  res.around = merged(hexesAround(cx, free), alive);
  // Inverted before the step and not touched by it (a touched one may have been degenerate then:
  // the smoothing tries to untangle it). `before` reads positions from cx: asked before any move.
  std::vector<HexId> already;
  for (HexId h : res.around)
    if (cx.isHex(h) && !before.touched(h) && before.invertedBefore(cx, h)) already.push_back(h);
  cx.beginTransaction();
  const SmoothingStats st = smoothVertices(cx, free, near, kStepEvaluationBudget - q.evaluations, already.empty());
  edits = cx.commitTransaction();
  q.evaluations += st.evaluations;
  for (VertexId v : st.moved) res.moves.push_back({v, cx.position(v)});
  for (HexId h : invertedRegular(cx, res.around))
    if (!std::binary_search(already.begin(), already.end(), h)) res.inverted.push_back(h);
  return res;
}

// The interior vertices of the hexes the step placed, then (while a regular hex around them or
// touched by the step is newly inverted and not every such hex is pinned) those of the hexes
// around them, ring by ring. Each ring starts again from the operation's own placement (a wider
// region is a new, larger problem); the ring leaving the fewest regular hexes newly inverted wins,
// the narrowest on ties. Leaves cx at the operation's placement.
RingResult fixedBoundaryRings(Complex& cx, const Complex::EditLog& log, const std::vector<HexId>& alive,
                              const std::vector<HexId>& near, const StepBefore& before, StepQuality& q) {
  std::vector<HexId> hexes = reshapedByStep(cx, log);
  RingResult best;
  Complex::EditLog edits;
  for (int ring = 0;; ++ring) {
    if (ring > 0) cx.undo(edits);
    RingResult res = smoothRing(cx, hexes, alive, near, before, edits, q);
    res.ring = ring;
    if (ring == 0 || res.inverted.size() < best.inverted.size()) best = res;
    if (res.inverted.empty() || ring == kWideningRings || q.evaluations >= kStepEvaluationBudget) break;
    if (std::all_of(res.inverted.begin(), res.inverted.end(), [&](HexId h) { return pinnedInversion(cx, h); })) break;
    hexes = res.around;
  }
  cx.undo(edits);
  return best;
}

// Places the step's vertices by the fixed-boundary rings, or keeps the operation's own placement
// when it leaves fewer regular hexes newly inverted (never worse than no smoothing: on a mesh
// tangled already the untangling can trade inversions the step did not make for new ones). Its
// moves join `log`; returns the hexes around its free vertices.
std::vector<HexId> smoothStep(Complex& cx, Complex::EditLog& log, const std::vector<HexId>& alive,
                              const StepBefore& before, StepQuality& q) {
  const std::vector<HexId> near = nearHexes(cx, alive);
  const int unsmoothed = before.newlyInverted(cx, near);
  RingResult best = fixedBoundaryRings(cx, log, alive, near, before, q);
  const auto newly = [&](HexId h) { return !before.invertedBefore(cx, h); };  // (cx is at the operation's placement)
  if (unsmoothed < std::count_if(best.inverted.begin(), best.inverted.end(), newly))
    best = RingResult{-1, {}, alive, {}};
  cx.beginTransaction();
  for (auto [v, p] : best.moves) cx.setPosition(v, p);
  const Complex::EditLog moves = cx.commitTransaction();
  log.edits.reserve(log.edits.size() + moves.edits.size());  // exactly (insert alone would double a large log)
  log.edits.insert(log.edits.end(), moves.edits.begin(), moves.edits.end());
  q.moved.clear();
  for (auto [v, p] : best.moves) q.moved.push_back(v);
  q.rings = std::max(best.ring, 0);
  q.kept = best.ring < 0;
  return best.around;
}

// The hexes of `region` with a corner the smoothing moved.
std::vector<HexId> reshaped(const Complex& cx, const std::vector<HexId>& region, const std::vector<VertexId>& moved) {
  std::vector<HexId> out;
  for (HexId h : region)
    for (VertexId v : cx.hexVertices(h))
      if (std::binary_search(moved.begin(), moved.end(), v)) {
        out.push_back(h);
        break;
      }
  return out;
}

// Measures `measured` (the touched hexes and those the smoothing reshaped) before and after.
void measure(const Complex& cx, const StepBefore& before, const std::vector<HexId>& measured, StepQuality& q) {
  for (HexId h : measured) {
    double sj = 1;
    if (before.scaledJacobianBefore(cx, h, sj)) q.before = std::min(q.before, sj);
  }
  VertexStars stars(cx);  // cx does not change while it is measured
  for (HexId h : measured) {
    if (!cx.isHex(h)) continue;
    const double sj = scaledJacobian(cx, h);
    const bool degenerate = degenerateByConstruction(cx, h, stars);
    q.after = std::min(q.after, sj);
    if (degenerate)
      q.degenerate.push_back(h);
    else
      q.afterRegular = std::min(q.afterRegular, sj);
    if (!degenerate && sj <= 0) q.inverted.push_back(h);
    if (!degenerate && sj <= 0 && pinnedInversion(cx, h, stars)) q.pinned.push_back(h);
  }
  q.measured = true;
}

}  // namespace

StepQuality placeStepGeometry(Complex& cx, Complex::EditLog& log, StepGeometry mode) {
  StepQuality q;
  if (mode == StepGeometry::Keep) return q;
  const std::vector<HexId> touched = touchedHexes(cx, log);
  std::vector<HexId> alive;
  for (HexId h : touched)
    if (cx.isHex(h)) alive.push_back(h);
  std::vector<HexId> measured = touched;
  if (mode == StepGeometry::Smooth) {
    measured = merged(reshaped(cx, smoothStep(cx, log, alive, StepBefore(cx, log, touched), q), q.moved), touched);
    q.smoothed = true;
  }
  measure(cx, StepBefore(cx, log, touched), measured, q);  // `log` now holds the smoothing's moves too
  return q;
}

}  // namespace hexdual
