// Picture of one planning query: map, inflated cells, expanded cells, path, start and goal.
#pragma once

#include <filesystem>

#include "voronav/core/occupancy.hpp"
#include "voronav/planning/grid_planner.hpp"

namespace voronav::cli {

struct PlanPicture {
  const OccupancyGrid& map;
  const BinaryGrid& planning_grid;  ///< inflated grid actually searched
  Cell start, goal;
  const planning::PlanResult* result = nullptr;
  bool show_inflation = false;
};

void save_plan_picture(const PlanPicture& pic, const std::filesystem::path& out);

}  // namespace voronav::cli
