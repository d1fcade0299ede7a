// Every mesh of the development set (../shared/meshes/, not in the repository) and every format
// variant: exact hex and vertex counts, or the exact refusal. Skipped with a message when absent.
#include <doctest/doctest.h>

#include <sys/stat.h>

#include <cstdlib>

#include "complex/manifold.hpp"
#include "helpers.hpp"
#include "io/io.hpp"

using namespace hexdual;
using namespace hexdual::test;

namespace {
// ../shared/meshes/ next to the repository (HEXDUAL_MESHES overrides, e.g. from a worktree).
const std::string kDir = std::getenv("HEXDUAL_MESHES") ? std::string(std::getenv("HEXDUAL_MESHES")) + "/"
                                                       : std::string(HEXDUAL_SOURCE_DIR "/../shared/meshes/");
bool haveDevSet() {
  struct stat st {};
  return ::stat((std::string(kDir) + "MANIFEST.md").c_str(), &st) == 0;
}
struct Expect {
  const char* file;
  int64_t hexes, vertices;  // hexes 0: refused with `error`
  const char* error;
  int64_t quads = 0, lines = 0, unused = 0, nonManifold = 0;
};
}  // namespace

TEST_CASE("development set: every mesh and variant opens with exact counts or is refused precisely") {
  if (!haveDevSet()) {
    MESSAGE("skipped: " << kDir << " is absent");
    return;
  }
  const std::vector<Expect> expect = {
      {"ECR_block_stresstest_in.mesh.gz", 2520, 3180, "", 1200},
      {"ECR_cap_in.mesh.gz", 4420, 5449, "", 1950},
      {"G_cylinder_1.vtk.gz", 630, 880, ""},
      {"G_cylinder_2.vtk.gz", 980, 1280, ""},
      {"MOAB_125hex.vtk.gz", 125, 216, ""},
      {"MOAB_brick.vtk.gz", 1000, 1331, "", 600, 1200},
      {"MOAB_hex_2048.vtk.gz", 2048, 2601, ""},
      {"MOAB_hexes_mixed.vtk.gz", 4, 18, "", 4, 1},
      {"P_big_buddy.mesh.gz", 15232, 18951, "", 6784},
      {"P_double-torus.vtk.gz", 632, 1025, ""},
      {"P_hex_sphere.vtk.gz", 0, 0,
       "P_hex_sphere.vtk.gz: cell 0 (VTK type 10) is typed as a tetrahedron (4 vertices) but lists 8 vertices; the "
       "file is mislabelled"},
      {"P_joint.vtk.gz", 2010, 2711, ""},
      {"P_kitten.mesh.gz", 1728, 2126, ""},
      {"P_rockarm.vtk.gz", 1858, 2651, "", 0, 0, 0, 9},
      {"variants/m00_base.mesh", 240, 540, "", 480},
      {"variants/m01_comments.mesh", 240, 540, "", 480},
      {"variants/m02_tets0_tris_edges.mesh", 240, 540, "", 480, 1},
      {"variants/m03_unused_vertex.mesh", 240, 540, "", 480, 0, 1},
      {"variants/m04_crlf.mesh", 240, 540, "", 480},
      {"variants/m05_version2_dim_inline.mesh", 240, 540, "", 480},
      {"variants/m06_tets_nonzero.mesh", 0, 0,
       "m06_tets_nonzero.mesh: the file holds 1 tetrahedron, 0 prisms and 0 pyramids besides 240 hexahedra; hexdual "
       "reads hex meshes (--hexes-only, or { hexesOnly: true } in the package, reads the hex part)"},
      {"variants/m07_no_end.mesh", 240, 540, "", 480},
      {"variants/m08_lowercase_indent.mesh", 240, 540, "", 480},
      {"variants/v00_base.vtk", 632, 1025, ""},
      {"variants/v01_pointdata_celldata_field.vtk", 632, 1025, ""},
      {"variants/v02_field_before_points.vtk", 632, 1025, ""},
      {"variants/v03_unused_vertex.vtk", 632, 1025, "", 0, 0, 1},
      {"variants/v04_crlf.vtk", 632, 1025, ""},
      {"variants/v05_float.vtk", 632, 1025, ""},
      {"variants/v06_vtk9_metadata.vtk", 632, 1025, ""},
      {"variants/v07_vtk51_offsets.vtk", 632, 1025, ""},
      {"variants/v08_hex_plus_quads.vtk", 632, 1025, "", 5},
      {"variants/v09_hex_plus_tet.vtk", 0, 0,
       "v09_hex_plus_tet.vtk: the file holds 1 tetrahedron, 0 prisms and 0 pyramids besides 632 hexahedra; hexdual "
       "reads hex meshes (--hexes-only, or { hexesOnly: true } in the package, reads the hex part)"},
      {"variants/v10_xml.vtu", 632, 1025, ""},
      {"variants/v11_gzip.vtk.gz", 632, 1025, ""},
      {"variants/v12_blank_lines_tabs.vtk", 632, 1025, ""},
  };
  for (const Expect& e : expect) {
    std::string path = std::string(kDir) + e.file;
    INFO(e.file);
    if (e.hexes == 0) {
      std::string err = errorOf([&] { io::readFile(path); });
      CHECK(err.size() >= std::string(e.error).size());
      CHECK(err.substr(err.size() - std::string(e.error).size()) == e.error);
      continue;
    }
    io::ReadReport rep;
    Complex cx = io::readFile(path, {}, &rep);
    CHECK(cx.numHexes() == e.hexes);
    CHECK(cx.numVertices() == e.vertices);
    CHECK(rep.quadCells == e.quads);
    CHECK(rep.lineCells == e.lines);
    CHECK(rep.unusedVertices == e.unused);
    CHECK(int64_t(rep.nonManifoldVertices.size()) == e.nonManifold);
  }
  // With --hexes-only the tet variants read as their hex part.
  io::ReadOptions only;
  only.hexesOnly = true;
  CHECK(io::readFile(std::string(kDir) + "variants/v09_hex_plus_tet.vtk", only).numHexes() == 632);
  CHECK(io::readFile(std::string(kDir) + "variants/m06_tets_nonzero.mesh", only).numHexes() == 240);
  // The first non-manifold vertex of P_rockarm, named as validate names it.
  Complex rock = io::readFile(std::string(kDir) + "P_rockarm.vtk.gz");
  CHECK(describeLinkIssue(rock, vertexLinkIssues(rock)[0]) ==
        "vertex 1697 at (0.0663078, 0.132627, 0.138827) in hexes 1082, 1435, 1810, 1826 is non-manifold: its link has "
        "2 components");
}
