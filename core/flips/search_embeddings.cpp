// The host meshes a decomposition is replayed in (flipEmbeddings): the closed 4-cube boundary as
// is and changed, places in grids and O-grids, and for the triple-chord push the 8 hexes around a
// vertex of other grids.
#include "flips/search_parts.hpp"

#include <algorithm>

#include "complex/builders.hpp"
#include "flips/flip.hpp"
#include "flips/fourcube.hpp"

namespace hexdual {
using namespace tables;
using namespace flipsearch;

// Places for the triple-chord push: the 8 hexes around an interior vertex of other grids, an
// O-grid, and the problem's grid with its host pillowed (the problem's own place touches the mesh
// boundary, and so do some of these).
std::vector<Embedding> tripleChordPushEmbeddings() {
  auto block = [](auto id, int i0, int j0, int k0) {
    std::vector<HexId> out;
    for (int k = 0; k < 2; ++k)
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) out.push_back(id(i0 + i, j0 + j, k0 + k));
    return out;
  };
  auto gridId = [](int n) { return [n](int i, int j, int k) { return HexId(i + n * (j + n * k)); }; };
  auto rid = [](int t, int s, int k) { return HexId((k * 8 + t) * 3 + s); };
  std::vector<Embedding> out;
  Complex pillowed = makeGrid(3, 3, 3);
  pillow(pillowed, {26, 0});
  out.push_back({"3x3x3 grid, host pillowed at h26f0", pillowed, block(gridId(3), 0, 0, 0)});
  out.push_back({"4x4x4 grid at vertex (2,2,2)", makeGrid(4, 4, 4), block(gridId(4), 1, 1, 1)});
  out.push_back({"5x5x5 grid at vertex (2,3,2)", makeGrid(5, 5, 5), block(gridId(5), 1, 2, 1)});
  out.push_back({"8x3x3 O-grid at h" + std::to_string(rid(2, 0, 0)), makeRing(8, 3, 3), block(rid, 2, 0, 0)});
  return out;
}

std::vector<Embedding> flipEmbeddings(const std::string& name) {
  if (name == "tripleChordPush") return tripleChordPushEmbeddings();
  const FlipClass& fc = flipClass(name);
  std::vector<Embedding> out;
  auto before = facetsOf(fc.before), hostFacets = facetsOf(uint8_t(~fc.before));
  Complex c = makeFourCubeBoundary();
  out.push_back({"4-cube boundary", c, before});
  // A quad between two host facets (every pair of adjacent facets shares exactly one quad).
  for (HexId a : hostFacets)
    for (int f = 0; f < 6; ++f) {
      Gluing g = c.gluing(a, f);
      if (!g.boundary() && std::find(hostFacets.begin(), hostFacets.end(), g.hex) != hostFacets.end()) {
        Complex p = c;
        pillow(p, {a, f});
        out.push_back({"4-cube boundary, host pillowed at h" + std::to_string(a) + "f" + std::to_string(f), p, before});
        Complex q = c;
        hexPush(q, {a, f});
        out.push_back(
            {"4-cube boundary, host hex-pushed at h" + std::to_string(a) + "f" + std::to_string(f), q, before});
        goto grids;
      }
    }
grids:
  if (name == "7-1" || name == "6-2" || name == "5-3c") {
    // The before side of an inverse flip is what the forward flip creates: flip grids and rings.
    for (const Embedding& e : flipEmbeddings(fc.inverse)) {
      if (e.name.rfind("4-cube", 0) == 0) continue;
      Embedding m{e.name + " after " + fc.inverse, e.mesh, {}};
      m.before = flip(m.mesh, fc.inverse, e.before).createdHexes;
      out.push_back(m);
    }
  }
  if (name == "1-7" || name == "2-6" || name == "3-5c") {
    Complex g = makeGrid(5, 5, 5), r = makeRing(8, 3, 3);
    auto gid = [](int i, int j, int k) { return HexId(i + 5 * (j + 5 * k)); };
    auto rid = [](int t, int s, int k) { return HexId((k * 8 + t) * 3 + s); };
    size_t n = facetsOf(fc.before).size();
    std::vector<std::vector<HexId>> gridPlaces, ringPlaces;
    // Interior places: near the mesh boundary some atomic steps are refused by design (an unpillow
    // of a pillow on the boundary, a ring collapse merging boundary vertices).
    if (n == 1) gridPlaces = {{gid(2, 2, 2)}, {gid(1, 2, 3)}}, ringPlaces = {{rid(2, 1, 1)}};
    if (n == 2)
      gridPlaces = {{gid(2, 2, 2), gid(3, 2, 2)}, {gid(1, 1, 2), gid(1, 1, 3)}},
      ringPlaces = {{rid(2, 1, 1), rid(3, 1, 1)}};
    // (3-5c's decomposition uses a ring collapse, which never merges boundary vertices: interior places.)
    if (n == 3)
      gridPlaces = {{gid(2, 2, 1), gid(2, 2, 2), gid(2, 2, 3)}, {gid(1, 2, 2), gid(2, 2, 2), gid(3, 2, 2)}},
      ringPlaces = {{rid(2, 1, 1), rid(3, 1, 1), rid(4, 1, 1)}};
    for (auto& pl : gridPlaces) out.push_back({"5x5x5 grid at h" + std::to_string(pl[0]), g, pl});
    for (auto& pl : ringPlaces) out.push_back({"8x3x3 O-grid at h" + std::to_string(pl[0]), r, pl});
  }
  return out;
}

}  // namespace hexdual
