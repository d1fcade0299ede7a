// Engine facts the tutorials show: every stored decomposition record (found or not, with its
// search bounds), so no page types a step count or a "none of at most k" by hand; and the ring
// splits through a picked edge (candidates() does not enumerate ring splits). Its own
// EMSCRIPTEN_BINDINGS block; it reads a mesh through WasmMesh::complexAddress (addressed.hpp).
#include <emscripten/bind.h>

#include <string>

#include "addressed.hpp"
#include "flips/decompositions.hpp"
#include "ops/oplog.hpp"
#include "ops/ring_splits.hpp"

using namespace emscripten;
using namespace hexdual;

namespace {

using wasm::complexAt;
using wasm::guardedObject;

val stepList(const std::vector<OpStep>& steps) {
  val out = val::array();
  for (const OpStep& s : steps) out.call<void>("push", formatOpStep(s));
  return out;
}

// core/flips/decompositions.txt as objects, one per record (the file's fields by name).
val tutorialRecords() {
  return guardedObject([] {
    val records = val::array();
    for (const StoredDecomposition& d : storedDecompositions()) {
      val r = val::object();
      r.set("problem", d.problem);
      r.set("found", d.found);
      r.set("steps", d.found ? stepList(d.steps) : val::null());
      r.set("maxDepth", d.maxDepth);
      r.set("depthSearched", d.depthSearched);
      r.set("states", double(d.states));
      r.set("seconds", d.seconds);
      r.set("ops", d.ops);
      records.call<void>("push", r);
    }
    val out = val::object();
    out.set("records", records);
    return out;
  });
}

val tutorialRingSplits(double complexAddress, int hex, int edge, int maxEdges) {
  return guardedObject([&] {
    val out = val::object();
    out.set("steps", stepList(ringSplitsThrough(complexAt(complexAddress), EdgeRef{hex, edge}, maxEdges)));
    return out;
  });
}

}  // namespace

EMSCRIPTEN_BINDINGS(hexdual_tutorial) {
  function("tutorialRecords", &tutorialRecords);
  function("tutorialRingSplits", &tutorialRingSplits);
}
