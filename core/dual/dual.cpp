#include "dual/dual.hpp"

#include <algorithm>


namespace hexdual {
using namespace tables;

namespace {

int axisAcrossGluing(int f, int a, const Gluing& g) { return kCrossings[size_t(crossingIndex(f, a, g.face, g.orient))].axis; }

size_t slotIndex(HexId h, int a) { return size_t(3) * size_t(h) + size_t(a); }

}  // namespace

// Floods one sheet from a slot: labels its slots with `id` and an orientation sign per slot.
// Returns false when two paths disagree on a sign (a non-orientable sheet).
bool floodSheet(const Complex& cx, Slot start, int32_t id, int32_t* sheetOf, int8_t* sign, std::vector<Slot>& stack,
                std::vector<Slot>* outSlots) {
  bool orientable = true;
  sheetOf[slotIndex(start.hex, start.axis)] = id;
  sign[slotIndex(start.hex, start.axis)] = 1;
  stack.assign(1, start);
  while (!stack.empty()) {
    Slot cur = stack.back();
    stack.pop_back();
    if (outSlots) outSlots->push_back(cur);
    int sc = sign[slotIndex(cur.hex, cur.axis)];
    for (int f = 0; f < 6; ++f) {
      if (axisOfFace(f) == cur.axis) continue;
      Gluing g = cx.gluing(cur.hex, f);
      if (g.boundary()) continue;
      int a2 = axisAcrossGluing(f, cur.axis, g);
      const MidSide& ours = kMidSides[f * 3 + cur.axis];
      const MidSide& theirs = kMidSides[g.face * 3 + a2];
      // Where does our first a-edge land in the neighbour? Its image decides the neighbour's direction.
      int c0 = kFaceCorners[g.face][mapPosition(positionInFace(f, kEdgeCorners[ours.firstEdge][0]), g.orient)];
      int c1 = kFaceCorners[g.face][mapPosition(positionInFace(f, kEdgeCorners[ours.firstEdge][1]), g.orient)];
      int dirImage = edgeBetween(c0, c1) == theirs.firstEdge ? theirs.dir : -theirs.dir;
      int want = -sc * ours.dir * dirImage;  // shared mid-edges are run in opposite directions
      size_t k = slotIndex(g.hex, a2);
      if (sheetOf[k] < 0) {
        sheetOf[k] = id;
        sign[k] = int8_t(want);
        stack.push_back({g.hex, a2});
      } else if (sign[k] != want) {
        orientable = false;
      }
    }
  }
  return orientable;
}

// Walks one chord from a slot: back to a boundary end (or once round), then forward, labelling.
void walkChord(const Complex& cx, Slot start, Chord& ch, int32_t* chordOf) {
  Slot cur = start;
  int back = 2 * cur.axis;  // leaving backwards through the low face
  bool closed = false;
  for (;;) {
    Gluing g = cx.gluing(cur.hex, back);
    if (g.boundary()) break;
    cur = {g.hex, axisOfFace(g.face)};
    back = oppositeFace(g.face);
    if (cur == start) {
      closed = back == 2 * start.axis;
      break;  // round once (a twisted return leaves the chord open-ended at start)
    }
  }
  if (closed) {
    cur = start;
    back = 2 * start.axis;
  }
  int exitFace = oppositeFace(back);
  for (;;) {
    ch.slots.push_back(cur);
    chordOf[slotIndex(cur.hex, cur.axis)] = ch.id;
    Gluing g = cx.gluing(cur.hex, exitFace);
    if (g.boundary()) break;
    cur = {g.hex, axisOfFace(g.face)};
    exitFace = oppositeFace(g.face);
    if (chordOf[slotIndex(cur.hex, cur.axis)] == ch.id) break;
  }
  ch.closed = closed;
}

int mapAxisAcross(const Complex& cx, HexId h, int face, int axis) { return axisAcrossGluing(face, axis, cx.gluing(h, face)); }

std::string classifySurface(int64_t euler, int loops, bool orientable) {
  if (!orientable) return "other";
  if (loops == 0 && euler == 2) return "sphere";
  if (loops == 0 && euler == 0) return "torus";
  if (loops == 1 && euler == 1) return "disk";
  if (loops == 2 && euler == 0) return "annulus";
  return "other";
}

Dual extractDual(const Complex& cx) {
  const size_t n = size_t(cx.hexCapacity());
  Dual d;
  d.sheetOf.assign(n, {-1, -1, -1});
  d.chordOf.assign(n, {-1, -1, -1});
  // Flat views of the per-hex arrays (std::array<int32_t,3> is contiguous).
  int32_t* sheetOf = n ? d.sheetOf[0].data() : nullptr;
  int32_t* chordOf = n ? d.chordOf[0].data() : nullptr;
  std::vector<int8_t> sign(3 * n, 0);
  std::vector<Slot> stack;
  std::vector<uint8_t> orientable;
  for (HexId h : cx.hexes())
    for (int a = 0; a < 3; ++a) {
      if (sheetOf[slotIndex(h, a)] < 0) {
        int32_t id = int32_t(d.sheets.size());
        d.sheets.emplace_back();
        d.sheets.back().id = id;
        d.sheets.back().orientable = floodSheet(cx, {h, a}, id, sheetOf, sign.data(), stack, nullptr);
      }
      if (chordOf[slotIndex(h, a)] < 0) {
        d.chords.emplace_back();
        d.chords.back().id = int32_t(d.chords.size() - 1);
        walkChord(cx, {h, a}, d.chords.back(), chordOf);
      }
    }

  for (HexId h : cx.hexes()) {
    const auto &s = d.sheetOf[h], &c = d.chordOf[h];
    if (s[0] == s[1] || s[0] == s[2]) d.sheets[size_t(s[0])].selfIntersecting = true;
    if (s[1] == s[2]) d.sheets[size_t(s[1])].selfIntersecting = true;
    if (c[0] == c[1] || c[0] == c[2]) d.chords[size_t(c[0])].selfIntersecting = true;
    if (c[1] == c[2]) d.chords[size_t(c[1])].selfIntersecting = true;
  }
  // Sheet slot lists in (hex, axis) order, sized first to avoid regrowth.
  std::vector<size_t> sizes(d.sheets.size(), 0);
  for (HexId h : cx.hexes())
    for (int a = 0; a < 3; ++a) ++sizes[size_t(d.sheetOf[h][a])];
  for (size_t s = 0; s < d.sheets.size(); ++s) d.sheets[s].slots.reserve(sizes[s]);
  for (HexId h : cx.hexes())
    for (int a = 0; a < 3; ++a) d.sheets[size_t(d.sheetOf[h][a])].slots.push_back({h, a});

  // Mid-surfaces: faces = slots, edges = (slot, parallel face) incidences, vertices = edge classes.
  int32_t numEdges = 0;
  auto edgeClass = cx.edgeClasses(&numEdges);
  const size_t ns = d.sheets.size();
  std::vector<int64_t> interiorSides(ns, 0), boundarySides(ns, 0), verts(ns, 0);
  std::vector<int32_t> edgeSheet(size_t(numEdges), -1);
  // Boundary loops: union-find over boundary edge classes along boundary mid-edges.
  std::vector<int32_t> loopParent(size_t(numEdges), -1);
  auto root = [&](int32_t x) {
    while (loopParent[size_t(x)] != x) x = loopParent[size_t(x)] = loopParent[size_t(loopParent[size_t(x)])];
    return x;
  };
  for (HexId h : cx.hexes())
    for (int a = 0; a < 3; ++a) {
      size_t s = size_t(d.sheetOf[h][a]);
      for (int k = 0; k < 4; ++k) {
        int32_t ec = edgeClass[size_t(12) * h + 4 * a + k];
        if (edgeSheet[size_t(ec)] < 0) {
          edgeSheet[size_t(ec)] = int32_t(s);
          ++verts[s];
        }
      }
      for (int f = 0; f < 6; ++f) {
        if (axisOfFace(f) == a) continue;
        if (!cx.isBoundary({h, f})) {
          ++interiorSides[s];
          continue;
        }
        ++boundarySides[s];
        const MidSide& m = kMidSides[f * 3 + a];
        int32_t e0 = edgeClass[size_t(12) * h + m.firstEdge], e1 = edgeClass[size_t(12) * h + m.secondEdge];
        for (int32_t e : {e0, e1})
          if (loopParent[size_t(e)] < 0) loopParent[size_t(e)] = e;
        int32_t r0 = root(e0), r1 = root(e1);
        if (r0 != r1) loopParent[size_t(std::max(r0, r1))] = std::min(r0, r1);
      }
    }
  for (int32_t ec = 0; ec < numEdges; ++ec)
    if (loopParent[size_t(ec)] == ec) ++d.sheets[size_t(edgeSheet[size_t(ec)])].boundaryLoops;
  for (Sheet& sh : d.sheets) {
    size_t s = size_t(sh.id);
    sh.euler = verts[s] - (interiorSides[s] / 2 + boundarySides[s]) + int64_t(sh.slots.size());
    sh.topology = classifySurface(sh.euler, sh.boundaryLoops, sh.orientable);
  }
  return d;
}

}  // namespace hexdual

namespace hexdual {

void validateDual(const Complex& cx, const Dual& d) {
  auto fail = [](const std::string& m) { throw Error("validateDual: " + m); };
  auto slotName = [](Slot s) { return "slot (hex " + std::to_string(s.hex) + ", axis " + std::to_string(s.axis) + ")"; };
  if (d.sheetOf.size() < size_t(cx.hexCapacity()) || d.chordOf.size() < size_t(cx.hexCapacity()))
    fail("per-hex arrays are shorter than the hex capacity");
  std::vector<uint8_t> seenSheet(size_t(3) * size_t(cx.hexCapacity()), 0), seenChord(seenSheet.size(), 0);
  auto mark = [&](std::vector<uint8_t>& seen, Slot s, const char* what, int id) {
    if (!cx.isHex(s.hex)) fail(std::string(what) + " " + std::to_string(id) + " lists dead hex " + std::to_string(s.hex));
    uint8_t& m = seen[size_t(3) * size_t(s.hex) + size_t(s.axis)];
    if (m) fail(slotName(s) + " is listed twice among " + what + "s");
    m = 1;
  };
  for (size_t i = 0; i < d.sheets.size(); ++i)
    for (Slot s : d.sheets[i].slots) {
      mark(seenSheet, s, "sheet", d.sheets[i].id);
      if (d.sheetOf[s.hex][s.axis] != d.sheets[i].id) fail(slotName(s) + " is in sheet " + std::to_string(d.sheets[i].id) + " but sheetOf says otherwise");
    }
  for (size_t i = 0; i < d.chords.size(); ++i) {
    const Chord& ch = d.chords[i];
    for (size_t k = 0; k < ch.slots.size(); ++k) {
      Slot s = ch.slots[k];
      mark(seenChord, s, "chord", ch.id);
      if (d.chordOf[s.hex][s.axis] != ch.id) fail(slotName(s) + " is in chord " + std::to_string(ch.id) + " but chordOf says otherwise");
      bool last = k + 1 == ch.slots.size();
      if (last && !ch.closed) continue;
      Slot next = ch.slots[last ? 0 : k + 1];
      Gluing a = cx.gluing(s.hex, 2 * s.axis), b = cx.gluing(s.hex, 2 * s.axis + 1);
      bool adjacent = (!a.boundary() && a.hex == next.hex && axisOfFace(a.face) == next.axis) ||
                      (!b.boundary() && b.hex == next.hex && axisOfFace(b.face) == next.axis);
      if (!adjacent) fail("chord " + std::to_string(ch.id) + ": " + slotName(s) + " is not glued to the next " + slotName(next));
    }
  }
  for (HexId h : cx.hexes())
    for (int a = 0; a < 3; ++a) {
      Slot s{h, a};
      if (!seenSheet[size_t(3) * size_t(h) + size_t(a)]) fail(slotName(s) + " is in no sheet");
      if (!seenChord[size_t(3) * size_t(h) + size_t(a)]) fail(slotName(s) + " is in no chord");
      for (int f = 0; f < 6; ++f) {
        Gluing g = cx.gluing(h, f);
        if (g.boundary()) continue;
        int a2 = mapAxisAcross(cx, h, f, a);
        if (axisOfFace(f) == a) {
          if (d.chordOf[h][a] != d.chordOf[g.hex][a2]) fail(slotName(s) + " and its neighbour across face " + std::to_string(f) + " are in different chords");
        } else if (d.sheetOf[h][a] != d.sheetOf[g.hex][a2]) {
          fail(slotName(s) + " and its neighbour across face " + std::to_string(f) + " are in different sheets");
        }
      }
    }
}

}  // namespace hexdual

#include <unordered_map>

namespace hexdual {

namespace {
uint64_t edgeKey(EdgeRef e) { return (uint64_t(uint32_t(e.hex)) << 4) | uint64_t(e.edge); }
}  // namespace

void classifySheet(const Complex& cx, Sheet& sh) {
  std::sort(sh.slots.begin(), sh.slots.end());
  sh.selfIntersecting = false;
  for (size_t i = 1; i < sh.slots.size(); ++i)
    if (sh.slots[i].hex == sh.slots[i - 1].hex) sh.selfIntersecting = true;
  // Mid-surface vertices = primal edges crossing the sheet; boundary loops by union-find over them.
  std::unordered_map<uint64_t, int32_t> vertexIndex;
  std::vector<int32_t> parent;
  auto indexOf = [&](EdgeRef e) {
    auto [it, inserted] = vertexIndex.try_emplace(edgeKey(cx.canonical(e)), int32_t(parent.size()));
    if (inserted) parent.push_back(-1);
    return it->second;
  };
  auto root = [&](int32_t x) {
    while (parent[size_t(x)] != x) x = parent[size_t(x)] = parent[size_t(parent[size_t(x)])];
    return x;
  };
  int64_t interiorSides = 0, boundarySides = 0;
  for (Slot s : sh.slots) {
    for (int k = 0; k < 4; ++k) indexOf({s.hex, 4 * s.axis + k});
    for (int f = 0; f < 6; ++f) {
      if (axisOfFace(f) == s.axis) continue;
      if (!cx.isBoundary({s.hex, f})) {
        ++interiorSides;
        continue;
      }
      ++boundarySides;
      const MidSide& m = kMidSides[f * 3 + s.axis];
      int32_t e0 = indexOf({s.hex, m.firstEdge}), e1 = indexOf({s.hex, m.secondEdge});
      for (int32_t e : {e0, e1})
        if (parent[size_t(e)] < 0) parent[size_t(e)] = e;
      int32_t r0 = root(e0), r1 = root(e1);
      if (r0 != r1) parent[size_t(std::max(r0, r1))] = std::min(r0, r1);
    }
  }
  sh.boundaryLoops = 0;
  for (size_t i = 0; i < parent.size(); ++i) sh.boundaryLoops += parent[i] == int32_t(i);
  sh.euler = int64_t(vertexIndex.size()) - (interiorSides / 2 + boundarySides) + int64_t(sh.slots.size());
  sh.topology = classifySurface(sh.euler, sh.boundaryLoops, sh.orientable);
}

void compareDuals(const Complex& cx, const Dual& a, const Dual& b) {
  auto fail = [](const std::string& m) { throw Error("compareDuals: " + m); };
  std::unordered_map<int32_t, int32_t> sheetMap, chordMap, sheetBack, chordBack;
  auto link = [&](std::unordered_map<int32_t, int32_t>& fwd, std::unordered_map<int32_t, int32_t>& back, int32_t x,
                  int32_t y, const char* what, Slot s) {
    auto [it, ins] = fwd.try_emplace(x, y);
    auto [jt, jns] = back.try_emplace(y, x);
    if (it->second != y || jt->second != x)
      fail(std::string(what) + "s differ at slot (hex " + std::to_string(s.hex) + ", axis " + std::to_string(s.axis) + ")");
  };
  for (HexId h : cx.hexes())
    for (int ax = 0; ax < 3; ++ax) {
      link(sheetMap, sheetBack, a.sheetOf[h][ax], b.sheetOf[h][ax], "sheet", {h, ax});
      link(chordMap, chordBack, a.chordOf[h][ax], b.chordOf[h][ax], "chord", {h, ax});
    }
  size_t liveA = 0, liveB = 0;
  for (const Sheet& s : a.sheets) liveA += s.alive;
  for (const Sheet& s : b.sheets) liveB += s.alive;
  if (liveA != liveB || liveA != sheetMap.size()) fail("different numbers of sheets");
  for (auto [x, y] : sheetMap) {
    const Sheet &p = a.sheets[size_t(x)], &q = b.sheets[size_t(y)];
    if (p.slots.size() != q.slots.size() || p.euler != q.euler || p.boundaryLoops != q.boundaryLoops ||
        p.topology != q.topology || p.selfIntersecting != q.selfIntersecting || p.orientable != q.orientable)
      fail("sheet " + std::to_string(x) + " and sheet " + std::to_string(y) + " are classified differently (" +
           p.topology + " euler " + std::to_string(p.euler) + " vs " + q.topology + " euler " + std::to_string(q.euler) + ")");
  }
  liveA = liveB = 0;
  for (const Chord& c : a.chords) liveA += c.alive;
  for (const Chord& c : b.chords) liveB += c.alive;
  if (liveA != liveB || liveA != chordMap.size()) fail("different numbers of chords");
  for (auto [x, y] : chordMap) {
    const Chord &p = a.chords[size_t(x)], &q = b.chords[size_t(y)];
    if (p.slots.size() != q.slots.size() || p.closed != q.closed || p.selfIntersecting != q.selfIntersecting)
      fail("chord " + std::to_string(x) + " and chord " + std::to_string(y) + " are classified differently");
  }
}

}  // namespace hexdual
