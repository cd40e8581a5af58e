// Pictures of the stages of the topological map (seed 003, figure 8 (a)-(f)): binary map, edge
// codes, Voronoi diagram, critical points and lines, regions, graph. Shared by `voronav topo` and
// the demo.
#pragma once

#include <filesystem>

#include "voronav/topology/topological_map.hpp"

namespace voronav::cli {

/// Writes a_binary.png ... f_graph.png into `dir` (created when missing).
void save_stages(const OccupancyGrid& grid, const BinaryGrid& blocked,
                 const topology::TopologicalMap& m, bool border_blocked,
                 const std::filesystem::path& dir);

}  // namespace voronav::cli
