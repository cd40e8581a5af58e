#include "voronav/planning/planner_factory.hpp"

#include <string>

#include "voronav/planning/astar.hpp"

namespace voronav::planning {

std::vector<std::string_view> planner_names() {
  return {"astar", "dijkstra", "ras"};
}

PlannerKind parse_planner_kind(std::string_view name) {
  if (name == "astar" || name == "a*") return PlannerKind::kAStar;
  if (name == "dijkstra") return PlannerKind::kDijkstra;
  if (name == "ras") return PlannerKind::kRas;
  throw Error("--planner", 0,
              "unknown planner '" + std::string(name) + "'; expected one of: astar, dijkstra, ras");
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
  }
  throw Error("make_planner: unknown planner kind");
}

PlanResult plan_on_map(const OccupancyGrid& map, Cell start, Cell goal,
                       const PlannerOptions& options, PlannerKind kind) {
  const BinaryGrid grid = make_planning_grid(binarize(map), options.robot_radius);
  return make_planner(kind, options)->plan(grid, start, goal);
}

}  // namespace voronav::planning
