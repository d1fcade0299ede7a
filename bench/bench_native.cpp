// Native benchmarks. `hexdual_bench build N [REPS]` prints one JSON line: the median time to
// build an N^3 grid and extract its dual, the complex's bytes per hex, and the process's peak RSS.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <malloc.h>
#include <string>
#include <vector>

#include "complex/builders.hpp"
#include "dual/dual.hpp"

using namespace hexdual;
using Clock = std::chrono::steady_clock;

static long peakRssKb() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stol(line.substr(6));
  return -1;
}

static double ms(Clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); }

static int benchBuild(int n, int reps) {
  // Keep freed memory in the process so warm repetitions measure computation, not the VM's page faults.
  mallopt(M_MMAP_THRESHOLD, 1 << 30);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  std::vector<double> build, dual;
  size_t bytes = 0, sheets = 0, chords = 0;
  for (int r = 0; r < reps; ++r) {
    auto t0 = Clock::now();
    Complex cx = makeGrid(n, n, n);
    auto t1 = Clock::now();
    Dual d = extractDual(cx);
    auto t2 = Clock::now();
    build.push_back(ms(t1 - t0));
    dual.push_back(ms(t2 - t1));
    bytes = cx.memoryBytes();
    sheets = d.sheets.size();
    chords = d.chords.size();
  }
  double coldMs = build[0] + dual[0];
  if (reps > 1) {  // warm: drop the cold first repetition
    build.erase(build.begin());
    dual.erase(dual.begin());
  }
  std::sort(build.begin(), build.end());
  std::sort(dual.begin(), dual.end());
  double hexes = double(n) * n * n;
  std::printf(
      "{\"bench\":\"build\",\"n\":%d,\"hexes\":%.0f,\"coldMs\":%.3f,\"buildMs\":%.3f,\"dualMs\":%.3f,\"totalMs\":%.3f,"
      "\"bytesPerHex\":%.1f,\"sheets\":%zu,\"chords\":%zu,\"peakRssMb\":%.1f}\n",
      n, hexes, coldMs, build[build.size() / 2], dual[dual.size() / 2], build[build.size() / 2] + dual[dual.size() / 2],
      double(bytes) / hexes, sheets, chords, peakRssKb() / 1024.0);
  return 0;
}

int main(int argc, char** argv) {
  if (argc >= 3 && !std::strcmp(argv[1], "build")) return benchBuild(std::atoi(argv[2]), argc > 3 ? std::atoi(argv[3]) : 5);
  std::fprintf(stderr, "usage: hexdual_bench build N [REPS]\n");
  return 2;
}
