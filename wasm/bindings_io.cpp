// Bindings of file input and output: reading a mesh file (any supported format), its info, and
// writing it as VTK, Medit or the native format (text, or bytes for binary VTK).
#include "bindings_common.hpp"
#include "io/json.hpp"
#include "wasm_mesh.hpp"

namespace hexdual::wasm {

namespace {
io::Format formatNamed(const std::string& format) {
  if (format == "vtk") return io::Format::Vtk;
  if (format == "mesh") return io::Format::Medit;
  if (format == "hxd") return io::Format::Native;
  throw Error("unknown format '" + format + "' (vtk, mesh or hxd)");
}
}  // namespace

WasmMesh* WasmMesh::load(const std::string& bytes, const std::string& name, bool hexesOnly) {
  return guarded(
      "PARSE",
      [&] {
        io::ReadOptions opt;
        opt.hexesOnly = hexesOnly;
        io::ReadReport rep;
        auto* m = new WasmMesh(io::readMesh(bytes, name, opt, &rep));
        m->file_ = rep;
        return m;
      },
      nullptr);
}

std::string WasmMesh::infoJson() {
  return guarded(
      "PRECONDITION", [&] { return io::infoJson(cx_, dual(), file_ ? &*file_ : nullptr); }, std::string());
}

std::string WasmMesh::countsJson() {
  return guarded(
      "PRECONDITION",
      [&] {
        if (!euler_) {
          const Counts c = cx_.counts();
          euler_ = c.vertices - c.edges + c.quads - c.hexes;
        }
        Counts c;
        c.vertices = cx_.numVertices(), c.quads = cx_.numQuads(), c.hexes = cx_.numHexes();
        c.edges = c.vertices + c.quads - c.hexes - *euler_;
        c.boundaryQuads = cx_.numBoundaryQuads();
        return io::countsJson(c);
      },
      std::string());
}

std::string WasmMesh::save(const std::string& format, bool binary) {
  return guarded(
      "PRECONDITION", [&] { return io::writeMesh(cx_, formatNamed(format), binary); }, std::string());
}

val WasmMesh::saveBytes(const std::string& format, bool binary) {
  std::string bytes;
  if (!guarded(
          "PRECONDITION",
          [&] {
            bytes = io::writeMesh(cx_, formatNamed(format), binary);
            return true;
          },
          false))
    return val::null();
  return val::global("Uint8Array")
      .new_(val(emscripten::typed_memory_view(bytes.size(), reinterpret_cast<const uint8_t*>(bytes.data()))));
}

}  // namespace hexdual::wasm
