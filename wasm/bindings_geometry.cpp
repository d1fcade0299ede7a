// Geometry and singularity calls of the package (mesh.singularities(), mesh.edgeDual(),
// mesh.quality()'s distribution, mesh.positionsHash()). Its own EMSCRIPTEN_BINDINGS block; like
// bindings_view.cpp it reads the mesh through the addresses WasmMesh hands out. Each returns an
// object: {json} (the same JSON as the CLI) or {error, code}.
#include <emscripten/bind.h>

#include <string>

#include "addressed.hpp"  // complexAt, dualAt
#include "analysis/edge_dual.hpp"
#include "analysis/singularity.hpp"
#include "geometry/positions_hash.hpp"
#include "geometry/quality_stats.hpp"
#include "io/geometry_json.hpp"

using namespace emscripten;
using namespace hexdual;

namespace {

using wasm::complexAt;
using wasm::dualAt;

template <class F>
val jsonOrError(F&& f) {
  val out = val::object();
  try {
    out.set("json", f());
  } catch (const std::exception& e) {
    out.set("error", std::string(e.what()));
    out.set("code", std::string("PRECONDITION"));
  }
  return out;
}

val geometrySingularities(double complexAddress) {
  return jsonOrError([&] { return io::singularityGraphJson(singularityGraph(complexAt(complexAddress))); });
}

val geometryEdgeDual(double complexAddress, double dualAddress, int hex, int edge) {
  return jsonOrError([&] { return io::edgeDualJson(edgeDual(complexAt(complexAddress), dualAt(dualAddress), {hex, edge})); });
}

val geometryQualityStats(double complexAddress) {
  return jsonOrError([&] { return io::qualityStatsJson(qualityStats(complexAt(complexAddress))); });
}

std::string geometryPositionsHash(double complexAddress) { return positionsHash(complexAt(complexAddress)); }

// x, y, z of each vertex id in `ids` (an array of integers), or {error} naming the first id that
// is not a live vertex.
val geometryVertexPositions(double complexAddress, val ids) {
  const Complex& cx = complexAt(complexAddress);
  const std::vector<int> vs = vecFromJSArray<int>(ids);
  std::vector<double> xyz;
  xyz.reserve(3 * vs.size());
  for (int v : vs) {
    if (v < 0 || !cx.isVertex(VertexId(v))) {
      val out = val::object();
      out.set("error", "vertexPositions: vertex " + std::to_string(v) + " does not exist");
      out.set("code", std::string("PRECONDITION"));
      return out;
    }
    const Vec3 p = cx.position(VertexId(v));
    xyz.insert(xyz.end(), {p.x, p.y, p.z});
  }
  val out = val::object();
  out.set("xyz", val::global("Float64Array").new_(val(typed_memory_view(xyz.size(), xyz.data()))));
  return out;
}

}  // namespace

EMSCRIPTEN_BINDINGS(hexdual_geometry) {
  function("geometrySingularities", &geometrySingularities);
  function("geometryEdgeDual", &geometryEdgeDual);
  function("geometryQualityStats", &geometryQualityStats);
  function("geometryPositionsHash", &geometryPositionsHash);
  function("geometryVertexPositions", &geometryVertexPositions);
}
