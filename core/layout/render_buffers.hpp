// Triangle and line buffers for drawing hexes in 3D. Each hex is shrunk and moved to its own dual
// point (layout/dual_points.hpp), so coincident hexes (a pillow pair, a blind chord of 2) draw
// apart; degenerate hexes are shrunk further so they fit in the gap between their neighbours.
#pragma once
#include <cstdint>
#include <vector>

#include "complex/complex.hpp"

namespace hexdual {

struct RenderBuffers {
  std::vector<float> positions;      // 3 per vertex; 4 vertices per hex face, corners in kFaceCorners order
  std::vector<float> normals;        // 3 per vertex, pointing away from the hex centre
  std::vector<uint32_t> indices;     // 3 per triangle; 2 triangles per hex face (face k: triangles 2k, 2k+1)
  std::vector<int32_t> triangleHex;  // hex id per triangle
  std::vector<uint8_t> triangleFace; // local face (0..5) per triangle
  std::vector<float> edgePositions;  // with edges: 3 per vertex, 2 vertices per hex edge
  std::vector<int32_t> edgeHex;      // hex id per edge segment
  std::vector<uint8_t> edgeLocal;    // local edge (0..11) per segment
};

// Which hexes to draw (all by default). With `shell`, only those a viewer can see: a face on the
// boundary or facing a hidden hex, so a 100k-hex grid draws its outer layer, not 1.2 M triangles.
// `hidden[h] != 0` hides hex h (cut away by a slice); `always` are drawn regardless (a step's
// created hexes, deep inside).
struct DrawnHexes {
  bool shell = false;
  std::vector<uint8_t> hidden;
  std::vector<HexId> always;
};

// The live hexes `drawn` selects, in increasing id order.
std::vector<HexId> drawnHexes(const Complex& cx, const DrawnHexes& drawn);

// shrink in [0,1): 0 draws hexes at full size. `edges` also fills the edge line buffers.
RenderBuffers buildRenderBuffers(const Complex& cx, double shrink, bool edges = false, const DrawnHexes& drawn = {});

}  // namespace hexdual
