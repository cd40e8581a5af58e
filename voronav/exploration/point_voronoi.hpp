// Voronoi diagram of feature points (seed 004, section 4.2): the feature points are the Voronoi
// generators; the diagram's vertices become the nodes of the Voronoi tree and its edges
// ("partitions") the robots' paths. Computed exactly with Boost.Polygon's sweep-line Voronoi,
// which takes integer input: world coordinates are scaled by PointVoronoiOptions::scale
// (default 1000 units per metre, i.e. 1 mm) and rounded; sites that round to the same integer
// point are merged.
#pragma once

#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include "voronav/core/vec2.hpp"

namespace voronav::exploration {

struct PointVoronoiOptions {
  /// Integer units per metre for Boost.Polygon (1000 = 1 mm). |coordinate * scale| must stay
  /// below 2^31.
  double scale = 1000.0;
};

struct PointVoronoi {
  std::vector<Vec2> sites;     ///< generators after quantisation and deduplication [m]
  std::vector<Vec2> vertices;  ///< Voronoi vertices [m]
  /// Finite edges between two vertices (indices into vertices), each once.
  std::vector<std::pair<std::size_t, std::size_t>> edges;
};

/// Throws voronav::Error for non-finite points, points out of the integer range, or a
/// non-positive scale. Fewer than 3 distinct sites give no vertices.
[[nodiscard]] PointVoronoi voronoi_of_points(std::span<const Vec2> points,
                                             const PointVoronoiOptions& options = {});

}  // namespace voronav::exploration
