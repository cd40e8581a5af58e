// Driver of bench/topology_dynamic_cg.sh: the update sequence of bench/topology_dynamic_bench.cpp
// (10 accumulated 3x3 obstacle insertions at random free places, then their removal) on one map,
// one warm-up iteration (first-update allocations) and then N iterations whose DynamicGvd::update
// calls go through measured_update(), the function Callgrind collects (--toggle-collect). The
// counts (instructions, simulated cache misses) do not depend on the machine's load, unlike CPU
// time on a shared machine. Uses the public API only, so it builds against older trees too (the
// script compiles it against each side's headers and libraries).
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "free_spots.hpp"
#include "voronav/core/occupancy.hpp"
#include "voronav/io/map_loader.hpp"
#include "voronav/voronoi/gvd.hpp"

using namespace voronav;

// Same places as the benchmark (seed 7): free 3x3 blocks away from the border.
static std::vector<Cell> random_spots(const BinaryGrid& map, std::uint32_t seed, std::size_t n) {
  return voronav::bench::free_3x3_spots(map, seed, n);
}

__attribute__((noinline)) void measured_update(voronoi::DynamicGvd& g,
                                               const std::vector<voronoi::CellChange>& c) {
  (void)g.update(c);
  asm volatile("");
}

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s MAP ITERATIONS\n", argv[0]);
    return 2;
  }
  const BinaryGrid map = binarize(io::load_map(argv[1]).grid);
  const int iters = std::atoi(argv[2]);
  voronoi::DynamicGvd g(map);
  const std::vector<Cell> spots = random_spots(map, 7, 200);
  if (spots.size() < 10) {
    std::fprintf(stderr, "%s: fewer than 10 free 3x3 places\n", argv[1]);
    return 1;
  }
  std::vector<voronoi::CellChange> changes(9);
  std::size_t k = 0;
  auto apply = [&](Cell c, bool add, bool measured) {
    std::size_t n = 0;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        changes[n++] = {c + Cell{dx, dy}, add};
    if (measured)
      measured_update(g, changes);
    else
      (void)g.update(changes);
  };
  for (int it = 0; it <= iters; ++it) {  // iteration 0 warms up
    std::vector<Cell> batch;
    for (int i = 0; i < 10; ++i)
      batch.push_back(spots[k++ % spots.size()]);
    for (const Cell c : batch)
      apply(c, true, it > 0);
    for (auto r = batch.rbegin(); r != batch.rend(); ++r)
      apply(*r, false, it > 0);
  }
  std::printf("measured updates %d\n", iters * 20);
  return 0;
}
