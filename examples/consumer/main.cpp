// The smallest voronav program: a 20x10 map with a wall, planned around with A*.
#include <cstdio>

#include "voronav/planning/planner_factory.hpp"

int main() {
  voronav::OccupancyGrid map(20, 10, voronav::kFree, /*resolution [m]=*/0.1);
  for (int y = 0; y < 8; ++y) map[voronav::Cell{10, y}] = voronav::kOccupied;  // a wall with a gap
  const auto result = voronav::planning::plan_on_map(map, {2, 2}, {17, 2});
  if (!result.ok()) return 1;
  std::printf("path of %zu cells, length %.3f m\n", result.path.size(),
              result.length_cells * map.resolution());
  return 0;
}
