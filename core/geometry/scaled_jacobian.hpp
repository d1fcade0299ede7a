// The scaled Jacobian of a hex (HexaLab, Verdict): at each corner the determinant of its three
// unit edge vectors; the hex's value is the minimum over its 8 corners. Plain scalar arithmetic in
// a fixed order (no FMA, no libm beyond sqrt), so native and wasm give the same bits.
#pragma once
#include <array>

#include "complex/complex.hpp"

namespace hexdual {

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
