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

// ---- precomputed crossing tables (one lookup per step of a flood or walk) ----

// Axis of the neighbour continuing axis `a` across face f glued to face f2 with orientation o.
constexpr int axisAcross(int f, int a, int f2, int o) {
  int n = axisOfFace(f);
  if (a == n) return axisOfFace(f2);
  int u = (n + 1) % 3;
  // Positions 0->1 run along u, 1->2 along v.
  int q0 = mapPosition(a == u ? 0 : 1, o), q1 = mapPosition(a == u ? 1 : 2, o);
  int m = ((q1 - q0) & 3) == 1 ? q0 : q1;
  int n2 = axisOfFace(f2);
  return (m % 2 == 0) ? (n2 + 1) % 3 : (n2 + 2) % 3;
}

// Position of an a-edge of a hex in the cycle of its sheet slot's mid-quad: (u,v) bits 00,10,11,01.
constexpr int midIndex(int edge) { return (edge & 1) ^ ((edge >> 1) & 1) ? ((edge & 1) ? 1 : 3) : ((edge & 1) ? 2 : 0); }

// For face f parallel to axis a: its two a-edges and the direction (+1/-1) in which the slot's
// mid-quad runs over the face (from the first a-edge to the second).
struct MidSide {
  int8_t firstEdge = -1, secondEdge = -1, dir = 0;
};
constexpr std::array<MidSide, 18> makeMidSides() {
  std::array<MidSide, 18> t{};
  for (int f = 0; f < 6; ++f)
    for (int a = 0; a < 3; ++a) {
      if (axisOfFace(f) == a) continue;
      MidSide m;
      for (int p = 0; p < 4; ++p) {
        int e = kFaceEdges[f][p];
        if (axisOfEdge(e) != a) continue;
        if (m.firstEdge < 0) m.firstEdge = int8_t(e);
        else m.secondEdge = int8_t(e);
      }
      m.dir = ((midIndex(m.secondEdge) - midIndex(m.firstEdge)) & 3) == 1 ? 1 : -1;
      t[f * 3 + a] = m;
    }
  return t;
}
inline constexpr auto kMidSides = makeMidSides();

// A crossing of face f (axis a) into face f2 with orientation o: the neighbour's axis, and for a
// sheet slot (a parallel to f) whether the mid-quad orientation flips (shared mid-edges are run
// in opposite directions by consistently oriented quads). Index ((f*3+a)*6+f2)*8+o. TK03 §1.1.
struct Crossing {
  int8_t axis = 0, sign = 1;
};
constexpr int crossingIndex(int f, int a, int f2, int o) { return ((f * 3 + a) * 6 + f2) * 8 + o; }
constexpr std::array<Crossing, 6 * 3 * 6 * 8> makeCrossings() {
  std::array<Crossing, 6 * 3 * 6 * 8> t{};
  for (int f = 0; f < 6; ++f)
    for (int a = 0; a < 3; ++a)
      for (int f2 = 0; f2 < 6; ++f2)
        for (int o = 0; o < 8; ++o) {
          Crossing c;
          c.axis = int8_t(axisAcross(f, a, f2, o));
          if (axisOfFace(f) != a) {
            const MidSide& ours = kMidSides[f * 3 + a];
            const MidSide& theirs = kMidSides[f2 * 3 + c.axis];
            // Where our first a-edge lands in the neighbour decides the neighbour's direction.
            int c0 = kFaceCorners[f2][mapPosition(positionInFace(f, kEdgeCorners[ours.firstEdge][0]), o)];
            int c1 = kFaceCorners[f2][mapPosition(positionInFace(f, kEdgeCorners[ours.firstEdge][1]), o)];
            int dirImage = edgeBetween(c0, c1) == theirs.firstEdge ? theirs.dir : -theirs.dir;
            c.sign = int8_t(-ours.dir * dirImage);
          }
          t[crossingIndex(f, a, f2, o)] = c;
        }
  return t;
}
inline constexpr auto kCrossings = makeCrossings();

// One step around an edge: edge e of a hex left through face x (which contains e) into face f2 of
// the neighbour with orientation o arrives at the neighbour's edge `edge`, which is left next
// through face `exit`. Index ((e*6+x)*6+f2)*8+o.
struct EdgeStep {
  int8_t edge = -1, exit = -1;
};
constexpr int edgeStepIndex(int e, int x, int f2, int o) { return ((e * 6 + x) * 6 + f2) * 8 + o; }
constexpr std::array<EdgeStep, 12 * 6 * 6 * 8> makeEdgeSteps() {
  std::array<EdgeStep, 12 * 6 * 6 * 8> t{};
  for (int e = 0; e < 12; ++e)
    for (int x = 0; x < 6; ++x) {
      if (positionInFace(x, kEdgeCorners[e][0]) < 0 || positionInFace(x, kEdgeCorners[e][1]) < 0) continue;
      for (int f2 = 0; f2 < 6; ++f2)
        for (int o = 0; o < 8; ++o) {
          int c0 = kFaceCorners[f2][mapPosition(positionInFace(x, kEdgeCorners[e][0]), o)];
          int c1 = kFaceCorners[f2][mapPosition(positionInFace(x, kEdgeCorners[e][1]), o)];
          EdgeStep s;
          s.edge = int8_t(edgeBetween(c0, c1));
          auto fs = facesOfEdge(s.edge);
          s.exit = int8_t(fs[0] == f2 ? fs[1] : fs[0]);
          t[edgeStepIndex(e, x, f2, o)] = s;
        }
    }
  return t;
}
inline constexpr auto kEdgeSteps = makeEdgeSteps();

// One step of a walk round a vertex: corner c of a hex left through its face along axis k
// (facesOfCorner(c)[k]) into face f2 of the neighbour with orientation o arrives at the
// neighbour's corner `corner`; the corner's two edges in that face (along axes k+1 and k+2, mod 3)
// arrive as the neighbour's edges along axes `axis[0]` and `axis[1]`. Index ((c*3+k)*6+f2)*8+o.
struct CornerStep {
  int8_t corner = -1;
  std::array<int8_t, 2> axis{};
};
constexpr int cornerStepIndex(int c, int k, int f2, int o) { return ((c * 3 + k) * 6 + f2) * 8 + o; }
constexpr std::array<CornerStep, 8 * 3 * 6 * 8> makeCornerSteps() {
  std::array<CornerStep, 8 * 3 * 6 * 8> t{};
  for (int c = 0; c < 8; ++c)
    for (int k = 0; k < 3; ++k) {
      const int f = 2 * k + cornerBit(c, k);
      for (int f2 = 0; f2 < 6; ++f2)
        for (int o = 0; o < 8; ++o) {
          auto image = [&](int corner) { return kFaceCorners[f2][mapPosition(positionInFace(f, corner), o)]; };
          CornerStep s;
          s.corner = int8_t(image(c));
          for (int i = 0; i < 2; ++i) {
            const int other = flipAxis(c, (k + 1 + i) % 3);  // the far corner of c's edge along that axis
            s.axis[i] = int8_t(axisOfEdge(edgeBetween(s.corner, image(other))));
          }
          t[cornerStepIndex(c, k, f2, o)] = s;
        }
    }
  return t;
}
inline constexpr auto kCornerSteps = makeCornerSteps();

}  // namespace hexdual::tables
