// VTK XML unstructured grids (.vtu): one Piece; DataArrays in ascii, inline binary (base64 with a
// size header), or appended (raw or base64), each optionally zlib-compressed in blocks
// (vtkZLibDataCompressor); UInt32 or UInt64 headers; little- or big-endian.
#include <cstring>
#include <map>
#include <vector>

#include "io/cells.hpp"
#include "io/inflate.hpp"
#include "io/io.hpp"
#include "io/lexer.hpp"

namespace hexdual::io {
namespace {

struct Tag {
  std::string name;
  std::map<std::string, std::string> attrs;
  bool closing = false, selfClosing = false;
  size_t end = 0;  // offset just after '>'
  std::string attr(const std::string& k, const std::string& dflt = "") const {
    auto it = attrs.find(k);
    return it == attrs.end() ? dflt : it->second;
  }
};

class Xml {
 public:
  Xml(std::string_view d, const std::string& name) : d_(d), name_(name) {}
  [[noreturn]] void fail(size_t at, const std::string& why) const {
    throw Error(name_ + ": byte " + std::to_string(at) + ": " + why);
  }
  // The next element tag at or after pos (skips text, comments, declarations); false at the end.
  bool next(size_t& pos, Tag& t) {
    for (;;) {
      size_t lt = d_.find('<', pos);
      if (lt == std::string_view::npos) return false;
      if (d_.substr(lt, 4) == "<!--") {
        size_t e = d_.find("-->", lt);
        if (e == std::string_view::npos) fail(lt, "unterminated comment");
        pos = e + 3;
        continue;
      }
      if (d_.substr(lt, 2) == "<?" || d_.substr(lt, 2) == "<!") {
        size_t e = d_.find('>', lt);
        if (e == std::string_view::npos) fail(lt, "unterminated declaration");
        pos = e + 1;
        continue;
      }
      parseTag(lt, t);
      pos = t.end;
      return true;
    }
  }

 private:
  void parseTag(size_t lt, Tag& t) {
    t = Tag{};
    size_t i = lt + 1;
    if (i < d_.size() && d_[i] == '/') {
      t.closing = true;
      ++i;
    }
    size_t b = i;
    while (i < d_.size() && !isSpace(d_[i]) && d_[i] != '>' && d_[i] != '/') ++i;
    t.name = std::string(d_.substr(b, i - b));
    for (;;) {
      while (i < d_.size() && isSpace(d_[i])) ++i;
      if (i >= d_.size()) fail(lt, "unterminated tag <" + Lexer::excerpt(t.name) + ">");
      if (d_[i] == '>') {
        t.end = i + 1;
        return;
      }
      if (d_[i] == '/' && i + 1 < d_.size() && d_[i + 1] == '>') {
        t.selfClosing = true;
        t.end = i + 2;
        return;
      }
      size_t kb = i;
      while (i < d_.size() && d_[i] != '=' && !isSpace(d_[i]) && d_[i] != '>') ++i;
      std::string key(d_.substr(kb, i - kb));
      while (i < d_.size() && isSpace(d_[i])) ++i;
      if (i >= d_.size() || d_[i] != '=') fail(i, "attribute '" + Lexer::excerpt(key) + "' has no value");
      ++i;
      while (i < d_.size() && isSpace(d_[i])) ++i;
      if (i >= d_.size() || (d_[i] != '"' && d_[i] != '\'')) fail(i, "attribute value must be quoted");
      char q = d_[i++];
      size_t vb = i;
      while (i < d_.size() && d_[i] != q) ++i;
      if (i >= d_.size()) fail(vb, "unterminated attribute value");
      t.attrs[key] = std::string(d_.substr(vb, i - vb));
      ++i;
    }
  }
  static bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
  std::string_view d_;
  const std::string& name_;
};

// Base64 with whitespace allowed and '=' padding allowed between separately encoded parts.
std::string base64Decode(std::string_view s, const std::string& name, size_t maxOut) {
  auto val = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
  };
  std::string out;
  uint32_t acc = 0;
  int n = 0;
  for (char c : s) {
    if (c == ' ' || c == '\n' || c == '\r' || c == '\t') continue;
    if (c == '=') {  // ends the current quantum
      if (n == 2) out.push_back(char(acc >> 4));
      if (n == 3) {
        out.push_back(char(acc >> 10));
        out.push_back(char(acc >> 2));
      }
      n = 0;
      acc = 0;
      continue;
    }
    int v = val(c);
    if (v < 0) throw Error(name + ": invalid base64 character in binary data");
    acc = (acc << 6) | uint32_t(v);
    if (++n == 4) {
      out.push_back(char(acc >> 16));
      out.push_back(char(acc >> 8));
      out.push_back(char(acc));
      n = 0;
      acc = 0;
      if (out.size() > maxOut) break;
    }
  }
  if (n == 2) out.push_back(char(acc >> 4));
  if (n == 3) {
    out.push_back(char(acc >> 10));
    out.push_back(char(acc >> 2));
  }
  return out;
}

struct ArrayType {
  size_t width = 0;
  bool real = false, isUnsigned = false;
};
ArrayType arrayType(const std::string& t) {
  static const std::map<std::string, ArrayType> kTypes = {
      {"Int8", {1}},          {"UInt8", {1, false, true}},  {"Int16", {2}},       {"UInt16", {2, false, true}},
      {"Int32", {4}},         {"UInt32", {4, false, true}}, {"Int64", {8}},       {"UInt64", {8, false, true}},
      {"Float32", {4, true}}, {"Float64", {8, true}},       {"Char", {1}},        {"UChar", {1, false, true}}};
  auto it = kTypes.find(t);
  return it == kTypes.end() ? ArrayType{} : it->second;
}

class VtuReader {
 public:
  VtuReader(std::string_view d, const std::string& name) : d_(d), name_(name), xml_(d, name) {}
  Complex read(const ReadOptions& opt, ReadReport* rep);

 private:
  uint64_t readUInt(const char* p, size_t w) const {
    unsigned char b[8] = {};
    std::memcpy(b, p, w);
    if (bigEndian_)
      for (size_t i = 0; i < w / 2; ++i) std::swap(b[i], b[w - 1 - i]);
    uint64_t v = 0;
    for (size_t i = 0; i < w; ++i) v |= uint64_t(b[i]) << (8 * i);
    return v;
  }
  [[noreturn]] void fail(size_t at, const std::string& why) const { xml_.fail(at, why); }
  // The arrays of the one Piece, as numbers.
  struct Arrays {
    int64_t numPoints = -1, numCells = -1;
    std::vector<double> pts, conn, offs, types;
  };
  void findAppendedData();
  void readElements(Arrays& a);
  void readFileFormat(const Tag& t);
  void readDataArray(const Tag& t, size_t pos, const std::string& section, Arrays& a);
  CellSoup toSoup(const Arrays& a) const;
  // The raw bytes of a binary array, after its header (and decompression).
  std::string payload(std::string_view bytes, size_t at, const std::string& arrayName);
  std::vector<double> values(const Tag& t, size_t contentBegin, int64_t expected);

  std::string_view d_;
  std::string name_;
  Xml xml_;
  bool bigEndian_ = false, compressed_ = false;
  size_t headerWidth_ = 4;
  size_t appendedStart_ = std::string::npos;  // byte after '_'
  bool appendedBase64_ = false;
};

std::string VtuReader::payload(std::string_view bytes, size_t at, const std::string& arrayName) {
  auto need = [&](size_t n) {
    if (bytes.size() < n) fail(at, "binary data of " + arrayName + " ends early");
  };
  const size_t w = headerWidth_;
  if (!compressed_) {
    need(w);
    uint64_t n = readUInt(bytes.data(), w);
    need(w + n);
    return std::string(bytes.substr(w, size_t(n)));
  }
  need(3 * w);
  uint64_t blocks = readUInt(bytes.data(), w), blockSize = readUInt(bytes.data() + w, w),
           lastSize = readUInt(bytes.data() + 2 * w, w);
  if (blocks > (bytes.size() - 3 * w) / w) fail(at, arrayName + ": compressed header declares too many blocks");
  need(3 * w + size_t(blocks) * w);
  std::string out;
  size_t p = 3 * w + size_t(blocks) * w;
  for (uint64_t k = 0; k < blocks; ++k) {
    uint64_t c = readUInt(bytes.data() + 3 * w + k * w, w);
    if (c > bytes.size() - p) fail(at, arrayName + ": compressed block " + std::to_string(k) + " ends early");
    uint64_t want = (k + 1 == blocks && lastSize) ? lastSize : blockSize;
    if (want > kMaxInflatedBytes) fail(at, arrayName + ": compressed block too large");
    std::string part;
    try {
      part = inflateZlib(bytes.substr(p, size_t(c)), size_t(want));
    } catch (const Error& e) {
      fail(at, arrayName + ": " + e.what());
    }
    if (part.size() != want) fail(at, arrayName + ": a block inflates to " + std::to_string(part.size()) + " bytes, not " + std::to_string(want));
    out += part;
    p += size_t(c);
  }
  return out;
}

// An integer stored in a numeric array (read as double): the value when it is a whole number in
// [0, 2^53), else -1, which every caller rejects as out of range (no float-to-int overflow).
static int64_t asIndex(double x) {
  if (!(x >= 0 && x < 9007199254740992.0)) return -1;
  const int64_t i = int64_t(x);
  return double(i) == x ? i : -1;
}

std::vector<double> VtuReader::values(const Tag& t, size_t contentBegin, int64_t expected) {
  std::string arrayName = t.attr("Name", "Points");
  ArrayType at = arrayType(t.attr("type"));
  if (!at.width) fail(contentBegin, arrayName + ": data type '" + Lexer::excerpt(t.attr("type")) + "' is not supported");
  std::string format = t.attr("format", "ascii");
  checkCountFits(name_, arrayName, expected, d_.size(), format == "ascii" ? 2 : 1);
  std::vector<double> v;
  v.reserve(size_t(expected));
  if (format == "ascii") {
    size_t e = d_.find('<', contentBegin);
    Lexer lx(d_.substr(contentBegin, (e == std::string_view::npos ? d_.size() : e) - contentBegin), name_);
    while (!lx.atEnd() && int64_t(v.size()) < expected) v.push_back(lx.real("a number"));
  } else {
    std::string raw;
    if (format == "binary") {
      size_t e = d_.find('<', contentBegin);
      raw = payload(base64Decode(d_.substr(contentBegin, e - contentBegin), name_, kMaxInflatedBytes), contentBegin, arrayName);
    } else if (format == "appended") {
      if (appendedStart_ == std::string::npos) fail(contentBegin, arrayName + ": appended data but no AppendedData section");
      std::string offText = t.attr("offset", "0");
      Lexer lx(offText, name_);
      int64_t off = lx.integer("an offset");
      if (off < 0 || uint64_t(off) > d_.size() - appendedStart_) fail(contentBegin, arrayName + ": offset outside the file");
      std::string_view rest = d_.substr(appendedStart_ + size_t(off));
      if (appendedBase64_) raw = payload(base64Decode(rest.substr(0, rest.find('<')), name_, kMaxInflatedBytes), appendedStart_ + size_t(off), arrayName);
      else raw = payload(rest, appendedStart_ + size_t(off), arrayName);
    } else {
      fail(contentBegin, arrayName + ": format '" + Lexer::excerpt(format) + "' is not supported");
    }
    if (raw.size() / at.width < uint64_t(expected))
      fail(contentBegin, arrayName + " has " + std::to_string(raw.size() / at.width) + " values, expected " + std::to_string(expected));
    for (int64_t i = 0; i < expected; ++i) {
      const char* p = raw.data() + size_t(i) * at.width;
      uint64_t u = readUInt(p, at.width);
      double x;
      if (at.real) {
        if (at.width == 8) std::memcpy(&x, &u, 8);
        else {
          uint32_t u32 = uint32_t(u);
          float f;
          std::memcpy(&f, &u32, 4);
          x = f;
        }
      } else if (at.isUnsigned) {
        x = double(u);
      } else {
        int shift = int(64 - 8 * at.width);
        x = double(int64_t(u << shift) >> shift);
      }
      v.push_back(x);
    }
  }
  if (int64_t(v.size()) != expected)
    fail(contentBegin, arrayName + " has " + std::to_string(v.size()) + " values, expected " + std::to_string(expected));
  return v;
}

Complex VtuReader::read(const ReadOptions& opt, ReadReport* rep) {
  findAppendedData();
  Arrays a;
  readElements(a);
  CellSoup soup = toSoup(a);
  return assemble(soup, name_, opt, rep, std::string("vtu") + (compressed_ ? " zlib" : ""));
}

// Find the appended data first: arrays refer to it by offset.
void VtuReader::findAppendedData() {
  Tag t;
  if (size_t a = d_.find("<AppendedData"); a != std::string_view::npos) {
    size_t p = a;
    xml_.next(p, t);
    appendedBase64_ = t.attr("encoding") == "base64";
    size_t u = d_.find('_', p);
    if (u == std::string_view::npos) fail(a, "AppendedData without its '_' marker");
    appendedStart_ = u + 1;
  }
}

// The file's elements in order: VTKFile (format), Piece (counts), the Points and Cells arrays.
void VtuReader::readElements(Arrays& a) {
  size_t pos = 0;
  Tag t;
  std::string section;
  bool haveFile = false;
  int pieces = 0;
  while (xml_.next(pos, t)) {
    if (t.closing) {
      if (t.name == "Points" || t.name == "Cells") section.clear();
      continue;
    }
    if (t.name == "AppendedData") break;
    if (t.name == "VTKFile") {
      haveFile = true;
      readFileFormat(t);
    } else if (t.name == "Piece") {
      if (++pieces > 1) fail(t.end, "more than one Piece is not supported");
      std::string np = t.attr("NumberOfPoints", "x"), nc = t.attr("NumberOfCells", "x");
      Lexer lp(np, name_), lc(nc, name_);
      a.numPoints = lp.count("NumberOfPoints", int64_t(1) << 40);
      a.numCells = lc.count("NumberOfCells", int64_t(1) << 40);
    } else if (t.name == "Points" || t.name == "Cells") {
      section = t.name;
    } else if (t.name == "DataArray" && !section.empty()) {
      readDataArray(t, pos, section, a);
    }
  }
  if (!haveFile) fail(0, "no VTKFile element");
  if (a.numPoints < 0) fail(0, "no Piece element");
  if (int64_t(a.pts.size()) != 3 * a.numPoints) fail(0, "no Points array");
  if (int64_t(a.types.size()) != a.numCells || int64_t(a.offs.size()) != a.numCells)
    fail(0, "Cells needs offsets and types arrays");
}

// The VTKFile element: an unstructured grid; byte order, header width and compressor.
void VtuReader::readFileFormat(const Tag& t) {
  if (t.attr("type") != "UnstructuredGrid")
    fail(0, "VTK XML type '" + Lexer::excerpt(t.attr("type")) + "' is not supported (UnstructuredGrid)");
  bigEndian_ = t.attr("byte_order") == "BigEndian";
  headerWidth_ = t.attr("header_type", "UInt32") == "UInt64" ? 8 : 4;
  std::string comp = t.attr("compressor");
  compressed_ = !comp.empty();
  if (compressed_ && comp != "vtkZLibDataCompressor")
    fail(0, "compressor '" + Lexer::excerpt(comp) + "' is not supported (vtkZLibDataCompressor only)");
}

// A DataArray of the Points or Cells section (the element ends at `pos`).
void VtuReader::readDataArray(const Tag& t, size_t pos, const std::string& section, Arrays& a) {
  if (a.numPoints < 0) fail(t.end, "DataArray before Piece");
  std::string n = t.attr("Name");
  if (section == "Points") a.pts = values(t, t.end, 3 * a.numPoints);
  else if (n == "offsets") a.offs = values(t, t.end, a.numCells);
  else if (n == "types") a.types = values(t, t.end, a.numCells);
  else if (n == "connectivity") {
    if (a.offs.empty() && a.numCells > 0) {  // the size comes from the offsets: read them first
      size_t p2 = pos;
      Tag t2;
      while (xml_.next(p2, t2) && !(t2.closing && t2.name == "Cells"))
        if (t2.name == "DataArray" && t2.attr("Name") == "offsets") a.offs = values(t2, t2.end, a.numCells);
    }
    int64_t m = a.offs.empty() ? 0 : asIndex(a.offs.back());
    if (m < 0) fail(t.end, "the last offset is not a non-negative integer");
    a.conn = values(t, t.end, m);
  }
}

// The points and cells as a cell soup (voxels reordered as hexes).
CellSoup VtuReader::toSoup(const Arrays& a) const {
  CellSoup soup;
  soup.points.resize(size_t(a.numPoints));
  for (size_t i = 0; i < soup.points.size(); ++i) soup.points[i] = {a.pts[3 * i], a.pts[3 * i + 1], a.pts[3 * i + 2]};
  static constexpr int kVoxelToHex[8] = {0, 1, 3, 2, 4, 5, 7, 6};
  for (size_t c = 0; c < a.types.size(); ++c) {
    int64_t b = c ? asIndex(a.offs[c - 1]) : 0, e = asIndex(a.offs[c]);
    if (b < 0 || e < b || e > int64_t(a.conn.size()))
      fail(0, "offsets of cell " + std::to_string(c) + " are out of order or range");
    int64_t ty = asIndex(a.types[c]);
    CellKind k = kindOfVtkType(ty, e - b);
    if (!vtkPolyType(ty))
      checkNodeCount(name_, "cell " + std::to_string(c) + " (VTK type " + std::to_string(ty) + ")", k, e - b);
    if (k == CellKind::Hex) {
      std::array<int64_t, 8> v;
      for (int i = 0; i < 8; ++i) v[size_t(i)] = asIndex(a.conn[size_t(b + (ty == 11 ? kVoxelToHex[i] : i))]);
      soup.hexes.push_back(v);
      soup.hexCell.push_back(int64_t(c));
    }
    soup.count(k, int64_t(c), "VTK cell type " + std::to_string(ty));
  }
  return soup;
}

}  // namespace

Complex readVtu(std::string_view data, const std::string& name, const ReadOptions& opt, ReadReport* rep) {
  return VtuReader(data, name).read(opt, rep);
}

}  // namespace hexdual::io
