// hexdual command-line tool: a thin layer over core. See docs/cli.md.
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include "complex/builders.hpp"
#include "dual/dual.hpp"
#include "io/io.hpp"
#include "io/json.hpp"

using namespace hexdual;

namespace {

const char* kUsage =
    "usage:\n"
    "  hexdual grid AxBxC -o FILE [--binary]     write a structured grid\n"
    "  hexdual ring NxRxZ -o FILE [--binary]     write an O-grid: N around, R radial, Z axial\n"
    "  hexdual info FILE [--json]                counts, sheets and chords\n"
    "  hexdual validate FILE                     check every invariant\n"
    "  hexdual convert IN OUT [--binary]         convert between .vtk, .mesh and .hxd\n";

struct Args {
  std::vector<std::string> positional;
  std::string output;
  bool json = false, binary = false;
};

Args parseArgs(int argc, char** argv, int from) {
  Args a;
  for (int i = from; i < argc; ++i) {
    std::string s = argv[i];
    if (s == "-o") {
      if (i + 1 >= argc) throw Error("-o needs a file name");
      a.output = argv[++i];
    } else if (s == "--json") {
      a.json = true;
    } else if (s == "--binary") {
      a.binary = true;
    } else if (s.size() > 1 && s[0] == '-') {
      throw Error("unknown option '" + s + "'");
    } else {
      a.positional.push_back(s);
    }
  }
  return a;
}

std::array<int, 3> parseDims(const std::string& s) {
  std::array<int, 3> d{};
  int n = 0;
  char tail = 0;
  if (std::sscanf(s.c_str(), "%dx%dx%d%c%n", &d[0], &d[1], &d[2], &tail, &n) != 3)
    throw Error("dimensions must look like 3x3x3, not '" + s + "'");
  return d;
}

void need(const Args& a, size_t n, const char* what) {
  if (a.positional.size() != n) throw Error(std::string("expected ") + what);
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
    Complex cx = io::readFile(a.positional[0]);
    Dual dual = extractDual(cx);
    std::cout << (a.json ? io::infoJson(cx, dual) + "\n" : io::infoText(cx, dual));
    return 0;
  }
  if (cmd == "validate") {
    need(a, 1, "one input file");
    Complex cx = io::readFile(a.positional[0]);  // readers validate
    cx.validate();
    std::cout << a.positional[0] << ": valid (" << cx.numHexes() << " hexes)\n";
    return 0;
  }
  if (cmd == "convert") {
    need(a, 2, "an input and an output file");
    Complex cx = io::readFile(a.positional[0]);
    io::writeFile(cx, a.positional[1], a.binary);
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
