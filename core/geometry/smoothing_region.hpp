// The local problem the smoothing solves (smoothing.hpp): the free vertices with working
// positions, and the hexes around them that count (not degenerate by construction), each corner a
// free vertex or a fixed one. Evaluates the corner energy (corner_energy.hpp) of the corners a
// free vertex moves, with its gradient; counts what that costs.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "complex/complex.hpp"
#include "geometry/max_min.hpp"

namespace hexdual {

struct FreeVertex {
  VertexId vertex;
  HexId hex;  // a hex with the vertex at `corner`: where the walk over its star starts
  int corner;
};

struct SmoothingRegion {
  const Complex* cx = nullptr;
  std::vector<VertexId> free;                   // ascending
  std::vector<Vec3> pos;                        // working positions, per free vertex
  std::vector<double> scale;                    // per free vertex: mean length of its edges at the start
  std::vector<HexId> hexIds;                    // the hexes that count, ascending
  std::vector<std::array<int32_t, 8>> corners;  // per such hex: free index (>= 0) or -1 - vertex id
  std::vector<uint8_t> counted;                 // per such hex: bit j = corner j is in the energy (not stuck,
                                                // a free vertex among its four)
  std::vector<uint8_t> doomed;                  // per such hex: bit j = corner j is counted but cannot be positive
                                                // together with the others on its one free vertex (oneVertexFeasible)
  std::vector<uint8_t> frozen;                  // per such hex: bit j = corner j was not positive before the step
                                                // (a hex not near the step): out of the energy, never lower
  std::vector<std::array<double, 8>> floors;    // per such hex: its corners' determinants at the start
  double doomedDelta2 = 0;                      // delta^2 of the doomed corners (always softened)
  std::vector<std::vector<std::pair<int32_t, int8_t>>> incidence;  // per free vertex: (hex index, corner)
  double volumeScale = 1;                                          // (mean edge length of the counted hexes)^3
  int64_t evaluations = 0;                                         // corner energies evaluated
  int64_t budget = INT64_MAX;                                      // sweeps stop when evaluations reach it

  Vec3 at(int32_t ref) const { return ref >= 0 ? pos[size_t(ref)] : cx->position(VertexId(-1 - ref)); }
};

// The region of `free` (interior, manifold vertices: the caller chooses them) in cx. `near`
// (ascending): the hexes sharing a vertex with a hex the step touched. A corner of another hex that
// is not positive now was so, in a regular hex, before the step (a mesh tangled already): it is
// frozen, so it neither holds the smoothing in its untangling phase nor ever gets lower.
SmoothingRegion buildSmoothingRegion(const Complex& cx, const std::vector<FreeVertex>& free,
                                     const std::vector<HexId>& near);

// Sum of the corner energies that free vertex i moves (its corner and the three next to it in each
// counted hex, leaving out stuck corners: they would only pull its neighbours onto them), with i
// at p; with `grad`, their gradient with respect to p. +infinity when delta2 == 0 and one of those
// corners is not positive, or a frozen one falls below its floor; doomed corners use at least
// doomedDelta2 (they are never barriers).
double vertexEnergy(SmoothingRegion& r, size_t i, Vec3 p, double delta2, Vec3* grad);
// Whether free vertex i at p keeps every frozen corner it moves at or above its floor.
bool keepsFloors(const SmoothingRegion& r, size_t i, Vec3 p);
// The smallest determinant over the corners in the energy that are not doomed.
double minCornerDeterminant(const SmoothingRegion& r);

// The determinants of the corners in the energy that free vertex i moves (not doomed), each an
// affine function of i's position, scaled by the product of its edge lengths now (so their values
// near the current position are about the corners' scaled Jacobians).
std::vector<AffineFunction> cornerFunctions(SmoothingRegion& r, size_t i);

// The smallest scaled Jacobian over the corners in the energy that are not doomed (1 when none).
double worstScaledCorner(const SmoothingRegion& r);
// How many counted hexes have a corner determinant <= 0 (inverted).
int invertedHexes(const SmoothingRegion& r);

}  // namespace hexdual
