// The singularity graph of a hex mesh (what HexaLab shows first): the irregular edges, the
// irregular vertices where they meet, branch or end, and the singular curves between those.
// Edges are the complex's edge classes (walked across gluings), never vertex pairs, so the doubled
// edges of a chord push are two edges, each with its own valence.
#pragma once
#include <array>
#include <map>
#include <vector>

#include "complex/complex.hpp"

namespace hexdual {

// An irregular edge: interior with valence (hexes around it) != 4, or boundary with valence != 2
// (on a smooth boundary 2 is regular; a CAD-like boundary's feature edges have 1 or 3).
struct SingularEdge {
  EdgeRef ref;                      // its smallest (hex, local edge) incidence
  std::array<VertexId, 2> vertices;  // its two ends
  int valence = 0;
  bool boundary = false;
  int curve = -1;  // index into SingularityGraph::curves
};

// A vertex where singular edges meet other than as one curve passing through: one singular edge
// (a curve ends), three or more (curves branch), or two of different kinds (boundary vs interior,
// or different valences).
struct SingularVertex {
  VertexId vertex = -1;
  bool boundary = false;
  int degree = 0;  // singular edges at it
};

// A maximal chain of singular edges of one kind (boundary flag and valence), joined at vertices
// where exactly two singular edges of that kind meet. `edges` in walk order; a closed curve has
// no ends.
struct SingularCurve {
  std::vector<int> edges;  // indices into SingularityGraph::edges
  int valence = 0;
  bool boundary = false;
  bool closed = false;
  std::array<VertexId, 2> ends{-1, -1};
};

struct SingularityCounts {
  std::map<int, int64_t> interiorByValence, boundaryByValence;  // irregular edges by valence
  int64_t interiorEdges = 0, boundaryEdges = 0, vertices = 0, boundaryVertices = 0, curves = 0;
};

struct SingularityGraph {
  std::vector<SingularEdge> edges;  // by smallest incidence
  std::vector<SingularVertex> vertices;  // by vertex id
  std::vector<SingularCurve> curves;  // by smallest edge index
  SingularityCounts counts;
};

// The whole graph (linear in the mesh: one pass over the edge classes).
SingularityGraph singularityGraph(const Complex& cx);

}  // namespace hexdual
