// hexdual command-line tool: a thin layer over core. See docs/cli.md.
#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "complex/builders.hpp"
#include "complex/manifold.hpp"
#include "dual/dual.hpp"
#include "dual/dual_tracker.hpp"
#include "flips/decompositions.hpp"
#include "flips/flip.hpp"
#include "flips/fourcube.hpp"
#include "flips/search.hpp"
#include "geometry/quality_stats.hpp"
#include "io/geometry_json.hpp"
#include "ops/candidates.hpp"
#include "ops/op_table.hpp"
#include "ops/oplog.hpp"
#include "ops/report.hpp"
#include "io/io.hpp"
#include "io/json.hpp"
#include "io/preview_json.hpp"
#include "layout/sheet_diagram.hpp"

using namespace hexdual;

namespace {

const char* kUsage =
    "usage:\n"
    "  hexdual grid AxBxC -o FILE [--binary]     write a structured grid\n"
    "  hexdual ring NxRxZ -o FILE [--binary]     write an O-grid: N around, R radial, Z axial\n"
    "  hexdual info FILE [--json]                counts, sheets and chords, and what the file held\n"
    "  hexdual validate FILE                     check every invariant; list non-manifold vertices\n"
    "  hexdual convert IN OUT [--binary]         read any supported format, write .vtk, .mesh or .hxd\n"
    "  hexdual apply FILE --ops LOG -o OUT [--json] [--no-smooth]\n"
    "                                            apply an operation log (text, URL form, or @file); each\n"
    "                                            step is untangled and smoothed locally (--no-smooth: new\n"
    "                                            vertices stay at the operations' offsets)\n"
    "  hexdual quality FILE [--json]             scaled-Jacobian distribution (min, mean, histogram)\n"
    "  hexdual candidates FILE OP                steps of operation OP that apply to FILE\n"
    "  hexdual apply FILE --ops LOG --dry-run [--json]\n"
    "                                            the same reports, nothing written\n"
    "  hexdual preview FILE --ops LOG [--json]   what the log's last step would change (after the others)\n"
    "  hexdual select FILE h12e3|h12f5 [--json]  the sheet through an edge, the chord through a quad\n"
    "  hexdual sheets FILE [--sheet ID | --all] [--local H1,H2,.. --rings K] --json|--svg OUTDIR\n"
    "                                            sheet diagrams as JSON or SVG files\n"
    "  hexdual flip list [--json]                the cubical flips and their stored decompositions\n"
    "  hexdual flip NAME --at H1,H2,.. FILE -o OUT [--via-atomic] [--no-smooth]\n"
    "                                            apply a flip to the named hexes (smoothed like apply)\n"
    "  hexdual flip verify --all [--json]        check every stored decomposition in host meshes\n"
    "  hexdual flip search NAME --max-depth D [--max-seconds S] [--max-states N] [--ops a,b]\n"
    "                   [--threads T] [--max-memory MB] [--max-region H] [--ring-split L] [--symmetry]\n"
    "                   [--lookup-last] [--reversible] [--checkpoint FILE [--checkpoint-every S]] [--resume FILE]\n"
    "                                            search atomic sequences for a flip (SIGUSR1: checkpoint\n"
    "                                            now; SIGINT/SIGTERM: checkpoint and stop)\n"
    "Reading (every command): .vtk (legacy 2.0-5.1), .vtu, .msh (2.2, 4.1), .mesh, .meshb, .hxd, any of\n"
    "them gzipped; --hexes-only reads the hexahedra of a file that also has tets, prisms or pyramids.\n";

struct Args {
  std::vector<std::string> positional;
  std::string output, ops, at, local, jsonDir, svgDir, checkpoint, resume;
  double checkpointEvery = 0;
  bool json = false, binary = false, noSmooth = false, viaAtomic = false, all = false, hexesOnly = false, symmetry = false, lookupLast = false, reversible = false;
  bool dryRun = false;
  int sheet = -1, rings = 2;
  int maxDepth = 4;
  double maxSeconds = 60;
  int64_t maxStates = 200000;
  int threads = 1, maxRegion = 16, ringSplit = 8;
  double maxMemory = 4096;
};

Args parseArgs(int argc, char** argv, int from) {
  Args a;
  const bool sheets = std::string(argv[from - 1]) == "sheets";
  for (int i = from; i < argc; ++i) {
    std::string s = argv[i];
    if (sheets && (s == "--json" || s == "--svg" || s == "--local" || s == "--sheet" || s == "--rings")) {
      if (i + 1 >= argc) throw Error(s + " needs a value");
      std::string v = argv[++i];
      if (s == "--json") a.jsonDir = v;
      if (s == "--svg") a.svgDir = v;
      if (s == "--local") a.local = v;
      try {
        if (s == "--sheet") a.sheet = std::stoi(v);
        if (s == "--rings") a.rings = std::stoi(v);
      } catch (const std::exception&) {
        throw Error(s + " needs a number, not '" + v + "'");
      }
      continue;
    }
    if (s == "-o") {
      if (i + 1 >= argc) throw Error("-o needs a file name");
      a.output = argv[++i];
    } else if (s == "--checkpoint" || s == "--resume") {
      if (i + 1 >= argc) throw Error(s + " needs a file name");
      (s == "--checkpoint" ? a.checkpoint : a.resume) = argv[++i];
    } else if (s == "--ops") {
      if (i + 1 >= argc) throw Error("--ops needs an operation log");
      a.ops = argv[++i];
    } else if (s == "--at" || s == "--max-depth" || s == "--max-seconds" || s == "--max-states" || s == "--threads" ||
               s == "--max-memory" || s == "--max-region" || s == "--ring-split" || s == "--checkpoint-every") {
      if (i + 1 >= argc) throw Error(s + " needs a value");
      std::string v = argv[++i];
      try {
        if (s == "--at") a.at = v;
        if (s == "--max-depth") a.maxDepth = std::stoi(v);
        if (s == "--max-seconds") a.maxSeconds = std::stod(v);
        if (s == "--max-states") a.maxStates = std::stoll(v);
        if (s == "--threads") a.threads = std::stoi(v);
        if (s == "--max-memory") a.maxMemory = std::stod(v);
        if (s == "--max-region") a.maxRegion = std::stoi(v);
        if (s == "--ring-split") a.ringSplit = std::stoi(v);
        if (s == "--checkpoint-every") a.checkpointEvery = std::stod(v);
      } catch (const std::exception&) {
        throw Error(s + " needs a number, not '" + v + "'");
      }
    } else if (s == "--symmetry") {
      a.symmetry = true;
    } else if (s == "--lookup-last") {
      a.lookupLast = true;
    } else if (s == "--reversible") {
      a.reversible = true;
    } else if (s == "--dry-run") {
      a.dryRun = true;
    } else if (s == "--via-atomic") {
      a.viaAtomic = true;
    } else if (s == "--all") {
      a.all = true;
    } else if (s == "--json") {
      a.json = true;
    } else if (s == "--no-smooth") {
      a.noSmooth = true;
    } else if (s == "--binary") {
      a.binary = true;
    } else if (s == "--hexes-only") {
      a.hexesOnly = true;
    } else if (s.size() > 1 && s[0] == '-') {
      throw Error("unknown option '" + s + "'");
    } else {
      a.positional.push_back(s);
    }
  }
  return a;
}

// "AxBxC" with each part a decimal 1..2^26 (overflow-safe: digits are counted before converting).
std::array<int, 3> parseDims(const std::string& s) {
  std::array<int, 3> d{};
  size_t pos = 0;
  for (int k = 0; k < 3; ++k) {
    size_t b = pos;
    while (pos < s.size() && s[pos] >= '0' && s[pos] <= '9') ++pos;
    bool sep = k < 2 ? pos < s.size() && s[pos] == 'x' : pos == s.size();
    if (pos == b || !sep) throw Error("dimensions must look like 3x3x3, not '" + s.substr(0, 40) + "'");
    std::string part = s.substr(b, pos - b);
    if (part.size() > 9 || std::stol(part) > (1L << 26) || std::stol(part) < 1)
      throw Error("dimension '" + part.substr(0, 40) + "' is out of range (1.." + std::to_string(1L << 26) + ")");
    d[size_t(k)] = int(std::stol(part));
    ++pos;
  }
  return d;
}

Complex readInput(const Args& a, const std::string& path, io::ReadReport* rep = nullptr) {
  io::ReadOptions opt;
  opt.hexesOnly = a.hexesOnly;
  return io::readFile(path, opt, rep);
}

void need(const Args& a, size_t n, const char* what) {
  if (a.positional.size() != n) throw Error(std::string("expected ") + what);
}

// The log from --ops: text ("v1;..."), the URL form ("1.P13f5"), or @FILE holding either.
OpLog readLog(const std::string& arg) {
  std::string text = arg;
  if (!text.empty() && text[0] == '@') {
    text = io::readBytes(text.substr(1), size_t(1) << 24);
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' ')) text.pop_back();
  }
  if (!text.empty() && text[0] >= '0' && text[0] <= '9') return decodeOpLogUrl(text);
  return parseOpLog(text);
}

// Steps from the CLI are smoothed, unless --no-smooth (then only measured).
StepOptions stepOptions(const Args& a) { return {a.noSmooth ? StepGeometry::Measure : StepGeometry::Smooth}; }

int runApply(const Args& a) {
  need(a, 1, "one input file");
  if (a.ops.empty()) throw Error("apply needs --ops LOG");
  if (a.output.empty() && !a.dryRun) throw Error("apply needs -o OUT (or --dry-run)");
  Complex cx = readInput(a, a.positional[0]);
  OpLog log = readLog(a.ops);
  DualTracker tracker(cx);
  std::vector<StepReport> reports;
  std::string text;
  for (size_t k = 0; k < log.steps.size(); ++k) {
    try {
      reports.push_back(applyStepTracked(cx, tracker, log.steps[k], stepOptions(a)));
    } catch (const Error& e) {
      throw Error("step " + std::to_string(k + 1) + " (" + formatOpStep(log.steps[k]) + "): " + e.what() +
                  "; nothing was written");
    }
    text += io::stepReportText(reports.back(), k + 1);
  }
  if (!a.dryRun) io::writeFile(cx, a.output, a.binary);
  // The written file numbers hexes densely: the last step's inverse as it applies to that file.
  std::optional<std::string> inverseInOutput;
  if (!a.dryRun && !reports.empty() && reports.back().result.inverse)
    if (const auto st = io::numberedAsWritten(cx, *reports.back().result.inverse)) inverseInOutput = formatOpStep(*st);
  if (inverseInOutput && *inverseInOutput != formatOpStep(*reports.back().result.inverse))
    text += "inverse of the last step in " + a.output + " (which numbers hexes densely): " + *inverseInOutput + "\n";
  std::cout << (a.json ? io::applyReportJson(reports, cx, inverseInOutput) + "\n" : text);
  return 0;
}

// hexdual preview FILE --ops LOG: the steps but the last are applied, the last is previewed (ops/preview.hpp).
int runPreview(const Args& a) {
  need(a, 1, "one input file");
  if (a.ops.empty()) throw Error("preview needs --ops LOG (its last step is previewed)");
  Complex cx = readInput(a, a.positional[0]);
  OpLog log = readLog(a.ops);
  if (log.steps.empty()) throw Error("preview: the log has no step");
  DualTracker tracker(cx);
  for (size_t k = 0; k + 1 < log.steps.size(); ++k) {
    try {
      applyStepTracked(cx, tracker, log.steps[k], stepOptions(a));
    } catch (const Error& e) {
      throw Error("step " + std::to_string(k + 1) + " (" + formatOpStep(log.steps[k]) + "): " + e.what());
    }
  }
  const Preview p = previewStep(cx, tracker, log.steps.back(), stepOptions(a));
  std::cout << (a.json ? io::previewJson(p, log.steps.back()) + "\n" : io::previewText(p, log.steps.back()));
  return p.applies ? 0 : 1;
}

// hexdual select FILE h12e3 | h12f5: the sheet through an edge or the chord through a quad.
int runSelect(const Args& a) {
  need(a, 2, "an input file and an edge (h12e3) or a quad (h12f5)");
  Complex cx = readInput(a, a.positional[0]);
  const std::string& t = a.positional[1];
  const size_t kind = t.find_first_of("ef");
  int hex = -1, local = -1;
  try {
    size_t used = 0, usedLocal = 0;
    if (t.size() < 4 || t[0] != 'h' || kind == std::string::npos) throw Error("");
    hex = std::stoi(t.substr(1, kind - 1), &used);
    local = std::stoi(t.substr(kind + 1), &usedLocal);
    if (used != kind - 1 || usedLocal != t.size() - kind - 1) throw Error("");
  } catch (const std::exception&) {
    throw Error("select takes an edge (h12e3) or a quad (h12f5), not '" + t.substr(0, 40) + "'");
  }
  const Dual dual = extractDual(cx);
  const Selection s = t[kind] == 'e' ? selectSheet(cx, dual, {hex, local}) : selectChord(cx, dual, {hex, local});
  std::cout << (a.json ? io::selectionJson(s) + "\n" : io::selectionText(s));
  return 0;
}

std::vector<std::string> splitList(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string x;
  while (std::getline(ss, x, ',')) out.push_back(x);
  return out;
}

// Hex ids from "12,13" or "h12,h13" (option `what` names the option in the error).
std::vector<HexId> parseHexList(const std::string& s, const std::string& what) {
  std::vector<HexId> out;
  for (const std::string& x : splitList(s)) {
    try {
      size_t used = 0;
      std::string t = !x.empty() && x[0] == 'h' ? x.substr(1) : x;
      out.push_back(std::stoi(t, &used));
      if (used != t.size()) throw Error("");
    } catch (const std::exception&) {
      throw Error(what + " takes hex ids like 12,13 or h12,h13, not '" + x + "'");
    }
  }
  return out;
}

OpKind opNamed(const std::string& name, const std::string& context) {
  const OpInfo* op = findOp(name);
  if (!op) throw Error(context + ": unknown operation '" + name + "'");
  return op->kind;
}

std::atomic<int> searchRequest{0};  // set by the signal handlers of `flip search --checkpoint`

// hexdual flip verify --all: every stored decomposition checked in its problem and its host meshes.
int runFlipVerify(const Args& a) {
  if (!a.all) throw Error("flip verify needs --all");
  io::JsonWriter w;
  w.beginArray();
  int failures = 0;
  for (const StoredDecomposition& d : storedDecompositions()) {
    if (!d.found) continue;
    SearchProblem pb = problemFor(d.problem);
    std::vector<std::string> places;
    std::string error;
    try {
      verifyDecomposition(pb, d.steps);
      places.push_back("search problem");
      if (d.problem.find('/') == std::string::npos)
        for (const Embedding& e : flipEmbeddings(d.problem)) {
          verifyInEmbedding(pb, d.steps, e);
          places.push_back(e.name);
        }
    } catch (const Error& e) {
      error = e.what();
    }
    bool ok = error.empty() && places.size() >= 3;
    if (error.empty() && places.size() < 3) error = "verified at " + std::to_string(places.size()) + " places only";
    failures += !ok;
    if (a.json) {
      w.beginObject().key("name").value(d.problem).key("verified").value(ok).key("length").value(int64_t(d.steps.size()));
      w.key("places").value(int64_t(places.size()));
      if (!ok) w.key("error").value(error);
      w.endObject();
    } else {
      std::cout << d.problem << ": " << (ok ? "verified" : "FAILED") << ", " << d.steps.size() << " steps, "
                << places.size() << " places" << (ok ? "" : " (" + error + ")") << "\n";
    }
  }
  w.endArray();
  if (a.json) std::cout << w.str() << "\n";
  return failures ? 1 : 0;
}

// The search options of hexdual flip search, from the command line (signals request checkpoints).
SearchOptions flipSearchOptions(const Args& a) {
  SearchOptions o;
  o.maxDepth = a.maxDepth;
  o.maxSeconds = a.maxSeconds;
  o.maxStates = a.maxStates;
  o.threads = a.threads;
  o.maxMemoryMB = a.maxMemory;
  o.maxRegionHexes = a.maxRegion;
  o.symmetry = a.symmetry;
  o.lookupLastLevel = a.lookupLast;
  o.reversible = a.reversible;
  o.ringSplitMax = a.ringSplit;
  o.checkpointFile = a.checkpoint;
  o.checkpointEvery = a.checkpointEvery;
  o.resumeFile = a.resume;
  if (a.checkpointEvery > 0 && a.checkpoint.empty()) throw Error("--checkpoint-every needs --checkpoint FILE");
  if (!a.checkpoint.empty()) {
    // SIGUSR1: write a checkpoint and go on; SIGINT, SIGTERM: write one and stop.
    o.request = &searchRequest;
    std::signal(SIGUSR1, [](int) { searchRequest = 1; });
    std::signal(SIGINT, [](int) { searchRequest = 2; });
    std::signal(SIGTERM, [](int) { searchRequest = 2; });
  }
  o.progress = [](const SearchLevel& l) {
    std::cerr << "depth " << l.depth << (l.side ? " from the goal: " : " from the start: ")
              << (l.lookedUp ? "looked up (not stored), " : std::to_string(l.newStates) + " new states, ")
              << l.storedStates << " stored, " << l.movesApplied << " moves applied, " << l.seconds << " s\n";
  };
  for (const std::string& op : splitList(a.ops)) o.ops.push_back(opNamed(op, "flip search --ops"));
  return o;
}

// hexdual flip search NAME: the record line on stdout, the summary on stderr.
int runFlipSearch(const Args& a) {
  need(a, 2, "flip search NAME");
  const SearchOptions o = flipSearchOptions(a);
  std::string name = a.positional[1];
  SearchProblem pb = problemFor(name);
  SearchResult r = searchDecomposition(pb, o);
  if (r.found) verifyDecomposition(pb, r.steps);
  std::string label = name + (a.ops == "chordpush,chordpull" ? "/chord-only" : "");
  std::cout << formatDecomposition(label, r, o) << "\n";
  std::cerr << (r.found ? "found " + std::to_string(r.steps.size()) + " steps (verified)" : "none found")
            << "; stopped by " << r.stoppedBy << " after " << r.statesExplored << " states, " << r.movesApplied
            << " moves applied, " << (r.memoryBytes >> 20) << " MB"
            << (r.symmetries > 1 ? ", " + std::to_string(r.symmetries) + " symmetries" : "")
            << (r.lookupKeys ? ", " + std::to_string(r.lookupKeys) + " image keys looked up" : "") << "\n";
  if (!r.message.empty()) std::cerr << r.message << "\n";
  if (r.checkpoints > 0) std::cerr << r.checkpoints << " checkpoint(s) written to " << o.checkpointFile << "\n";
  return 0;
}

int runFlip(const Args& a) {
  if (a.positional.empty()) throw Error("flip needs a subcommand or a flip name (see --help)");
  const std::string sub = a.positional[0];
  if (sub == "list") {
    std::vector<FlipSummary> flips = flipSummaries();
    std::cout << (a.json ? io::flipListJson(flips) + "\n" : io::flipListText(flips));
    return 0;
  }
  if (sub == "verify") return runFlipVerify(a);
  if (sub == "search") return runFlipSearch(a);
  // hexdual flip NAME --at H1,H2 FILE -o OUT [--via-atomic]
  need(a, 2, "flip NAME --at H1,H2,... FILE -o OUT");
  if (a.at.empty()) throw Error("flip needs --at H1,H2,...");
  if (a.output.empty()) throw Error("flip needs -o OUT");
  std::vector<HexId> hexes = parseHexList(a.at, "--at");
  Complex cx = readInput(a, a.positional[1]);
  const std::string name = a.positional[0];
  flipClass(name);
  if (a.viaAtomic) {
    const StoredDecomposition* d = storedFor(name);
    if (!d || !d->found) throw Error("flip " + name + " has no stored atomic decomposition (see hexdual flip list)");
    Complex trial = cx;  // the steps are found on a copy, then applied like `apply` applies them
    auto steps = replayInEmbedding(problemFor(name), d->steps, trial, hexes, "the mesh");
    for (const OpStep& st : steps) applyStep(cx, st, stepOptions(a));
    std::cout << formatOpLog({1, steps}) << "\n";
  } else {
    OpResult r = flip(cx, name, hexes);
    r.quality = placeStepGeometry(cx, r.edits, stepOptions(a).geometry);
    std::cout << "flip " << name << ": hexes created " << io::idList(r.createdHexes) << " removed " << io::idList(r.removedHexes) << "\n"
              << io::stepQualityText(r.quality);
  }
  io::writeFile(cx, a.output, a.binary);
  return 0;
}

int runSheets(const Args& a) {
  need(a, 1, "one input file");
  if (a.jsonDir.empty() && a.svgDir.empty()) throw Error("sheets needs --json OUTDIR or --svg OUTDIR");
  if (a.sheet < 0 && !a.all) throw Error("sheets needs --sheet ID or --all");
  Complex cx = readInput(a, a.positional[0]);
  Dual dual = extractDual(cx);
  std::vector<HexId> around = parseHexList(a.local, "--local");
  std::vector<int> ids;
  if (a.all) {
    for (const Sheet& s : dual.sheets)
      if (!around.empty()) {
        for (HexId h : around)
          if (cx.isHex(h) && (dual.sheetAt(h, 0) == s.id || dual.sheetAt(h, 1) == s.id || dual.sheetAt(h, 2) == s.id)) {
            ids.push_back(s.id);
            break;
          }
      } else {
        ids.push_back(s.id);
      }
  } else {
    ids.push_back(a.sheet);
  }
  for (const std::string& dir : {a.jsonDir, a.svgDir}) {  // made when missing, as `mkdir -p` would
    std::error_code ec;
    if (!dir.empty()) std::filesystem::create_directories(dir, ec);
    if (ec) throw Error(dir + ": cannot create the output directory (" + ec.message() + ")");
  }
  for (int id : ids) {
    SheetDiagram d = around.empty() ? layoutSheet(cx, dual, id) : layoutLocal(cx, dual, id, around, a.rings);
    std::string base = "sheet-" + std::to_string(id) + (around.empty() ? "" : "-local");
    auto write = [&](const std::string& dir, const std::string& ext, const std::string& text) {
      std::string path = dir + "/" + base + ext;
      std::ofstream out(path);
      if (!out) throw Error(path + ": cannot open file for writing");
      out << text;
      std::cout << path << "\n";
    };
    if (!a.jsonDir.empty()) write(a.jsonDir, ".json", diagramJson(d) + "\n");
    if (!a.svgDir.empty()) write(a.svgDir, ".svg", diagramSvg(d));
  }
  return 0;
}

int run(int argc, char** argv) {
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h")) {
    std::cout << kUsage;
    return argc < 2 ? 2 : 0;
  }
  std::string cmd = argv[1];
  Args a = parseArgs(argc, argv, 2);
  if (cmd == "grid" || cmd == "ring") {
    need(a, 1, "one dimensions argument, e.g. 3x3x3");
    if (a.output.empty()) throw Error(cmd + " needs -o FILE");
    auto d = parseDims(a.positional[0]);
    Complex cx = cmd == "grid" ? makeGrid(d[0], d[1], d[2]) : makeRing(d[0], d[1], d[2]);
    io::writeFile(cx, a.output, a.binary);
    return 0;
  }
  if (cmd == "info") {
    need(a, 1, "one input file");
    io::ReadReport rep;
    Complex cx = readInput(a, a.positional[0], &rep);
    Dual dual = extractDual(cx);
    std::cout << (a.json ? io::infoJson(cx, dual, &rep) + "\n" : io::reportText(rep) + io::infoText(cx, dual));
    return 0;
  }
  if (cmd == "validate") {
    need(a, 1, "one input file");
    // Every reader validates the complex it makes (Complex::validateAcceptingNonManifoldVertices)
    // and keeps the vertices whose link is not a sphere or a disk; their reasons are only worked
    // out when there are some (the edge classes and links of a 1M-hex mesh take a second).
    Complex cx = readInput(a, a.positional[0]);
    const auto issues = cx.nonManifoldVertices().empty() ? std::vector<LinkIssue>() : vertexLinkIssues(cx);
    for (const LinkIssue& li : issues) std::cout << a.positional[0] << ": " << describeLinkIssue(cx, li) << "\n";
    if (!issues.empty()) {
      std::cout << a.positional[0] << ": " << issues.size()
                << " non-manifold vertices; otherwise valid (" << cx.numHexes()
                << " hexes); operations refuse to touch these vertices\n";
      return 1;
    }
    std::cout << a.positional[0] << ": valid (" << cx.numHexes() << " hexes)\n";
    return 0;
  }
  if (cmd == "convert") {
    need(a, 2, "an input and an output file");
    Complex cx = readInput(a, a.positional[0]);
    io::writeFile(cx, a.positional[1], a.binary);
    return 0;
  }
  if (cmd == "apply") return runApply(a);
  if (cmd == "quality") {
    need(a, 1, "one input file");
    QualityStats q = qualityStats(readInput(a, a.positional[0]));
    std::cout << (a.json ? io::qualityStatsJson(q) + "\n" : io::qualityStatsText(q));
    return 0;
  }
  if (cmd == "flip") return runFlip(a);
  if (cmd == "sheets") return runSheets(a);
  if (cmd == "preview") return runPreview(a);
  if (cmd == "select") return runSelect(a);
  if (cmd == "candidates") {
    need(a, 2, "an input file and an operation name");
    Complex cx = readInput(a, a.positional[0]);
    for (const OpStep& step : candidates(cx, opNamed(a.positional[1], "candidates"))) std::cout << formatOpStep(step) << "\n";
    return 0;
  }
  throw Error("unknown command '" + cmd + "'\n" + kUsage);
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "hexdual: " << e.what() << "\n";
    return 1;
  }
}
