// GridGeometry: size, resolution [m/cell] and origin of a grid, and the cell <-> world transforms.
// The origin is the world pose of the lower-left corner of cell (0, 0), exactly as ROS map_server
// (REP-103 frames); cell (x, y) covers [x, x+1) x [y, y+1) in grid units.
#pragma once

#include <cmath>
#include <cstddef>
#include <optional>

#include "voronav/core/cell.hpp"
#include "voronav/core/pose2.hpp"
#include "voronav/core/vec2.hpp"

namespace voronav {

struct GridGeometry {
  int width = 0;
  int height = 0;
  double resolution = 1.0;  ///< [m/cell], > 0
  Pose2 origin;             ///< world pose of cell (0,0)'s lower-left corner

  [[nodiscard]] std::size_t size() const {
    return static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  }
  [[nodiscard]] bool empty() const { return width <= 0 || height <= 0; }
  [[nodiscard]] bool contains(Cell c) const {
    return c.x >= 0 && c.y >= 0 && c.x < width && c.y < height;
  }
  /// Row-major index (x fastest). Precondition: contains(c).
  [[nodiscard]] std::size_t index(Cell c) const {
    return static_cast<std::size_t>(c.y) * static_cast<std::size_t>(width) +
           static_cast<std::size_t>(c.x);
  }
  [[nodiscard]] Cell cell_at(std::size_t index) const {
    return {static_cast<int>(index % static_cast<std::size_t>(width)),
            static_cast<int>(index / static_cast<std::size_t>(width))};
  }
  /// Continuous grid coordinates (in cells, origin at cell (0,0)'s lower-left corner) of a world point.
  [[nodiscard]] Vec2 world_to_grid(Vec2 world) const {
    return origin.inverse_transform(world) / resolution;
  }
  [[nodiscard]] Vec2 grid_to_world(Vec2 grid) const { return origin.transform(grid * resolution); }
  /// World position [m] of the centre of a cell.
  [[nodiscard]] Vec2 cell_center(Cell c) const {
    return grid_to_world({static_cast<double>(c.x) + 0.5, static_cast<double>(c.y) + 0.5});
  }
  /// The cell containing a world point, even outside the grid (check with contains()).
  /// Empty for non-finite input.
  [[nodiscard]] std::optional<Cell> world_to_cell(Vec2 world) const {
    const Vec2 g = world_to_grid(world);
    if (!g.is_finite() || std::abs(g.x) > 1e9 || std::abs(g.y) > 1e9) return std::nullopt;
    return Cell{static_cast<int>(std::floor(g.x)), static_cast<int>(std::floor(g.y))};
  }
  friend bool operator==(const GridGeometry&, const GridGeometry&) = default;
};

}  // namespace voronav
