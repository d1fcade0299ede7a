#include "geometry/degenerate.hpp"

namespace hexdual {

bool degenerateByConstruction(const Complex& cx, HexId h) {
  for (int e = 0; e < 12; ++e) {
    EdgeRef cur{h, e};
    int exitFace = tables::facesOfEdge(e)[0];
    for (int steps = 1; steps <= 2; ++steps) {  // back at (h, e) within two steps: valence <= 2
      if (!cx.stepAroundEdge(cur, exitFace)) break;
      if (cur == EdgeRef{h, e}) return true;
    }
  }
  return false;
}

}  // namespace hexdual
