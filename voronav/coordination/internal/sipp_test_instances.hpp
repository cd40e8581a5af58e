// Random prioritized-planning instances for the coordination tests (not installed): a w x h grid
// whose cells are walls with probability wall_p, and n robots on distinct free cells (the free
// cells shuffled: the first n are the starts, the next n the goals), radius 0.5, 1 cell/s.
#pragma once

#include <algorithm>
#include <random>
#include <vector>

#include "voronav/coordination/prioritized.hpp"

namespace voronav::coordination::internal {

struct SippInstance {
  BinaryGrid grid;
  std::vector<SippRobot> robots;  ///< ids 1..n
};

/// Needs at least 2n free cells (the tests' maps have many more).
inline SippInstance random_sipp_instance(std::mt19937& rng, int w, int h, double wall_p, int n) {
  SippInstance out{BinaryGrid(w, h), {}};
  std::bernoulli_distribution wall(wall_p);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      out.grid[Cell{x, y}] = wall(rng) ? 1 : 0;
  std::vector<Cell> free;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (out.grid[Cell{x, y}] == 0) free.push_back({x, y});
  std::shuffle(free.begin(), free.end(), rng);
  for (int i = 0; i < n; ++i)
    out.robots.push_back({i + 1, free[static_cast<std::size_t>(i)],
                          free[static_cast<std::size_t>(i + n)], 0.5, 1.0});
  return out;
}

}  // namespace voronav::coordination::internal
