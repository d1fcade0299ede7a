// Sheet dicing: split a sheet into k parallel sheets, the refinement Cubit uses. Every edge of the
// sheet's class is cut into k and every hex of the sheet into k layers along it. Dually: k-1 new
// sheets beside the old one; every chord crossing the sheet gains k-1 hexes per crossing, every
// chord lying in it gets k-1 parallel copies. Cost: the sheet times k.
#include <algorithm>

#include "complex/id_map.hpp"
#include "ops/sheet_support.hpp"
#include "ops/support.hpp"

namespace hexdual {
using namespace tables;
using namespace ops;

namespace {

// Per edge of the class, its vertices by level: 0 and k are its ends (level 0 on the sheet's
// lower side), 1..k-1 new. Per sheet hex, which edge each of its 4 edges across the sheet is.
struct Levels {
  int k = 2;
  std::vector<VertexId> vertex;                   // class edge e's vertex at level L: vertex[(k + 1) e + L]
  IdMap<int32_t> place;                           // sheet hex -> its place in the sheet's (sorted) hexes
  std::vector<std::array<int32_t, 4>> edgeOf;     // per place: class edge of local edge 4a+i
  IdMap<int8_t> up;
  bool selfTouching = false;  // a vertex ends two edges of the class (then no layer extraction undoes the dicing)
  size_t edges() const { return vertex.size() / size_t(k + 1); }
  VertexId& at(size_t e, int L) { return vertex[size_t(k + 1) * e + size_t(L)]; }
  // The vertex at global level L on the edge through corner c of sheet hex h.
  VertexId at(const SheetHexes& s, HexId h, int c, int L) const {
    const int a = s.axisOf(h);
    const int i = edgesOfCorner(c)[size_t(a)] - 4 * a;
    return vertex[size_t(k + 1) * size_t(edgeOf[size_t(place.at(h))][size_t(i)]) + size_t(L)];
  }
  // Global level of corner c of layer j of sheet hex h (its local axis may point down).
  int level(const SheetHexes& s, HexId h, int c, int j) const {
    const int b = cornerBit(c, s.axisOf(h));
    return up.at(h) > 0 ? j + b : j + 1 - b;
  }
  // The layer holding face f of h when f is normal to the sheet's axis there.
  int layerOfFace(HexId h, int f) const { return ((f & 1) == 1) == (up.at(h) > 0) ? k - 1 : 0; }
};

// Finds the class edges (by their smallest incidence, so doubled edges stay apart) and lists each
// one's ends from the lower side up; new vertices are created later.
Levels levelsOf(const Complex& cx, const SheetHexes& sheet, int k, IdMap<int8_t> up) {
  Levels lv;
  lv.k = k;
  lv.up = std::move(up);
  lv.place.reserve(sheet.hexes.size());
  lv.edgeOf.reserve(sheet.hexes.size());
  // Class edge by its canonical incidence, keyed hex * 16 + edge (below 2^30: at most 2^26 hexes).
  static_assert(Complex::kMaxHexes * 16 <= int64_t(1) << 31);
  IdMap<int32_t> index(2 * sheet.hexes.size());
  IdMap<int32_t> endOf(2 * sheet.hexes.size());
  auto end = [&](VertexId v, int32_t e) {
    auto [at, fresh] = endOf.emplace(v, e);
    lv.selfTouching |= !fresh && *at != e;
  };
  for (HexId h : sheet.hexes) {
    lv.place.emplace(h, int32_t(lv.edgeOf.size()));
    const int a = sheet.axisOf(h);
    std::array<int32_t, 4> ids{};
    for (int i = 0; i < 4; ++i) {
      const EdgeRef key = cx.canonical(EdgeRef{h, 4 * a + i});
      auto [at, fresh] = index.emplace(key.hex * 16 + key.edge, int32_t(lv.edges()));
      if (fresh) {
        VertexId low = cx.vertex(h, kEdgeCorners[size_t(4 * a + i)][0]), high = cx.vertex(h, kEdgeCorners[size_t(4 * a + i)][1]);
        if (lv.up.at(h) < 0) std::swap(low, high);
        end(low, int32_t(lv.edges()));
        end(high, int32_t(lv.edges()));
        lv.vertex.push_back(low);
        lv.vertex.insert(lv.vertex.end(), size_t(k) - 1, -1);
        lv.vertex.push_back(high);
      }
      ids[size_t(i)] = *at;
    }
    lv.edgeOf.push_back(ids);
  }
  return lv;
}

void createLevelVertices(Complex& cx, Levels& lv, OpResult& res) {
  for (size_t e = 0; e < lv.edges(); ++e) {
    const Vec3 p = cx.position(lv.at(e, 0)), q = cx.position(lv.at(e, lv.k));
    for (int L = 1; L < lv.k; ++L) {
      lv.at(e, L) = cx.addVertex(p + (double(L) / lv.k) * (q - p));
      res.createdVertices.push_back(lv.at(e, L));
    }
  }
}

// The vertices of layer j of sheet hex h.
std::array<VertexId, 8> layerVertices(const SheetHexes& s, const Levels& lv, HexId h, int j) {
  std::array<VertexId, 8> v;
  for (int c = 0; c < 8; ++c) v[size_t(c)] = lv.at(s, h, c, lv.level(s, h, c, j));
  return v;
}

// Glues each hex's layers to each other, and re-glues every old gluing of a sheet hex: a side quad (parallel to the
// sheet's axis) of layer j to layer j across it; a face across the sheet, on its top or bottom
// layer, to what it was glued to (or to that hex's top or bottom layer).
// `old`: per place, the gluings of its hex before the edit; `layers`: per place, its new hexes
// (layers 1..k-1, k-1 per place).
void glueLayers(Complex& cx, const SheetHexes& s, const Levels& lv, const std::vector<std::array<Gluing, 6>>& old,
                const std::vector<HexId>& layers) {
  auto layerHex = [&](HexId h, int j) {
    return j == 0 ? h : layers[size_t(lv.k - 1) * size_t(lv.place.at(h)) + size_t(j - 1)];
  };
  for (size_t i = 0; i < s.hexes.size(); ++i) {  // i: the hex's place (Levels::place)
    const HexId h = s.hexes[i];
    const int a = s.axisOf(h);
    const int upper = lv.up.at(h) > 0 ? 2 * a + 1 : 2 * a;  // the face of a layer toward the next one
    for (int j = 0; j + 1 < lv.k; ++j) glueByVertices(cx, layerHex(h, j), upper, layerHex(h, j + 1), oppositeFace(upper));
    for (int f = 0; f < 6; ++f) {
      const Gluing g = old[i][size_t(f)];
      const bool across = axisOfFace(f) == a, inSheet = !g.boundary() && s.axisOf(g.hex) >= 0;
      if (g.boundary() || (inSheet && QuadSide{g.hex, g.face} < QuadSide{h, f})) continue;  // each gluing once
      if (!across) {
        for (int j = 0; j < lv.k; ++j) cx.glue(layerHex(h, j), f, layerHex(g.hex, j), g.face, g.orient);
        continue;
      }
      const HexId other = inSheet ? layerHex(g.hex, lv.layerOfFace(g.hex, g.face)) : g.hex;
      cx.glue(layerHex(h, lv.layerOfFace(h, f)), f, other, g.face, g.orient);
    }
  }
}

}  // namespace

OpResult sheetDice(Complex& cx, EdgeRef e, Count count) {
  const OpKind kind = OpKind::SheetDice;
  const std::string op = opName(kind);
  const int k = count.value;
  if (k < 2 || k > 64) refuse(op, "bad-count", "a sheet is diced into 2 to 64 sheets, not " + std::to_string(k));
  const SheetHexes sheet = sheetThrough(cx, e, op);
  requireManifold(cx, sheet.hexes, op);
  auto up = sheetUp(cx, sheet);
  if (up.empty()) refuse(op, "one-sided", "the sheet through " + entityName(e) + " is one-sided: its layers would not stay apart");
  Levels lv = levelsOf(cx, sheet, k, std::move(up));
  std::vector<std::array<Gluing, 6>> old(sheet.hexes.size());  // per place (Levels::place)
  size_t gluings = 0, sideGluings = 0;  // counted twice (a gluing inside the sheet: once from each side)
  for (size_t i = 0; i < sheet.hexes.size(); ++i)
    for (int f = 0; f < 6; ++f) {
      const HexId h = sheet.hexes[i];
      const Gluing g = old[i][size_t(f)] = cx.gluing(h, f);
      if (g.boundary()) continue;
      const size_t w = sheet.axisOf(g.hex) >= 0 ? 1 : 2;
      gluings += w;
      if (axisOfFace(f) != sheet.axisOf(h)) sideGluings += w;
    }
  // Its edits, at most: the unglues and glues (a side gluing once per layer, the layers to each
  // other), the new vertices and hexes, the old hexes' corners.
  const size_t n = sheet.hexes.size(), layersBetween = size_t(k - 1);
  const size_t edits = gluings / 2 + (gluings - sideGluings) / 2 + size_t(k) * sideGluings / 2 + layersBetween * n +
                       layersBetween * lv.edges() + 8 * n + layersBetween * n;

  Transaction tx(cx, edits);
  OpResult res;
  res.op = kind;
  for (HexId h : sheet.hexes)
    for (int f = 0; f < 6; ++f) cx.unglue(h, f);
  createLevelVertices(cx, lv, res);
  std::vector<HexId> layers;  // per place, layers 1..k-1
  layers.reserve(layersBetween * n);
  for (HexId h : sheet.hexes) {  // the old hex becomes layer 0; layers 1..k-1 are new
    const auto v0 = layerVertices(sheet, lv, h, 0);
    for (int c = 0; c < 8; ++c) cx.setCorner(h, c, v0[size_t(c)]);
    for (int j = 1; j < k; ++j) {
      layers.push_back(cx.addHex(layerVertices(sheet, lv, h, j)));
      res.createdHexes.push_back(layers.back());
    }
  }
  glueLayers(cx, sheet, lv, old, layers);
  std::vector<HexId> touched = withNeighbours(cx, sheet.hexes);
  touched.insert(touched.end(), res.createdHexes.begin(), res.createdHexes.end());
  if (lv.selfTouching) {
    res.noInverse = "the sheet touches itself (a vertex ends two of its edges): extracting a new layer would merge three "
                    "vertices";
  } else if (k == 2) {
    res.inverse = makeStep(OpKind::SheetExtract, EdgeRef{res.createdHexes[0], 4 * sheet.axisOf(sheet.hexes[0])});
  } else {
    res.noInverse = "the inverse is " + std::to_string(k - 1) + " sheet extractions, one per new layer (first: sheet-extract h" +
                    std::to_string(res.createdHexes[0]) + "e" + std::to_string(4 * sheet.axisOf(sheet.hexes[0])) + ")";
  }
  commitOrRefuse(tx, res, touched, op);
  return res;
}

}  // namespace hexdual
