// The floor of dual extraction: the least any program must do to find a complex's sheets and
// chords. One pass over the glued faces joins (hex, axis) slots in two union-finds (a sheet joins
// the two slots parallel to a face, a chord the one normal to it; TK03 §1.1), one pass over the
// slots numbers the classes. No orientation, Euler characteristic, loops or slot lists.
//
// `hexdual_floor N [REPS]` builds an N^3 grid and prints one JSON line with the floor's and
// extractDual's warm CPU time on that same complex (minimum over REPS interleaved repetitions, so
// the ratio holds on a loaded machine) and both programs' sheet and chord counts (which must agree).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <malloc.h>
#include <vector>

#include "complex/builders.hpp"
#include "dual/dual.hpp"

using namespace hexdual;
using namespace hexdual::tables;

namespace {

double cpuMs() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
}

uint32_t findRoot(std::vector<uint32_t>& parent, uint32_t x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}
// The smaller root wins, so every class is represented by its smallest slot.
void unite(std::vector<uint32_t>& parent, uint32_t a, uint32_t b) {
  a = findRoot(parent, a);
  b = findRoot(parent, b);
  if (a < b) parent[b] = a;
  else if (b < a) parent[a] = b;
}
// Numbers the classes in the order of their smallest slot; returns how many.
int32_t label(std::vector<uint32_t>& parent, std::vector<int32_t>& id) {
  int32_t n = 0;
  for (uint32_t i = 0; i < parent.size(); ++i) {
    uint32_t r = findRoot(parent, i);
    id[i] = r == i ? n++ : id[r];
  }
  return n;
}

struct FloorResult {
  int32_t sheets = 0, chords = 0;
};

FloorResult floorDual(const Complex& cx, std::vector<uint32_t>& sheetParent, std::vector<uint32_t>& chordParent,
                      std::vector<int32_t>& id) {
  const size_t slots = size_t(3) * size_t(cx.hexCapacity());
  sheetParent.resize(slots);
  chordParent.resize(slots);
  id.resize(slots);
  for (uint32_t i = 0; i < slots; ++i) sheetParent[i] = chordParent[i] = i;
  for (HexId h : cx.hexes())
    for (int f = 0; f < 6; ++f) {
      Gluing g = cx.gluing(h, f);
      if (g.boundary() || g.hex < h || (g.hex == h && g.face < f)) continue;  // each glued quad once
      const uint32_t here = 3 * uint32_t(h), there = 3 * uint32_t(g.hex);
      for (int a = 0; a < 3; ++a) {
        uint32_t a2 = uint32_t(kCrossings[size_t(crossingIndex(f, a, g.face, g.orient))].axis);
        unite(a == axisOfFace(f) ? chordParent : sheetParent, here + uint32_t(a), there + a2);
      }
    }
  FloorResult r;
  r.sheets = label(sheetParent, id);
  r.chords = label(chordParent, id);
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: hexdual_floor N [REPS]\n");
    return 2;
  }
  // Keep freed memory in the process: repetitions measure computation, not the VM's page faults.
  mallopt(M_MMAP_THRESHOLD, 1 << 30);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  const int n = std::atoi(argv[1]), reps = argc > 2 ? std::atoi(argv[2]) : 5;
  Complex cx = makeGrid(n, n, n);
  std::vector<uint32_t> sp, cp;
  std::vector<int32_t> id;
  double floorMs = 1e300, dualMs = 1e300;
  FloorResult fr;
  size_t sheets = 0, chords = 0;
  for (int r = 0; r < reps; ++r) {
    double t0 = cpuMs();
    fr = floorDual(cx, sp, cp, id);
    double t1 = cpuMs();
    Dual d = extractDual(cx);
    double t2 = cpuMs();
    sheets = d.sheets.size();
    chords = d.chords.size();
    floorMs = std::min(floorMs, t1 - t0);
    dualMs = std::min(dualMs, t2 - t1);
  }
  if (size_t(fr.sheets) != sheets || size_t(fr.chords) != chords) {
    std::fprintf(stderr, "floor: %d sheets, %d chords; extractDual: %zu, %zu\n", fr.sheets, fr.chords, sheets, chords);
    return 1;
  }
  const double hexes = double(n) * n * n;
  std::printf(
      "{\"bench\":\"floor\",\"n\":%d,\"hexes\":%.0f,\"floorMs\":%.3f,\"dualMs\":%.3f,\"ratio\":%.2f,"
      "\"floorNsPerHex\":%.1f,\"dualNsPerHex\":%.1f,\"sheets\":%zu,\"chords\":%zu}\n",
      n, hexes, floorMs, dualMs, dualMs / floorMs, 1e6 * floorMs / hexes, 1e6 * dualMs / hexes, sheets, chords);
  return 0;
}
