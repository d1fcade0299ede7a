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
std::string replaced(std::string s, const std::string& from, const std::string& to) {
  auto i = s.find(from);
  REQUIRE(i != std::string::npos);
  return s.replace(i, from.size(), to);
}
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
  // The same connectivity in VTK has 4 hexes around one vertex set: rejected with a reason.
  auto msg = errorOf([&] { io::readVtk(io::writeVtk(p), "p.vtk"); });
  CHECK(contains(msg, "p.vtk: quad (4,5,6,7) is shared by 4 hexes"));
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
  CHECK(contains(errorOf([] { io::detectFormat("solid cube", "x.stl"); }), "x.stl: not a VTK legacy"));
  CHECK(contains(errorOf([] { io::formatFromPath("a.obj"); }), "unknown file extension"));
  CHECK(contains(errorOf([] { io::readMesh("", "empty.vtk"); }), "empty.vtk: the file is empty"));
}

TEST_CASE("malformed files each get their own error, naming file and line or byte") {
  // Truncated ASCII.
  CHECK(contains(errorOf([] { io::readVtk(std::string(kTwoHexVtk).substr(0, 170), "t.vtk"); }),
                 "t.vtk:8: unexpected end of file; expected a vertex index"));
  // Truncated binary: the byte offset is named.
  std::string bin = io::writeVtk(makeGrid(1, 1, 1), true);
  auto cut = bin.substr(0, bin.find("CELLS") + 20);
  CHECK(contains(errorOf([&] { io::readVtk(cut, "b.vtk"); }), "b.vtk: byte "));
  CHECK(contains(errorOf([&] { io::readVtk(cut, "b.vtk"); }), "file ends inside CELLS"));
  // Wrong counts.
  CHECK(contains(errorOf([] { io::readVtk(replaced(kTwoHexVtk, "CELL_TYPES 2\n12\n12", "CELL_TYPES 1\n12"), "w.vtk"); }),
                 "CELL_TYPES has 1 entries but CELLS has 2"));
  CHECK(contains(errorOf([] { io::readVtk(replaced(kTwoHexVtk, "CELLS 2 18", "CELLS 2 17"), "w.vtk"); }),
                 "CELLS says the list has 17 numbers but its cells use 18"));
  // Index out of range.
  CHECK(contains(errorOf([] { io::readVtk(replaced(kTwoHexVtk, "8 9 11 10", "8 9 11 12"), "r.vtk"); }),
                 "r.vtk: cell 1 uses vertex 12, out of range (12 points)"));
  // Non-hex cells.
  CHECK(contains(errorOf([] { io::readVtk(replaced(kTwoHexVtk, "12\n12\n", "12\n10\n"), "n.vtk"); }),
                 "n.vtk: cell 1 has type 10; only hexahedra (12) and voxels (11) are supported"));
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
                 "hexahedron 1 uses vertex 99, out of range (1..8)"));
  CHECK(contains(errorOf([&] { io::readMedit(replaced(medit, "End", ""), "m.mesh"); }), "file ends without 'End'"));
  CHECK(contains(errorOf([&] { io::readMedit(replaced(medit, "Hexahedra", "Octahedra"), "m.mesh"); }),
                 "m.mesh:15: unknown keyword 'Octahedra'"));
  // Native: gluing that breaks vertex consistency, orientation out of range.
  std::string nat = io::writeNative(makeGrid(2, 1, 1));
  CHECK(contains(errorOf([&] { io::readNative(replaced(nat, "0 1 1 0 0", "0 1 1 0 1"), "g.hxd"); }),
                 "g.hxd: validate: hex 0 face 1 is glued to hex 1 face 0 but corner"));
  CHECK(contains(errorOf([&] { io::readNative(replaced(nat, "0 1 1 0 0", "0 1 1 0 9"), "g.hxd"); }),
                 "gluing 0 has orientation 9 (0..7)"));
}
