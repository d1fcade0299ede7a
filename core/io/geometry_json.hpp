// JSON and text for the geometry and singularity reports, shared by the CLI and the wasm module:
// the singularity graph (`info`, mesh.singularities()), the dual through an edge
// (mesh.edgeDual()), the scaled-Jacobian distribution (`hexdual quality`, mesh.quality()) and a
// step's quality (part of every step report).
#pragma once
#include <string>

#include "analysis/edge_dual.hpp"
#include "analysis/singularity.hpp"
#include "geometry/quality_stats.hpp"
#include "geometry/step_quality.hpp"

namespace hexdual::io {

// {"interiorEdges":N,"boundaryEdges":N,"interiorByValence":{"3":N,..},"boundaryByValence":{..},
//  "vertices":N,"boundaryVertices":N,"curves":N}
std::string singularityCountsJson(const SingularityCounts& c);
// The whole graph: {"counts":{..},"edges":[{"hex","edge","vertices":[a,b],"valence","boundary","curve"}],
// "vertices":[{"vertex","boundary","degree"}],"curves":[{"edges":[..],"valence","boundary","closed","ends":[a,b]|[]}]}
std::string singularityGraphJson(const SingularityGraph& g);
// "singular edges: interior 8 (valence 3: 8), boundary 24 (valence 1: 24); irregular vertices 8 (8 on the boundary); curves 6"
std::string singularityCountsText(const SingularityCounts& c);

// {"hex","edge","valence","boundary","sheet","hexes":[..],"quads":[{"hex","face","chord","sheet"}],"chords":[..],"sheets":[..]}
std::string edgeDualJson(const EdgeDual& d);

// {"hexes","min","max","mean","nonPositive","buckets":[20 counts]}
std::string qualityStatsJson(const QualityStats& s);
std::string qualityStatsText(const QualityStats& s);

// {"smoothed","before","after","afterRegular","inverted":[..],"pinned":[..],"degenerate":[..],"moved":[..],
//  "rings","evaluations"}, or null when the step was not measured (StepGeometry::Keep).
std::string stepQualityJson(const StepQuality& q);
// "  quality: min scaled Jacobian 0.41 -> 0.52 (smoothed, 16 vertices moved); inverted [..]; degenerate by
// construction [..], min of the others 0.5"; "" when not measured.
std::string stepQualityText(const StepQuality& q);

}  // namespace hexdual::io
