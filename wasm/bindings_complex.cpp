// Bindings of the complex: building (grids, rings, the 4-cube boundary), comparing (canonical hash,
// isomorphism), validating, hex centres and the render buffers of the package's Mesh.
#include <cmath>
#include <cstdio>

#include "bindings_common.hpp"
#include "complex/builders.hpp"
#include "complex/canonical.hpp"
#include "flips/fourcube.hpp"
#include "wasm_mesh.hpp"

namespace hexdual::wasm {

namespace {
std::string hexString(uint64_t h) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}
}  // namespace

WasmMesh* WasmMesh::grid(int a, int b, int c) {
  return guarded(
      "PRECONDITION", [&] { return new WasmMesh(makeGrid(a, b, c)); }, nullptr);
}

WasmMesh* WasmMesh::fourCube() {
  return guarded(
      "PRECONDITION", [&] { return new WasmMesh(makeFourCubeBoundary()); }, nullptr);
}

WasmMesh* WasmMesh::ring(int around, int radial, int axial) {
  return guarded(
      "PRECONDITION", [&] { return new WasmMesh(makeRing(around, radial, axial)); }, nullptr);
}

std::string WasmMesh::canonicalHash(bool boundaryFree) {
  return guarded(
      "PRECONDITION", [&] { return hexString(hexdual::canonicalHash(cx_, !boundaryFree)); }, std::string());
}

int WasmMesh::isomorphicTo(const WasmMesh& other, bool boundaryFree) {
  return guarded(
      "PRECONDITION", [&] { return isomorphic(cx_, other.cx_, !boundaryFree) ? 1 : 0; }, -1);
}

val WasmMesh::hexCenters() {
  std::vector<double> c(size_t(cx_.hexCapacity()) * 3, std::nan(""));
  for (HexId h : cx_.hexes()) {
    Vec3 p = cx_.hexCentroid(h);
    c[3 * size_t(h)] = p.x;
    c[3 * size_t(h) + 1] = p.y;
    c[3 * size_t(h) + 2] = p.z;
  }
  return copyOut("Float64Array", c);
}

bool WasmMesh::validate() {
  return guarded(
      "INVALID_RESULT",
      [&] {
        cx_.validate();
        return true;
      },
      false);
}

bool WasmMesh::buildRender(double shrink) {
  return guarded(
      "PRECONDITION",
      [&] {
        rb_ = buildRenderBuffers(cx_, shrink);
        return true;
      },
      false);
}

}  // namespace hexdual::wasm
