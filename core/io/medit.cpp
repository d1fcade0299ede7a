// Medit .mesh (ASCII): Vertices and Hexahedra; other known sections are skipped.
#include <cstdio>
#include <map>
#include <vector>

#include "complex/builders.hpp"
#include "io/dense.hpp"
#include "io/io.hpp"
#include "io/lexer.hpp"

namespace hexdual::io {

Complex readMedit(std::string_view data, const std::string& name) {
  Lexer lx(data, name);
  // Numbers per entry of the sections we read past.
  static const std::map<std::string, int> kSkipped = {
      {"edges", 3},   {"triangles", 4}, {"quadrilaterals", 5}, {"tetrahedra", 5},       {"prisms", 7},
      {"pyramids", 6}, {"corners", 1},  {"ridges", 1},         {"requiredvertices", 1}, {"requirededges", 1},
      {"normals", 3}, {"tangents", 3}};
  std::vector<Vec3> points;
  std::vector<std::array<VertexId, 8>> hexes;
  bool haveVersion = false, haveVertices = false;
  for (;;) {
    if (lx.atEnd()) lx.fail("file ends without 'End'");
    auto tok = lx.token();
    if (!tok.empty() && tok[0] == '#') {
      lx.restOfLine();
      continue;
    }
    std::string kw(tok);
    for (char& ch : kw) ch = char(std::tolower((unsigned char)ch));
    if (kw == "end") break;
    if (kw == "meshversionformatted") {
      int64_t ver = lx.integer("a version number");
      if (ver < 1 || ver > 2) lx.fail("MeshVersionFormatted " + std::to_string(ver) + " is not supported (1 or 2)");
      haveVersion = true;
    } else if (kw == "dimension") {
      int64_t dim = lx.integer("a dimension");
      if (dim != 3) lx.fail("Dimension " + std::to_string(dim) + " is not supported (3)");
    } else if (kw == "vertices") {
      int64_t n = lx.count("number of vertices");
      points.resize(size_t(n));
      for (auto& p : points) {
        p.x = lx.real("a vertex coordinate");
        p.y = lx.real("a vertex coordinate");
        p.z = lx.real("a vertex coordinate");
        lx.integer("a vertex reference");
      }
      haveVertices = true;
    } else if (kw == "hexahedra") {
      int64_t n = lx.count("number of hexahedra");
      hexes.resize(size_t(n));
      for (size_t h = 0; h < hexes.size(); ++h) {
        for (int c = 0; c < 8; ++c) {
          int64_t v = lx.integer("a vertex index");
          if (v < 1 || v > int64_t(points.size()))
            lx.fail("hexahedron " + std::to_string(h + 1) + " uses vertex " + std::to_string(v) + ", out of range (1.." +
                    std::to_string(points.size()) + ")");
          hexes[h][size_t(c)] = VertexId(v - 1);
        }
        lx.integer("a hexahedron reference");
      }
    } else if (kSkipped.count(kw)) {
      int64_t n = lx.count("number of entries");
      for (int64_t i = 0; i < n * kSkipped.at(kw); ++i) lx.real("a number");
    } else {
      lx.fail("unknown keyword '" + std::string(tok) + "'");
    }
  }
  if (!haveVersion) throw Error(name + ": no MeshVersionFormatted line");
  if (!haveVertices) throw Error(name + ": no Vertices section");
  try {
    return fromConnectivity(points, hexes);
  } catch (const Error& e) {
    throw Error(name + ": " + e.what());
  }
}

std::string writeMedit(const Complex& cx) {
  Dense d = denseNumbering(cx);
  std::string out = "MeshVersionFormatted 2\nDimension 3\n\nVertices\n" + std::to_string(d.vertices.size()) + "\n";
  char buf[128];
  for (VertexId v : d.vertices) {
    Vec3 p = cx.position(v);
    std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g 0\n", p.x, p.y, p.z);
    out += buf;
  }
  out += "\nHexahedra\n" + std::to_string(d.hexes.size()) + "\n";
  for (HexId h : d.hexes) {
    for (int c = 0; c < 8; ++c) out += std::to_string(d.vertexIndex[size_t(cx.vertex(h, c))] + 1) + " ";
    out += "0\n";
  }
  out += "\nEnd\n";
  return out;
}

}  // namespace hexdual::io
