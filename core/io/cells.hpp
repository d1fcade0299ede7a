// What every mesh reader produces before it becomes a Complex: points, hexahedra, and counts of
// the other cells; and the shared checks (cell kinds, node counts, sizes against remaining bytes).
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "io/io.hpp"

namespace hexdual::io {

enum class CellKind { Vertex, Line, Triangle, Quad, Tet, Hex, Prism, Pyramid, Unsupported };

struct CellSoup {
  std::vector<Vec3> points;
  std::vector<std::array<int64_t, 8>> hexes;  // 0-based point indices, VTK corner order
  std::vector<int64_t> hexCell;              // the file's cell number of each hex (messages)
  std::array<int64_t, 9> kindCount{};        // by CellKind
  int64_t firstUnsupported = -1;             // file cell number of the first unsupported cell
  std::string unsupportedWhat;               // its description ("cell type 42")
  int64_t pointBase = 0;                     // 1 for Medit/Gmsh numbering in messages
  void count(CellKind k, int64_t cell, const std::string& what = "");
};

// Corners a kind has (vertex 1, line 2, triangle 3, quad 4, tet 4, hex 8, prism 6, pyramid 5).
int cornerCount(CellKind k);
const char* kindName(CellKind k);
// The kind of VTK cell type t listing `nodes` nodes (a polygon, type 7, of 4 nodes is a quad); whether
// t is a poly type (poly-vertex, poly-line, triangle strip, polygon: any node count).
CellKind kindOfVtkType(int64_t t, int64_t nodes);
bool vtkPolyType(int64_t t);
// A clear error when a cell's listed node count contradicts its type (a mislabelled cell).
void checkNodeCount(const std::string& name, const std::string& cell, CellKind k, int64_t listed);
// Refuses a declared element count that the remaining bytes cannot hold (before any allocation):
// each element needs at least bytesPerElement bytes.
void checkCountFits(const std::string& name, const std::string& what, int64_t count, size_t bytesLeft,
                    size_t bytesPerElement);

// Turns the soup into a complex: refuses tets/prisms/pyramids unless opt.hexesOnly, checks
// indices, drops unused points (counted), tolerates non-manifold vertices (reported).
Complex assemble(CellSoup& soup, const std::string& name, const ReadOptions& opt, ReadReport* rep,
                 const std::string& format);

}  // namespace hexdual::io

namespace hexdual::io {
// Refuses (naming .hxd) a complex whose gluings do not follow from its vertices: two quads on the
// same 4 vertices (a pillow), or a boundary quad whose vertices another quad also has.
void requireRepresentableByVertices(const Complex& cx, const char* format);
}  // namespace hexdual::io
