#include "voronav/planning/grid_planner.hpp"

#include "voronav/field/distance_transform.hpp"

namespace voronav::planning {

std::string_view to_string(PlanStatus s) {
  switch (s) {
    case PlanStatus::kOk:
      return "ok";
    case PlanStatus::kStartOccupied:
      return "start_occupied";
    case PlanStatus::kGoalOccupied:
      return "goal_occupied";
    case PlanStatus::kOutOfMap:
      return "out_of_map";
    case PlanStatus::kUnreachable:
      return "unreachable";
    case PlanStatus::kCancelled:
      return "cancelled";
  }
  return "unknown";
}

BinaryGrid make_planning_grid(const BinaryGrid& blocked, double robot_radius_m) {
  return field::inflate(blocked, robot_radius_m);
}

}  // namespace voronav::planning
