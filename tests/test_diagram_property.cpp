// Sheet diagrams are planar by construction (Tutte/Floater on a triangulated mid-surface), so every
// sheet is drawn whole. Property test: random candidate steps of every operation kind on small
// grids and an O-grid (fixed, printed seeds), and random steps on development-set meshes; after
// each sequence every sheet (on the meshes: every sheet through an edited hex) is laid out, and an
// independent geometric check — not checkDiagram — asserts that no two chord segments meet
// except at a shared crossing. HEXDUAL_DIAGRAM_SEQUENCES sets the count (default 1,000).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <random>
#include <set>

#include "complex/builders.hpp"
#include "dev_mesh.hpp"
#include "helpers.hpp"
#include "layout/diagram_spread.hpp"
#include "layout/sheet_diagram.hpp"
#include "ops/candidates.hpp"
#include "ops/op_table.hpp"
#include "ops/oplog.hpp"

using namespace hexdual;

namespace {

struct Segment {
  Point2 a, b;
  size_t line, index;  // the chord polyline and the segment's place in it
};

long double orient(Point2 p, Point2 q, Point2 r) {
  return (static_cast<long double>(q.x) - p.x) * (static_cast<long double>(r.y) - p.y) -
         (static_cast<long double>(q.y) - p.y) * (static_cast<long double>(r.x) - p.x);
}
int sign(long double v) { return v > 0 ? 1 : v < 0 ? -1 : 0; }
bool same(Point2 a, Point2 b) { return a.x == b.x && a.y == b.y; }
bool onSegment(Point2 p, Point2 a, Point2 b) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
}

// Whether closed segments ab and cd have a point in common (exact signs of long-double orientations).
bool meet(Point2 a, Point2 b, Point2 c, Point2 d) {
  int o1 = sign(orient(a, b, c)), o2 = sign(orient(a, b, d)), o3 = sign(orient(c, d, a)), o4 = sign(orient(c, d, b));
  if (o1 != o2 && o3 != o4) return true;
  return (o1 == 0 && onSegment(c, a, b)) || (o2 == 0 && onSegment(d, a, b)) || (o3 == 0 && onSegment(a, c, d)) ||
         (o4 == 0 && onSegment(b, c, d));
}

// The shared endpoint of two segments that touch only there, or false.
bool touchOnlyAtEndpoint(const Segment& s, const Segment& t, Point2* at) {
  for (Point2 p : {s.a, s.b})
    for (Point2 q : {t.a, t.b})
      if (same(p, q)) {
        Point2 so = same(p, s.a) ? s.b : s.a, to = same(q, t.a) ? t.b : t.a;
        // Collinear and overlapping beyond the endpoint is a real meeting.
        if (sign(orient(p, so, to)) == 0 && (so.x - p.x) * (to.x - p.x) + (so.y - p.y) * (to.y - p.y) > 0) return false;
        *at = p;
        return true;
      }
  return false;
}

// Every pair of chord segments that meet, by a sweep over x; a pair may meet only where two
// consecutive segments of one polyline join, or at a crossing both pass. Returns what went wrong.
std::string chordsMeetOnlyAtCrossings(const SheetDiagram& d) {
  std::set<std::pair<double, double>> crossingAt;
  for (const auto& c : d.crossings) crossingAt.insert({c.p.x, c.p.y});
  std::vector<Segment> segs;
  for (size_t k = 0; k < d.chords.size(); ++k)
    for (size_t i = 0; i + 1 < d.chords[k].points.size(); ++i)
      segs.push_back({d.chords[k].points[i], d.chords[k].points[i + 1], k, i});
  std::sort(segs.begin(), segs.end(), [](const Segment& s, const Segment& t) {
    return std::min(s.a.x, s.b.x) < std::min(t.a.x, t.b.x);
  });
  for (size_t i = 0; i < segs.size(); ++i) {
    const Segment& s = segs[i];
    const double right = std::max(s.a.x, s.b.x);
    for (size_t j = i + 1; j < segs.size() && std::min(segs[j].a.x, segs[j].b.x) <= right; ++j) {
      const Segment& t = segs[j];
      if (!meet(s.a, s.b, t.a, t.b)) continue;
      Point2 at;
      if (!touchOnlyAtEndpoint(s, t, &at))
        return "chords " + std::to_string(d.chords[s.line].chord) + " and " + std::to_string(d.chords[t.line].chord) +
               " cross away from an endpoint";
      const auto& line = d.chords[s.line];
      bool consecutive = s.line == t.line && (s.index + 1 == t.index || t.index + 1 == s.index ||
                                              (line.closed && std::min(s.index, t.index) == 0 &&
                                               std::max(s.index, t.index) + 2 == line.points.size()));
      if (!consecutive && !crossingAt.count({at.x, at.y}))
        return "chords " + std::to_string(d.chords[s.line].chord) + " and " + std::to_string(d.chords[t.line].chord) +
               " meet at (" + std::to_string(at.x) + ", " + std::to_string(at.y) + "), which is not a crossing";
    }
  }
  return "";
}

struct Tally {
  int64_t sequences = 0, steps = 0, diagrams = 0;
  std::map<std::string, int64_t> methods, ops;
  double worstSpread = 1e9;
  std::string worst;  // where the smallest spread is
};

// Lays out the given sheets and checks them; returns false (with a message) on the first failure.
void checkSheets(const Complex& cx, const std::vector<int>& sheets, const std::string& what, Tally& tally) {
  Dual d = extractDual(cx);
  for (int s : sheets) {
    if (s < 0 || size_t(s) >= d.sheets.size() || !d.sheets[size_t(s)].alive) continue;
    CAPTURE(what);
    CAPTURE(s);
    SheetDiagram dg = layoutSheet(cx, d, s);  // throws when the sheet cannot be drawn whole
    REQUIRE(dg.method != "local");
    REQUIRE(dg.crossings.size() == d.sheets[size_t(s)].slots.size());
    const std::string why = chordsMeetOnlyAtCrossings(dg);
    if (!why.empty()) FAIL_CHECK(what << ": sheet " << s << " (" << dg.method << "): " << why);
    ++tally.diagrams;
    ++tally.methods[dg.method];
    const double spread = diagramSpread(dg);
    if (spread < tally.worstSpread) {
      tally.worstSpread = spread;
      tally.worst = what + ", sheet " + std::to_string(s) + " (" + dg.method + ")";
    }
  }
}

std::vector<int> allSheets(const Complex& cx) {
  std::vector<int> out;
  Dual d = extractDual(cx);
  for (const Sheet& s : d.sheets)
    if (s.alive) out.push_back(s.id);
  return out;
}

// 1-5 random candidate steps of random operation kinds.
std::string randomCandidateSequence(Complex& cx, std::mt19937& rng, Tally& tally) {
  static const OpKind kinds[] = {OpKind::Pillow,    OpKind::Unpillow,     OpKind::ChordPush, OpKind::ChordPull,
                                 OpKind::HexPush,   OpKind::HexPull,      OpKind::RingCollapse,
                                 OpKind::FaceCollapse, OpKind::FaceSplit};
  std::string log = "v1";
  const int length = 1 + int(rng() % 5);
  for (int step = 0, tries = 0; step < length && tries < 40; ++tries) {
    std::vector<OpStep> c = candidates(cx, kinds[rng() % (sizeof kinds / sizeof kinds[0])]);
    if (c.empty()) continue;
    const OpStep& pick = c[rng() % c.size()];
    applyStep(cx, pick);
    log += ";" + formatOpStep(pick);
    ++tally.ops[opName(pick.op)];
    ++tally.steps;
    ++step;
  }
  return log;
}

int sequenceCount() {
  const char* env = std::getenv("HEXDUAL_DIAGRAM_SEQUENCES");
  return env ? std::atoi(env) : 1000;
}

}  // namespace

TEST_CASE("diagram property: every sheet drawn whole after random candidate steps on grids (fixed seeds)") {
  const int sequences = sequenceCount();
  const uint32_t firstSeed = 20261203;
  const std::vector<Complex> meshes{makeGrid(3, 3, 3), makeGrid(4, 4, 4), makeGrid(5, 3, 3), makeRing(6, 2, 2)};
  Tally tally;
  for (int k = 0; k < sequences; ++k) {
    const uint32_t seed = firstSeed + uint32_t(k);
    std::mt19937 rng(seed);
    Complex cx = meshes[size_t(k) % meshes.size()];
    const std::string log = randomCandidateSequence(cx, rng, tally);
    checkSheets(cx, allSheets(cx), "seed " + std::to_string(seed) + " " + log, tally);
    ++tally.sequences;
  }
  std::string methods, ops;
  for (auto& [m, n] : tally.methods) methods += " " + m + "=" + std::to_string(n);
  for (auto& [o, n] : tally.ops) ops += " " + o + "=" + std::to_string(n);
  MESSAGE("diagram property: " << tally.sequences << " sequences, seeds " << firstSeed << ".."
                               << firstSeed + uint32_t(sequences) - 1 << ", " << tally.steps << " steps (" << ops
                               << "), " << tally.diagrams << " sheets drawn whole:" << methods
                               << "; smallest spread " << tally.worstSpread << " at " << tally.worst);
  CHECK(tally.methods["local"] == 0);
  if (sequences >= 200)
    for (const char* op : {"pillow", "unpillow", "chordpush", "chordpull", "hexpush", "hexpull", "ringcollapse", "facecollapse"}) {
      CAPTURE(op);
      CHECK(tally.ops[op] > 0);
    }
}

TEST_CASE("diagram property: sheets through edited hexes of development-set meshes are drawn whole") {
  const std::filesystem::path dir = test::devMeshDir();
  if (!std::filesystem::is_directory(dir)) {
    MESSAGE("skipped: no development-set meshes at " << dir.string());
    return;
  }
  const int sequences = std::max(1, sequenceCount() / 10);
  const uint32_t firstSeed = 20261204;
  std::vector<Complex> meshes;
  for (const char* name : {"MOAB_125hex.vtk.gz", "G_cylinder_1.vtk.gz", "P_double-torus.vtk.gz", "P_kitten.mesh.gz"})
    meshes.push_back(test::readDevMesh(dir / name));
  Tally tally;
  static const char* kOps[] = {"pillow", "hexpush", "chordpush", "facecollapse"};
  for (int k = 0; k < sequences; ++k) {
    const uint32_t seed = firstSeed + uint32_t(k);
    std::mt19937 rng(seed);
    Complex cx = meshes[size_t(k) % meshes.size()];
    std::string log = "v1";
    std::set<HexId> edited;
    for (int tries = 0, steps = 0; tries < 60 && steps < 3; ++tries) {
      std::vector<HexId> live;
      for (HexId h : cx.hexes()) live.push_back(h);
      HexId h = live[rng() % live.size()];
      const std::string op = kOps[rng() % 4], H = "h" + std::to_string(h);
      const std::string text = op == "chordpush" || op == "facecollapse"
                                   ? op + " " + H + "e" + std::to_string(rng() % 12) + " " + H + "f" +
                                         std::to_string(rng() % 6) + " " + H + "f" + std::to_string(rng() % 6)
                                   : op + " " + H + "f" + std::to_string(rng() % 6);
      std::optional<OpResult> r = tryApplyStep(cx, text);
      if (!r) continue;
      log += ";" + text;
      edited.insert(r->createdHexes.begin(), r->createdHexes.end());
      edited.insert(h);
      ++tally.ops[op];
      ++tally.steps;
      ++steps;
    }
    Dual d = extractDual(cx);
    std::set<int> sheets;
    for (HexId h : edited)
      if (cx.isHex(h))
        for (int a = 0; a < 3; ++a) sheets.insert(d.sheetAt(h, a));
    checkSheets(cx, std::vector<int>(sheets.begin(), sheets.end()), "seed " + std::to_string(seed) + " " + log, tally);
    ++tally.sequences;
  }
  std::string methods;
  for (auto& [m, n] : tally.methods) methods += " " + m + "=" + std::to_string(n);
  MESSAGE("diagram property (development set): " << tally.sequences << " sequences, seeds " << firstSeed << ".."
                                                 << firstSeed + uint32_t(sequences) - 1 << ", " << tally.steps
                                                 << " steps, " << tally.diagrams << " sheets drawn whole:" << methods
                                                 << "; smallest spread " << tally.worstSpread << " at "
                                                 << tally.worst);
  CHECK(tally.methods["local"] == 0);
  CHECK(tally.steps > 0);
}

TEST_CASE("the independent chord check finds chords that meet away from a crossing") {
  Complex cx = makeGrid(3, 3, 3);
  Dual d = extractDual(cx);
  SheetDiagram dg = layoutSheet(cx, d, 0);
  CHECK(chordsMeetOnlyAtCrossings(dg).empty());
  // Move one crossing far away: its chords now cut across others.
  const HexId moved = dg.crossings[0].hex;
  for (auto& line : dg.chords)
    for (size_t i = 0; i < line.hexes.size(); ++i)
      if (line.hexes[i] == moved) line.points[2 * i + 1] = {-5, -5};
  CHECK(test::contains(chordsMeetOnlyAtCrossings(dg), "chords"));
}
