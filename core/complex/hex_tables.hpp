// Local numbering of one hexahedron: the only place these tables are written.
//
// Corners follow VTK_HEXAHEDRON (0-3 bottom counter-clockwise, 4-7 top):
//   corner : 0       1       2       3       4       5       6       7
//   (x,y,z): (0,0,0) (1,0,0) (1,1,0) (0,1,0) (0,0,1) (1,0,1) (1,1,1) (0,1,1)
// Faces are numbered by the axis of their normal and their side: face = 2*axis + side,
//   0: x=0, 1: x=1, 2: y=0, 3: y=1, 4: z=0, 5: z=1.
// A face's 4 corners are listed in a cycle over its two in-plane axes u=(a+1)%3, v=(a+2)%3:
//   position 0:(u,v)=(0,0), 1:(1,0), 2:(1,1), 3:(0,1).
// Edges are numbered by their axis and the two other coordinates: edge = 4*axis + ub + 2*vb.
// A gluing between two faces maps cycle positions by an orientation code 0..7:
//   shift = code & 3, reflect = code & 4;  p' = reflect ? (shift - p) & 3 : (p + shift) & 3.
#pragma once
#include <array>
#include <cstdint>

namespace hexdual::tables {

constexpr int kCorners = 8, kFaces = 6, kEdges = 12;

constexpr int axisOfFace(int f) { return f >> 1; }
constexpr int sideOfFace(int f) { return f & 1; }
constexpr int oppositeFace(int f) { return f ^ 1; }
constexpr int axisOfEdge(int e) { return e >> 2; }

// Coordinate bit of a corner along an axis.
constexpr int cornerBit(int c, int axis) {
  constexpr int x[8] = {0, 1, 1, 0, 0, 1, 1, 0};
  constexpr int y[8] = {0, 0, 1, 1, 0, 0, 1, 1};
  return axis == 0 ? x[c] : axis == 1 ? y[c] : (c >> 2);
}
constexpr int cornerAt(int x, int y, int z) {
  constexpr int table[8] = {0, 1, 3, 2, 4, 5, 7, 6};
  return table[x + 2 * y + 4 * z];
}
constexpr int cornerWithBits(int axisA, int bitA, int axisB, int bitB, int axisC, int bitC) {
  int b[3] = {0, 0, 0};
  b[axisA] = bitA;
  b[axisB] = bitB;
  b[axisC] = bitC;
  return cornerAt(b[0], b[1], b[2]);
}

constexpr std::array<std::array<int, 4>, 6> makeFaceCorners() {
  std::array<std::array<int, 4>, 6> t{};
  constexpr int uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int f = 0; f < 6; ++f) {
    int a = f >> 1, u = (a + 1) % 3, v = (a + 2) % 3;
    for (int p = 0; p < 4; ++p) t[f][p] = cornerWithBits(a, f & 1, u, uv[p][0], v, uv[p][1]);
  }
  return t;
}
inline constexpr auto kFaceCorners = makeFaceCorners();

constexpr std::array<std::array<int, 2>, 12> makeEdgeCorners() {
  std::array<std::array<int, 2>, 12> t{};
  for (int e = 0; e < 12; ++e) {
    int a = e >> 2, u = (a + 1) % 3, v = (a + 2) % 3;
    int ub = e & 1, vb = (e >> 1) & 1;
    t[e][0] = cornerWithBits(a, 0, u, ub, v, vb);
    t[e][1] = cornerWithBits(a, 1, u, ub, v, vb);
  }
  return t;
}
inline constexpr auto kEdgeCorners = makeEdgeCorners();

// The local edge joining two corners, or -1 when they are not adjacent (table lookup).
constexpr std::array<std::array<int8_t, 8>, 8> makeEdgeBetween() {
  std::array<std::array<int8_t, 8>, 8> t{};
  for (auto& row : t) row.fill(-1);
  for (int e = 0; e < 12; ++e) {
    t[kEdgeCorners[e][0]][kEdgeCorners[e][1]] = int8_t(e);
    t[kEdgeCorners[e][1]][kEdgeCorners[e][0]] = int8_t(e);
  }
  return t;
}
inline constexpr auto kEdgeBetween = makeEdgeBetween();
constexpr int edgeBetween(int c0, int c1) { return kEdgeBetween[c0][c1]; }

// Local edge between face positions p and p+1.
constexpr std::array<std::array<int, 4>, 6> makeFaceEdges() {
  std::array<std::array<int, 4>, 6> t{};
  for (int f = 0; f < 6; ++f)
    for (int p = 0; p < 4; ++p) t[f][p] = edgeBetween(kFaceCorners[f][p], kFaceCorners[f][(p + 1) & 3]);
  return t;
}
inline constexpr auto kFaceEdges = makeFaceEdges();

// Position of a corner in a face's cycle, or -1 (table lookup).
constexpr std::array<std::array<int8_t, 8>, 6> makePositionInFace() {
  std::array<std::array<int8_t, 8>, 6> t{};
  for (auto& row : t) row.fill(-1);
  for (int f = 0; f < 6; ++f)
    for (int p = 0; p < 4; ++p) t[f][kFaceCorners[f][p]] = int8_t(p);
  return t;
}
inline constexpr auto kPositionInFace = makePositionInFace();
constexpr int positionInFace(int f, int c) { return kPositionInFace[f][c]; }

// The two faces that contain an edge: normal to the edge's other two axes.
constexpr std::array<int, 2> facesOfEdge(int e) {
  int a = e >> 2, u = (a + 1) % 3, v = (a + 2) % 3;
  return {2 * u + (e & 1), 2 * v + ((e >> 1) & 1)};
}

// The three faces at a corner (one per axis).
constexpr std::array<int, 3> facesOfCorner(int c) {
  return {0 + cornerBit(c, 0), 2 + cornerBit(c, 1), 4 + cornerBit(c, 2)};
}
// The three edges at a corner (one per axis).
constexpr std::array<int, 3> edgesOfCorner(int c) {
  std::array<int, 3> r{};
  for (int a = 0; a < 3; ++a) {
    int u = (a + 1) % 3, v = (a + 2) % 3;
    r[a] = 4 * a + cornerBit(c, u) + 2 * cornerBit(c, v);
  }
  return r;
}

// The corner across the hex from c along one axis.
constexpr int flipAxis(int c, int axis) {
  int b[3] = {cornerBit(c, 0), cornerBit(c, 1), cornerBit(c, 2)};
  b[axis] ^= 1;
  return cornerAt(b[0], b[1], b[2]);
}

constexpr int mapPosition(int p, int orient) {
  int shift = orient & 3;
  return (orient & 4) ? (shift - p) & 3 : (p + shift) & 3;
}
constexpr int inverseOrient(int orient) { return (orient & 4) ? orient : ((4 - (orient & 3)) & 3); }
// The orientation code that sends position 0 to p0 and position 1 to p1 (p1 = p0 +- 1).
constexpr int orientFromPositions(int p0, int p1) {
  return ((p1 - p0) & 3) == 1 ? p0 : (4 | p0);
}

}  // namespace hexdual::tables
