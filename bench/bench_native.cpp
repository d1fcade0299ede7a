// Native benchmarks. `hexdual_bench build N [REPS]` prints one JSON line: the minimum CPU time to
// build an N^3 grid and extract its dual, the complex's bytes per hex, and the process's peak RSS.
#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <malloc.h>
#include <sys/resource.h>
#include <string>
#include <vector>

#include <functional>
#include <random>

#include "complex/builders.hpp"
#include "dual/dual.hpp"
#include "dual/dual_tracker.hpp"
#include "io/io.hpp"
#include "layout/sheet_diagram.hpp"
#include "ops/op_table.hpp"
#include "ops/oplog.hpp"
#include "ops/sheet_ops.hpp"
#include "complex/canonical.hpp"
#include "io/io.hpp"
#include <map>
#include <optional>

using namespace hexdual;
// CPU time of this process: the machine is shared, so wall time measures the neighbours.
struct Clock {
  using duration = std::chrono::duration<double, std::nano>;
  struct time_point {
    double ns;
    duration operator-(time_point o) const { return duration(ns - o.ns); }
  };
  static time_point now() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return {1e9 * double(t.tv_sec) + double(t.tv_nsec)};
  }
};

static long peakRssKb() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stol(line.substr(6));
  return -1;
}

static double ms(Clock::duration d) { return d.count() / 1e6; }

// Minor page faults of this process so far: a fault costs this VM about 13 µs (bench/README.md,
// "The journal reserved once"), so a step that touches fresh memory shows here.
static long minorFaults() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_minflt;
}
// System CPU ms of this process so far (page faults are most of it).
static double systemMs() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return 1e3 * double(u.ru_stime.tv_sec) + double(u.ru_stime.tv_usec) / 1e3;
}

// Transparent huge pages the kernel has faulted in since boot, machine-wide (/proc/vmstat), or -1
// where it cannot be read. Each clears 2 MiB; compare deltas on a quiet machine only.
static long hugePageFaults() {
  std::FILE* f = std::fopen("/proc/vmstat", "r");
  if (!f) return -1;
  char key[64];
  long value = 0, found = -1;
  while (std::fscanf(f, "%63s %ld", key, &value) == 2)
    if (std::strcmp(key, "thp_fault_alloc") == 0) found = value;
  std::fclose(f);
  return found;
}

static int benchBuild(int n, int reps) {
  // Keep freed memory in the process so warm repetitions measure computation, not the VM's page faults.
  mallopt(M_MMAP_THRESHOLD, 1 << 30);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  std::vector<double> build, dual, tracker;
  size_t bytes = 0, sheets = 0, chords = 0;
  for (int r = 0; r < reps; ++r) {
    auto t0 = Clock::now();
    Complex cx = makeGrid(n, n, n);
    auto t1 = Clock::now();
    Dual d = extractDual(cx);
    auto t2 = Clock::now();
    // What the package's Mesh does: the dual with the tracker's per-slot state (the wasm column's work).
    { DualTracker keep(cx); }
    auto t3 = Clock::now();
    build.push_back(ms(t1 - t0));
    dual.push_back(ms(t2 - t1));
    tracker.push_back(ms(t3 - t2));
    bytes = cx.memoryBytes();
    sheets = d.sheets.size();
    chords = d.chords.size();
  }
  double coldMs = build[0] + dual[0];
  if (reps > 1) {  // warm: drop the cold first repetition
    build.erase(build.begin());
    dual.erase(dual.begin());
    tracker.erase(tracker.begin());
  }
  std::sort(build.begin(), build.end());
  std::sort(dual.begin(), dual.end());
  std::sort(tracker.begin(), tracker.end());
  double hexes = double(n) * n * n;
  std::printf(
      "{\"bench\":\"build\",\"n\":%d,\"hexes\":%.0f,\"coldMs\":%.3f,\"buildMs\":%.3f,\"dualMs\":%.3f,\"totalMs\":%.3f,"
      "\"trackerMs\":%.3f,\"bytesPerHex\":%.1f,\"sheets\":%zu,\"chords\":%zu,\"peakRssMb\":%.1f}\n",
      n, hexes, coldMs, build[0], dual[0], build[0] + dual[0], tracker[0],
      double(bytes) / hexes, sheets, chords, peakRssKb() / 1024.0);
  return 0;
}

// Latency of each operation at the centre of an N^3 grid: the operation alone, and the operation
// followed by the incremental dual update. Each is applied and undone REPS times (minimum CPU time reported).
static int benchOps(int n, int reps) {
  Complex cx = makeGrid(n, n, n);
  DualTracker tracker(cx);
  auto id = [&](int i, int j, int k) { return i + n * (j + n * k); };
  const int c = n / 2;
  const HexId centre = id(c, c, c);
  // The z-edge at the centre hex's (x=1,y=1) corner: f = centre|+x, g = (c,c+1)|(c+1,c+1).
  const std::string edge = "h" + std::to_string(centre) + "e11";
  const std::string f = "h" + std::to_string(centre) + "f1", g = "h" + std::to_string(id(c, c + 1, c)) + "f1";
  struct Case {
    const char* name;
    std::string setup, step;
  };
  std::vector<Case> cases = {
      {"pillow", "", "pillow h" + std::to_string(centre) + "f5"},
      {"unpillow", "pillow h" + std::to_string(centre) + "f5", "unpillow h" + std::to_string(cx.hexCapacity())},
      {"chordPush", "", "chordpush " + edge + " " + f + " " + g},
      {"chordPull", "chordpush " + edge + " " + f + " " + g, "chordpull h" + std::to_string(cx.hexCapacity())},
      {"hexPush", "", "hexpush h" + std::to_string(centre) + "f5"},
      {"hexPull", "hexpush h" + std::to_string(centre) + "f5", "hexpull h" + std::to_string(cx.hexCapacity()) + "f5"},
      {"faceCollapse", "", "facecollapse " + edge + " " + f + " " + g},
      {"ringCollapse", "hexpush h" + std::to_string(centre) + "f5", "ringcollapse h" + std::to_string(cx.hexCapacity() + 2) + "e"},
  };
  for (Case& k : cases) {
    Complex::EditLog setupLog;
    if (!k.setup.empty()) {
      OpResult s = applyStep(cx, k.setup);
      tracker.update(cx, s.edits, keepsSheetTopology(s));
      setupLog = s.edits;
    }
    std::string step = k.step;
    if (std::string(k.name) == "ringCollapse") {
      // The ring chord's axis in the first ring hex.
      HexId rh = cx.hexCapacity() - 4;
      for (int a = 0; a < 3; ++a)
        if (tracker.dual().chords[size_t(tracker.dual().chordAt(rh, a))].closed) step += std::to_string(4 * a);
    }
    std::vector<double> opOnly, withDual, opInDual, undoWithDual;
    for (int r = 0; r < reps; ++r) {  // the operation alone (then undone)
      auto t0 = Clock::now();
      OpResult res = applyStep(cx, step);
      auto t1 = Clock::now();
      cx.undo(res.edits);
      opOnly.push_back(ms(t1 - t0));
    }
    for (int r = 0; r < reps; ++r) {  // the operation and the incremental dual update (then both undone)
      // The update keeps what its exact undo needs (a merge's sheets: DualTracker::updateUndone), as
      // the package's and the CLI's steps do; the ids are not given back (no idMemo), as before.
      DualIdMemo memo;
      auto t2 = Clock::now();
      OpResult res = applyStep(cx, step);
      auto tOp = Clock::now();
      tracker.update(cx, res.edits, keepsSheetTopology(res), memo);
      auto t3 = Clock::now();
      cx.undo(res.edits);
      tracker.updateUndone(cx, res.edits, keepsSheetTopology(res), memo);
      auto t4 = Clock::now();
      withDual.push_back(ms(t3 - t2));
      undoWithDual.push_back(ms(t4 - t3));
      opInDual.push_back(ms(tOp - t2));
    }
    if (!k.setup.empty()) {
      cx.undo(setupLog);
      tracker.update(cx, touchedHexes(cx, setupLog));
    }
    std::sort(opOnly.begin(), opOnly.end());
    std::sort(withDual.begin(), withDual.end());
    std::sort(opInDual.begin(), opInDual.end());
    std::sort(undoWithDual.begin(), undoWithDual.end());
    // opInDualUs: the operation's own time inside the with-dual loop, where the tracker's undo of
    // the previous repetition ran just before it (the cache it leaves is the operation's too).
    // undoPlusDualUs: that undo, cx.undo and the tracker's update after it (updateUndone).
    std::printf(
        "{\"bench\":\"op\",\"n\":%d,\"op\":\"%s\",\"opUs\":%.2f,\"opPlusDualUs\":%.2f,\"opInDualUs\":%.2f,\"undoPlusDualUs\":%.2f}\n",
        n, k.name, 1000 * opOnly[0], 1000 * withDual[0], 1000 * opInDual[0], 1000 * undoWithDual[0]);
  }
  return 0;
}

// Throughput of random operation sequences (as in the property test, without the checks); the
// seed and the order of draws are fixed, so every build attempts and applies the same steps.
static int benchThroughput(int n, int steps) {
  Complex cx = makeGrid(n, n, n);
  DualTracker tracker(cx);
  std::mt19937 rng(7);
  int64_t applied = 0, attempted = 0;
  std::vector<HexId> live;
  const long faults0 = minorFaults(), huge0 = hugePageFaults();
  const double sys0 = systemMs();
  auto t0 = Clock::now();
  const char* ops[] = {"pillow", "hexpush", "chordpush"};
  for (int s = 0; s < steps; ++s) {
    HexId h = HexId(rng() % uint32_t(cx.hexCapacity()));
    if (!cx.isHex(h)) continue;
    std::string op = ops[rng() % 3];
    std::string text = op == "chordpush" ? "chordpush h" + std::to_string(h) + "e" + std::to_string(rng() % 12) + " h" +
                                               std::to_string(h) + "f" + std::to_string(rng() % 6) + " h" + std::to_string(h) +
                                               "f" + std::to_string(rng() % 6)
                                         : op + " h" + std::to_string(h) + "f" + std::to_string(rng() % 6);
    ++attempted;
    if (std::optional<OpResult> r = tryApplyStep(cx, text)) {  // a rejected step leaves cx unchanged
      tracker.update(cx, r->edits, keepsSheetTopology(*r));
      ++applied;
    }
  }
  double sec = ms(Clock::now() - t0) / 1000;
  const long faults = minorFaults() - faults0, huge = huge0 < 0 ? -1 : hugePageFaults() - huge0;
  const double sys = systemMs() - sys0;
  std::printf("{\"bench\":\"throughput\",\"n\":%d,\"attempted\":%lld,\"applied\":%lld,\"appliedPerSec\":%.0f,\"hexesAfter\":%lld,\"pageFaults\":%ld,\"hugePageFaultsMachineWide\":%ld,\"systemMs\":%.1f,\"cpuMs\":%.1f}\n",
              n, (long long)attempted, (long long)applied, applied / sec, (long long)cx.numHexes(), faults, huge, sys, 1e3 * sec);
  return 0;
}

// A session that keeps its undo history (as the CLI, the explorer and the package do): the x-layers
// 10, 20, ..., 80 of an N^3 grid extracted one after another with the dual kept current, every
// result kept. Unlike sheetops' apply-and-undo loop, each step meets fresh memory and cold caches.
// Per extraction: mean CPU ms and page faults of the operation and of the dual update.
static int benchSession(int n) {
  Complex cx = makeGrid(n, n, n);
  DualTracker tracker(cx);
  std::vector<OpResult> history;
  double opMs = 0, dualMs = 0;
  long opFaults = 0, dualFaults = 0;
  const int steps = 8, c = n / 2;
  for (int i = 0; i < steps; ++i) {
    const int x = (i + 1) * n / (steps + 2);  // a hex of the layer in the original grid's ids (removed hexes leave holes)
    const std::string step = "sheet-extract h" + std::to_string(x + n * (c + n * c)) + "e0";
    const long f0 = minorFaults();
    const auto t0 = Clock::now();
    history.push_back(applyStep(cx, step));
    const auto t1 = Clock::now();
    const long f1 = minorFaults();
    tracker.update(cx, history.back().edits, keepsSheetTopology(history.back()));
    const auto t2 = Clock::now();
    opMs += ms(t1 - t0), dualMs += ms(t2 - t1);
    opFaults += f1 - f0, dualFaults += minorFaults() - f1;
  }
  std::printf("{\"bench\":\"session\",\"n\":%d,\"extractions\":%d,\"opMs\":%.3f,\"dualMs\":%.3f,\"opFaults\":%ld,\"dualFaults\":%ld}\n",
              n, steps, opMs / steps, dualMs / steps, opFaults / steps, dualFaults / steps);
  return 0;
}

// Layout of one sheet of an N x N x 2 grid: a sheet of N*N hexes (the z-layer).
static int benchLayout(int n, int reps) {
  Complex cx = makeGrid(n, n, 2);
  Dual d = extractDual(cx);
  int sheet = d.sheetAt(0, 2);
  std::vector<double> t;
  size_t crossings = 0;
  for (int r = 0; r < reps; ++r) {
    auto t0 = Clock::now();
    SheetDiagram dg = layoutSheet(cx, d, sheet);
    t.push_back(ms(Clock::now() - t0));
    crossings = dg.crossings.size();
  }
  std::sort(t.begin(), t.end());
  std::printf("{\"bench\":\"layout\",\"n\":%d,\"slots\":%zu,\"ms\":%.3f}\n", n, crossings, t[t.size() / 2]);
  return 0;
}

// Layout of every sheet of a mesh file (the development set): total CPU ms, minimum of REPS.
static int benchLayoutFile(const char* file, int reps) {
  Complex cx = io::readFile(file);
  Dual d = extractDual(cx);
  double best = 1e300;
  size_t sheets = 0, slots = 0;
  for (int r = 0; r < reps; ++r) {
    sheets = slots = 0;
    auto t0 = Clock::now();
    for (const Sheet& s : d.sheets) {
      if (!s.alive) continue;
      SheetDiagram dg = layoutSheet(cx, d, s.id);
      ++sheets;
      slots += dg.crossings.size();
    }
    best = std::min(best, ms(Clock::now() - t0));
  }
  const char* base = std::strrchr(file, '/');
  std::printf("{\"bench\":\"layoutFile\",\"mesh\":\"%s\",\"sheets\":%zu,\"slots\":%zu,\"ms\":%.3f,\"usPerSheet\":%.1f}\n",
              base ? base + 1 : file, sheets, slots, best, 1000 * best / double(sheets));
  return 0;
}

// The floor of an operation: the edits it made, replayed into the complex in a transaction of
// their own (journaled for undo, as the operation's are) with no planning, no checks and no dual
// update. replayOf reads what each edit set (a gluing, a corner, a position) right after the
// operation, before its undo.
struct EditReplay {
  Complex::Edit e;
  Gluing glued;
  VertexId corner = -1;
};
static std::vector<EditReplay> replayOf(const Complex& cx, const Complex::EditLog& log) {
  std::vector<EditReplay> out;
  for (const Complex::Edit& e : log.edits) {
    EditReplay r{e, {}, -1};
    if (e.kind == Complex::Edit::Glue) r.glued = cx.gluing(e.hex, e.face);
    if (e.kind == Complex::Edit::SetCorner) r.corner = cx.vertex(e.hex, e.face);
    if (e.kind == Complex::Edit::SetPosition) r.e.pos = cx.position(e.hex);
    if (e.kind == Complex::Edit::AddVertex || e.kind == Complex::Edit::AddHex) return {};  // removals and re-gluings only
    out.push_back(r);
  }
  return out;
}
static Complex::EditLog replay(Complex& cx, const std::vector<EditReplay>& edits) {
  cx.beginTransaction();
  cx.reserveEdits(edits.size());  // as the sheet operations do
  for (const EditReplay& r : edits) switch (r.e.kind) {
      case Complex::Edit::Unglue: cx.unglue(r.e.hex, r.e.face); break;
      case Complex::Edit::RemoveHex: cx.removeHex(r.e.hex); break;
      case Complex::Edit::SetCorner: cx.setCorner(r.e.hex, r.e.face, r.corner); break;
      case Complex::Edit::SetPosition: cx.setPosition(r.e.hex, r.e.pos); break;
      case Complex::Edit::Glue: cx.glue(r.e.hex, r.e.face, r.glued.hex, r.glued.face, r.glued.orient); break;
      default: break;
    }
  return cx.commitTransaction();
}

// The sheet operations on an N^3 grid: extraction of the middle x-layer (N^2 hexes) and its
// inverse insertion, dicing it in two, pillowing the centre hex, collapsing the middle x-chord.
// Each is applied and undone REPS times (minimum CPU time): the operation alone, and with the
// dual tracker's update; slots: what the update visited; editsMs: the floor, the step's own edits
// replayed (replayOf; -1 for steps that add hexes or vertices).
static int benchSheetOps(int n, int reps, const char* only) {
  Complex cx = makeGrid(n, n, n);
  DualTracker tracker(cx);
  const int c = n / 2;
  const std::string mid = std::to_string(c + n * (c + n * c));
  OpResult extracted = applyStep(cx, "sheet-extract h" + mid + "e0");
  const std::string insert = formatOpStep(*extracted.inverse);
  cx.undo(extracted.edits);
  struct Case {
    const char* name;
    std::string setup, step;
  };
  std::vector<Case> cases = {
      {"sheetExtract", "", "sheet-extract h" + mid + "e0"},
      {"sheetInsert", "sheet-extract h" + mid + "e0", insert},
      {"sheetDice2", "", "sheet-dice h" + mid + "e0 2"},
      {"sheetPillow", "", "sheet-pillow h" + mid},
      {"columnCollapse", "", "column-collapse h" + mid + "e0"},
  };
  for (const Case& k : cases) {
    if (only && std::strcmp(only, k.name)) continue;
    Complex::EditLog setupLog;
    if (!k.setup.empty()) {
      OpResult s = applyStep(cx, k.setup);
      tracker.update(cx, s.edits, keepsSheetTopology(s));
      setupLog = s.edits;
    }
    std::vector<double> opOnly, withDual;
    size_t slots = 0;
    long opFaults = 0, dualFaults = 0;  // in the fastest repetition
    for (int r = 0; r < reps; ++r) {
      const long f0 = minorFaults();
      auto t0 = Clock::now();
      OpResult res = applyStep(cx, k.step);
      auto t1 = Clock::now();
      const long f1 = minorFaults();
      cx.undo(res.edits);
      if (opOnly.empty() || ms(t1 - t0) < *std::min_element(opOnly.begin(), opOnly.end())) opFaults = f1 - f0;
      opOnly.push_back(ms(t1 - t0));
    }
    std::vector<double> ids;  // exact undo's ids: idMemo before the update plus restoreIds after the undo's
    for (int r = 0; r < reps; ++r) {
      const long f2 = minorFaults();
      auto t2 = Clock::now();
      OpResult res = applyStep(cx, k.step);
      auto tm = Clock::now();
      const DualIdMemo memo = tracker.idMemo(cx, res.edits);
      auto tm2 = Clock::now();
      tracker.update(cx, res.edits, keepsSheetTopology(res));
      auto t3 = Clock::now();
      const long f3 = minorFaults();
      slots = tracker.slotsTouched();
      cx.undo(res.edits);
      tracker.update(cx, res.edits, keepsSheetTopology(res));
      auto t4 = Clock::now();
      tracker.restoreIds(memo);
      auto t5 = Clock::now();
      const double t = ms(t3 - t2) - ms(tm2 - tm);
      if (withDual.empty() || t < *std::min_element(withDual.begin(), withDual.end())) dualFaults = f3 - f2;
      withDual.push_back(t);
      ids.push_back(ms(tm2 - tm) + ms(t5 - t4));
    }
    if (!k.setup.empty()) {
      cx.undo(setupLog);
      tracker.update(cx, setupLog, true);
      tracker.releaseRetiredTail();
    }
    // The floor: the same edits replayed (only for steps that add nothing: an extraction, a collapse).
    std::vector<double> floor;
    {
      OpResult res = applyStep(cx, k.step);
      const std::vector<EditReplay> edits = replayOf(cx, res.edits);
      cx.undo(res.edits);
      for (int r = 0; r < reps && !edits.empty(); ++r) {
        auto t0 = Clock::now();
        const Complex::EditLog log = replay(cx, edits);
        floor.push_back(ms(Clock::now() - t0));
        cx.undo(log);
      }
    }
    std::sort(opOnly.begin(), opOnly.end());
    std::sort(withDual.begin(), withDual.end());
    std::sort(ids.begin(), ids.end());
    std::sort(floor.begin(), floor.end());
    std::printf("{\"bench\":\"sheetop\",\"n\":%d,\"op\":\"%s\",\"opMs\":%.3f,\"opPlusDualMs\":%.3f,\"undoIdsMs\":%.3f,\"slotsTouched\":%zu,\"editsMs\":%.3f,\"opFaults\":%ld,\"opPlusDualFaults\":%ld}\n",
                n, k.name, opOnly[0], withDual[0], ids[0], slots, floor.empty() ? -1.0 : floor[0], opFaults, dualFaults);
  }
  return 0;
}

// Every sheet of a mesh file: extracted (or refused, by rule), checked (validate, H - |sheet|, one
// sheet fewer, the tracked dual against a fresh extraction), undone (exact state and canonical
// hash), then extracted again and inserted back with its inverse (isomorphic around a hex that
// stayed). One JSON line per mesh: counts per rule, inverses, and the CPU time of the steps.
static int benchSheetsDevset(const char* path) {
  Complex cx = io::readFile(path);
  DualTracker tracker(cx);
  const uint64_t hash = canonicalHash(cx);
  const Dual d = extractDual(cx);
  std::map<std::string, int> tally;
  int inverses = 0, isomorphicBack = 0, checksFailed = 0;
  double opMs = 0, dualMs = 0, maxOpMs = 0;
  auto live = [](const Dual& x) { return std::count_if(x.sheets.begin(), x.sheets.end(), [](const Sheet& s) { return s.alive; }); };
  const auto sheets0 = live(tracker.dual());
  for (const Sheet& s : d.sheets) {
    const OpStep step = makeStep(OpKind::SheetExtract, EdgeRef{s.slots[0].hex, 4 * s.slots[0].axis});
    std::string why;
    auto t0 = Clock::now();
    std::optional<OpResult> r = tryApplyStep(cx, step, &why);
    auto t1 = Clock::now();
    if (!r) {
      ++tally[ruleOf(why)];
      continue;
    }
    ++tally["applied"];
    tracker.update(cx, r->edits, keepsSheetTopology(*r));
    auto t2 = Clock::now();
    opMs += ms(t1 - t0), dualMs += ms(t2 - t1), maxOpMs = std::max(maxOpMs, ms(t1 - t0));
    try {
      cx.validate();
      compareDuals(cx, tracker.dual(), extractDual(cx));
      if (r->dH != -int64_t(s.slots.size()) || live(tracker.dual()) != sheets0 - 1) throw Error("counts");
      if (r->inverse) {
        Complex back = cx, original = cx;
        applyStep(back, *r->inverse);
        original.undo(r->edits);
        ++inverses;
        for (HexId h : back.hexes())
          if (original.isHex(h)) {  // a hex the extraction left in place anchors the isomorphism
            isomorphicBack += isomorphicAt(back, h, original, h);
            break;
          }
      }
    } catch (const Error&) {
      ++checksFailed;
    }
    cx.undo(r->edits);
    tracker.update(cx, r->edits, true);
    tracker.releaseRetiredTail();
    checksFailed += canonicalHash(cx) != hash;
  }
  std::printf("{\"bench\":\"sheetsDevset\",\"file\":\"%s\",\"hexes\":%lld,\"sheets\":%zu,\"rules\":{", path,
              (long long)cx.numHexes(), d.sheets.size());
  bool first = true;
  for (auto& [k, v] : tally) std::printf("%s\"%s\":%d", first ? "" : ",", k.c_str(), v), first = false;
  std::printf("},\"inverses\":%d,\"isomorphicBack\":%d,\"checksFailed\":%d,\"opMsTotal\":%.2f,\"opMsMax\":%.2f,\"dualMsTotal\":%.2f}\n",
              inverses, isomorphicBack, checksFailed, opMs, maxOpMs, dualMs);
  return checksFailed ? 1 : 0;
}

int main(int argc, char** argv) {
  if (argc >= 3 && !std::strcmp(argv[1], "layout-file")) return benchLayoutFile(argv[2], argc > 3 ? std::atoi(argv[3]) : 3);
  if (argc >= 3 && !std::strcmp(argv[1], "sheets-devset")) {
    try {
      return benchSheetsDevset(argv[2]);
    } catch (const std::exception& e) {  // a file the readers refuse
      std::fprintf(stderr, "%s\n", e.what());
      return 2;
    }
  }
  if (argc >= 3 && !std::strcmp(argv[1], "sheetops")) return benchSheetOps(std::atoi(argv[2]), argc > 3 ? std::atoi(argv[3]) : 5, argc > 4 ? argv[4] : nullptr);
  if (argc >= 3 && !std::strcmp(argv[1], "layout")) return benchLayout(std::atoi(argv[2]), argc > 3 ? std::atoi(argv[3]) : 5);
  if (argc >= 3 && !std::strcmp(argv[1], "build")) return benchBuild(std::atoi(argv[2]), argc > 3 ? std::atoi(argv[3]) : 5);
  if (argc >= 3 && !std::strcmp(argv[1], "session")) return benchSession(std::atoi(argv[2]));
  if (argc >= 3 && !std::strcmp(argv[1], "ops")) return benchOps(std::atoi(argv[2]), argc > 3 ? std::atoi(argv[3]) : 21);
  if (argc >= 3 && !std::strcmp(argv[1], "throughput"))
    return benchThroughput(std::atoi(argv[2]), argc > 3 ? std::atoi(argv[3]) : 20000);
  std::fprintf(stderr, "usage: hexdual_bench build N [REPS] | ops N [REPS] | sheetops N [REPS] [OP] | throughput N [STEPS] | session N | layout N [REPS] | layout-file MESH [REPS]\n");
  return 2;
}
