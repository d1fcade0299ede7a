// Gmsh .msh 2.2 and 4.1, ASCII and binary (little-endian): nodes and first-order elements.
// Hexahedra (type 5) are read; points, lines, triangles and quadrangles are skipped and counted;
// tetrahedra, prisms and pyramids are refused (or dropped with hexesOnly); other types are refused.
#include <cstring>
#include <unordered_map>
#include <vector>

#include "io/cells.hpp"
#include "io/io.hpp"
#include "io/lexer.hpp"

namespace hexdual::io {
namespace {

CellKind gmshKind(int64_t type) {
  switch (type) {
    case 15: return CellKind::Vertex;
    case 1: return CellKind::Line;
    case 2: return CellKind::Triangle;
    case 3: return CellKind::Quad;
    case 4: return CellKind::Tet;
    case 5: return CellKind::Hex;
    case 6: return CellKind::Prism;
    case 7: return CellKind::Pyramid;
    default: return CellKind::Unsupported;
  }
}

class GmshReader {
 public:
  GmshReader(std::string_view d, const std::string& name) : d_(d), name_(name), lx_(d, name) {}
  Complex read(const ReadOptions& opt, ReadReport* rep);

 private:
  size_t left() const { return d_.size() - lx_.offset(); }
  template <class T>
  T bin(const char* what) {
    auto b = lx_.bytes(sizeof(T), what);
    T v;
    std::memcpy(&v, b.data(), sizeof(T));
    return v;
  }
  // A size_t-sized or int-sized integer (binary), or a token (ASCII).
  int64_t num(const char* what, bool isSize) {
    if (!binary_) return lx_.integer(what);
    if (!isSize) return bin<int32_t>(what);
    return sizeWidth_ == 8 ? int64_t(bin<uint64_t>(what) & 0x7FFFFFFFFFFFFFFFull) : int64_t(bin<uint32_t>(what));
  }
  double real(const char* what) { return binary_ ? bin<double>(what) : lx_.real(what); }
  void skipSection(std::string_view tag);
  void endSection(const char* end) {
    auto t = lx_.token();
    if (t != end) lx_.fail(std::string("expected ") + end + " but found '" + Lexer::excerpt(t) + "'");
  }
  void addNode(int64_t tag, Vec3 p) {
    if (tag < 1) lx_.fail("node tag " + std::to_string(tag) + " is not positive");
    if (!index_.emplace(tag, int64_t(soup_.points.size())).second) lx_.fail("node " + std::to_string(tag) + " appears twice");
    soup_.points.push_back(p);
  }
  void addElement(int64_t tag, int64_t type, const int64_t* nodes, int n);
  void nodes2();
  void elements2();
  void nodes4();
  void elements4();

  std::string_view d_;
  std::string name_;
  Lexer lx_;
  bool binary_ = false, v4_ = false;
  size_t sizeWidth_ = 8;
  CellSoup soup_;
  std::unordered_map<int64_t, int64_t> index_;
  std::vector<std::pair<int64_t, std::array<int64_t, 8>>> hexTags_;  // element tag, node tags
};

void GmshReader::addElement(int64_t tag, int64_t type, const int64_t* nodes, int n) {
  CellKind k = gmshKind(type);
  if (k == CellKind::Hex) {
    std::array<int64_t, 8> v;
    for (int i = 0; i < 8; ++i) v[size_t(i)] = nodes[i];
    hexTags_.push_back({tag, v});
  }
  (void)n;
  soup_.count(k, tag, "Gmsh element type " + std::to_string(type));
}

int nodesOfType(int64_t type) {
  CellKind k = gmshKind(type);
  return k == CellKind::Unsupported ? -1 : cornerCount(k);
}

void GmshReader::skipSection(std::string_view tag) {
  std::string end = "$End" + std::string(tag.substr(1));
  size_t p = d_.find(end, lx_.offset());
  if (p == std::string_view::npos) lx_.fail("section " + Lexer::excerpt(tag) + " has no " + Lexer::excerpt(end));
  lx_.bytes(p + end.size() - lx_.offset(), "a section");
}

void GmshReader::nodes2() {
  int64_t n = lx_.integer("number of nodes");
  checkCountFits(name_, "$Nodes", n, left(), binary_ ? 28 : 8);
  if (binary_) lx_.restOfLine();
  soup_.points.reserve(size_t(n));
  for (int64_t i = 0; i < n; ++i) {
    int64_t tag = binary_ ? bin<int32_t>("a node tag") : lx_.integer("a node tag");
    Vec3 p{real("a coordinate"), real("a coordinate"), real("a coordinate")};
    addNode(tag, p);
  }
  endSection("$EndNodes");
}

void GmshReader::elements2() {
  int64_t n = lx_.integer("number of elements");
  checkCountFits(name_, "$Elements", n, left(), binary_ ? 12 : 8);
  if (binary_) lx_.restOfLine();
  int64_t done = 0;
  int64_t nodes[8];
  while (done < n) {
    if (binary_) {  // blocks: type, count, tags; then per element: id, tags, nodes
      int64_t type = bin<int32_t>("an element type"), count = bin<int32_t>("an element count"), tags = bin<int32_t>("a tag count");
      int nn = nodesOfType(type);
      if (nn < 0) lx_.fail("Gmsh element type " + std::to_string(type) + " is not supported (first-order elements only)");
      if (count < 1 || count > n - done || tags < 0 || tags > 1000) lx_.fail("bad element block header");
      for (int64_t e = 0; e < count; ++e) {
        int64_t id = bin<int32_t>("an element id");
        for (int64_t t = 0; t < tags; ++t) bin<int32_t>("an element tag");
        for (int i = 0; i < nn; ++i) nodes[i] = bin<int32_t>("a node tag");
        addElement(id, type, nodes, nn);
      }
      done += count;
    } else {
      int64_t id = lx_.integer("an element id"), type = lx_.integer("an element type"), tags = lx_.integer("a tag count");
      int nn = nodesOfType(type);
      if (nn < 0) lx_.fail("Gmsh element type " + std::to_string(type) + " is not supported (first-order elements only)");
      if (tags < 0 || tags > 1000) lx_.fail("bad tag count " + std::to_string(tags));
      for (int64_t t = 0; t < tags; ++t) lx_.integer("an element tag");
      for (int i = 0; i < nn; ++i) nodes[i] = lx_.integer("a node tag");
      addElement(id, type, nodes, nn);
      ++done;
    }
  }
  endSection("$EndElements");
}

void GmshReader::nodes4() {
  if (binary_) lx_.restOfLine();
  int64_t blocks = num("number of entity blocks", true), n = num("number of nodes", true);
  num("min node tag", true);
  num("max node tag", true);
  checkCountFits(name_, "$Nodes", n, left(), binary_ ? 32 : 8);
  checkCountFits(name_, "$Nodes entity blocks", blocks, left(), binary_ ? 20 : 8);
  soup_.points.reserve(size_t(n));
  std::vector<int64_t> tags;
  for (int64_t b = 0; b < blocks; ++b) {
    num("entity dimension", false);
    num("entity tag", false);
    int64_t parametric = num("parametric flag", false), count = num("nodes in block", true);
    int64_t dim = 0;
    (void)dim;
    if (count < 0 || count > n - int64_t(soup_.points.size())) lx_.fail("node block holds more nodes than declared");
    tags.resize(size_t(count));
    for (auto& t : tags) t = num("a node tag", true);
    for (int64_t i = 0; i < count; ++i) {
      Vec3 p{real("a coordinate"), real("a coordinate"), real("a coordinate")};
      for (int64_t k = 0; k < (parametric ? 3 : 0); ++k) real("a parametric coordinate");  // at most 3; dimension unknown here
      addNode(tags[size_t(i)], p);
    }
  }
  endSection("$EndNodes");
}

void GmshReader::elements4() {
  if (binary_) lx_.restOfLine();
  int64_t blocks = num("number of entity blocks", true), n = num("number of elements", true);
  num("min element tag", true);
  num("max element tag", true);
  checkCountFits(name_, "$Elements", n, left(), binary_ ? 16 : 4);
  int64_t done = 0, nodes[8];
  for (int64_t b = 0; b < blocks; ++b) {
    num("entity dimension", false);
    num("entity tag", false);
    int64_t type = num("element type", false), count = num("elements in block", true);
    int nn = nodesOfType(type);
    if (nn < 0) lx_.fail("Gmsh element type " + std::to_string(type) + " is not supported (first-order elements only)");
    if (count < 0 || count > n - done) lx_.fail("element block holds more elements than declared");
    for (int64_t e = 0; e < count; ++e) {
      int64_t id = num("an element tag", true);
      for (int i = 0; i < nn; ++i) nodes[i] = num("a node tag", true);
      addElement(id, type, nodes, nn);
    }
    done += count;
  }
  endSection("$EndElements");
}

Complex GmshReader::read(const ReadOptions& opt, ReadReport* rep) {
  lx_.expectKeyword("$MeshFormat");
  std::string version(lx_.expectToken("a version"));
  int64_t fileType = lx_.integer("a file type"), dataSize = lx_.integer("a data size");
  if (version != "2.2" && version.substr(0, 2) != "4." ) lx_.fail("Gmsh format " + Lexer::excerpt(version) + " is not supported (2.2 or 4.1)");
  if (version.substr(0, 2) == "4." && version != "4.1") lx_.fail("Gmsh format " + Lexer::excerpt(version) + " is not supported (2.2 or 4.1)");
  v4_ = version == "4.1";
  binary_ = fileType == 1;
  if (dataSize != 4 && dataSize != 8) lx_.fail("data size " + std::to_string(dataSize) + " is not supported");
  sizeWidth_ = size_t(dataSize);
  if (binary_) {
    lx_.restOfLine();
    if (bin<int32_t>("the byte-order mark") != 1) lx_.fail("big-endian binary Gmsh files are not supported");
  }
  endSection("$EndMeshFormat");
  bool haveNodes = false, haveElements = false;
  while (!lx_.atEnd()) {
    auto tag = lx_.token();
    if (tag == "$Nodes") {
      v4_ ? nodes4() : nodes2();
      haveNodes = true;
    } else if (tag == "$Elements") {
      if (!haveNodes) lx_.fail("$Elements before $Nodes");
      v4_ ? elements4() : elements2();
      haveElements = true;
    } else if (!tag.empty() && tag[0] == '$') {
      skipSection(tag);
    } else {
      lx_.fail("expected a section but found '" + Lexer::excerpt(tag) + "'");
    }
  }
  if (!haveNodes) lx_.fail("no $Nodes section");
  if (!haveElements) lx_.fail("no $Elements section");
  soup_.pointBase = 0;
  for (auto& [tag, nodes] : hexTags_) {
    std::array<int64_t, 8> v;
    for (int i = 0; i < 8; ++i) {
      auto it = index_.find(nodes[size_t(i)]);
      if (it == index_.end())
        throw Error(name_ + ": element " + std::to_string(tag) + " uses node " + std::to_string(nodes[size_t(i)]) +
                    ", which $Nodes does not define");
      v[size_t(i)] = it->second;
    }
    soup_.hexes.push_back(v);
    soup_.hexCell.push_back(tag);
  }
  return assemble(soup_, name_, opt, rep, "gmsh " + version + (binary_ ? " binary" : " ascii"));
}

}  // namespace

Complex readGmsh(std::string_view data, const std::string& name, const ReadOptions& opt, ReadReport* rep) {
  return GmshReader(data, name).read(opt, rep);
}

}  // namespace hexdual::io
