// Per-slot shares of each sheet's Euler characteristic (TK03 §1.1: V - E + F of its mid-surface)
// and the per-hex edge marks they are read from, kept between updates so that a sheet cut or
// re-glued in one place learns its Euler characteristic from the edit alone.
// Owns: edgeMarks_, share_, and the scratch marks walked_.
// Only the edges whose cycles the edit can have changed are walked (edgesToWalk_, when the
// update knows its edits); the other marks stand.
// Keeps: bit e of edgeMarks_[h] is set exactly when (h, e) is its primal edge's smallest
// incidence, kNearBoundary exactly when one of h's 12 edges reaches the boundary and
// kEdgeAxisNearBoundary(a) exactly when one of its 4 edges along axis a does; every live
// slot's share_ is slotShare() of its hex's marks, a dead slot's is 0; a sheet's Euler
// characteristic is half the sum of its slots' shares; walked_ is 0 outside refreshShares (and
// outside update's touchedHexesWithEdges, which borrows it).
#include <algorithm>

#include "dual/dual_tracker.hpp"
#include "dual/tracker/slots.hpp"

namespace hexdual {
using namespace tracker;

namespace {

constexpr uint16_t kNearBoundary = kEdgeNearBoundary;
constexpr uint16_t kAxesNearBoundary = uint16_t(7u << 12);  // kEdgeAxisNearBoundary(0..2)
// In walked_: bit 12 + a when one of the hex's edges along axis a walked is a fan.
uint16_t walkedFan(int edge) { return uint16_t(1u << (12 + tables::axisOfEdge(edge))); }

// The near-boundary bits of hex m after an edit that walked the edges marked in `walked`: an axis
// is near when one of its edges walked is a fan now, or (when it was near before) one of its
// other edges is (an edge walked and not a fan is closed: it is not walked again).
uint16_t nearBits(const Complex& cx, HexId m, uint16_t marks, uint16_t walked) {
  uint16_t bits = 0;
  for (int a = 0; a < 3; ++a)
    if ((walked & kEdgeAxisNearBoundary(a)) ||
        ((marks & kEdgeAxisNearBoundary(a)) && edgesNear(cx, m, (0xFu << (4 * a)) & ~unsigned(walked))))
      bits |= kEdgeAxisNearBoundary(a);
  return bits ? uint16_t(bits | kNearBoundary) : 0;
}

// The incidences of the edge at e, round its cycle or along its fan, and the smallest of them;
// false for a fan.
bool edgeIncidences(const Complex& cx, EdgeRef e, std::vector<EdgeRef>& out, EdgeRef& least) {
  out.clear();
  out.push_back(e);
  least = e;
  auto fs = tables::facesOfEdge(e.edge);
  for (int dir = 0; dir < 2; ++dir) {
    EdgeRef cur = e;
    int exit = fs[size_t(dir)];
    while (cx.stepAroundEdge(cur, exit)) {
      if (cur == e) return true;
      out.push_back(cur);
      if (cur < least) least = cur;
    }
  }
  return false;
}

}  // namespace

bool tracker::edgesNear(const Complex& cx, HexId h, unsigned edges) {
  for (int e = 0; e < 12; ++e) {
    if (!((edges >> e) & 1u)) continue;
    EdgeRef cur{h, e};
    int exit = tables::facesOfEdge(e)[0];
    for (;;) {
      if (!cx.stepAroundEdge(cur, exit)) return true;
      if (cur.hex == h && cur.edge == e) break;
    }
  }
  return false;
}

void DualTracker::refreshShares(const Complex& cx, const std::vector<HexId>& touched,
                                std::vector<ShareChange>* changes) {
  auto onChange = [&](Slot t, int before, int after) {
    if (changes) changes->push_back({t, before, after});
  };
  bool nearBefore = false;
  // Scratch kept between calls (every update runs this): no allocation once warm.
  thread_local std::vector<Slot> dirty;
  thread_local std::vector<HexId> met;
  thread_local std::vector<EdgeRef> inc;
  dirty.clear();
  met.clear();
  for (HexId h : touched) {
    nearBefore = nearBefore || (edgeMarks_[size_t(h)] & kNearBoundary);
    if (cx.isHex(h)) {
      for (int a = 0; a < 3; ++a) dirty.push_back({h, a});
      continue;
    }
    for (int a = 0; a < 3; ++a) {
      int8_t& old = share_[3 * size_t(h) + size_t(a)];
      if (old) onChange(Slot{h, a}, int(old), 0);
      old = 0;
    }
    edgeMarks_[size_t(h)] = 0;
  }
  bool fan = false;
  const bool known = edgesToWalk_.size() == touched.size();  // else every edge may have changed
  for (size_t i = 0; i < touched.size(); ++i) {
    const HexId h = touched[i];
    if (!cx.isHex(h)) continue;
    const unsigned changed = known ? edgesToWalk_[i] : 0xFFFu;
    // The changed edges not walked yet (a walk can pass h again, at another of its edges).
    for (unsigned left = changed & ~unsigned(walked_[size_t(h)]) & 0xFFFu; left; left &= ~unsigned(walked_[size_t(h)])) {
      const int e = __builtin_ctz(left);
      left &= left - 1;
      EdgeRef least;
      const bool closed = edgeIncidences(cx, {h, e}, inc, least);
      fan = fan || !closed;
      for (EdgeRef r : inc) {
        if (!walked_[size_t(r.hex)]) met.push_back(r.hex);
        walked_[size_t(r.hex)] |= uint16_t((1u << r.edge) | (closed ? 0u : walkedFan(r.edge)));
        const uint16_t bit = uint16_t(1u << r.edge);
        if (((edgeMarks_[size_t(r.hex)] & bit) != 0) != (r == least)) {
          edgeMarks_[size_t(r.hex)] ^= bit;
          dirty.push_back({r.hex, tables::axisOfEdge(r.edge)});
        }
      }
    }
  }
  // Only an edge through a touched hex can have reached or left the boundary (nearBits).
  if (fan || nearBefore)
    for (HexId m : met) {
      const uint16_t marks = edgeMarks_[size_t(m)];
      edgeMarks_[size_t(m)] = uint16_t((marks & ~(kNearBoundary | kAxesNearBoundary)) | nearBits(cx, m, marks, walked_[size_t(m)]));
    }
  for (HexId m : met) walked_[size_t(m)] = 0;
  for (Slot s : dirty) {
    const int8_t now = slotShare(cx, s.hex, s.axis, edgeMarks_[size_t(s.hex)]);
    int8_t& old = share_[slotIndex(s)];
    if (now != old) {
      onChange(s, int(old), int(now));
      old = now;
    }
  }
}

// ---- invariants ----

// Every hex's edge marks and every slot's share recomputed from the complex; each alive sheet's
// Euler characteristic is half its slots' shares and its topology named from it.
void DualTracker::checkShares(const Complex& cx) const {
  std::vector<EdgeRef> inc;
  std::vector<int64_t> sum(dual_.sheets.size(), 0);
  for (HexId h = 0; h < HexId(dual_.sheetLabel.size()); ++h) {
    uint16_t marks = 0;
    if (cx.isHex(h)) {
      for (int e = 0; e < 12; ++e) {
        bool closed = false;
        inc = cx.edgeCycle({h, e}, &closed);  // (not edgeIncidences: refreshShares stays its one caller, inlined)
        if (*std::min_element(inc.begin(), inc.end()) == EdgeRef{h, e}) marks |= uint16_t(1u << e);
        if (!closed) marks |= uint16_t(kNearBoundary | kEdgeAxisNearBoundary(tables::axisOfEdge(e)));
      }
    }
    if (edgeMarks_[size_t(h)] != marks)
      invariantBroken("hex " + std::to_string(h) + " has edge marks " + std::to_string(edgeMarks_[size_t(h)]) +
                      ", the complex gives " + std::to_string(marks));
    for (int a = 0; a < 3; ++a) {
      const int share = cx.isHex(h) ? slotShare(cx, h, a, marks) : 0;
      if (share_[slotIndex({h, a})] != share)
        invariantBroken("slot " + slotName({h, a}) + " has share " + std::to_string(share_[slotIndex({h, a})]) +
                        ", the complex gives " + std::to_string(share));
      if (cx.isHex(h)) sum[size_t(dual_.sheetAt(h, a))] += share;
    }
  }
  for (size_t id = 0; id < dual_.sheets.size(); ++id) {
    const Sheet& sh = dual_.sheets[id];
    if (!sh.alive) continue;
    if (sum[id] != 2 * sh.euler)
      invariantBroken("sheet " + std::to_string(id) + " has Euler characteristic " + std::to_string(sh.euler) +
                      ", its slots' shares give " + std::to_string(sum[id]) + "/2");
    if (sh.topology != classifySurface(sh.euler, sh.boundaryLoops, sh.orientable))
      invariantBroken("sheet " + std::to_string(id) + " is named " + sh.topology +
                      ", not what its Euler characteristic, loops and orientability give");
  }
}

}  // namespace hexdual
