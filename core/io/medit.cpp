// Medit .mesh (ASCII) and .meshb (binary, versions 1-4): Vertices and Hexahedra are read;
// Edges, Triangles and Quadrilaterals are skipped and counted; Tetrahedra, Prisms and Pyramids are
// refused with their counts (or dropped with hexesOnly); other known sections are read past.
#include <cstdio>
#include <cstring>
#include <map>
#include <vector>

#include "io/cells.hpp"
#include "io/dense.hpp"
#include "io/io.hpp"
#include "io/lexer.hpp"

namespace hexdual::io {
namespace {

// A 1-based index from the file as 0-based; anything below 1 becomes -1 (rejected as out of range
// later, without overflowing on INT64_MIN).
int64_t oneBased(int64_t raw) { return raw >= 1 ? raw - 1 : -1; }

// Element sections: corners per entry and kind (each entry also has a reference number).
struct Section {
  int corners;
  CellKind kind;
};
const Section* elementSection(const std::string& kw) {
  static const std::map<std::string, Section> kSections = {
      {"edges", {2, CellKind::Line}},          {"triangles", {3, CellKind::Triangle}},
      {"quadrilaterals", {4, CellKind::Quad}}, {"quads", {4, CellKind::Quad}},  // non-standard, seen in the wild
      {"tetrahedra", {4, CellKind::Tet}},      {"prisms", {6, CellKind::Prism}},
      {"pyramids", {5, CellKind::Pyramid}},    {"hexahedra", {8, CellKind::Hex}}};
  auto it = kSections.find(kw);
  return it == kSections.end() ? nullptr : &it->second;
}

}  // namespace

Complex readMedit(std::string_view data, const std::string& name, const ReadOptions& opt, ReadReport* rep) {
  Lexer lx(data, name);
  // Numbers per entry of other sections we read past.
  static const std::map<std::string, int> kSkipped = {{"corners", 1},          {"ridges", 1},  {"requiredvertices", 1},
                                                      {"requirededges", 1},    {"normals", 3}, {"tangents", 3},
                                                      {"normalatvertices", 2}, {"tangentatvertices", 2}};
  CellSoup soup;
  soup.pointBase = 1;
  bool haveVersion = false, haveVertices = false;
  int64_t cellNumber = 0;
  while (!lx.atEnd()) {
    auto tok = lx.token();
    if (!tok.empty() && tok[0] == '#') {
      lx.restOfLine();
      continue;
    }
    std::string kw(tok.substr(0, 40));
    for (char& ch : kw) ch = char(std::tolower((unsigned char)ch));
    if (kw == "end") break;
    if (kw == "meshversionformatted") {
      int64_t ver = lx.integer("a version number");
      if (ver < 1 || ver > 4) lx.fail("MeshVersionFormatted " + std::to_string(ver) + " is not supported (1 to 4)");
      haveVersion = true;
    } else if (kw == "dimension") {
      int64_t dim = lx.integer("a dimension");
      if (dim != 3) lx.fail("Dimension " + std::to_string(dim) + " is not supported (3)");
    } else if (kw == "vertices") {
      int64_t n = lx.count("number of vertices", int64_t(1) << 40);
      checkCountFits(name, "Vertices", n, data.size() - lx.offset(), 8);
      soup.points.resize(size_t(n));
      for (auto& p : soup.points) {
        p.x = lx.real("a vertex coordinate");
        p.y = lx.real("a vertex coordinate");
        p.z = lx.real("a vertex coordinate");
        lx.integer("a vertex reference");
      }
      haveVertices = true;
    } else if (const Section* sec = elementSection(kw)) {
      int64_t n = lx.count("number of entries", int64_t(1) << 40);
      checkCountFits(name, std::string(tok.substr(0, 40)), n, data.size() - lx.offset(), size_t(2 * (sec->corners + 1)));
      if (sec->kind == CellKind::Hex) soup.hexes.reserve(soup.hexes.size() + size_t(n));
      for (int64_t i = 0; i < n; ++i, ++cellNumber) {
        std::array<int64_t, 8> v{};
        for (int c = 0; c < sec->corners; ++c) v[size_t(c)] = oneBased(lx.integer("a vertex index"));
        lx.integer("an element reference");
        if (sec->kind == CellKind::Hex) {
          soup.hexes.push_back(v);
          soup.hexCell.push_back(cellNumber + 1);
        }
        soup.count(sec->kind, cellNumber + 1);
      }
    } else if (kSkipped.count(kw)) {
      int64_t n = lx.count("number of entries", int64_t(1) << 40);
      checkCountFits(name, std::string(tok.substr(0, 40)), n, data.size() - lx.offset(), 2);
      for (int64_t i = 0; i < n * kSkipped.at(kw); ++i) lx.real("a number");
    } else {
      lx.fail("unknown keyword '" + Lexer::excerpt(tok) + "'");
    }
  }
  if (!haveVersion) throw Error(name + ": no MeshVersionFormatted line");
  if (!haveVertices) throw Error(name + ": no Vertices section");
  return assemble(soup, name, opt, rep, "medit ascii");
}

namespace {
// libMeshb keyword codes.
enum : int { kDimension = 3, kVertices = 4, kEdges = 5, kTriangles = 6, kQuadrilaterals = 7, kTetrahedra = 8,
             kPrisms = 9, kHexahedra = 10, kPyramids = 49, kEnd = 54 };

class BinaryCursor {
 public:
  BinaryCursor(std::string_view d, const std::string& name, bool swap) : d_(d), name_(name), swap_(swap) {}
  template <class T>
  T get(const char* what) {
    if (d_.size() - pos_ < sizeof(T) || pos_ > d_.size())
      throw Error(name_ + ": byte " + std::to_string(pos_) + ": file ends inside " + what);
    unsigned char b[sizeof(T)];
    std::memcpy(b, d_.data() + pos_, sizeof(T));
    if (swap_)
      for (size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
    T v;
    std::memcpy(&v, b, sizeof(T));
    pos_ += sizeof(T);
    return v;
  }
  size_t& at() { return pos_; }
  size_t left() const { return pos_ <= d_.size() ? d_.size() - pos_ : 0; }

 private:
  std::string_view d_;
  const std::string& name_;
  bool swap_;
  size_t pos_ = 0;
};
}  // namespace

Complex readMeditBinary(std::string_view data, const std::string& name, const ReadOptions& opt, ReadReport* rep) {
  if (data.size() < 8) throw Error(name + ": too short for a Medit binary file");
  bool swap = data[0] == 0;
  BinaryCursor in(data, name, swap);
  in.get<int32_t>("the header");
  int32_t version = in.get<int32_t>("the version");
  if (version < 1 || version > 4) throw Error(name + ": Medit binary version " + std::to_string(version) + " is not supported (1 to 4)");
  auto position = [&]() -> int64_t { return version >= 3 ? in.get<int64_t>("a position") : in.get<int32_t>("a position"); };
  auto index = [&]() -> int64_t { return version == 4 ? in.get<int64_t>("an index") : in.get<int32_t>("an index"); };
  auto real = [&]() -> double { return version == 1 ? in.get<float>("a coordinate") : in.get<double>("a coordinate"); };
  const size_t intBytes = version == 4 ? 8 : 4, realBytes = version == 1 ? 4 : 8;
  CellSoup soup;
  soup.pointBase = 1;
  bool haveVertices = false;
  int64_t cellNumber = 0;
  int32_t dim = 3;
  while (in.left() >= 4) {
    size_t kwAt = in.at();
    int32_t kw = in.get<int32_t>("a keyword");
    if (kw == kEnd) break;
    int64_t next = position();
    if (kw == kDimension) {
      dim = in.get<int32_t>("the dimension");
      if (dim != 3) throw Error(name + ": Dimension " + std::to_string(dim) + " is not supported (3)");
    } else if (kw == kVertices) {
      int64_t n = index();
      checkCountFits(name, "Vertices", n, in.left(), 3 * realBytes + intBytes);
      soup.points.resize(size_t(n));
      for (auto& p : soup.points) {
        p.x = real();
        p.y = real();
        p.z = real();
        index();
      }
      haveVertices = true;
    } else if ((kw >= kEdges && kw <= kHexahedra) || kw == kPyramids) {
      static const std::map<int, Section> kBin = {{kEdges, {2, CellKind::Line}},         {kTriangles, {3, CellKind::Triangle}},
                                                  {kQuadrilaterals, {4, CellKind::Quad}}, {kTetrahedra, {4, CellKind::Tet}},
                                                  {kPrisms, {6, CellKind::Prism}},        {kHexahedra, {8, CellKind::Hex}},
                                                  {kPyramids, {5, CellKind::Pyramid}}};
      const Section& sec = kBin.at(kw);
      int64_t n = index();
      checkCountFits(name, "an element section", n, in.left(), size_t(sec.corners + 1) * intBytes);
      for (int64_t i = 0; i < n; ++i, ++cellNumber) {
        std::array<int64_t, 8> v{};
        for (int c = 0; c < sec.corners; ++c) v[size_t(c)] = oneBased(index());
        index();
        if (sec.kind == CellKind::Hex) {
          soup.hexes.push_back(v);
          soup.hexCell.push_back(cellNumber + 1);
        }
        soup.count(sec.kind, cellNumber + 1);
      }
    }
    if (next == 0) break;
    if (next <= int64_t(kwAt) || next > int64_t(data.size()))
      throw Error(name + ": byte " + std::to_string(kwAt) + ": keyword " + std::to_string(kw) +
                  " points to a next keyword at " + std::to_string(next) + ", outside the file or backwards");
    if (size_t(next) < in.at())
      throw Error(name + ": byte " + std::to_string(kwAt) + ": keyword " + std::to_string(kw) + " overlaps the next one");
    in.at() = size_t(next);
  }
  if (!haveVertices) throw Error(name + ": no Vertices section");
  return assemble(soup, name, opt, rep, "medit binary v" + std::to_string(version));
}

std::string writeMedit(const Complex& cx) {
  requireRepresentableByVertices(cx, "Medit");
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
