// Small grids for the unit tests (not installed): a grid drawn as text rows ('#' blocked, any
// other character free; the first row is the top, y = height - 1, as a map image reads) and a
// grid of independently blocked cells. Written once here so the planners' tests build their
// cases the same way.
#pragma once

#include <cstddef>
#include <cstring>
#include <initializer_list>
#include <random>

#include "voronav/core/occupancy.hpp"

namespace voronav::test {

/// The grid drawn by `rows_top_first` (all rows as long as the first).
[[nodiscard]] inline BinaryGrid from_rows(std::initializer_list<const char*> rows_top_first) {
  const int h = static_cast<int>(rows_top_first.size());
  const int w = static_cast<int>(std::strlen(*rows_top_first.begin()));
  BinaryGrid g(w, h, 0);
  int j = 0;
  for (const char* row : rows_top_first) {
    for (int x = 0; x < w; ++x)
      g[Cell{x, h - 1 - j}] = row[x] == '#' ? 1 : 0;
    ++j;
  }
  return g;
}

/// A w x h grid whose cells are blocked each with probability p.
[[nodiscard]] inline BinaryGrid random_grid(std::mt19937& rng, int w, int h, double p) {
  BinaryGrid g(w, h, 0);
  std::bernoulli_distribution b(p);
  for (std::size_t i = 0; i < g.size(); ++i)
    g[i] = b(rng) ? 1 : 0;
  return g;
}

}  // namespace voronav::test
