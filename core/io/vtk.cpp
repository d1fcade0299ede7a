// VTK legacy unstructured grids, versions 2.0 to 5.1: ASCII and binary (big-endian); CELLS as
// counted lists (<= 4.2) or OFFSETS/CONNECTIVITY (5.1) with 32/64-bit ids; FIELD data and
// METADATA blocks anywhere are read past. Hexahedra (12) and voxels (11) are read; vertices,
// lines, triangles and quads are skipped and counted; other 3D cells are refused or dropped.
#include <cstring>
#include <vector>

#include "io/cells.hpp"
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

// A VTK data type name: its binary width and whether it is floating point (0 width: unknown).
struct VtkType {
  size_t width = 0;
  bool real = false, isUnsigned = false;
};
VtkType vtkType(std::string_view t) {
  auto is = [&](const char* n) { return Lexer::equalsIgnoreCase(t, n); };
  if (is("float")) return {4, true};
  if (is("double")) return {8, true};
  if (is("char") || is("bit")) return {1};
  if (is("unsigned_char")) return {1, false, true};
  if (is("short")) return {2};
  if (is("unsigned_short")) return {2, false, true};
  if (is("int") || is("vtktypeint32") || is("vtkIdType")) return {4};
  if (is("unsigned_int") || is("vtktypeuint32")) return {4, false, true};
  if (is("long") || is("vtktypeint64")) return {8};
  if (is("unsigned_long") || is("vtktypeuint64")) return {8, false, true};
  return {};
}

class VtkReader {
 public:
  VtkReader(std::string_view data, const std::string& name) : lx_(data, name), name_(name), size_(data.size()) {}
  Complex read(const ReadOptions& opt, ReadReport* rep);

 private:
  size_t left() const { return size_ - lx_.offset(); }
  VtkType type(const char* what) {
    auto t = lx_.expectToken(what);
    VtkType vt = vtkType(t);
    if (!vt.width) lx_.fail(std::string(what) + " '" + excerpt(t) + "' is not a VTK data type");
    return vt;
  }
  // n numbers of a type, as doubles (coordinates) or integers.
  std::vector<double> reals(int64_t n, VtkType t, const char* what);
  std::vector<int64_t> integers(int64_t n, VtkType t, const char* what);
  void checkFits(const char* what, int64_t n, VtkType t, int perEntry) {
    checkCountFits(name_, what, n, left(), binary_ ? t.width * size_t(perEntry) : size_t(2 * perEntry));
  }
  void skipValues(int64_t n, VtkType t, const char* what);
  void skipMetadata();
  void skipField();
  void readPoints();
  void readCells();
  void readCellTypes();
  static std::string excerpt(std::string_view t) { return Lexer::excerpt(t); }

  Lexer lx_;
  std::string name_;
  size_t size_;
  bool binary_ = false;
  std::vector<Vec3> points_;
  std::vector<int64_t> offsets_, conn_, types_;
  bool havePoints_ = false, haveCells_ = false, haveTypes_ = false;
};

// How a value of a section is named in errors: "one of the 8133 values of POINTS".
static std::string valueOf(const char* section, int64_t n) {
  return "one of the " + std::to_string(n) + " values of " + section;
}

std::vector<double> VtkReader::reals(int64_t n, VtkType t, const char* what) {
  std::vector<double> v(static_cast<size_t>(n));
  if (binary_) {
    lx_.restOfLine();
    auto raw = lx_.bytes(size_t(n) * t.width, what);
    for (size_t i = 0; i < size_t(n); ++i) {
      const char* p = raw.data() + i * t.width;
      if (t.real) v[i] = t.width == 8 ? readBigEndian<double>(p) : readBigEndian<float>(p);
      else if (t.width == 4) v[i] = t.isUnsigned ? readBigEndian<uint32_t>(p) : readBigEndian<int32_t>(p);
      else if (t.width == 8) v[i] = double(readBigEndian<int64_t>(p));
      else lx_.fail(std::string(what) + ": unsupported binary type");
    }
  } else {
    // Named once for every value, so that a file cut inside the section says where it ended.
    const std::string value = valueOf(what, n);
    for (auto& x : v) x = lx_.real(value.c_str());
  }
  return v;
}

std::vector<int64_t> VtkReader::integers(int64_t n, VtkType t, const char* what) {
  if (t.real) lx_.fail(std::string(what) + " must have an integer type");
  std::vector<int64_t> v(static_cast<size_t>(n));
  if (binary_) {
    lx_.restOfLine();
    auto raw = lx_.bytes(size_t(n) * t.width, what);
    for (size_t i = 0; i < size_t(n); ++i) {
      const char* p = raw.data() + i * t.width;
      switch (t.width) {
        case 1: v[i] = t.isUnsigned ? int64_t(uint8_t(*p)) : int64_t(int8_t(*p)); break;
        case 2: v[i] = t.isUnsigned ? int64_t(readBigEndian<uint16_t>(p)) : readBigEndian<int16_t>(p); break;
        case 4: v[i] = t.isUnsigned ? int64_t(readBigEndian<uint32_t>(p)) : readBigEndian<int32_t>(p); break;
        default: v[i] = readBigEndian<int64_t>(p);
      }
    }
  } else {
    const std::string value = valueOf(what, n);
    for (auto& x : v) x = lx_.integer(value.c_str());
  }
  return v;
}

void VtkReader::skipValues(int64_t n, VtkType t, const char* what) {
  checkFits(what, n, t, 1);
  if (binary_) {
    lx_.restOfLine();
    lx_.bytes(size_t(n) * t.width, what);
  } else {
    for (int64_t i = 0; i < n; ++i) lx_.expectToken(what);
  }
}

// METADATA (VTK >= 9): optional COMPONENT_NAMES (names up to an empty line) and INFORMATION n
// (n entries of a NAME line and a DATA line).
void VtkReader::skipMetadata() {
  lx_.restOfLine();
  for (;;) {
    auto save = lx_;
    auto kw = lx_.token();
    if (Lexer::equalsIgnoreCase(kw, "COMPONENT_NAMES")) {
      lx_.restOfLine();
      while (lx_.offset() < size_) {
        auto line = lx_.restOfLine();
        if (line.find_first_not_of(" \t") == std::string_view::npos) break;
      }
    } else if (Lexer::equalsIgnoreCase(kw, "INFORMATION")) {
      int64_t n = lx_.count("number of information entries", int64_t(1) << 20);
      lx_.restOfLine();
      for (int64_t i = 0; i < 2 * n; ++i) {  // NAME ... LOCATION ..., then DATA ...
        lx_.atEnd();                            // skips blank lines
        lx_.restOfLine();
      }
    } else {
      lx_ = save;
      return;
    }
  }
}

// FIELD name n, then n arrays "name components tuples type" with their values.
void VtkReader::skipField() {
  lx_.expectToken("a field name");
  int64_t arrays = lx_.count("number of field arrays", int64_t(1) << 20);
  for (int64_t a = 0; a < arrays; ++a) {
    auto arrayName = lx_.expectToken("a field array name");
    if (Lexer::equalsIgnoreCase(arrayName, "METADATA")) {  // belongs to the previous array
      skipMetadata();
      --a;
      continue;
    }
    int64_t comps = lx_.count("number of components", int64_t(1) << 20);
    int64_t tuples = lx_.count("number of tuples", int64_t(1) << 40);
    auto t = lx_.expectToken("a field data type");
    VtkType vt = vtkType(t);
    if (Lexer::equalsIgnoreCase(t, "string")) lx_.fail("string field arrays are not supported");
    if (!vt.width) lx_.fail("field data type '" + excerpt(t) + "' is not a VTK data type");
    if (comps > 0 && tuples > (int64_t(1) << 40) / comps) lx_.fail("field array is too large");
    skipValues(comps * tuples, vt, "field data");
  }
}

void VtkReader::readPoints() {
  int64_t n = lx_.count("number of points", int64_t(1) << 40);
  VtkType t = type("point data type");
  if (!t.real) lx_.fail("point data type must be float or double");
  checkFits("POINTS", n, t, 3);
  auto xyz = reals(3 * n, t, "POINTS");
  points_.resize(size_t(n));
  for (size_t i = 0; i < size_t(n); ++i) points_[i] = {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
  havePoints_ = true;
}

// CELLS n size (counted lists), or VTK 5.1: CELLS offsets connectivity, OFFSETS t, CONNECTIVITY t.
void VtkReader::readCells() {
  int64_t a = lx_.count("number of cells", int64_t(1) << 40), b = lx_.count("cell list size", int64_t(1) << 40);
  auto save = lx_;
  auto next = lx_.token();
  if (Lexer::equalsIgnoreCase(next, "OFFSETS")) {
    VtkType ot = type("offset type");
    checkFits("OFFSETS", a, ot, 1);
    offsets_ = integers(a, ot, "OFFSETS");
    lx_.expectKeyword("CONNECTIVITY");
    VtkType ct = type("connectivity type");
    checkFits("CONNECTIVITY", b, ct, 1);
    conn_ = integers(b, ct, "CONNECTIVITY");
    if (offsets_.empty() || offsets_[0] != 0) lx_.fail("OFFSETS must start with 0");
    for (size_t i = 1; i < offsets_.size(); ++i)
      if (offsets_[i] < offsets_[i - 1]) lx_.fail("OFFSETS decrease at entry " + std::to_string(i));
    if (offsets_.back() != b)
      lx_.fail("OFFSETS end at " + std::to_string(offsets_.back()) + " but CONNECTIVITY has " + std::to_string(b) +
               " entries");
    offsets_.erase(offsets_.begin());  // from here: end of each cell
  } else {
    lx_ = save;
    checkFits("CELLS", b, VtkType{4}, 1);
    if (a > b) lx_.fail("CELLS says " + std::to_string(a) + " cells in a list of " + std::to_string(b) + " numbers");
    auto list = integers(b, VtkType{4}, "CELLS");
    offsets_.resize(size_t(a));
    size_t k = 0;
    for (int64_t c = 0; c < a; ++c) {
      if (k >= list.size()) lx_.fail("cell list is shorter than its " + std::to_string(a) + " cells");
      int64_t m = list[k++];
      if (m < 0 || uint64_t(m) > list.size() - k)
        lx_.fail("cell " + std::to_string(c) + " has a bad vertex count " + std::to_string(m));
      for (int64_t i = 0; i < m; ++i) conn_.push_back(list[k++]);
      offsets_[size_t(c)] = int64_t(conn_.size());
    }
    if (k != list.size())
      lx_.fail("CELLS says the list has " + std::to_string(b) + " numbers but its cells use " + std::to_string(k));
  }
  haveCells_ = true;
}

void VtkReader::readCellTypes() {
  int64_t n = lx_.count("number of cell types", int64_t(1) << 40);
  checkFits("CELL_TYPES", n, VtkType{4}, 1);
  types_ = integers(n, VtkType{4}, "CELL_TYPES");
  haveTypes_ = true;
}


Complex VtkReader::read(const ReadOptions& opt, ReadReport* rep) {
  auto header = lx_.restOfLine();
  if (header.substr(0, 5) != "# vtk") lx_.fail("not a VTK legacy file (first line must start with '# vtk')");
  std::string version = "legacy";
  if (auto p = header.find("Version "); p != std::string_view::npos) version = std::string(header.substr(p + 8, 6));
  while (!version.empty() && (version.back() == ' ' || version.back() == '\r')) version.pop_back();
  lx_.restOfLine();  // title
  auto mode = lx_.token();
  binary_ = Lexer::equalsIgnoreCase(mode, "BINARY");
  if (!binary_ && !Lexer::equalsIgnoreCase(mode, "ASCII"))
    lx_.fail("expected ASCII or BINARY but found '" + excerpt(mode) + "'");
  lx_.expectKeyword("DATASET");
  auto kind = lx_.token();
  if (!Lexer::equalsIgnoreCase(kind, "UNSTRUCTURED_GRID"))
    lx_.fail("dataset type '" + excerpt(kind) + "' is not supported; only UNSTRUCTURED_GRID holds hexahedra");

  while (!lx_.atEnd()) {
    auto kw = lx_.token();
    auto is = [&](const char* k) { return Lexer::equalsIgnoreCase(kw, k); };
    if (is("POINTS")) readPoints();
    else if (is("CELLS")) readCells();
    else if (is("CELL_TYPES")) readCellTypes();
    else if (is("METADATA")) skipMetadata();
    else if (is("FIELD")) skipField();
    else if (is("POINT_DATA") || is("CELL_DATA")) {
      if (havePoints_ && haveCells_ && haveTypes_) break;  // attributes are not part of the complex
      lx_.fail(std::string(kw) + " before the geometry is complete");
    } else lx_.fail("unexpected keyword '" + excerpt(kw) + "'");
  }
  if (!havePoints_) lx_.fail("no POINTS section");
  if (!haveCells_) lx_.fail("no CELLS section");
  if (!haveTypes_) lx_.fail("no CELL_TYPES section");
  if (types_.size() != offsets_.size())
    lx_.fail("CELL_TYPES has " + std::to_string(types_.size()) + " entries but CELLS has " +
             std::to_string(offsets_.size()));
  CellSoup soup;
  soup.points = std::move(points_);
  for (size_t c = 0; c < types_.size(); ++c) {
    int64_t b = c ? offsets_[c - 1] : 0, n = offsets_[c] - b;
    CellKind k = kindOfVtkType(types_[c], n);
    std::string cell = "cell " + std::to_string(c);
    if (!vtkPolyType(types_[c])) checkNodeCount(name_, cell + " (VTK type " + std::to_string(types_[c]) + ")", k, n);
    if (k == CellKind::Hex) {
      std::array<int64_t, 8> v;
      for (int i = 0; i < 8; ++i) v[size_t(i)] = conn_[size_t(b + (types_[c] == 11 ? kVoxelToHex[i] : i))];
      soup.hexes.push_back(v);
      soup.hexCell.push_back(int64_t(c));
    }
    soup.count(k, int64_t(c), "VTK cell type " + std::to_string(types_[c]));
  }
  conn_.clear();
  conn_.shrink_to_fit();
  return assemble(soup, name_, opt, rep, "vtk " + version + (binary_ ? " binary" : " ascii"));
}

}  // namespace

Complex readVtk(std::string_view data, const std::string& name, const ReadOptions& opt, ReadReport* rep) {
  return VtkReader(data, name).read(opt, rep);
}

std::string writeVtk(const Complex& cx, bool binary) {
  requireRepresentableByVertices(cx, "VTK");
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
