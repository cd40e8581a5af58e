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

/// `title`: empty = "path of L m (N cells expanded)" or the failure; `scale_unit`: "m", or
/// "cells" for Moving AI maps.
void save_plan_picture(const PlanPicture& pic, const std::filesystem::path& out,
                       const std::string& title = "", const std::string& scale_unit = "m");

}  // namespace voronav::cli
