// The geometry before a step, read back from its edit log (step_geometry.hpp): each hex's corners
// and each vertex's position then. The smoothing's choice (never more regular hexes newly inverted
// than the operation's own placement) and the step report's `before` both need it.
#pragma once
#include <array>
#include <map>
#include <set>
#include <vector>

#include "complex/complex.hpp"

namespace hexdual {

class StepBefore {
 public:
  // `log`: the operation's edits (and any position edits after it); `touched`: the hexes it touched.
  // Positions are read from cx for vertices `log` does not move: build it again after moving more.
  StepBefore(const Complex& cx, const Complex::EditLog& log, const std::vector<HexId>& touched);
  // The scaled Jacobian of hex h (touched, or with the same corners now) before the step; false when
  // the step added it.
  bool scaledJacobianBefore(const Complex& cx, HexId h, double& out) const;
  // Whether live hex h existed before the step with scaled Jacobian <= 0.
  bool invertedBefore(const Complex& cx, HexId h) const;
  // Whether the step touched hex h. Whether a touched hex was degenerate by construction before
  // (inverted but not counted then, counted now: a face split's hexes) is not known from its shape.
  bool touched(HexId h) const { return touched_.count(h) > 0; }
  // Regular hexes (not degenerate by construction) of `hexes` inverted now and not before the step
  // (invertedBefore).
  int newlyInverted(const Complex& cx, const std::vector<HexId>& hexes) const;

 private:
  Vec3 position(const Complex& cx, VertexId v) const;
  std::map<HexId, std::array<VertexId, 8>> corners_;  // touched hexes: their corners before the step
  std::set<HexId> added_;                             // hexes the step added (alive now)
  std::set<HexId> touched_;
  std::map<VertexId, Vec3> positions_;                // vertices the edits moved: their first recorded position
};

}  // namespace hexdual
