// The boundary of the 4-cube [0,1]^4 as a closed complex of 8 cubes, and the cubical flips of
// Bern, Eppstein & Erickson read off it: a flip replaces one part of the boundary (a set S of
// facets forming a 3-ball) by the complementary part S^c, which has the same quad boundary.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "complex/complex.hpp"

namespace hexdual {

// Vertex id = the 4 coordinate bits (x_i = bit i); hex id = facet 2*axis + side. Each facet's
// local x, y, z are its free axes in increasing order. Positions: a 4D -> 3D projection.
Complex makeFourCubeBoundary();

// The hexes of `hexes` with their gluings among themselves, keeping hex and vertex ids (other
// hexes become tombstones, so ids stay comparable with cx).
Complex subcomplex(const Complex& cx, const std::vector<HexId>& hexes);

struct FlipClass {
  std::string name;        // "1-7", "2-6", "3-5e", "3-5c", "4-4v", "4-4m" and inverses "7-1", ...
  std::string inverse;     // the name of the inverse flip
  uint8_t before = 0;      // facet mask of a representative "before" side S
  Counts interiorBefore, interiorAfter;  // interior (V,E,F,H) of S and of S^c
  bool geometric = false;  // realisable with convex hexes (BEE 2001); not computed here
  std::string description;
};

// Every split of the 8 facets into two 3-balls, up to the 384 symmetries of the 4-cube, as
// ordered (before, after) classes. Classes are named from their structure.
std::vector<FlipClass> enumerateFlipClasses();
// The class with this name; throws Error listing the names otherwise.
const FlipClass& flipClass(const std::string& name);
// Whether the facets of a mask form a 3-ball in the 4-cube boundary.
bool isBall(uint8_t mask);
std::vector<HexId> facetsOf(uint8_t mask);

}  // namespace hexdual
