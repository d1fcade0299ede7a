#include "dual/dual.hpp"

#include <algorithm>

#include "complex/union_find.hpp"

namespace hexdual {
using namespace tables;

int mapAxisAcross(const Complex& cx, HexId h, int face, int axis) {
  Gluing g = cx.gluing(h, face);
  int n = axisOfFace(face);
  if (axis == n) return axisOfFace(g.face);
  int u = (n + 1) % 3;
  // Positions 0->1 run along u, 1->2 along v.
  int q0 = mapPosition(axis == u ? 0 : 1, g.orient), q1 = mapPosition(axis == u ? 1 : 2, g.orient);
  int m = ((q1 - q0) & 3) == 1 ? q0 : q1;
  int n2 = axisOfFace(g.face);
  return (m % 2 == 0) ? (n2 + 1) % 3 : (n2 + 2) % 3;
}

std::string classifySurface(int64_t euler, int loops, bool orientable) {
  if (!orientable) return "other";
  if (loops == 0 && euler == 2) return "sphere";
  if (loops == 0 && euler == 0) return "torus";
  if (loops == 1 && euler == 1) return "disk";
  if (loops == 2 && euler == 0) return "annulus";
  return "other";
}

namespace {

size_t slotIndex(HexId h, int a) { return size_t(3) * size_t(h) + size_t(a); }

// Position of an a-edge of a hex in the cycle of the sheet's mid-quad: (u,v) bits 00,10,11,01.
int midIndex(int edge) {
  constexpr int idx[4] = {0, 1, 3, 2};
  return idx[edge & 3];
}

// Direction (+1/-1) in which the mid-quad of slot (h,a) runs over face f, and the face's first a-edge.
int midDirection(int face, int axis, int* firstEdge) {
  int e0 = -1, e1 = -1;
  for (int p = 0; p < 4; ++p) {
    int e = kFaceEdges[face][p];
    if (axisOfEdge(e) != axis) continue;
    (e0 < 0 ? e0 : e1) = e;
  }
  *firstEdge = e0;
  return ((midIndex(e1) - midIndex(e0)) & 3) == 1 ? 1 : -1;
}

void orderChord(const Complex& cx, Chord& ch) {
  // Walk backwards from the smallest slot to a boundary end (or all the way round).
  Slot start = ch.slots.front();
  Slot cur = start;
  int entry = 2 * cur.axis;  // walking backwards: leave through the low face
  size_t guard = ch.slots.size() + 1;
  bool closed = false;
  for (size_t i = 0; i < guard; ++i) {
    Gluing g = cx.gluing(cur.hex, entry);
    if (g.boundary()) break;
    cur = {g.hex, axisOfFace(g.face)};
    entry = oppositeFace(g.face);
    if (cur == start && entry == 2 * start.axis) {
      closed = true;
      break;
    }
  }
  // Now walk forwards from cur, leaving through the face opposite to where we came in.
  std::vector<Slot> order;
  int exitFace = closed ? 2 * start.axis + 1 : oppositeFace(entry);
  if (closed) cur = start;
  Slot first = cur;
  int firstExit = exitFace;
  for (size_t i = 0; i < guard; ++i) {
    order.push_back(cur);
    Gluing g = cx.gluing(cur.hex, exitFace);
    if (g.boundary()) break;
    cur = {g.hex, axisOfFace(g.face)};
    exitFace = oppositeFace(g.face);
    if (cur == first && exitFace == firstExit) break;
  }
  ch.closed = closed;
  ch.slots = std::move(order);
}

}  // namespace

Dual extractDual(const Complex& cx) {
  const size_t n = size_t(cx.hexCapacity());
  UnionFind sheetUF(3 * n), chordUF(3 * n);
  for (HexId h : cx.hexes())
    for (int f = 0; f < 6; ++f) {
      Gluing g = cx.gluing(h, f);
      if (g.boundary()) continue;
      int nf = axisOfFace(f);
      chordUF.unite(slotIndex(h, nf), slotIndex(g.hex, axisOfFace(g.face)));
      for (int a = 0; a < 3; ++a)
        if (a != nf) sheetUF.unite(slotIndex(h, a), slotIndex(g.hex, mapAxisAcross(cx, h, f, a)));
    }

  Dual d;
  d.sheetOf.assign(n, {-1, -1, -1});
  d.chordOf.assign(n, {-1, -1, -1});
  std::vector<int32_t> sheetRoot(3 * n, -1), chordRoot(3 * n, -1);
  for (HexId h : cx.hexes())
    for (int a = 0; a < 3; ++a) {
      size_t rs = sheetUF.find(slotIndex(h, a)), rc = chordUF.find(slotIndex(h, a));
      if (sheetRoot[rs] < 0) {
        sheetRoot[rs] = int32_t(d.sheets.size());
        d.sheets.emplace_back();
        d.sheets.back().id = sheetRoot[rs];
      }
      if (chordRoot[rc] < 0) {
        chordRoot[rc] = int32_t(d.chords.size());
        d.chords.emplace_back();
        d.chords.back().id = chordRoot[rc];
      }
      d.sheetOf[h][a] = sheetRoot[rs];
      d.chordOf[h][a] = chordRoot[rc];
      d.sheets[size_t(sheetRoot[rs])].slots.push_back({h, a});
      d.chords[size_t(chordRoot[rc])].slots.push_back({h, a});
    }

  for (Chord& ch : d.chords) {
    for (size_t i = 1; i < ch.slots.size(); ++i)
      if (ch.slots[i].hex == ch.slots[i - 1].hex) ch.selfIntersecting = true;  // slots are sorted by hex
    orderChord(cx, ch);
  }

  // Sheet mid-surfaces: faces = slots, edges = (slot, parallel face) incidences, vertices = edge classes.
  int32_t numEdges = 0;
  auto edgeClass = cx.edgeClasses(&numEdges);
  std::vector<int64_t> interiorSides(d.sheets.size(), 0), boundarySides(d.sheets.size(), 0), verts(d.sheets.size(), 0);
  std::vector<uint8_t> edgeSeen(size_t(numEdges), 0);
  UnionFind loopUF{size_t(numEdges)};
  std::vector<uint8_t> onBoundary(size_t(numEdges), 0);
  for (HexId h : cx.hexes())
    for (int a = 0; a < 3; ++a) {
      size_t s = size_t(d.sheetOf[h][a]);
      for (int k = 0; k < 4; ++k) {
        int32_t ec = edgeClass[size_t(12) * h + 4 * a + k];
        if (!edgeSeen[size_t(ec)]) {
          edgeSeen[size_t(ec)] = 1;
          ++verts[s];
        }
      }
      for (int f = 0; f < 6; ++f) {
        if (axisOfFace(f) == a) continue;
        if (!cx.gluing(h, f).boundary()) {
          ++interiorSides[s];
          continue;
        }
        ++boundarySides[s];
        int e0 = -1;
        midDirection(f, a, &e0);
        for (int p = 0; p < 4; ++p) {
          int e = kFaceEdges[f][p];
          if (axisOfEdge(e) != a) continue;
          int32_t ec = edgeClass[size_t(12) * h + e];
          onBoundary[size_t(ec)] = 1;
          loopUF.unite(size_t(edgeClass[size_t(12) * h + e0]), size_t(ec));
        }
      }
    }
  std::vector<uint8_t> rootCounted(size_t(numEdges), 0);
  std::vector<int32_t> edgeSheet(size_t(numEdges), -1);
  for (HexId h : cx.hexes())
    for (int a = 0; a < 3; ++a)
      for (int k = 0; k < 4; ++k) edgeSheet[size_t(edgeClass[size_t(12) * h + 4 * a + k])] = d.sheetOf[h][a];
  for (int32_t ec = 0; ec < numEdges; ++ec) {
    if (!onBoundary[size_t(ec)]) continue;
    size_t r = loopUF.find(size_t(ec));
    if (rootCounted[r]) continue;
    rootCounted[r] = 1;
    ++d.sheets[size_t(edgeSheet[size_t(ec)])].boundaryLoops;
  }

  // Orientability: propagate a sign per slot; across a shared mid-edge the two quads must run opposite ways.
  std::vector<int8_t> sign(3 * n, 0);
  std::vector<Slot> stack;
  for (Sheet& sh : d.sheets) {
    size_t s = size_t(sh.id);
    sh.euler = verts[s] - (interiorSides[s] / 2 + boundarySides[s]) + int64_t(sh.slots.size());
    for (size_t i = 1; i < sh.slots.size(); ++i)
      if (sh.slots[i].hex == sh.slots[i - 1].hex) sh.selfIntersecting = true;
    sign[slotIndex(sh.slots[0].hex, sh.slots[0].axis)] = 1;
    stack.assign(1, sh.slots[0]);
    while (!stack.empty() && sh.orientable) {
      Slot cur = stack.back();
      stack.pop_back();
      int sc = sign[slotIndex(cur.hex, cur.axis)];
      for (int f = 0; f < 6 && sh.orientable; ++f) {
        if (axisOfFace(f) == cur.axis) continue;
        Gluing g = cx.gluing(cur.hex, f);
        if (g.boundary()) continue;
        int e0 = -1;
        int dir = midDirection(f, cur.axis, &e0);
        int a2 = mapAxisAcross(cx, cur.hex, f, cur.axis);
        int e0b = -1;
        int dir2 = midDirection(g.face, a2, &e0b);
        // Where does our first a-edge land in the neighbour?
        int c0 = cx.mappedCorner(cur.hex, f, kEdgeCorners[e0][0]);
        int c1 = cx.mappedCorner(cur.hex, f, kEdgeCorners[e0][1]);
        int img = edgeBetween(c0, c1);
        int dirImage = img == e0b ? dir2 : -dir2;  // direction the neighbour runs from our first edge
        int want = -sc * dir * dirImage;
        int8_t& sn = sign[slotIndex(g.hex, a2)];
        if (sn == 0) {
          sn = int8_t(want);
          stack.push_back({g.hex, a2});
        } else if (sn != want) {
          sh.orientable = false;
        }
      }
    }
    sh.topology = classifySurface(sh.euler, sh.boundaryLoops, sh.orientable);
  }
  return d;
}

}  // namespace hexdual
