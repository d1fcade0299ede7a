// Helpers shared by the sheet operations (sheet_extract, sheet_insert, column_collapse,
// sheet_dice); not part of the public API. Everything here costs the sheet or chord it is given
// (hash maps keyed by hex or vertex id), never a pass over the mesh.
#pragma once
#include <functional>
#include <span>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "complex/complex.hpp"
#include "ops/sheet_ops.hpp"
#include "complex/id_map.hpp"
#include "ops/support.hpp"

namespace hexdual::ops {

// Throws Error("<op>: <rule>: <details>"): every refusal of a sheet operation names its rule.
[[noreturn]] void refuse(const std::string& op, const char* rule, const std::string& details);

// Refuses (no-such-entity) an edge whose hex or local index does not exist.
void requireEdge(const Complex& cx, EdgeRef e, const std::string& op);
// Refuses (non-manifold-vertex) when a hex uses a vertex the input file left non-manifold.
void requireManifold(const Complex& cx, const std::vector<HexId>& hexes, const std::string& op);
// Commits, or refuses naming the broken invariant: rule non-manifold-result for a vertex link,
// invalid-result for any other.
void commitOrRefuse(Transaction& tx, OpResult& r, const std::vector<HexId>& touched, const std::string& op,
                    bool validByConstruction = false);

// A sheet: its hexes (ascending) and, per hex, the local axis crossed by its edge class there.
struct SheetHexes {
  std::vector<HexId> hexes;
  IdMap<int8_t> axis;
  int axisOf(HexId h) const { return axis.get(h, -1); }
};
// The sheet through edge e: its slot (e.hex, axis of e) flooded across the quads parallel to the
// slot's axis (TK03 §1.1). Refuses no-such-entity and self-intersecting (a hex met with two axes).
SheetHexes sheetThrough(const Complex& cx, EdgeRef e, const std::string& op);

// A consistent "up" for every hex of the sheet: +1 when its local axis points up, -1 when it
// points down, so that the side "up" of a hex glued to another is that one's side "up". Empty
// when the sheet has none: it is one-sided (its neighbourhood is a twisted I-bundle).
IdMap<int8_t> sheetUp(const Complex& cx, const SheetHexes& sheet);

// Vertex merges planned by a collapse: each class keeps one vertex, its smallest boundary vertex
// (else its smallest), placed at the mean of its boundary vertices (else of all of them), so a
// boundary vertex never leaves the boundary surface.
struct VertexMerges {
  IdMap<VertexId> into;                              // every merged vertex -> the kept one
  std::vector<std::pair<VertexId, Vec3>> placed;     // kept vertex, its place after the merge
  std::vector<std::pair<HexId, int>> renamed;        // corners to renumber (outside the removed hexes)
  std::vector<HexId> renamedHexes;                   // the hexes of those corners (ascending, once each)
  std::vector<VertexId> dropped;                     // vertices merged away, ascending
  VertexId split = -1;  // a merged vertex whose corners outside the removed hexes fall apart (face-connected pieces)
  std::vector<std::pair<HexId, int>> anchors;  // per class: a corner off the removed hexes (it holds the kept vertex after)
  std::vector<std::pair<HexId, int>> members;  // every merged vertex, by one of its corners (before the edit)
  std::vector<int> boundaryMembers;            // per class: how many of its vertices are on the boundary
  std::vector<int> removedCorners;             // per member: its corners in the removed hexes
  VertexId target(VertexId v) const { return into.get(v, v); }
};
// Classes of vertices to merge: per class, one corner of each of its vertices (distinct
// vertices), all in one array (a sheet extraction has one class per collapsed edge: thousands).
struct MergeClasses {
  std::vector<std::pair<HexId, int>> corners;
  std::vector<uint32_t> begin{0};  // class k: corners[begin[k], begin[k + 1])
  size_t size() const { return begin.size() - 1; }
  std::span<const std::pair<HexId, int>> operator[](size_t k) const {
    return {corners.data() + begin[k], corners.data() + begin[k + 1]};
  }
  void add(std::span<const std::pair<HexId, int>> cls) {
    corners.insert(corners.end(), cls.begin(), cls.end());
    begin.push_back(uint32_t(corners.size()));
  }
};
VertexMerges planMerges(const Complex& cx, const MergeClasses& classes, const std::function<bool(HexId)>& removed);
// The number of edges with an end at one of these vertices (each named by one of its corners):
// the only edges a collapse of them can change. Costs their stars.
int64_t edgesAt(const Complex& cx, const std::vector<std::pair<HexId, int>>& vertices);
// A collapse must keep the mesh's topology: V - E + F - H (with E counted, not derived) may not
// change; a valid complex can still gain or lose a handle when boundary vertices merge. Called
// after the committed edit (so the result is known to be a valid complex): undoes it and refuses
// (topology-change) otherwise. `before`: V, F, H and the edgesAt() of the merged vertices.
struct EulerBefore {
  int64_t vertices, edgesAround, quads, hexes;
};
void keepTopologyOrUndo(Complex& cx, const EulerBefore& before, int64_t edgesAfter, const OpResult& r, const std::string& op);

// The end of a collapse (sheet extraction, column collapse) after its hexes are gone and its
// vertices merged: glues the quad pairs it closes, commits (refusing an invalid result), refuses a
// change of topology (undoing), and lists the vertices that went away. `after`: corners of the
// vertices counted in `before` that stay (edgesAt); no topology check when before.edgesAround < 0.
// `validByConstruction`: the caller has shown the result valid (sheet_extract.cpp), so the commit
// walks no vertex link (Transaction::commitValidByConstruction).
void finishCollapse(Complex& cx, Transaction& tx, OpResult& res, const VertexMerges& m,
                    const std::vector<std::pair<QuadSide, QuadSide>>& glues, const EulerBefore& before,
                    const std::vector<std::pair<HexId, int>>& after, const std::string& op,
                    bool validByConstruction = false);

// Refuses (hex-vertices-merge) when a hex that keeps a renumbered corner would get two equal vertices.
void requireDistinctCorners(const Complex& cx, const VertexMerges& m, const std::string& op);
// At most how many edits a collapse of `hexes` hexes makes: each hex's unglues and removal, the
// merges' renumbered corners and placed vertices, the glues (for Transaction's reservation).
inline size_t collapseEdits(size_t hexes, const VertexMerges& m, size_t glues) {
  return 7 * hexes + m.renamed.size() + m.placed.size() + glues;
}
// Renumbers the corners and places the kept vertices (call inside the transaction).
void applyMerges(Complex& cx, const VertexMerges& m);

}  // namespace hexdual::ops
