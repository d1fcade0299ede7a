#include <doctest/doctest.h>

#include <cmath>

#include "complex/builders.hpp"
#include "helpers.hpp"
#include "io/io.hpp"

using namespace hexdual;
using namespace hexdual::test;

namespace {
void checkSameMesh(const Complex& a, const Complex& b) {
  CHECK(a.counts() == b.counts());
  REQUIRE(a.hexCapacity() == b.hexCapacity());
  for (HexId h : a.hexes())
    for (int c = 0; c < 8; ++c) {
      Vec3 p = a.position(a.vertex(h, c)), q = b.position(b.vertex(h, c));
      CHECK(p.x == q.x);
      CHECK(p.y == q.y);
      CHECK(p.z == q.z);
    }
}
const char* kTwoHexVtk =
    "# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 12 float\n"
    "0 0 0 1 0 0 0 1 0 1 1 0 0 0 1 1 0 1 0 1 1 1 1 1 0 0 2 1 0 2 0 1 2 1 1 2\n"
    "CELLS 2 18\n8 0 1 3 2 4 5 7 6\n8 4 5 7 6 8 9 11 10\nCELL_TYPES 2\n12\n12\n";
}  // namespace

TEST_CASE("round trips through every format keep counts and positions exactly") {
  Complex ring = makeRing(8, 2, 2);
  checkSameMesh(ring, io::readVtk(io::writeVtk(ring, false), "a.vtk"));
  checkSameMesh(ring, io::readVtk(io::writeVtk(ring, true), "b.vtk"));
  checkSameMesh(ring, io::readMedit(io::writeMedit(ring), "c.mesh"));
  checkSameMesh(ring, io::readNative(io::writeNative(ring), "d.hxd"));
  CHECK(io::writeNative(io::readNative(io::writeNative(ring), "e.hxd")) == io::writeNative(ring));
}

TEST_CASE("the native format keeps a pillow that VTK cannot express") {
  Complex p = io::readNative(kPillowNative, "p.hxd");
  Complex q = io::readNative(io::writeNative(p), "q.hxd");
  checkSameMesh(p, q);
  CHECK(extractDual(q).sheets.size() == 5);  // 1+1+2 grid sheets and the sphere
  // VTK and Medit store hexes by vertices only: writing the pillow is refused, naming .hxd.
  CHECK(errorOf([&] { io::writeVtk(p); }) ==
        "VTK cannot represent this complex: hex 0 face 5 has the same 4 vertices as 3 other quad side(s) (e.g. a "
        "pillow); write it as .hxd, which stores gluings");
  CHECK(contains(errorOf([&] { io::writeMedit(p); }), "Medit cannot represent this complex"));
}

TEST_CASE("voxels (cell type 11) are reordered to hexahedra") {
  std::string vox = replaced(replaced(replaced(kTwoHexVtk, "8 0 1 3 2 4 5 7 6", "8 0 1 2 3 4 5 6 7"), "12\n12\n", "11\n12\n"),
                             "", "");
  Complex cx = io::readVtk(vox, "vox.vtk");
  CHECK(cx.counts() == makeGrid(1, 1, 2).counts());
  CHECK(cx.vertex(0, 2) == 3);
}

TEST_CASE("format detection and extensions") {
  CHECK(io::detectFormat(kTwoHexVtk, "x") == io::Format::Vtk);
  CHECK(io::detectFormat("MeshVersionFormatted 2", "x") == io::Format::Medit);
  CHECK(io::detectFormat(kPillowNative, "x") == io::Format::Native);
  CHECK(contains(errorOf([] { io::detectFormat("solid cube", "x.stl"); }), "x.stl: not a mesh file hexdual reads (VTK legacy or .vtu, Gmsh .msh, Medit .mesh/.meshb, .hxd; gzipped or not)"));
  CHECK(contains(errorOf([] { io::formatFromPath("a.obj"); }), "unknown file extension"));
  CHECK(contains(errorOf([] { io::readMesh("", "empty.vtk"); }), "empty.vtk: the file is empty"));
}

TEST_CASE("malformed files each get their own error, naming file and line or byte") {
  // Truncated ASCII.
  CHECK(errorOf([] { io::readVtk(std::string(kTwoHexVtk).substr(0, 170), "t.vtk"); }) ==
        "t.vtk: CELLS declares 18 entries but only 11 bytes remain (at least 2 per entry)");
  // Cut inside POINTS or CELLS with enough bytes left to pass the size check: the error says which
  // section's values ran out.
  {
    Complex cx = makeGrid(3, 3, 3);
    for (VertexId v = 0; v < cx.vertexCapacity(); ++v) cx.setPosition(v, 0.1 * cx.position(v));  // long decimals
    const std::string grid = io::writeVtk(cx, false);
    const std::string inPoints = grid.substr(0, grid.find("CELLS") - 20);
    CHECK(contains(errorOf([&] { io::readVtk(inPoints, "p.vtk"); }), "unexpected end of file; expected one of the 192 values of POINTS"));
    const std::string inCells = grid.substr(0, grid.find("CELL_TYPES") - 30);
    CHECK(contains(errorOf([&] { io::readVtk(inCells, "c.vtk"); }), "unexpected end of file; expected one of the 243 values of CELLS"));
  }
  // Truncated binary: the byte offset is named.
  std::string bin = io::writeVtk(makeGrid(1, 1, 1), true);
  auto cut = bin.substr(0, bin.find("CELLS") + 20);
  CHECK(errorOf([&] { io::readVtk(cut, "b.vtk"); }) ==
        "b.vtk: CELLS declares 9 entries but only 11 bytes remain (at least 4 per entry)");
  // Wrong counts.
  CHECK(contains(errorOf([] { io::readVtk(replaced(kTwoHexVtk, "CELL_TYPES 2\n12\n12", "CELL_TYPES 1\n12"), "w.vtk"); }),
                 "CELL_TYPES has 1 entries but CELLS has 2"));
  CHECK(errorOf([] { io::readVtk(replaced(kTwoHexVtk, "CELLS 2 18", "CELLS 2 17"), "w.vtk"); }) ==
        "w.vtk:9: cell 1 has a bad vertex count 8");
  // Index out of range.
  CHECK(contains(errorOf([] { io::readVtk(replaced(kTwoHexVtk, "8 9 11 10", "8 9 11 12"), "r.vtk"); }),
                 "r.vtk: cell 1 uses vertex 12, out of range (12 points)"));
  // Non-hex cells.
  CHECK(errorOf([] { io::readVtk(replaced(kTwoHexVtk, "12\n12\n", "12\n10\n"), "n.vtk"); }) ==
        "n.vtk: cell 1 (VTK type 10) is typed as a tetrahedron (4 vertices) but lists 8 vertices; the file is "
        "mislabelled");
  CHECK(errorOf([] { io::readVtk(replaced(kTwoHexVtk, "12\n12\n", "12\n42\n"), "u.vtk"); }) ==
        "u.vtk: cell 1 is a VTK cell type 42, which hexdual does not read (1 such cells); only hexahedra, and "
        "lower-dimensional cells that are skipped");
  // NaN coordinates.
  CHECK(contains(errorOf([] { io::readVtk(replaced(kTwoHexVtk, "0 0 0 1 0 0", "nan 0 0 1 0 0"), "nan.vtk"); }),
                 "nan.vtk: point 0 has a coordinate that is not a finite number"));
  // Three hexes on one quad.
  std::string three = replaced(replaced(replaced(kTwoHexVtk, "CELLS 2 18", "CELLS 3 27"), "CELL_TYPES 2\n12\n12",
                                        "CELL_TYPES 3\n12\n12\n12"),
                               "8 4 5 7 6 8 9 11 10", "8 4 5 7 6 8 9 11 10\n8 4 5 7 6 0 1 3 2");
  CHECK(contains(errorOf([&] { io::readVtk(three, "3.vtk"); }), "3.vtk: quad (4,5,6,7) is shared by 3 hexes (0, 1, 2)"));
  // Medit: bad index, missing End, unknown keyword.
  std::string medit = io::writeMedit(makeGrid(1, 1, 1));
  CHECK(contains(errorOf([&] { io::readMedit(replaced(medit, "\n1 2 4 3", "\n1 2 4 99"), "m.mesh"); }),
                 "m.mesh: cell 1 uses vertex 99, out of range (8 points, numbered from 1)"));
  CHECK(io::readMedit(replaced(medit, "End", ""), "m.mesh").numHexes() == 1);  // End is optional
  CHECK(contains(errorOf([&] { io::readMedit(replaced(medit, "Hexahedra", "Octahedra"), "m.mesh"); }),
                 "m.mesh:15: unknown keyword 'Octahedra'"));
  // Native: gluing that breaks vertex consistency, orientation out of range.
  std::string nat = io::writeNative(makeGrid(2, 1, 1));
  CHECK(contains(errorOf([&] { io::readNative(replaced(nat, "0 1 1 0 0", "0 1 1 0 1"), "g.hxd"); }),
                 "g.hxd: validate: hex 0 face 1 is glued to hex 1 face 0 but corner"));
  CHECK(contains(errorOf([&] { io::readNative(replaced(nat, "0 1 1 0 0", "0 1 1 0 9"), "g.hxd"); }),
                 "gluing 0 has orientation 9 (0..7)"));
}
