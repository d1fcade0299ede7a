// The mid-surface of a set of sheet slots (TK03 §1.1): one quad per (hex, axis) slot, one corner
// per primal edge crossing the sheet. Refined with one vertex per mid-edge (a side of a quad) and
// one per quad centre, so that degenerate hexes (two quads on the same corners) are drawn apart.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "complex/complex.hpp"
#include "dual/dual.hpp"

namespace hexdual {

// The a-edges of slot (h, a) in the cycle of its mid-quad: (u,v) = 00, 10, 11, 01.
std::array<int, 4> midCycle(int axis);
// Position of hex edge `edge` in midCycle(axis), or -1.
int cyclePos(int axis, int edge);
// The two a-edges on face f (parallel to axis a), in the face's order.
std::array<int, 2> edgesOnFace(int face, int axis);

struct MidSurface {
  std::vector<Slot> slots;                  // sorted
  std::vector<std::array<int, 6>> adj;      // per slot, per side (face parallel to its axis): neighbour slot or -1
  std::vector<std::array<int8_t, 6>> adjFace;  // the neighbour's face
  std::vector<std::array<bool, 6>> cut;     // sides cut open (empty: none)
  std::vector<EdgeRef> verts;               // corners: canonical primal edges (repeated when cut open)
  std::vector<int> origin;                  // per corner: the corner of the uncut surface it comes from
  std::vector<std::array<int, 4>> quad;     // corner indices in mid-cycle order
  std::vector<int8_t> sign;                 // orientation per quad (+1 keeps the cycle)
  bool orientable = true;
  std::vector<std::array<int, 6>> mid;      // per slot, per side: mid vertex (numbered after the corners)
  std::vector<std::pair<int, int>> midEnds; // corners of each mid vertex
  std::vector<std::array<int, 2>> midSide;  // one side (slot, face) of each mid vertex
  std::vector<bool> midBoundary;            // on the boundary: no neighbour, or cut open
  int nCorner = 0, nMid = 0;
  bool degenerate = false;  // two quads on the same corners, or two mid-edges on the same ends

  int centre(int i) const { return nCorner + nMid + i; }
  int total() const { return nCorner + nMid + int(slots.size()); }
  // The slot across side f of slot i on the surface, or -1 (boundary, or not in the set).
  int neighbour(int i, int f) const { return adj[size_t(i)][size_t(f)]; }
  // The same, but -1 across a cut.
  int joined(int i, int f) const { return cut.empty() || !cut[size_t(i)][size_t(f)] ? adj[size_t(i)][size_t(f)] : -1; }
  // The corners of side f of slot i, in the quad's cycle direction when `oriented`.
  std::pair<int, int> sideCorners(int i, int f) const;
};

// The mid-surface of the given slots (all on one sheet).
MidSurface buildMidSurface(const Complex& cx, std::vector<Slot> slots);

// The same surface cut open along the given sides (cut[i][f] for both sides of each cut edge):
// corners and mid vertices on a cut are split, one copy per side.
MidSurface cutOpen(const MidSurface& s, const std::vector<std::array<bool, 6>>& cut);

}  // namespace hexdual
