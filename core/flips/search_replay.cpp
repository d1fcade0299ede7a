// Replay: steps translated between isomorphic regions (through their canonical labellings), and a
// found decomposition replayed step by step in a host mesh and checked against the flip (or the
// triple-chord push) applied there directly.
#include <algorithm>
#include <map>

#include "flips/flip.hpp"
#include "flips/fourcube.hpp"
#include "flips/search_parts.hpp"

namespace hexdual::flipsearch {
using namespace tables;

// Rewrites a step's hex ids and local indices from complex `from` to the isomorphic `to`.
OpStep translateStep(OpStep st, const CanonicalLabelling& from, const CanonicalLabelling& to,
                     const std::vector<HexId>& host) {
  auto indexOf = [&](HexId h) {
    for (size_t i = 0; i < from.order.size(); ++i)
      if (from.order[i] == h) return int(i);
    throw Error("translate: hex " + std::to_string(h) + " is not in the region");
  };
  auto bitsOf = [](const std::array<int8_t, 8>& frame, int corner) {
    for (int b = 0; b < 8; ++b)
      if (frame[size_t(b)] == corner) return b;
    return -1;
  };
  auto mapFace = [&](HexId h, int face, HexId& h2) {
    if (isHost(host, h)) {
      h2 = h;
      return face;
    }
    int i = indexOf(h);
    h2 = to.order[size_t(i)];
    int corners[4];
    for (int q = 0; q < 4; ++q)
      corners[q] = to.frame[size_t(i)][size_t(bitsOf(from.frame[size_t(i)], kFaceCorners[size_t(face)][size_t(q)]))];
    for (int g = 0; g < 6; ++g) {
      int hits = 0;
      for (int q = 0; q < 4; ++q) hits += positionInFace(g, corners[q]) >= 0;
      if (hits == 4) return g;
    }
    return -1;
  };
  for (OpArg& a : st.args) {
    if (a.kind == OpArg::Quad || a.kind == OpArg::Pair) {
      HexId h2;
      a.local = mapFace(a.hex, a.local, h2);
      a.hex = h2;
      if (a.kind == OpArg::Pair) a.second.face = mapFace(a.second.hex, a.second.face, a.second.hex);
    } else if (a.kind == OpArg::Edge) {
      if (!isHost(host, a.hex)) {
        int i = indexOf(a.hex);
        int c0 = to.frame[size_t(i)][size_t(bitsOf(from.frame[size_t(i)], kEdgeCorners[size_t(a.local)][0]))];
        int c1 = to.frame[size_t(i)][size_t(bitsOf(from.frame[size_t(i)], kEdgeCorners[size_t(a.local)][1]))];
        a.hex = to.order[size_t(i)];
        a.local = edgeBetween(c0, c1);
      }
    } else if (!isHost(host, a.hex)) {
      a.hex = to.order[size_t(indexOf(a.hex))];
    }
  }
  return st;
}

// The vertex shared by all of `hexes` (the centre of a triple-chord push's 8 hexes), or -1.
VertexId commonVertex(const Complex& cx, const std::vector<HexId>& hexes) {
  for (VertexId v : cx.hexVertices(hexes.at(0))) {
    bool all = true;
    for (HexId h : hexes) {
      auto vs = cx.hexVertices(h);
      all = all && std::find(vs.begin(), vs.end(), v) != vs.end();
    }
    if (all) return v;
  }
  return -1;
}

// Every triple-chord push at vertex v (TK03 §4.5.1): one per hex at v, pulling apart its three
// faces at the corner on v. The 8 hexes around v are symmetric, so a placed sequence is checked
// against all of them: it must give one.
std::vector<Complex> tripleChordPushesAt(const Complex& cx, const std::vector<HexId>& hexes, VertexId v) {
  std::vector<Complex> out;
  for (HexId h : hexes)
    for (int c = 0; c < 8; ++c) {
      if (cx.vertex(h, c) != v) continue;
      std::vector<QuadSide> q;
      for (int f = 0; f < 6; ++f)
        for (int p = 0; p < 4; ++p)
          if (kFaceCorners[size_t(f)][size_t(p)] == c) q.push_back({h, f});
      out.push_back(cx);
      tripleChordPush(out.back(), h, c, q.at(0), q.at(1), q.at(2));
    }
  return out;
}

// The region of `cx` as a complex whose vertex ids are renamed: ids in `rename` take their mapped
// value (boundary vertices shared with the problem), all others get fresh ids from `fresh` on.
Complex renamedRegion(const Complex& cx, const std::vector<HexId>& region, const std::map<VertexId, VertexId>& rename,
                      VertexId fresh, std::vector<HexId>& regionOrder) {
  std::map<VertexId, VertexId> ids = rename;
  Complex out;
  std::vector<std::array<VertexId, 8>> hexes;
  for (HexId h : region) {
    std::array<VertexId, 8> v;
    for (int c = 0; c < 8; ++c) {
      VertexId x = cx.vertex(h, c);
      auto it = ids.find(x);
      if (it == ids.end()) it = ids.emplace(x, fresh++).first;
      v[size_t(c)] = it->second;
    }
    hexes.push_back(v);
  }
  VertexId maxId = 0;
  for (auto [a, b] : ids) maxId = std::max(maxId, b);
  for (VertexId v = 0; v <= maxId; ++v) out.addVertex({});
  for (auto& v : hexes) out.addHex(v);
  regionOrder = region;
  for (size_t i = 0; i < region.size(); ++i)
    for (int f = 0; f < 6; ++f) {
      Gluing g = cx.gluing(region[i], f);
      if (g.boundary()) continue;
      auto j = std::find(region.begin(), region.end(), g.hex) - region.begin();
      if (size_t(j) == region.size() || QuadSide{g.hex, g.face} < QuadSide{region[i], f}) continue;
      out.glue(HexId(i), f, HexId(j), g.face, g.orient);
    }
  return out;
}

// Labelling of a region with its hexes named by their ids in cx (not 0..n-1 of the renamed copy).
CanonicalLabelling labelRegion(const Complex& cx, const std::vector<HexId>& host,
                               const std::map<VertexId, VertexId>& rename, VertexId fresh) {
  std::vector<HexId> order;
  Complex r = renamedRegion(cx, regionOf(cx, host), rename, fresh, order);
  CanonicalLabelling L = canonicalLabelling(r, true);
  for (HexId& h : L.order) h = order[size_t(h)];
  return L;
}

}  // namespace hexdual::flipsearch

namespace hexdual {
using namespace tables;
using namespace flipsearch;

namespace {

// A problem's steps replayed in a host mesh: the problem's before side matched with the mesh's, the
// vertex names both regions are labelled with, and each step carried over through the canonical
// labellings of the two regions.
struct Replay {
  const SearchProblem& pb;
  const std::string what;
  const Embedding where;  // the mesh as it was: its host and before side
  std::vector<HexId> regionP, hostP, hostE;
  std::map<VertexId, VertexId> toProblem;  // embedding vertex -> problem vertex
  std::map<VertexId, VertexId> idP, toProblemHost;
  VertexId fresh = 0;

  Replay(const SearchProblem& problem, const Complex& mesh, const std::vector<HexId>& beforeHexes,
         const std::string& placeName);
  void matchBeforeSides();
  void nameVertices();
  OpStep throughRegion(OpStep src, size_t k, const Complex& cp, std::vector<bool>& partner,
                       std::vector<bool>& partner2) const;
  OpStep place(const OpStep& step, size_t k, const Complex& cp, const Complex& ce) const;
};

Replay::Replay(const SearchProblem& problem, const Complex& mesh, const std::vector<HexId>& beforeHexes,
               const std::string& placeName)
    : pb(problem), what(problem.name + " in " + placeName), where{placeName, mesh, beforeHexes} {
  regionP = regionOf(pb.start, pb.host);
  for (HexId h : where.mesh.hexes())
    if (std::find(where.before.begin(), where.before.end(), h) == where.before.end()) hostE.push_back(h);
  matchBeforeSides();
  hostP = pb.host;
  std::sort(hostP.begin(), hostP.end());
  std::sort(hostE.begin(), hostE.end());
  nameVertices();
}

// Match the problem's before side (its region) with the embedding's before hexes: flipping both
// directly and comparing is the goal; the boundary vertex map comes from the region boundary.
// Boundary vertex map (problem -> embedding): the before sides are isomorphic with boundary kept,
// so match them by their canonical labellings with both boundaries left free.
void Replay::matchBeforeSides() {
  CanonicalLabelling lp = canonicalLabelling(subcomplex(pb.start, regionP), false, FreeStarts::Every);
  CanonicalLabelling le = canonicalLabelling(subcomplex(where.mesh, where.before), false, FreeStarts::Every);
  if (lp.form != le.form) throw Error(what + ": the hexes are not the before side");
  for (size_t i = 0; i < lp.order.size(); ++i)
    for (int b = 0; b < 8; ++b)
      toProblem[where.mesh.vertex(le.order[i], le.frame[i][size_t(b)])] =
          pb.start.vertex(lp.order[i], lp.frame[i][size_t(b)]);
}

// Boundary (host) vertices keep shared names: problem ids on both sides; others get fresh ids.
void Replay::nameVertices() {
  for (HexId h : hostP)
    for (VertexId v : pb.start.hexVertices(h)) idP[v] = v;
  // (and so do region vertices on the mesh boundary, which the embedding names through toProblem)
  for (HexId h : regionP)
    for (VertexId v : pb.start.hexVertices(h)) idP[v] = v;
  for (HexId h : where.before)  // the before side's vertices, on the mesh boundary or not
    for (VertexId v : where.mesh.hexVertices(h)) toProblemHost[v] = toProblem[v];
  fresh = std::max(pb.start.vertexCapacity(), where.mesh.vertexCapacity()) + 64;
}

// Arguments named through a host hex are re-expressed through the region side of the same quad
// or edge (host hexes may differ between hosts); `partner` remembers a side to swap back.
OpStep Replay::throughRegion(OpStep src, size_t k, const Complex& cp, std::vector<bool>& partner,
                             std::vector<bool>& partner2) const {
  for (size_t i = 0; i < src.args.size(); ++i) {
    OpArg& arg = src.args[i];
    if (arg.kind == OpArg::Pair && isHost(hostP, arg.second.hex)) {
      Gluing g = cp.gluing(arg.second);
      if (g.boundary() || isHost(hostP, g.hex))
        throw Error(what + ": step " + std::to_string(k + 1) + " names a host quad");
      arg.second = {g.hex, g.face};
      partner2[i] = true;
    }
    if (!isHost(hostP, arg.hex)) continue;
    if (arg.kind == OpArg::Quad || arg.kind == OpArg::Pair) {
      Gluing g = cp.gluing(arg.hex, arg.local);
      if (g.boundary() || isHost(hostP, g.hex))
        throw Error(what + ": step " + std::to_string(k + 1) + " names a host quad");
      arg.hex = g.hex;
      arg.local = g.face;
      partner[i] = true;
    } else if (arg.kind == OpArg::Edge) {
      bool placed = false;
      for (EdgeRef x : cp.edgeCycle({arg.hex, arg.local}))
        if (!isHost(hostP, x.hex)) {
          arg.hex = x.hex;
          arg.local = x.edge;
          placed = true;
          break;
        }
      if (!placed) throw Error(what + ": step " + std::to_string(k + 1) + " names a host edge away from the region");
    } else {
      throw Error(what + ": step " + std::to_string(k + 1) + " names host hex " + std::to_string(arg.hex));
    }
  }
  return src;
}

// Step k (of the problem, applied next to cp) as it applies to ce: the regions' labellings must
// agree; the step is translated through them and its host sides swapped back.
OpStep Replay::place(const OpStep& step, size_t k, const Complex& cp, const Complex& ce) const {
  CanonicalLabelling a = labelRegion(cp, hostP, idP, fresh);
  CanonicalLabelling b = labelRegion(ce, hostE, toProblemHost, fresh);
  if (a.form != b.form) throw Error(what + ": before step " + std::to_string(k + 1) + " the regions differ");
  std::vector<bool> partner(step.args.size(), false), partner2(step.args.size(), false);
  OpStep st = translateStep(throughRegion(step, k, cp, partner, partner2), a, b, hostP);
  for (size_t i = 0; i < st.args.size(); ++i) {
    if (partner[i]) {
      Gluing g = ce.gluing(st.args[i].hex, st.args[i].local);
      st.args[i].hex = g.hex;
      st.args[i].local = g.face;
    }
    if (partner2[i]) {
      Gluing g = ce.gluing(st.args[i].second);
      st.args[i].second = {g.hex, g.face};
    }
  }
  return st;
}

}  // namespace

std::vector<OpStep> replayInEmbedding(const SearchProblem& pb, const std::vector<OpStep>& steps, Complex& mesh,
                                      const std::vector<HexId>& beforeHexes, const std::string& placeName) {
  const Replay rp(pb, mesh, beforeHexes, placeName);
  HostSnapshot snapE = snapshot(rp.where.mesh, rp.hostE);
  Complex cp = pb.start;
  Complex& ce = mesh;
  std::vector<OpStep> applied;
  for (size_t k = 0; k < steps.size(); ++k) {
    OpStep st = rp.place(steps[k], k, cp, ce);
    try {
      applyStep(cp, steps[k]);
      applyStep(ce, st);
    } catch (const Error& e) {
      throw Error(rp.what + ": step " + std::to_string(k + 1) + " (" + formatOpStep(st) + "): " + e.what());
    }
    std::string why = localityViolation(ce, snapE);
    if (!why.empty()) throw Error(rp.what + ": step " + std::to_string(k + 1) + " is not local: " + why);
    applied.push_back(st);
  }
  return applied;
}

void verifyInEmbedding(const SearchProblem& pb, const std::vector<OpStep>& steps, const Embedding& where) {
  const std::string what = "verify " + pb.name + " in " + where.name;
  Complex viaSteps = where.mesh;
  std::vector<Complex> directs;  // the operation applied directly there (any one of them must match)
  if (pb.name == "tripleChordPush") {
    directs = tripleChordPushesAt(where.mesh, where.before, commonVertex(where.mesh, where.before));
  } else {
    directs = {where.mesh};
    flip(directs[0], pb.name, where.before);
  }
  try {
    replayInEmbedding(pb, steps, viaSteps, where.before, where.name);
  } catch (const Error& e) {
    throw Error("verify " + std::string(e.what()));
  }
  viaSteps.validate();
  std::vector<HexId> hostE;
  for (HexId h : where.mesh.hexes())
    if (std::find(where.before.begin(), where.before.end(), h) == where.before.end()) hostE.push_back(h);
  std::map<VertexId, VertexId> idE;
  for (HexId h : where.mesh.hexes())
    for (VertexId v : where.mesh.hexVertices(h)) idE[v] = v;
  VertexId fresh = viaSteps.vertexCapacity();
  for (const Complex& d : directs) fresh = std::max(fresh, d.vertexCapacity());
  fresh += 64;
  const auto form = labelRegion(viaSteps, hostE, idE, fresh).form;
  for (const Complex& d : directs)
    if (labelRegion(d, hostE, idE, fresh).form == form) return;
  throw Error(what + ": the result is not isomorphic to the " +
              (pb.name == "tripleChordPush" ? "operation" : std::string("flip")) + " applied directly");
}

}  // namespace hexdual
