// Dense numbering of live vertices and hexes, shared by the writers.
#pragma once
#include <vector>

#include "complex/complex.hpp"

namespace hexdual::io {

struct Dense {
  std::vector<VertexId> vertexIndex;  // per vertex id: dense index or -1
  std::vector<VertexId> vertices;     // dense index -> vertex id
  std::vector<HexId> hexIndex;        // per hex id: dense index or -1
  std::vector<HexId> hexes;           // dense index -> hex id
};

inline Dense denseNumbering(const Complex& cx) {
  Dense d;
  d.vertexIndex.assign(size_t(cx.vertexCapacity()), -1);
  d.hexIndex.assign(size_t(cx.hexCapacity()), -1);
  for (HexId h : cx.hexes()) {
    d.hexIndex[size_t(h)] = HexId(d.hexes.size());
    d.hexes.push_back(h);
  }
  for (VertexId v = 0; v < cx.vertexCapacity(); ++v)
    if (cx.isVertex(v)) {
      d.vertexIndex[size_t(v)] = VertexId(d.vertices.size());
      d.vertices.push_back(v);
    }
  return d;
}

}  // namespace hexdual::io
