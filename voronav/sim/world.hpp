// The simulated world of the networked-robot experiments (seed 000, section 4.1): a ground-truth
// occupancy grid with obstacle changes, exact range-limited sensing (3 m, no noise, exact
// localisation as the paper assumes) into each robot's own local map, the office-like world
// generator used for the scenarios of Table 6, and robot placement "half on the Voronoi diagram
// of the map, half at random" (Table 7 note).
#pragma once

#include <cstdint>
#include <vector>

#include "voronav/core/occupancy.hpp"
#include "voronav/core/vec2.hpp"

namespace voronav::sim {

/// A robot's own map: a window of the world grid (kUnknown / kFree / kOccupied) that grows as
/// the robot senses new places. Cells are world-aligned (same resolution and origin as the world).
class LocalMap {
 public:
  LocalMap() = default;
  explicit LocalMap(const GridGeometry& world) : world_(world) {}
  /// Value of a world cell (kUnknown outside the window).
  [[nodiscard]] std::int8_t at(Cell world_cell) const;
  /// Sets a world cell, growing the window when needed.
  void set(Cell world_cell, std::int8_t value);
  /// Grows the window to contain [lo, hi] (world cells) plus a margin.
  void ensure(Cell lo, Cell hi);
  /// The window as a georeferenced grid (cell_center() gives world positions).
  [[nodiscard]] const OccupancyGrid& grid() const { return grid_; }
  [[nodiscard]] Cell offset() const { return offset_; }
  [[nodiscard]] const GridGeometry& world() const { return world_; }
  [[nodiscard]] std::size_t known_cells() const;
  /// Changes with every set() (caches of answers computed from the map compare it).
  [[nodiscard]] std::uint64_t version() const { return version_; }

 private:
  GridGeometry world_;
  std::uint64_t version_ = 0;
  Cell offset_{0, 0};
  OccupancyGrid grid_;
};

/// Senses exactly: every cell within `range_m` of `position` that is visible (no blocked cell on
/// the Bresenham line before it) is copied from `truth` (1 = blocked) into `map`. Returns the
/// number of cells examined (work) and whether any map cell changed.
struct SenseResult {
  std::size_t cells = 0;
  bool changed = false;
};
SenseResult sense(const BinaryGrid& truth, Vec2 position, double range_m, LocalMap& map);

/// Office-like world generator (documented in docs/reproductions/networked.md): a rectangular
/// building of rooms on a regular grid with walls and doors; every third row of rooms is an open
/// corridor; doors follow a random spanning tree of the rooms (all connected) plus extra doors;
/// a few furniture blocks per room.
struct OfficeWorldOptions {
  double width_m = 40.0;
  double height_m = 40.0;
  double resolution = 0.2;        ///< [m/cell]
  double room_size_m = 8.0;       ///< room pitch [m]
  double wall_m = 0.4;            ///< wall thickness [m]
  double door_m = 1.6;            ///< door opening [m]
  double extra_door_prob = 0.35;  ///< probability of a door beyond the spanning tree
  int furniture_per_room = 1;
  std::uint64_t seed = 1;
  void validate() const;  ///< throws voronav::Error naming the bad field
};

/// A door: the cells of its opening (closing a door blocks them: an obstacle change).
struct Door {
  std::vector<Cell> cells;
  Vec2 centre;
};

struct OfficeWorld {
  OccupancyGrid grid;  ///< kFree / kOccupied
  std::vector<Door> doors;
};

[[nodiscard]] OfficeWorld make_office_world(const OfficeWorldOptions& options);

/// Free cells on the generalized Voronoi diagram of `blocked` whose clearance is at least
/// `min_clearance_m` (candidates for "robots on the Voronoi diagram of the map").
[[nodiscard]] std::vector<Cell> voronoi_cells(const BinaryGrid& blocked, double min_clearance_m);

}  // namespace voronav::sim
