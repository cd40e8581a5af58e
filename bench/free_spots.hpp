// free_3x3_spots: the random places the topology benchmarks insert 3x3 obstacle blocks at (free
// 3x3 blocks away from the border, drawn with std::mt19937 from `seed`), shared by
// topology_bench.cpp, topology_dynamic_bench.cpp and topology_dynamic_drive.cpp so that every
// benchmark and the Callgrind driver measure the same changes.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "voronav/core/occupancy.hpp"

namespace voronav::bench {

/// Up to `n` cells whose 3x3 block is free in `map`, drawn in `max_tries` attempts at most.
inline std::vector<Cell> free_3x3_spots(const BinaryGrid& map, std::uint32_t seed, std::size_t n,
                                        int max_tries = 1000000) {
  std::vector<Cell> spots;
  std::mt19937 rng(seed);
  for (int tries = 0; tries < max_tries && spots.size() < n; ++tries) {
    const Cell c{1 + static_cast<int>(rng() % static_cast<unsigned>(map.width() - 2)),
                 1 + static_cast<int>(rng() % static_cast<unsigned>(map.height() - 2))};
    bool free = true;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        free &= map[c + Cell{dx, dy}] == 0;
    if (free) spots.push_back(c);
  }
  return spots;
}

}  // namespace voronav::bench
