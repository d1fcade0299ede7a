// The scaled Jacobian of a hex (HexaLab, Verdict): at each corner the determinant of its three
// unit edge vectors; the hex's value is the minimum over its 8 corners. Plain scalar arithmetic in
// a fixed order (no FMA, no libm beyond sqrt), so native and wasm give the same bits.
#pragma once
#include <array>

#include "complex/complex.hpp"

namespace hexdual {

// The three neighbours of each VTK corner, ordered so a cube's corner frame is right-handed (the
// frame of the scaled Jacobian and of the smoothing's corner energy).
inline constexpr int kCornerFrame[8][3] = {{1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7},
                                           {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}};

// det [a b c]: the corner determinant (positive for a right-handed frame).
double det3(Vec3 a, Vec3 b, Vec3 c);

// Of 8 corner positions in VTK order: in [-1, 1], 1 for a cube, <= 0 when inverted or degenerate
// (a corner with a zero-length edge counts as 0).
double scaledJacobian(const std::array<Vec3, 8>& p);
// The same, adding the 8 corner values to *cornerSum (the smoothing's tie-break: it moves when a
// single corner improves, where the minimum alone would not).
double scaledJacobian(const std::array<Vec3, 8>& p, double* cornerSum);
// Of a live hex at its vertices' positions.
double scaledJacobian(const Complex& cx, HexId h);
// The 8 positions of a hex's corners.
std::array<Vec3, 8> hexPoints(const Complex& cx, HexId h);

}  // namespace hexdual
