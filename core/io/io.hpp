// Reading and writing hex complexes. Readers: VTK legacy 2.0-5.1 (ASCII/binary), VTK XML .vtu
// (ascii, base64, appended raw, zlib-compressed), Gmsh .msh 2.2/4.1 (ASCII/binary), Medit .mesh
// and .meshb, the lossless native format (.hxd); any of them gzipped. Writers: .vtk, .mesh, .hxd.
// Readers are all-or-nothing: on error they throw Error naming the file, line (or byte) and reason.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "complex/complex.hpp"
#include "ops/op_step.hpp"

namespace hexdual::io {

enum class Format { Vtk, Vtu, Gmsh, Medit, MeditBinary, Native };

struct ReadOptions {
  // Read the hexahedra of a file that also holds tetrahedra, prisms or pyramids; the dropped
  // cells' faces become boundary. Without it such files are refused with their counts.
  bool hexesOnly = false;
};

// What a reader found besides the hexes (shown by `hexdual info`).
struct ReadReport {
  std::string format;           // e.g. "vtk 5.1 binary", "gmsh 4.1 ascii"
  bool gzipped = false;
  int64_t points = 0;           // points in the file
  int64_t unusedVertices = 0;   // points no hex uses: not part of the complex (ids stay dense)
  int64_t vertexCells = 0, lineCells = 0, triangleCells = 0, quadCells = 0;  // skipped, lower-dimensional
  int64_t tetrahedra = 0, prisms = 0, pyramids = 0;  // dropped with hexesOnly
  std::vector<VertexId> nonManifoldVertices;         // accepted; operations refuse to touch them
};

// Format for writing, from a file name's extension (.vtk, .mesh, .hxd); throws for anything else.
Format formatFromPath(const std::string& path);
// Format from the first bytes of (decompressed) data; throws when none matches.
Format detectFormat(std::string_view data, const std::string& name);
const char* formatName(Format f);

Complex readVtk(std::string_view data, const std::string& name, const ReadOptions& opt = {}, ReadReport* rep = nullptr);
Complex readVtu(std::string_view data, const std::string& name, const ReadOptions& opt = {}, ReadReport* rep = nullptr);
Complex readGmsh(std::string_view data, const std::string& name, const ReadOptions& opt = {}, ReadReport* rep = nullptr);
Complex readMedit(std::string_view data, const std::string& name, const ReadOptions& opt = {}, ReadReport* rep = nullptr);
Complex readMeditBinary(std::string_view data, const std::string& name, const ReadOptions& opt = {},
                        ReadReport* rep = nullptr);
Complex readNative(std::string_view data, const std::string& name, ReadReport* rep = nullptr);
// Detects the format (and gzip) from the bytes.
Complex readMesh(std::string_view data, const std::string& name, const ReadOptions& opt = {}, ReadReport* rep = nullptr);

// Writers number the live vertices and hexes densely, in id order. VTK and Medit store hexes by
// vertices only, so they refuse a complex whose gluings do not follow from its vertices (a
// pillow: two hexes on the same 8 vertices) with a message naming .hxd.
std::string writeVtk(const Complex& cx, bool binary = false);
std::string writeMedit(const Complex& cx);
std::string writeNative(const Complex& cx);
std::string writeMesh(const Complex& cx, Format f, bool binary = false);

// Files larger than this are refused before they are read in full.
constexpr size_t kMaxFileBytes = size_t(1) << 30;
// Reads a whole file or stream, refusing directories and anything over maxBytes.
std::string readBytes(const std::string& path, size_t maxBytes = kMaxFileBytes);
Complex readFile(const std::string& path, const ReadOptions& opt = {}, ReadReport* rep = nullptr);
// Writes to a temporary file next to `path` and renames it over `path` only on success.
void writeFile(const Complex& cx, const std::string& path, bool binary = false);
// The step with its hex ids as every writer numbers hexes (densely, in id order, skipping ids
// steps removed), so that a step reported against `cx` applies to a file written from it; local
// faces and edges stay (writers keep each hex's corner order). Empty when it names a hex cx does
// not hold.
std::optional<OpStep> numberedAsWritten(const Complex& cx, const OpStep& step);
void writeTextFile(const std::string& path, const std::string& data);

// The report as text lines ("file: ...") and as JSON members for `info`.
std::string reportText(const ReadReport& r);
std::string reportJson(const ReadReport& r);

}  // namespace hexdual::io
