// Vertices whose link is not a 2-sphere (interior) or a disk (boundary): real meshes have them
// (two parts touching at a point). Such a complex can be inspected, but no operation may touch them.
#pragma once
#include <string>
#include <vector>

#include "complex/complex.hpp"

namespace hexdual {

struct LinkIssue {
  VertexId vertex = -1;
  std::string why;  // e.g. "its link has 2 components"
};

// Every vertex whose link is neither a sphere nor a disk, ascending.
std::vector<LinkIssue> vertexLinkIssues(const Complex& cx);
// "vertex 12 at (0, 1, 2) in hexes 3, 4: its link has 2 components"
std::string describeLinkIssue(const Complex& cx, const LinkIssue& issue);
// Throws Error("op: touches non-manifold vertex ...") when one of the hexes uses a vertex of
// cx.nonManifoldVertices().
void requireManifoldVertices(const Complex& cx, const std::vector<HexId>& hexes, const std::string& op);

}  // namespace hexdual
