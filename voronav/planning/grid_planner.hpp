// GridPlanner: the one interface every grid planner implements (A*, Dijkstra, RAS, ...), with one
// options struct, a status enum for expected outcomes and a cancel/deadline hook (the role of
// OMPL's PlannerTerminationCondition). Planners are reusable workspaces: plan() keeps its buffers
// between queries, so running many queries on one map allocates nothing per node.
#pragma once

#include <chrono>
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "voronav/core/cell.hpp"
#include "voronav/core/occupancy.hpp"

namespace voronav::planning {

enum class PlanStatus {
  kOk,
  kStartOccupied,
  kGoalOccupied,
  kOutOfMap,
  kUnreachable,
  kCancelled,
};

[[nodiscard]] std::string_view to_string(PlanStatus s);

enum class Connectivity { k4 = 4, k8 = 8 };

/// Returns true when the search must stop (checked every few thousand expansions).
using CancelFn = std::function<bool()>;

struct PlannerOptions {
  Connectivity connectivity = Connectivity::k8;
  /// Robot radius [m]: cells whose centre is closer than this to a blocked cell centre are
  /// blocked too (exact Euclidean distance transform). 0 = point robot.
  double robot_radius = 0.0;
  /// Record the expanded cells in PlanResult::expanded_cells (for pictures).
  bool record_expanded = false;
  /// Optional cancel hook and deadline; either stops the search with kCancelled.
  CancelFn cancel{};
  std::optional<std::chrono::steady_clock::time_point> deadline{};
};

struct PlanResult {
  PlanStatus status = PlanStatus::kUnreachable;
  /// Cells from start to goal, both included (empty unless kOk).
  std::vector<Cell> path;
  /// Path cost in cells: octile (1 per straight step, sqrt 2 per diagonal step).
  double length_cells = 0.0;
  std::size_t expanded = 0;
  double time_ms = 0.0;
  /// Time spent building per-map data (JPS's bit-packed map, JPS+'s jump tables) in this call;
  /// not part of time_ms, 0 when the data was cached or the planner needs none.
  double preprocess_ms = 0.0;
  std::vector<Cell> expanded_cells;  ///< when PlannerOptions::record_expanded

  [[nodiscard]] bool ok() const { return status == PlanStatus::kOk; }
};

/// The traversability a planner searches: a BinaryGrid (1 = blocked) already inflated by the
/// robot radius. Build it once per map and radius with make_planning_grid().
[[nodiscard]] BinaryGrid make_planning_grid(const BinaryGrid& blocked, double robot_radius_m);

class GridPlanner {
 public:
  virtual ~GridPlanner() = default;
  [[nodiscard]] virtual std::string_view name() const = 0;
  /// Plans from start to goal on `grid` (1 = blocked; not inflated again: the caller inflates
  /// with make_planning_grid, or uses plan_on_map()).
  virtual PlanResult plan(const BinaryGrid& grid, Cell start, Cell goal) = 0;
  [[nodiscard]] const PlannerOptions& options() const { return options_; }

 protected:
  explicit GridPlanner(PlannerOptions options) : options_(std::move(options)) {}
  PlannerOptions options_;
};

}  // namespace voronav::planning
