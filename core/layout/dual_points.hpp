// Per-hex dual points and the 3D pieces of the dual drawn over the primal mesh (TK03 Fig. 1):
// sheet mid-surfaces, chord polylines through dual points, dual vertices.
#pragma once
#include <cstdint>
#include <vector>

#include "complex/complex.hpp"
#include "dual/dual.hpp"

namespace hexdual {

// A hex's dual point: its centroid moved halfway toward the mean of its distinct face neighbours'
// centroids (a boundary face counts as the centroid mirrored through it). Hexes on the same 8
// vertices (a pillow pair, a blind chord of 2) have different neighbours, so their points differ;
// in a regular grid the point is the centroid. Indexed by hex id (capacity); tombstones get {}.
std::vector<Vec3> dualPoints(const Complex& cx);

// True when a face neighbour of h appears on two or more of its faces (a degenerate hex: it shares
// several quads with one hex, as in a pillow pair or a blind chord of 2).
bool isDegenerateHex(const Complex& cx, HexId h);

struct DualOverlay {
  std::vector<float> sheetPositions;    // 3 per vertex, 4 vertices per sheet slot (a mid-surface quad)
  std::vector<uint32_t> sheetIndices;   // 2 triangles per slot
  std::vector<int32_t> sheetTriangle;   // sheet id per triangle
  std::vector<float> chordPositions;    // 3 per vertex, 2 vertices per segment
  std::vector<int32_t> chordSegment;    // chord id per segment
  std::vector<float> dualVertices;      // 3 per live hex, in hex id order
  std::vector<int32_t> dualVertexHex;   // hex id per dual vertex
};

// Mid-surface quads (the midpoints of each slot's 4 edges along its axis), chords as polylines
// through dual points (open chords end at their boundary quads' centres), and the dual points.
// Hex geometry is translated to its dual point so degenerate hexes' pieces separate.
// With `only` (hex ids), just their sheet quads, dual points and the chord segments between them
// (a big mesh's overlay follows its drawn shell).
DualOverlay buildDualOverlay(const Complex& cx, const Dual& dual, const std::vector<HexId>* only = nullptr);

}  // namespace hexdual
