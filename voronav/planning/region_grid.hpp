// RegionGrid: a cell grid cut into square regions of side r cells, [m n] = P / r (seed 001,
// eq. 5), the space the RAS planner numbers. A region is blocked when any of its cells is blocked
// (the safe rule: every cell of a free region is free, so a robot moving inside free regions never
// touches an obstacle); RegionRule::kMajorityBlocked is offered for noisy maps (blocked when more
// than half of its cells are blocked). Regions at the right and top borders may be partial when
// the map size is not a multiple of r; only their in-map cells count.
//
// The paper also considers triangles, hexagons and free-form regions (figure 6) and chooses
// squares; RegionGrid is the extension point for other shapes: the RAS search only needs, per
// region, a blocked flag and an ordered list of neighbours, which a hexagonal grid would supply.
#pragma once

#include <utility>

#include "voronav/core/cell.hpp"
#include "voronav/core/grid_geometry.hpp"
#include "voronav/core/occupancy.hpp"
#include "voronav/core/vec2.hpp"

namespace voronav::planning {

enum class RegionRule {
  kAnyBlocked,       ///< blocked if any of its cells is blocked (default)
  kMajorityBlocked,  ///< blocked if more than half of its in-map cells are blocked
};

/// Largest region side [cells]: the largest map side (io's limit), so the arithmetic stays in int.
inline constexpr int kMaxRegionSize = 1 << 16;

struct RegionGridOptions {
  /// Side r of a square region [cells], >= 1 (seed 001: S_p).
  int region_size = 1;
  RegionRule rule = RegionRule::kAnyBlocked;
};

class RegionGrid {
 public:
  RegionGrid() = default;
  /// Cuts `cells` (1 = blocked) into regions. Throws voronav::Error for region_size
  /// outside 1..kMaxRegionSize.
  RegionGrid(const BinaryGrid& cells, const RegionGridOptions& options);

  [[nodiscard]] int region_size() const { return r_; }
  [[nodiscard]] RegionRule rule() const { return rule_; }
  /// One value per region, 1 = blocked. Its geometry has the map's origin and resolution r times
  /// the map's (so full regions have the right world extent).
  [[nodiscard]] const BinaryGrid& blocked() const { return blocked_; }
  [[nodiscard]] const GridGeometry& cell_geometry() const { return cells_; }
  [[nodiscard]] int width() const { return blocked_.width(); }
  [[nodiscard]] int height() const { return blocked_.height(); }
  [[nodiscard]] bool contains(Cell region) const { return blocked_.contains(region); }
  [[nodiscard]] bool is_blocked(Cell region) const { return blocked_[region] != 0; }

  /// The region holding a map cell (the cell must lie in the map).
  [[nodiscard]] Cell region_of(Cell cell) const { return {cell.x / r_, cell.y / r_}; }
  /// Inclusive cell box [lo, hi] of a region's in-map part.
  [[nodiscard]] std::pair<Cell, Cell> cell_box(Cell region) const;
  /// The middle cell of a region's in-map part (the cell a robot aims for).
  [[nodiscard]] Cell center_cell(Cell region) const;
  /// World position [m] of the centre of a region's in-map part (p in F = (k, p, N, d, n)).
  [[nodiscard]] Vec2 center_world(Cell region) const;

 private:
  int r_ = 1;
  RegionRule rule_ = RegionRule::kAnyBlocked;
  GridGeometry cells_;
  BinaryGrid blocked_;
};

}  // namespace voronav::planning
