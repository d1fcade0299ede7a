// Triangle buffers for drawing hexes in 3D, each hex shrunk toward its own centre so that
// coincident hexes (a pillow pair) and neighbours stay apart.
#pragma once
#include <cstdint>
#include <vector>

#include "complex/complex.hpp"

namespace hexdual {

struct RenderBuffers {
  std::vector<float> positions;    // 3 per vertex; 4 vertices per hex face
  std::vector<float> normals;      // 3 per vertex, pointing away from the hex centre
  std::vector<uint32_t> indices;   // 3 per triangle; 2 triangles per hex face
  std::vector<int32_t> triangleHex;  // hex id per triangle
};

// shrink in [0,1): 0 draws hexes at full size.
RenderBuffers buildRenderBuffers(const Complex& cx, double shrink);

}  // namespace hexdual
