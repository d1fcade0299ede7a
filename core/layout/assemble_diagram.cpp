#include "layout/assemble_diagram.hpp"

#include <algorithm>
#include <cmath>


namespace hexdual {
using namespace tables;

namespace {

const double kPi = std::acos(-1.0);

// The opened face of a sphere, drawn outside the circle: its mid-edge midpoints in angular order
// are 0..3; the chord through (0,2) runs on an arc of radius 1.2 that passes the crossing at angle
// 1; the chord through (1,3) leaves radially through the crossing and runs on an arc of radius 1.4.
// They meet only there.
struct OpenedFace {
  double angle[6] = {0, 0, 0, 0, 0, 0};  // per face: angle of its mid-edge midpoint
  int order[6] = {-1, -1, -1, -1, -1, -1};
  Point2 crossing;

  OpenedFace() = default;
  OpenedFace(const MidSurface& s, const Placement& pl) {
    Slot os = s.slots[size_t(pl.opened)];
    std::vector<std::pair<double, int>> byAngle;
    for (int f = 0; f < 6; ++f)
      if (axisOfFace(f) != os.axis) {
        Point2 m = pl.pos[size_t(s.mid[size_t(pl.opened)][size_t(f)])];
        double t = std::atan2(m.y, m.x);
        if (t < 0) t += 2 * kPi;
        angle[f] = t;
        byAngle.push_back({t, f});
      }
    std::sort(byAngle.begin(), byAngle.end());
    for (int k = 0; k < 4; ++k) order[byAngle[size_t(k)].second] = k;
    double t1 = byAngle[1].first;
    crossing = {1.2 * std::cos(t1), 1.2 * std::sin(t1)};
  }

  void route(int in, int out, std::vector<Point2>& pts) const {
    int kin = order[in], kout = order[out];
    int a = kin < kout ? in : out, b = kin < kout ? out : in;
    double ta = angle[a], tb = angle[b];
    auto P = [](double r, double t) { return Point2{r * std::cos(t), r * std::sin(t)}; };
    std::vector<Point2> r;
    const int steps = 24;
    if (std::min(kin, kout) == 0) {  // inner arc a -> b, through the crossing
      double t1 = std::atan2(crossing.y, crossing.x);
      if (t1 < 0) t1 += 2 * kPi;
      for (int k = 0; k <= steps; ++k) {
        double t = ta + (tb - ta) * k / steps;
        if (k > 0) {
          double tp = ta + (tb - ta) * (k - 1) / steps;
          if (t1 > tp && t1 < t) r.push_back(crossing);
        }
        r.push_back(P(1.2, t));
      }
    } else {  // out through the crossing, outer arc a -> b
      r.push_back(crossing);
      for (int k = 0; k <= steps; ++k) r.push_back(P(1.4, ta + (tb - ta) * k / steps));
    }
    if (kin > kout) std::reverse(r.begin(), r.end());
    pts.insert(pts.end(), r.begin(), r.end());
  }
};

// A closed chord cut into pieces: its last piece continues into its first.
void joinClosedEnds(std::vector<SheetDiagram::ChordLine>& pieces) {
  if (pieces.size() < 2 || !pieces[0].closed) return;
  SheetDiagram::ChordLine& last = pieces.back();
  last.points.insert(last.points.end(), pieces[0].points.begin() + 1, pieces[0].points.end());
  last.hexes.insert(last.hexes.end(), pieces[0].hexes.begin(), pieces[0].hexes.end());
  pieces[0].points = std::move(last.points);
  pieces[0].hexes = std::move(last.hexes);
  pieces.pop_back();
}

}  // namespace

SheetDiagram assembleDiagram(const Dual& dual, int sheet, const MidSurface& s, const Placement& pl, bool local) {
  SheetDiagram d;
  d.sheet = sheet;
  d.topology = dual.sheets[size_t(sheet)].topology;
  d.method = local ? "local" : pl.method;
  d.local = local;
  for (int v = 0; v < s.nCorner; ++v) d.cells.push_back({s.verts[size_t(v)], pl.pos[size_t(v)]});
  d.quads = s.quad;
  auto edgeMid = [&](int i, int f) { return pl.pos[size_t(s.mid[size_t(i)][size_t(f)])]; };
  const bool opened = pl.opened >= 0;
  OpenedFace of = opened ? OpenedFace(s, pl) : OpenedFace{};
  if (opened) {
    Slot os = s.slots[size_t(pl.opened)];
    d.openedHex = os.hex;
    d.openedAxis = os.axis;
    d.note = "the face of hex " + std::to_string(os.hex) + " (axis " + std::to_string(os.axis) +
             ") is opened: it is the outside";
  }
  for (size_t i = 0; i < s.slots.size(); ++i) {
    Slot sl = s.slots[i];
    int b = (sl.axis + 1) % 3, c = (sl.axis + 2) % 3;
    bool out = int(i) == pl.opened;
    d.crossings.push_back({sl.hex,
                           sl.axis,
                           out ? of.crossing : pl.pos[size_t(s.centre(int(i)))],
                           {dual.chordAt(sl.hex, b), dual.chordAt(sl.hex, c)},
                           out});
  }
  // Chords: walk each (slot, chord axis) pair once.
  std::vector<std::array<bool, 3>> done(s.slots.size(), {false, false, false});
  for (size_t i0 = 0; i0 < s.slots.size(); ++i0)
    for (int b0 : {(s.slots[i0].axis + 1) % 3, (s.slots[i0].axis + 2) % 3}) {
      if (done[i0][size_t(b0)]) continue;
      // Walk backwards to an end (or once round).
      int i = int(i0), b = b0, entry = 2 * b0;
      bool closed = false;
      for (size_t guard = 0; guard <= s.slots.size(); ++guard) {
        int j = s.neighbour(i, entry);
        if (j < 0) break;
        int g = s.adjFace[size_t(i)][size_t(entry)];
        i = j;
        b = axisOfFace(g);
        entry = oppositeFace(g);
        if (i == int(i0) && b == b0) {
          closed = true;
          break;
        }
      }
      if (closed) {
        i = int(i0);
        b = b0;
        entry = 2 * b0;
      }
      int in = closed ? 2 * b0 : entry;  // the face we enter through
      std::vector<SheetDiagram::ChordLine> pieces(1);
      Slot first = s.slots[size_t(i)];
      pieces[0].chord = dual.chordAt(first.hex, b);
      pieces[0].otherSheet = dual.sheetAt(first.hex, 3 - first.axis - b);
      pieces[0].closed = closed;
      int startI = i, startB = b;
      bool closingSeam = false;
      for (size_t guard = 0; guard <= 2 * s.slots.size(); ++guard) {
        SheetDiagram::ChordLine& line = pieces.back();
        done[size_t(i)][size_t(b)] = true;
        int out = oppositeFace(in);
        Slot sl = s.slots[size_t(i)];
        Point2 pin = edgeMid(i, in), pout = edgeMid(i, out);
        if (line.points.empty()) {
          line.points.push_back(pin);
          if (s.neighbour(i, in) < 0) d.boundary.push_back({sl.hex, in, pin});
        }
        if (i == pl.opened) {
          of.route(in, out, line.points);
          line.points.push_back(pout);
        } else {
          line.points.push_back(pl.pos[size_t(s.centre(i))]);
          line.points.push_back(pout);
        }
        line.hexes.push_back(sl.hex);
        int j = s.neighbour(i, out);
        if (j < 0) {
          d.boundary.push_back({sl.hex, out, pout});
          break;
        }
        int g = s.adjFace[size_t(i)][size_t(out)];
        bool seam = s.joined(i, out) < 0;  // a cut: the chord continues on the seam's other side
        i = j;
        b = axisOfFace(g);
        in = g;
        if (i == startI && b == startB) {
          closingSeam = seam;
          break;
        }
        if (seam) {
          pieces.emplace_back();
          pieces.back().chord = pieces[0].chord;
          pieces.back().otherSheet = pieces[0].otherSheet;
          pieces.back().closed = closed;
        }
      }
      if (!closingSeam) joinClosedEnds(pieces);
      for (size_t k = 0; k < pieces.size(); ++k) {
        pieces[k].piece = int(k);
        d.chords.push_back(std::move(pieces[k]));
      }
    }
  // Boundary loops as polygons of their corners and mid-edges, the one on the circle first.
  const Triangulation& t = pl.tri;
  for (size_t j = 0; j < t.loopEdges.size(); ++j) {
    size_t k = j == 0 ? t.outer : j == t.outer ? 0 : j;
    std::vector<Point2> poly;
    for (int e : t.loopEdges[k]) {
      poly.push_back(pl.pos[size_t(t.edges[size_t(e)].from)]);
      poly.push_back(edgeMid(t.edges[size_t(e)].slot, t.edges[size_t(e)].face));
    }
    d.loops.push_back(std::move(poly));
  }
  return d;
}

}  // namespace hexdual
