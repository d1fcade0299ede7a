#include "geometry/step_before.hpp"

#include "geometry/degenerate.hpp"
#include "geometry/scaled_jacobian.hpp"

namespace hexdual {

// Replays the SetCorner edits backwards for the touched hexes (removed ones too); a hex added by
// the step has no corners before it.
StepBefore::StepBefore(const Complex& cx, const Complex::EditLog& log, const std::vector<HexId>& touched) {
  for (HexId h : touched) corners_[h] = cx.hexVertices(h), touched_.insert(h);
  for (auto it = log.edits.rbegin(); it != log.edits.rend(); ++it) {
    if (it->kind == Complex::Edit::AddHex && corners_.erase(it->hex)) added_.insert(it->hex);
    if (it->kind == Complex::Edit::SetCorner && corners_.count(it->hex))
      corners_[it->hex][size_t(it->face)] = VertexId(it->value);
  }
  for (const Complex::Edit& e : log.edits)
    if (e.kind == Complex::Edit::SetPosition) positions_.emplace(e.hex, e.pos);
}

Vec3 StepBefore::position(const Complex& cx, VertexId v) const {
  auto it = positions_.find(v);
  return it != positions_.end() ? it->second : cx.position(v);
}

bool StepBefore::scaledJacobianBefore(const Complex& cx, HexId h, double& out) const {
  if (added_.count(h)) return false;
  auto it = corners_.find(h);
  const std::array<VertexId, 8> corners = it != corners_.end() ? it->second : cx.hexVertices(h);
  std::array<Vec3, 8> p;
  for (size_t c = 0; c < 8; ++c) p[c] = position(cx, corners[c]);
  out = scaledJacobian(p);
  return true;
}

bool StepBefore::invertedBefore(const Complex& cx, HexId h) const {
  double sj = 1;
  return scaledJacobianBefore(cx, h, sj) && sj <= 0;
}

int StepBefore::newlyInverted(const Complex& cx, const std::vector<HexId>& hexes) const {
  int n = 0;
  for (HexId h : hexes)
    if (cx.isHex(h) && scaledJacobian(cx, h) <= 0 && !degenerateByConstruction(cx, h) && !invertedBefore(cx, h)) ++n;
  return n;
}

}  // namespace hexdual
