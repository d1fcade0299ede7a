// View data for the explorer (web/): render buffers with per-triangle hex and local face, edge
// lines, dual points, the dual overlay, quality, and per-hex sheet/chord ids. Its own
// EMSCRIPTEN_BINDINGS block; it reads the mesh through the addresses WasmMesh hands out
// (complexAddress/dualAddress: same module, same heap) so bindings.cpp stays the package's.
#include <emscripten/bind.h>

#include <algorithm>
#include <bit>
#include <map>
#include <set>
#include <string>

#include "addressed.hpp"
#include "dual/dual.hpp"
#include "flips/decompositions.hpp"
#include "flips/flip.hpp"
#include "flips/fourcube.hpp"
#include "layout/dual_points.hpp"
#include "layout/quality.hpp"
#include "layout/render_buffers.hpp"

using namespace emscripten;
using namespace hexdual;

namespace {

using wasm::complexAt;
using wasm::copyOut;
using wasm::dualAt;
using wasm::guardedObject;

// `shell`, `hidden` (bytes per hex id) and `always` (hex ids) choose the drawn hexes (DrawnHexes).
val viewRenderBuffers(double complexAddress, double shrink, bool edges, bool shell, val hidden, val always) {
  return guardedObject([&] {
    DrawnHexes drawn;
    drawn.shell = shell;
    if (!hidden.isUndefined() && !hidden.isNull()) drawn.hidden = convertJSArrayToNumberVector<uint8_t>(hidden);
    if (!always.isUndefined() && !always.isNull()) drawn.always = convertJSArrayToNumberVector<int32_t>(always);
    RenderBuffers rb = buildRenderBuffers(complexAt(complexAddress), shrink, edges, drawn);
    val out = val::object();
    out.set("positions", copyOut("Float32Array", rb.positions));
    out.set("normals", copyOut("Float32Array", rb.normals));
    out.set("indices", copyOut("Uint32Array", rb.indices));
    out.set("triangleHex", copyOut("Int32Array", rb.triangleHex));
    out.set("triangleFace", copyOut("Uint8Array", rb.triangleFace));
    if (edges) {
      out.set("edgePositions", copyOut("Float32Array", rb.edgePositions));
      out.set("edgeHex", copyOut("Int32Array", rb.edgeHex));
      out.set("edgeLocal", copyOut("Uint8Array", rb.edgeLocal));
    }
    return out;
  });
}

val viewDualPoints(double complexAddress) {
  return guardedObject([&] {
    std::vector<Vec3> dp = dualPoints(complexAt(complexAddress));
    std::vector<float> flat;
    flat.reserve(dp.size() * 3);
    for (Vec3 p : dp) flat.insert(flat.end(), {float(p.x), float(p.y), float(p.z)});
    val out = val::object();
    out.set("points", copyOut("Float32Array", flat));
    return out;
  });
}

// `only`: hex ids whose part of the overlay is wanted (undefined: all).
val viewDualOverlay(double complexAddress, double dualAddress, val only) {
  return guardedObject([&] {
    std::vector<HexId> hexes;
    const bool some = !only.isUndefined() && !only.isNull();
    if (some) hexes = convertJSArrayToNumberVector<int32_t>(only);
    DualOverlay o = buildDualOverlay(complexAt(complexAddress), dualAt(dualAddress), some ? &hexes : nullptr);
    val out = val::object();
    out.set("sheetPositions", copyOut("Float32Array", o.sheetPositions));
    out.set("sheetIndices", copyOut("Uint32Array", o.sheetIndices));
    out.set("sheetTriangle", copyOut("Int32Array", o.sheetTriangle));
    out.set("chordPositions", copyOut("Float32Array", o.chordPositions));
    out.set("chordSegment", copyOut("Int32Array", o.chordSegment));
    out.set("dualVertices", copyOut("Float32Array", o.dualVertices));
    out.set("dualVertexHex", copyOut("Int32Array", o.dualVertexHex));
    return out;
  });
}

val viewQuality(double complexAddress) {
  return guardedObject([&] {
    QualityReport q = measureQuality(complexAt(complexAddress));
    val out = val::object();
    out.set("scaledJacobian", copyOut("Float32Array", q.scaledJacobian));
    out.set("inverted", copyOut("Int32Array", q.inverted));
    out.set("min", q.min);
    out.set("max", q.max);
    return out;
  });
}

// Sheet and chord ids per hex and axis (3 + 3 per hex id, -1 for tombstones).
val viewHexDual(double dualAddress) {
  return guardedObject([&] {
    const Dual& d = dualAt(dualAddress);
    std::vector<int32_t> sheets, chords;
    sheets.reserve(d.sheetLabel.size() * 3);
    chords.reserve(d.chordLabel.size() * 3);
    for (size_t h = 0; h < d.sheetLabel.size(); ++h)
      for (int a = 0; a < 3; ++a) sheets.push_back(d.sheetAt(HexId(h), a));
    for (size_t h = 0; h < d.chordLabel.size(); ++h)
      for (int a = 0; a < 3; ++a) chords.push_back(d.chordAt(HexId(h), a));
    val out = val::object();
    out.set("sheetOf", copyOut("Int32Array", sheets));
    out.set("chordOf", copyOut("Int32Array", chords));
    return out;
  });
}

// Local numbering tables: corners of each face (in buffer order) and of each edge.
val viewTables() {
  std::vector<int32_t> face, edge;
  for (const auto& f : tables::kFaceCorners) face.insert(face.end(), f.begin(), f.end());
  for (const auto& e : tables::kEdgeCorners) edge.insert(edge.end(), e.begin(), e.end());
  val out = val::object();
  out.set("faceCorners", copyOut("Int32Array", face));
  out.set("edgeCorners", copyOut("Int32Array", edge));
  return out;
}

// The region alone: its hexes renumbered 0..k-1 with their gluings among themselves. flip() matches
// a before side by the region's own vertices and gluings, so trying it here says whether it applies.
Complex regionCopy(const Complex& cx, const std::vector<HexId>& region) {
  Complex out;
  std::map<VertexId, VertexId> vertex;
  std::map<HexId, HexId> local;
  for (HexId h : region) {
    std::array<VertexId, 8> v{};
    for (int c = 0; c < 8; ++c) {
      auto [it, fresh] = vertex.try_emplace(cx.vertex(h, c), 0);
      if (fresh) it->second = out.addVertex(cx.position(cx.vertex(h, c)));
      v[size_t(c)] = it->second;
    }
    local[h] = out.addHex(v);
  }
  for (HexId h : region)
    for (int f = 0; f < 6; ++f) {
      Gluing g = cx.gluing(h, f);
      if (g.boundary() || !local.count(g.hex) || !(QuadSide{h, f} < QuadSide{g.hex, g.face})) continue;
      out.glue(local[h], f, local[g.hex], g.face, g.orient);
    }
  return out;
}

// Hex sets near a pick that could be a flip's before side: the hex, the two hexes of a quad, a hex
// with each face neighbour, and runs of consecutive hexes around an edge (TK03 §4.5: flips replace
// a ball of hexes glued to the same outside).
std::set<std::vector<HexId>> regionsNear(const Complex& cx, HexId hex, const std::string& kind, int local) {
  std::set<std::vector<HexId>> out;
  auto add = [&](std::vector<HexId> r) {
    std::sort(r.begin(), r.end());
    if (std::adjacent_find(r.begin(), r.end()) == r.end()) out.insert(r);
  };
  auto around = [&](EdgeRef e, bool anyRun) {
    bool closed = false;
    std::vector<EdgeRef> cyc = cx.edgeCycle(e, &closed);
    const size_t n = cyc.size();
    if (n > 8) return;
    for (size_t len = 2; len <= std::min<size_t>(n, 4); ++len)
      for (size_t i = 0; i < (closed ? n : n - len + 1); ++i) {
        std::vector<HexId> r;
        for (size_t k = 0; k < len; ++k) r.push_back(cyc[(i + k) % n].hex);
        if (anyRun || std::find(r.begin(), r.end(), hex) != r.end()) add(r);
      }
  };
  auto pair = [&](int f) {
    Gluing g = cx.gluing(hex, f);
    if (!g.boundary()) add({hex, g.hex});
  };
  if (kind == "edge") return around({hex, local}, true), out;
  if (kind == "quad") return pair(local), out;
  add({hex});
  for (int f = 0; f < 6; ++f) pair(f);
  for (int e = 0; e < 12; ++e) around({hex, e}, false);
  return out;
}

// Flips with a stored atomic decomposition that apply near a hex, quad or edge: [{name, hexes}].
val viewFlipPlaces(double complexAddress, int hex, const std::string& kind, int local) {
  return guardedObject([&] {
    const Complex& cx = complexAt(complexAddress);
    if (!cx.isHex(hex)) throw Error("flip places: hex " + std::to_string(hex) + " does not exist");
    if ((kind == "quad" && (local < 0 || local > 5)) || (kind == "edge" && (local < 0 || local > 11)))
      throw Error("flip places: no local " + kind + " " + std::to_string(local));
    std::vector<std::pair<std::string, int>> flips;  // name, hexes of its before side
    for (const FlipSummary& f : flipSummaries())
      if (f.decomposition && f.decomposition->found) flips.push_back({f.flip.name, std::popcount(f.flip.before)});
    val places = val::array();
    for (const std::vector<HexId>& region : regionsNear(cx, hex, kind, local))
      for (const auto& [name, size] : flips) {
        if (size_t(size) != region.size()) continue;
        Complex trial = regionCopy(cx, region);
        std::vector<HexId> ids(region.size());
        for (size_t k = 0; k < ids.size(); ++k) ids[k] = HexId(k);
        try {
          flip(trial, name, ids);
        } catch (const Error&) {
          continue;
        }
        val p = val::object();
        p.set("name", name);
        p.set("hexes", copyOut("Int32Array", region));
        places.call<void>("push", p);
      }
    val out = val::object();
    out.set("places", places);
    return out;
  });
}

}  // namespace

EMSCRIPTEN_BINDINGS(hexdual_view) {
  function("viewFlipPlaces", &viewFlipPlaces);
  function("viewRenderBuffers", &viewRenderBuffers);
  function("viewDualPoints", &viewDualPoints);
  function("viewDualOverlay", &viewDualOverlay);
  function("viewQuality", &viewQuality);
  function("viewHexDual", &viewHexDual);
  function("viewTables", &viewTables);
}
