#include "io/cells.hpp"

#include "complex/builders.hpp"

namespace hexdual::io {

void CellSoup::count(CellKind k, int64_t cell, const std::string& what) {
  ++kindCount[size_t(k)];
  if (k == CellKind::Unsupported && firstUnsupported < 0) {
    firstUnsupported = cell;
    unsupportedWhat = what;
  }
}

int cornerCount(CellKind k) {
  static constexpr int kCorners[] = {1, 2, 3, 4, 4, 8, 6, 5, 0};
  return kCorners[size_t(k)];
}

const char* kindName(CellKind k) {
  static constexpr const char* kNames[] = {"vertex", "line", "triangle", "quadrilateral", "tetrahedron",
                                           "hexahedron", "prism", "pyramid", "unsupported cell"};
  return kNames[size_t(k)];
}

void checkNodeCount(const std::string& name, const std::string& cell, CellKind k, int64_t listed) {
  if (k == CellKind::Unsupported || listed == cornerCount(k)) return;
  throw Error(name + ": " + cell + " is typed as a " + kindName(k) + " (" + std::to_string(cornerCount(k)) +
              " vertices) but lists " + std::to_string(listed) + " vertices; the file is mislabelled");
}

void checkCountFits(const std::string& name, const std::string& what, int64_t count, size_t bytesLeft,
                    size_t bytesPerElement) {
  if (count < 0 || uint64_t(count) > bytesLeft / bytesPerElement)
    throw Error(name + ": " + what + " declares " + std::to_string(count) + " entries but only " +
                std::to_string(bytesLeft) + " bytes remain (at least " + std::to_string(bytesPerElement) +
                " per entry)");
}

namespace {
std::string plural(int64_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}
}  // namespace

Complex assemble(CellSoup& soup, const std::string& name, const ReadOptions& opt, ReadReport* rep,
                 const std::string& format) {
  auto kc = [&](CellKind k) { return soup.kindCount[size_t(k)]; };
  if (soup.firstUnsupported >= 0)
    throw Error(name + ": cell " + std::to_string(soup.firstUnsupported) + " is a " + soup.unsupportedWhat +
                ", which hexdual does not read (" + std::to_string(kc(CellKind::Unsupported)) +
                " such cells); only hexahedra, and lower-dimensional cells that are skipped");
  int64_t volume = kc(CellKind::Tet) + kc(CellKind::Prism) + kc(CellKind::Pyramid);
  if (volume > 0 && !opt.hexesOnly)
    throw Error(name + ": the file holds " + plural(kc(CellKind::Tet), "tetrahedron", "tetrahedra") + ", " +
                plural(kc(CellKind::Prism), "prism", "prisms") + " and " +
                plural(kc(CellKind::Pyramid), "pyramid", "pyramids") + " besides " +
                plural(int64_t(soup.hexes.size()), "hexahedron", "hexahedra") +
                "; hexdual reads hex meshes (--hexes-only, or { hexesOnly: true } in the package, reads the hex part)");
  if (soup.hexes.empty()) throw Error(name + ": the file holds no hexahedra");
  // Points no hex uses are dropped (a Complex has no isolated vertices) and counted.
  const int64_t np = int64_t(soup.points.size());
  std::vector<VertexId> newIndex(soup.points.size(), -1);
  for (size_t h = 0; h < soup.hexes.size(); ++h)
    for (int64_t v : soup.hexes[h]) {
      if (v < 0 || v >= np)
        throw Error(name + ": cell " + std::to_string(soup.hexCell[h]) + " uses vertex " +
                    std::to_string(v + soup.pointBase) + ", out of range (" + std::to_string(np) + " points" +
                    (soup.pointBase ? ", numbered from 1)" : ")"));
      newIndex[size_t(v)] = 0;
    }
  std::vector<Vec3> points;
  for (size_t v = 0; v < soup.points.size(); ++v)
    if (newIndex[v] == 0) {
      newIndex[v] = VertexId(points.size());
      points.push_back(soup.points[v]);
    }
  std::vector<std::array<VertexId, 8>> hexes(soup.hexes.size());
  for (size_t h = 0; h < hexes.size(); ++h)
    for (int c = 0; c < 8; ++c) hexes[h][size_t(c)] = newIndex[size_t(soup.hexes[h][size_t(c)])];
  Complex cx;
  try {
    cx = fromConnectivity(points, hexes, /*allowNonManifoldVertices=*/true);
  } catch (const Error& e) {
    throw Error(name + ": " + e.what());
  }
  if (rep) {
    rep->format = format;
    rep->points = np;
    rep->unusedVertices = np - int64_t(points.size());
    rep->vertexCells = kc(CellKind::Vertex);
    rep->lineCells = kc(CellKind::Line);
    rep->triangleCells = kc(CellKind::Triangle);
    rep->quadCells = kc(CellKind::Quad);
    rep->tetrahedra = kc(CellKind::Tet);
    rep->prisms = kc(CellKind::Prism);
    rep->pyramids = kc(CellKind::Pyramid);
    rep->nonManifoldVertices = cx.nonManifoldVertices();
  }
  return cx;
}

}  // namespace hexdual::io

#include <algorithm>

namespace hexdual::io {

void requireRepresentableByVertices(const Complex& cx, const char* format) {
  struct Side {
    std::array<VertexId, 4> key;
    QuadSide side;
    bool operator<(const Side& o) const { return key != o.key ? key < o.key : side < o.side; }
  };
  std::vector<Side> sides;
  sides.reserve(size_t(cx.numHexes()) * 6);
  for (HexId h : cx.hexes())
    for (int f = 0; f < 6; ++f) {
      Side s{{}, {h, f}};
      for (int p = 0; p < 4; ++p) s.key[size_t(p)] = cx.vertex(h, tables::kFaceCorners[size_t(f)][size_t(p)]);
      std::sort(s.key.begin(), s.key.end());
      sides.push_back(s);
    }
  std::sort(sides.begin(), sides.end());
  for (size_t i = 0; i < sides.size();) {
    size_t j = i;
    while (j < sides.size() && sides[j].key == sides[i].key) ++j;
    bool ok = j - i == 1 || (j - i == 2 && cx.gluing(sides[i].side).hex == sides[i + 1].side.hex &&
                             cx.gluing(sides[i].side).face == sides[i + 1].side.face);
    if (!ok)
      throw Error(std::string(format) + " cannot represent this complex: hex " + std::to_string(sides[i].side.hex) +
                  " face " + std::to_string(sides[i].side.face) + " has the same 4 vertices as " +
                  std::to_string(j - i - 1) +
                  " other quad side(s) (e.g. a pillow); write it as .hxd, which stores gluings");
    i = j;
  }
}

// VTK cell type numbers (legacy and XML alike).
CellKind kindOfVtkType(int64_t t, int64_t nodes) {
  switch (t) {
    case 1: case 2: return CellKind::Vertex;
    case 3: case 4: return CellKind::Line;
    case 5: case 6: return CellKind::Triangle;
    case 7: return nodes == 4 ? CellKind::Quad : CellKind::Triangle;  // polygon
    case 8: case 9: return CellKind::Quad;
    case 10: return CellKind::Tet;
    case 11: case 12: return CellKind::Hex;
    case 13: return CellKind::Prism;
    case 14: return CellKind::Pyramid;
    default: return CellKind::Unsupported;
  }
}
bool vtkPolyType(int64_t t) { return t == 2 || t == 4 || t == 6 || t == 7; }

}  // namespace hexdual::io
