// VTK legacy unstructured grids: ASCII and binary (big-endian), hexahedra (12) and voxels (11).
#include <cstring>
#include <vector>

#include "complex/builders.hpp"
#include "io/dense.hpp"
#include "io/io.hpp"
#include "io/lexer.hpp"

namespace hexdual::io {
namespace {

template <class T>
T readBigEndian(const char* p) {
  unsigned char b[sizeof(T)];
  for (size_t i = 0; i < sizeof(T); ++i) b[i] = (unsigned char)p[sizeof(T) - 1 - i];
  T v;
  std::memcpy(&v, b, sizeof(T));
  return v;
}
template <class T>
void appendBigEndian(std::string& out, T v) {
  unsigned char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  for (size_t i = 0; i < sizeof(T); ++i) out.push_back(char(b[sizeof(T) - 1 - i]));
}

// Voxel corners are in (x,y,z) binary order; VTK hexahedra go around each face.
constexpr int kVoxelToHex[8] = {0, 1, 3, 2, 4, 5, 7, 6};

}  // namespace

Complex readVtk(std::string_view data, const std::string& name) {
  Lexer lx(data, name);
  auto header = lx.restOfLine();
  if (header.substr(0, 5) != "# vtk") lx.fail("not a VTK legacy file (first line must start with '# vtk')");
  lx.restOfLine();  // title
  auto mode = lx.token();
  bool binary = Lexer::equalsIgnoreCase(mode, "BINARY");
  if (!binary && !Lexer::equalsIgnoreCase(mode, "ASCII"))
    lx.fail("expected ASCII or BINARY but found '" + std::string(mode) + "'");
  lx.expectKeyword("DATASET");
  auto kind = lx.token();
  if (!Lexer::equalsIgnoreCase(kind, "UNSTRUCTURED_GRID"))
    lx.fail("dataset type '" + std::string(kind) + "' is not supported; only UNSTRUCTURED_GRID holds hexahedra");

  std::vector<Vec3> points;
  std::vector<std::vector<int64_t>> cells;
  std::vector<int64_t> types;
  bool havePoints = false, haveCells = false, haveTypes = false;
  while (!lx.atEnd()) {
    auto kw = std::string(lx.token());
    if (Lexer::equalsIgnoreCase(kw, "POINTS")) {
      int64_t n = lx.count("number of points");
      auto type = std::string(lx.expectToken("point data type"));
      bool isDouble = Lexer::equalsIgnoreCase(type, "double");
      if (!isDouble && !Lexer::equalsIgnoreCase(type, "float"))
        lx.fail("point data type '" + type + "' is not supported (float or double)");
      points.resize(size_t(n));
      if (binary) {
        lx.restOfLine();
        size_t w = isDouble ? 8 : 4;
        auto raw = lx.bytes(size_t(n) * 3 * w, "POINTS");
        for (size_t i = 0; i < size_t(n) * 3; ++i) {
          double v = isDouble ? readBigEndian<double>(raw.data() + i * w) : readBigEndian<float>(raw.data() + i * w);
          (&points[i / 3].x)[i % 3] = v;
        }
      } else {
        for (auto& p : points) {
          p.x = lx.real("a point coordinate");
          p.y = lx.real("a point coordinate");
          p.z = lx.real("a point coordinate");
        }
      }
      havePoints = true;
    } else if (Lexer::equalsIgnoreCase(kw, "CELLS")) {
      int64_t n = lx.count("number of cells"), size = lx.count("cell list size", int64_t(1) << 30);
      cells.resize(size_t(n));
      int64_t used = 0;
      if (binary) {
        lx.restOfLine();
        size_t start = lx.offset();
        auto raw = lx.bytes(size_t(size) * 4, "CELLS");
        size_t k = 0;
        for (int64_t c = 0; c < n; ++c) {
          if (k >= size_t(size)) lx.failAtByte(start + 4 * k, "cell list is shorter than its " + std::to_string(n) + " cells");
          int32_t m = readBigEndian<int32_t>(raw.data() + 4 * k++);
          if (m < 0 || k + size_t(m) > size_t(size)) lx.failAtByte(start + 4 * (k - 1), "cell " + std::to_string(c) + " has a bad vertex count");
          for (int32_t i = 0; i < m; ++i) cells[size_t(c)].push_back(readBigEndian<int32_t>(raw.data() + 4 * k++));
        }
        used = int64_t(k);
      } else {
        for (auto& cell : cells) {
          int64_t m = lx.count("a cell's vertex count", 1000);
          for (int64_t i = 0; i < m; ++i) cell.push_back(lx.integer("a vertex index"));
          used += m + 1;
        }
      }
      if (used != size)
        lx.fail("CELLS says the list has " + std::to_string(size) + " numbers but its cells use " + std::to_string(used));
      haveCells = true;
    } else if (Lexer::equalsIgnoreCase(kw, "CELL_TYPES")) {
      int64_t n = lx.count("number of cell types");
      types.resize(size_t(n));
      if (binary) {
        lx.restOfLine();
        auto raw = lx.bytes(size_t(n) * 4, "CELL_TYPES");
        for (size_t i = 0; i < size_t(n); ++i) types[i] = readBigEndian<int32_t>(raw.data() + 4 * i);
      } else {
        for (auto& t : types) t = lx.integer("a cell type");
      }
      haveTypes = true;
    } else if (Lexer::equalsIgnoreCase(kw, "POINT_DATA") || Lexer::equalsIgnoreCase(kw, "CELL_DATA") ||
               Lexer::equalsIgnoreCase(kw, "FIELD") || Lexer::equalsIgnoreCase(kw, "METADATA")) {
      break;  // attributes are not part of the complex
    } else {
      lx.fail("unexpected keyword '" + kw + "'");
    }
  }
  if (!havePoints) lx.fail("no POINTS section");
  if (!haveCells) lx.fail("no CELLS section");
  if (!haveTypes) lx.fail("no CELL_TYPES section");
  if (types.size() != cells.size())
    lx.fail("CELL_TYPES has " + std::to_string(types.size()) + " entries but CELLS has " + std::to_string(cells.size()));
  std::vector<std::array<VertexId, 8>> hexes(cells.size());
  for (size_t c = 0; c < cells.size(); ++c) {
    if (types[c] != 12 && types[c] != 11)
      throw Error(name + ": cell " + std::to_string(c) + " has type " + std::to_string(types[c]) +
                  "; only hexahedra (12) and voxels (11) are supported");
    if (cells[c].size() != 8)
      throw Error(name + ": cell " + std::to_string(c) + " is a hexahedron with " + std::to_string(cells[c].size()) +
                  " vertices (needs 8)");
    for (int i = 0; i < 8; ++i) {
      int64_t v = cells[c][size_t(types[c] == 11 ? kVoxelToHex[i] : i)];
      if (v < 0 || v >= int64_t(points.size()))
        throw Error(name + ": cell " + std::to_string(c) + " uses vertex " + std::to_string(v) + ", out of range (" +
                    std::to_string(points.size()) + " points)");
      hexes[c][size_t(i)] = VertexId(v);
    }
  }
  try {
    return fromConnectivity(points, hexes);
  } catch (const Error& e) {
    throw Error(name + ": " + e.what());
  }
}

std::string writeVtk(const Complex& cx, bool binary) {
  Dense d = denseNumbering(cx);
  std::string out = "# vtk DataFile Version 3.0\nhexdual\n";
  out += binary ? "BINARY\n" : "ASCII\n";
  out += "DATASET UNSTRUCTURED_GRID\nPOINTS " + std::to_string(d.vertices.size()) + " double\n";
  char buf[128];
  for (VertexId v : d.vertices) {
    Vec3 p = cx.position(v);
    if (binary) {
      appendBigEndian(out, p.x);
      appendBigEndian(out, p.y);
      appendBigEndian(out, p.z);
    } else {
      std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g\n", p.x, p.y, p.z);
      out += buf;
    }
  }
  if (binary) out += "\n";
  out += "CELLS " + std::to_string(d.hexes.size()) + " " + std::to_string(d.hexes.size() * 9) + "\n";
  for (HexId h : d.hexes) {
    if (binary) {
      appendBigEndian<int32_t>(out, 8);
      for (int c = 0; c < 8; ++c) appendBigEndian<int32_t>(out, d.vertexIndex[size_t(cx.vertex(h, c))]);
    } else {
      out += "8";
      for (int c = 0; c < 8; ++c) out += " " + std::to_string(d.vertexIndex[size_t(cx.vertex(h, c))]);
      out += "\n";
    }
  }
  if (binary) out += "\n";
  out += "CELL_TYPES " + std::to_string(d.hexes.size()) + "\n";
  for (size_t i = 0; i < d.hexes.size(); ++i) {
    if (binary) appendBigEndian<int32_t>(out, 12);
    else out += "12\n";
  }
  if (binary) out += "\n";
  return out;
}

}  // namespace hexdual::io
