#include "geometry/step_geometry.hpp"

#include <algorithm>
#include <map>

#include "dual/dual_tracker.hpp"
#include "geometry/degenerate.hpp"
#include "geometry/scaled_jacobian.hpp"
#include "geometry/smoothing.hpp"

namespace hexdual {

namespace {

bool onBoundary(const Complex& cx, HexId h, int corner) {
  for (auto [hh, c] : cx.cornersOfVertex(h, corner))
    for (int f : tables::facesOfCorner(c))
      if (cx.isBoundary({hh, f})) return true;
  return false;
}

bool isNonManifold(const Complex& cx, VertexId v) {
  const auto& nm = cx.nonManifoldVertices();
  return std::binary_search(nm.begin(), nm.end(), v);
}

// The interior vertices at the corners of `hexes` that `wanted` accepts, each once, with a corner.
template <class Wanted>
std::vector<FreeVertex> interiorCorners(const Complex& cx, const std::vector<HexId>& hexes, Wanted wanted) {
  std::map<VertexId, std::pair<HexId, int>> seen;
  for (HexId h : hexes)
    for (int c = 0; c < 8; ++c) seen.emplace(cx.vertex(h, c), std::pair{h, c});
  std::vector<FreeVertex> out;
  for (auto [v, hc] : seen)
    if (wanted(v) && !isNonManifold(cx, v) && !onBoundary(cx, hc.first, hc.second)) out.push_back({v, hc.first, hc.second});
  return out;
}

// The vertices the operation created or set as a corner (a merge's survivor, a split's new side).
std::vector<VertexId> newOrMoved(const Complex& cx, const Complex::EditLog& log) {
  std::vector<VertexId> out;
  for (const Complex::Edit& e : log.edits) {
    if (e.kind == Complex::Edit::AddVertex) out.push_back(e.hex);
    if (e.kind == Complex::Edit::SetCorner && cx.isHex(e.hex)) out.push_back(cx.vertex(e.hex, e.face));
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// Each touched hex's corners before the operation (replaying its SetCorner edits backwards); hexes
// it added are left out.
std::map<HexId, std::array<VertexId, 8>> cornersBefore(const Complex& cx, const Complex::EditLog& log,
                                                       const std::vector<HexId>& touched) {
  std::map<HexId, std::array<VertexId, 8>> out;
  for (HexId h : touched) out[h] = cx.hexVertices(h);
  for (auto it = log.edits.rbegin(); it != log.edits.rend(); ++it) {
    if (it->kind == Complex::Edit::AddHex) out.erase(it->hex);
    if (it->kind == Complex::Edit::SetCorner && out.count(it->hex)) out[it->hex][size_t(it->face)] = VertexId(it->value);
  }
  return out;
}

StepQuality runSmoothing(Complex& cx, Complex::EditLog& log, const std::vector<FreeVertex>& free) {
  StepQuality q;
  if (free.empty()) return q;
  cx.beginTransaction();
  SmoothingStats st = smoothVertices(cx, free);
  Complex::EditLog moves = cx.commitTransaction();
  log.edits.insert(log.edits.end(), moves.edits.begin(), moves.edits.end());
  q.moved = std::move(st.moved);
  q.evaluations = st.evaluations;
  return q;
}

bool anyRegularInverted(const Complex& cx, const std::vector<HexId>& hexes) {
  for (HexId h : hexes)
    if (cx.isHex(h) && scaledJacobian(cx, h) <= 0 && !degenerateByConstruction(cx, h)) return true;
  return false;
}

// Hexes around the given vertices (walking from any of `hexes` holding them).
std::vector<HexId> hexesAround(const Complex& cx, const std::vector<HexId>& hexes, const std::vector<VertexId>& vertices) {
  std::vector<HexId> out;
  for (const FreeVertex& f : interiorCorners(cx, hexes, [&](VertexId v) { return std::binary_search(vertices.begin(), vertices.end(), v); }))
    for (auto [h, c] : cx.cornersOfVertex(f.hex, f.corner)) out.push_back(h);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

void measure(const Complex& cx, const Complex::EditLog& log, const std::vector<HexId>& touched, StepQuality& q) {
  std::vector<HexId> measured = touched;
  for (HexId h : hexesAround(cx, touched, q.moved)) measured.push_back(h);
  std::sort(measured.begin(), measured.end());
  measured.erase(std::unique(measured.begin(), measured.end()), measured.end());
  std::map<VertexId, Vec3> original;  // positions before the smoothing: the first recorded of each vertex
  for (const Complex::Edit& e : log.edits)
    if (e.kind == Complex::Edit::SetPosition) original.emplace(e.hex, e.pos);
  auto pos = [&](VertexId v) { auto it = original.find(v); return it != original.end() ? it->second : cx.position(v); };
  const auto before = cornersBefore(cx, log, measured);
  for (const auto& [h, corners] : before) {
    std::array<Vec3, 8> p;
    for (size_t c = 0; c < 8; ++c) p[c] = pos(corners[c]);
    q.before = std::min(q.before, scaledJacobian(p));
  }
  for (HexId h : measured) {
    if (!cx.isHex(h)) continue;
    const double sj = scaledJacobian(cx, h);
    const bool degenerate = degenerateByConstruction(cx, h);
    q.after = std::min(q.after, sj);
    if (degenerate) q.degenerate.push_back(h);
    else q.afterRegular = std::min(q.afterRegular, sj);
    if (!degenerate && sj <= 0) q.inverted.push_back(h);
  }
}

}  // namespace

StepQuality placeStepGeometry(Complex& cx, Complex::EditLog& log, bool smooth) {
  const std::vector<HexId> touched = touchedHexes(cx, log);
  std::vector<HexId> alive;
  for (HexId h : touched)
    if (cx.isHex(h)) alive.push_back(h);
  StepQuality q;
  if (smooth) {
    const std::vector<VertexId> placed = newOrMoved(cx, log);
    q = runSmoothing(cx, log, interiorCorners(cx, alive, [&](VertexId v) { return std::binary_search(placed.begin(), placed.end(), v); }));
    if (anyRegularInverted(cx, alive)) {  // widen: every interior vertex of the touched hexes
      StepQuality wide = runSmoothing(cx, log, interiorCorners(cx, alive, [](VertexId) { return true; }));
      q.moved.insert(q.moved.end(), wide.moved.begin(), wide.moved.end());
      std::sort(q.moved.begin(), q.moved.end());
      q.moved.erase(std::unique(q.moved.begin(), q.moved.end()), q.moved.end());
      q.evaluations += wide.evaluations;
    }
    q.smoothed = true;
  }
  measure(cx, log, touched, q);
  return q;
}

}  // namespace hexdual
