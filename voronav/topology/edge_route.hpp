// The cells a topological graph edge stands for, for pictures and for following an edge: from the
// centre of region a through the edge's crossing (critical-line midpoint or border cell) to the
// centre of region b, along the Voronoi diagram where it can (seed 003 draws the graph on the
// diagram; straight centre-to-crossing segments cut through walls in non-convex regions).
#pragma once

#include <vector>

#include "voronav/topology/topological_map.hpp"

namespace voronav::topology {

/// Cost multiplier for a step onto a free cell that is not on the diagram: the route leaves the
/// diagram only to reach a centre or a crossing that lies off it.
inline constexpr double kOffDiagramCost = 4.0;

/// The 8-connected cell route of `edge`: centre(a) -> edge.midpoint -> centre(b), each leg a
/// cheapest path over free cells of regions a and b (no corner cutting past a blocked cell), where
/// a step onto a diagram cell costs its length and any other step kOffDiagramCost times its length.
/// Empty if a leg has no such path (it cannot happen for edges of build_topological_map).
[[nodiscard]] std::vector<Cell> edge_route(const TopologicalMap& map, const TopoEdge& edge);

}  // namespace voronav::topology
