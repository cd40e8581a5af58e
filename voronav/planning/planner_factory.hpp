// make_planner: builds a GridPlanner by name ("astar", "dijkstra", "ras", "jps", "jps+"), so the
// CLI, scenario files and benchmarks select planners the same way. plan_on_map() is the one-call
// convenience: binarize, inflate by the robot radius, plan.
#pragma once

#include <memory>
#include <string_view>
#include <vector>

#include "voronav/planning/grid_planner.hpp"
#include "voronav/planning/ras.hpp"

namespace voronav::planning {

enum class PlannerKind { kAStar, kDijkstra, kRas, kJps, kJpsPlus };

/// Parses "astar" / "dijkstra" / "ras" / "jps" / "jps+"; throws voronav::Error naming the accepted
/// values otherwise.
[[nodiscard]] PlannerKind parse_planner_kind(std::string_view name);
[[nodiscard]] std::vector<std::string_view> planner_names();

[[nodiscard]] std::unique_ptr<GridPlanner> make_planner(PlannerKind kind,
                                                        PlannerOptions options = {});
/// The same, with the RAS options used when kind == kRas (seed 001; ignored otherwise).
[[nodiscard]] std::unique_ptr<GridPlanner> make_planner(PlannerKind kind, PlannerOptions options,
                                                        const RasOptions& ras);

/// Binarizes `map` (unknown = blocked), inflates it by options.robot_radius and plans with A*.
[[nodiscard]] PlanResult plan_on_map(const OccupancyGrid& map, Cell start, Cell goal,
                                     const PlannerOptions& options = {},
                                     PlannerKind kind = PlannerKind::kAStar);

}  // namespace voronav::planning
