// The Voronoi graph of a one-cell-wide diagram: nodes at junctions (3 or more branches) and end
// points, edges along the skeleton between them with their length and minimum clearance (the
// narrowest passage a robot meets along the edge). A closed loop without junctions gets one node
// and a self-loop edge. Used by the topological map (seed 003) and by colleagues' planners.
#pragma once

#include <cstdint>
#include <vector>

#include "voronav/core/grid_map.hpp"
#include "voronav/core/occupancy.hpp"
#include "voronav/voronoi/gvd.hpp"

namespace voronav::voronoi {

enum class VoronoiNodeKind : std::uint8_t {
  kEnd,       ///< one branch
  kJunction,  ///< three or more branches
  kLoop,      ///< a point chosen on a closed loop without junctions
  kIsolated,  ///< a diagram component of a single cell or a single cluster
};

struct VoronoiNode {
  Cell cell;                  ///< representative cell (of a junction cluster: nearest its centre)
  std::vector<Cell> cluster;  ///< all diagram cells merged into this node
  VoronoiNodeKind kind = VoronoiNodeKind::kEnd;
  double clearance_m = 0.0;  ///< clearance of `cell` [m]
  int degree = 0;            ///< number of incident edge ends
};

struct VoronoiEdge {
  int a = 0, b = 0;              ///< node ids (a == b for a self-loop)
  std::vector<Cell> cells;       ///< from a's cluster to b's cluster, both ends included
  double length_m = 0.0;         ///< along the cells [m]
  double min_clearance_m = 0.0;  ///< smallest clearance along the cells [m]
};

struct VoronoiGraph {
  std::vector<VoronoiNode> nodes;
  std::vector<VoronoiEdge> edges;
  /// Node id of every node cell, -1 elsewhere.
  GridMap<std::int32_t> node_of;
};

/// Builds the graph of `diagram` (1 = diagram cell), with clearance [cells] per cell.
/// Throws voronav::Error when the sizes differ.
[[nodiscard]] VoronoiGraph build_voronoi_graph(const BinaryGrid& diagram,
                                               const GridMap<float>& clearance);
/// The graph of gvd.diagram.
[[nodiscard]] VoronoiGraph build_voronoi_graph(const GeneralizedVoronoi& gvd);

}  // namespace voronav::voronoi
