#include "layout/assemble_diagram.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hexdual {
using namespace tables;

namespace {

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
        if (t < 0) t += 2 * std::numbers::pi;
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
      if (t1 < 0) t1 += 2 * std::numbers::pi;
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

// Builds the sheet diagram of a placed mid-surface, one step per part of the picture.
class Assembler {
 public:
  Assembler(const Dual& dual, const MidSurface& s, const Placement& pl, SheetDiagram& d)
      : dual_(dual), s_(s), pl_(pl), d_(d), opened_(pl.opened >= 0 ? OpenedFace(s, pl) : OpenedFace{}) {}

  // A crossing per slot at its quad's centre (the opened face's outside the circle).
  void addCrossings() {
    for (size_t i = 0; i < s_.slots.size(); ++i) {
      Slot sl = s_.slots[i];
      int b = (sl.axis + 1) % 3, c = (sl.axis + 2) % 3;
      bool out = int(i) == pl_.opened;
      d_.crossings.push_back({sl.hex,
                              sl.axis,
                              out ? opened_.crossing : pl_.pos[size_t(s_.centre(int(i)))],
                              {dual_.chordAt(sl.hex, b), dual_.chordAt(sl.hex, c)},
                              out});
    }
  }

  // Every chord of the sheet, each (slot, chord axis) pair walked once.
  void addChords() {
    done_.assign(s_.slots.size(), {false, false, false});
    for (size_t i0 = 0; i0 < s_.slots.size(); ++i0)
      for (int b0 : {(s_.slots[i0].axis + 1) % 3, (s_.slots[i0].axis + 2) % 3})
        if (!done_[i0][size_t(b0)]) addChord(int(i0), b0);
  }

  // Boundary loops as polygons of their corners and mid-edges, the one on the circle first.
  void addLoops() {
    const Triangulation& t = pl_.tri;
    for (size_t j = 0; j < t.loopEdges.size(); ++j) {
      size_t k = j == 0 ? t.outer : j == t.outer ? 0 : j;
      std::vector<Point2> poly;
      for (int e : t.loopEdges[k]) {
        poly.push_back(pl_.pos[size_t(t.edges[size_t(e)].from)]);
        poly.push_back(edgeMid(t.edges[size_t(e)].slot, t.edges[size_t(e)].face));
      }
      d_.loops.push_back(std::move(poly));
    }
  }

 private:
  // Where a chord walk stands: slot i, the chord's axis b there, the face it enters through.
  struct Step {
    int i, b, in;
  };

  Point2 edgeMid(int i, int f) const { return pl_.pos[size_t(s_.mid[size_t(i)][size_t(f)])]; }

  // Back from (i0, b0) to the chord's end, or once round; closed when it came round.
  Step chordStart(int i0, int b0, bool& closed) const {
    int i = i0, b = b0, entry = 2 * b0;
    closed = false;
    for (size_t guard = 0; guard <= s_.slots.size(); ++guard) {
      int j = s_.neighbour(i, entry);
      if (j < 0) break;
      int g = s_.adjFace[size_t(i)][size_t(entry)];
      i = j;
      b = axisOfFace(g);
      entry = oppositeFace(g);
      if (i == i0 && b == b0) {
        closed = true;
        return {i0, b0, 2 * b0};
      }
    }
    return {i, b, entry};
  }

  // The chord through slot i0 along axis b0, walked forward from its start, in pieces split at
  // the seams of a cut-open surface.
  void addChord(int i0, int b0) {
    bool closed = false;
    Step at = chordStart(i0, b0, closed);
    const Step start = at;
    Slot first = s_.slots[size_t(at.i)];
    SheetDiagram::ChordLine proto;
    proto.chord = dual_.chordAt(first.hex, at.b);
    proto.otherSheet = dual_.sheetAt(first.hex, 3 - first.axis - at.b);
    proto.closed = closed;
    std::vector<SheetDiagram::ChordLine> pieces{proto};
    bool closingSeam = false;
    for (size_t guard = 0; guard <= 2 * s_.slots.size(); ++guard) {
      const int out = passSlot(at, pieces.back());
      const int j = s_.neighbour(at.i, out);
      if (j < 0) break;
      const int g = s_.adjFace[size_t(at.i)][size_t(out)];
      const bool seam = s_.joined(at.i, out) < 0;  // a cut: the chord continues on the seam's other side
      at = {j, axisOfFace(g), g};
      if (at.i == start.i && at.b == start.b) {
        closingSeam = seam;
        break;
      }
      if (seam) pieces.push_back(proto);
    }
    if (!closingSeam) joinClosedEnds(pieces);
    for (size_t k = 0; k < pieces.size(); ++k) {
      pieces[k].piece = int(k);
      d_.chords.push_back(std::move(pieces[k]));
    }
  }

  // The chord's pass through one slot: in at a mid-edge, through the crossing, out at the
  // opposite mid-edge (round the outside for the opened face); returns the face it leaves by.
  int passSlot(const Step& at, SheetDiagram::ChordLine& line) {
    done_[size_t(at.i)][size_t(at.b)] = true;
    const int out = oppositeFace(at.in);
    const Slot sl = s_.slots[size_t(at.i)];
    const Point2 pin = edgeMid(at.i, at.in), pout = edgeMid(at.i, out);
    if (line.points.empty()) {
      line.points.push_back(pin);
      if (s_.neighbour(at.i, at.in) < 0) d_.boundary.push_back({sl.hex, at.in, pin});
    }
    if (at.i == pl_.opened)
      opened_.route(at.in, out, line.points);
    else
      line.points.push_back(pl_.pos[size_t(s_.centre(at.i))]);
    line.points.push_back(pout);
    line.hexes.push_back(sl.hex);
    if (s_.neighbour(at.i, out) < 0) d_.boundary.push_back({sl.hex, out, pout});
    return out;
  }

  const Dual& dual_;
  const MidSurface& s_;
  const Placement& pl_;
  SheetDiagram& d_;
  OpenedFace opened_;
  std::vector<std::array<bool, 3>> done_;
};

}  // namespace

SheetDiagram assembleDiagram(const Dual& dual, int sheet, const MidSurface& s, const Placement& pl, bool local) {
  SheetDiagram d;
  d.sheet = sheet;
  d.topology = dual.sheets[size_t(sheet)].topology;
  d.method = local ? "local" : pl.method;
  d.local = local;
  for (int v = 0; v < s.nCorner; ++v) d.cells.push_back({s.verts[size_t(v)], pl.pos[size_t(v)]});
  d.quads = s.quad;
  if (pl.opened >= 0) {
    Slot os = s.slots[size_t(pl.opened)];
    d.openedHex = os.hex;
    d.openedAxis = os.axis;
    d.note = "the face of hex " + std::to_string(os.hex) + " (axis " + std::to_string(os.axis) +
             ") is opened: it is the outside";
  }
  Assembler a(dual, s, pl, d);
  a.addCrossings();
  a.addChords();
  a.addLoops();
  return d;
}

}  // namespace hexdual
