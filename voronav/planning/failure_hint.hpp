// Why a query failed, in words a user can act on (issue 20): a start or goal that is free on the
// map but closer than the robot radius to an obstacle gets the nearest cell that keeps the radius;
// a goal that the robot cannot reach with its radius but could reach as a point gets the width of
// the narrowest passage on the way (twice the clearance of its tightest cell) against the robot's
// diameter. Plain A* and the exact distance transform, so the hint holds for every planner.
#pragma once

#include <optional>
#include <string>

#include "voronav/core/cell.hpp"
#include "voronav/core/grid_geometry.hpp"
#include "voronav/core/occupancy.hpp"

namespace voronav::planning {

struct FailureHint {
  std::string text;                  ///< one or two sentences; empty when there is nothing to add
  std::optional<Cell> nearest_free;  ///< start/goal in the radius: nearest cell that keeps it
  double narrowest_passage_m = 0.0;  ///< unreachable only with the radius: passage width [m]
};

/// `blocked`: the map's blocked cells (not inflated); `radius_m`: the robot radius the query used.
/// Call after a plan failed with kStartOccupied, kGoalOccupied or kUnreachable; other cases (and
/// cells blocked on the map itself, or goals unreachable even as a point) get a plain sentence.
[[nodiscard]] FailureHint explain_failure(const BinaryGrid& blocked, const GridGeometry& geometry,
                                          Cell start, Cell goal, double radius_m);

}  // namespace voronav::planning
