#include "voronav/planning/planner_factory.hpp"

#include <string>

#include "voronav/planning/astar.hpp"
#include "voronav/planning/jps.hpp"

namespace voronav::planning {

std::vector<std::string_view> planner_names() {
  return {"astar", "dijkstra", "ras", "jps", "jps+"};
}

PlannerKind parse_planner_kind(std::string_view name) {
  if (name == "astar" || name == "a*") return PlannerKind::kAStar;
  if (name == "dijkstra") return PlannerKind::kDijkstra;
  if (name == "ras") return PlannerKind::kRas;
  if (name == "jps") return PlannerKind::kJps;
  if (name == "jps+" || name == "jps_plus") return PlannerKind::kJpsPlus;
  throw Error("--planner", 0,
              "unknown planner '" + std::string(name) +
                  "'; expected one of: astar, dijkstra, ras, jps, jps+");
}

std::unique_ptr<GridPlanner> make_planner(PlannerKind kind, PlannerOptions options) {
  return make_planner(kind, std::move(options), RasOptions{});
}

std::unique_ptr<GridPlanner> make_planner(PlannerKind kind, PlannerOptions options,
                                          const RasOptions& ras) {
  switch (kind) {
    case PlannerKind::kRas:
      return std::make_unique<RasPlanner>(ras, std::move(options));
    case PlannerKind::kAStar:
      return std::make_unique<AStarPlanner>(std::move(options));
    case PlannerKind::kDijkstra:
      return std::make_unique<DijkstraPlanner>(std::move(options));
    case PlannerKind::kJps:
      return std::make_unique<JpsPlanner>(std::move(options));
    case PlannerKind::kJpsPlus:
      return std::make_unique<JpsPlusPlanner>(std::move(options));
  }
  throw Error("make_planner: unknown planner kind");
}

PlanResult plan_on_map(const OccupancyGrid& map, Cell start, Cell goal,
                       const PlannerOptions& options, PlannerKind kind) {
  const BinaryGrid grid = make_planning_grid(binarize(map), options.robot_radius);
  return make_planner(kind, options)->plan(grid, start, goal);
}

}  // namespace voronav::planning
