// Small synthetic maps shared by the voronoi and topology tests (header only, no library code).
#pragma once

#include <algorithm>
#include <random>

#include "voronav/core/occupancy.hpp"

namespace voronav::voronoi::testing {

/// Fills the rectangle [x0, x1] x [y0, y1] (inclusive, clipped) with value v.
inline void fill_rect(BinaryGrid& g, int x0, int y0, int x1, int y1, std::uint8_t v = 1) {
  for (int y = std::max(0, y0); y <= std::min(g.height() - 1, y1); ++y)
    for (int x = std::max(0, x0); x <= std::min(g.width() - 1, x1); ++x)
      g[Cell{x, y}] = v;
}

/// A walled room with `boxes` random rectangular obstacles (some touching the walls).
inline BinaryGrid random_room(std::uint32_t seed, int w = 48, int h = 36, int boxes = 5) {
  std::mt19937 rng(seed);
  BinaryGrid g(GridGeometry{w, h, 0.1, {}}, 0);
  fill_rect(g, 0, 0, w - 1, 0);
  fill_rect(g, 0, h - 1, w - 1, h - 1);
  fill_rect(g, 0, 0, 0, h - 1);
  fill_rect(g, w - 1, 0, w - 1, h - 1);
  std::uniform_int_distribution<int> ux(1, w - 2), uy(1, h - 2), us(1, 6);
  for (int b = 0; b < boxes; ++b) {
    const int x = ux(rng), y = uy(rng);
    fill_rect(g, x, y, x + us(rng), y + us(rng));
  }
  return g;
}

/// Two rooms side by side (each room_w x h inside), joined by one door of `door` cells in the
/// middle of the dividing wall. Walls are one cell thick.
inline BinaryGrid two_rooms(int room_w = 30, int h = 24, int door = 4) {
  const int w = 2 * room_w + 3;
  BinaryGrid g(GridGeometry{w, h + 2, 0.1, {}}, 0);
  fill_rect(g, 0, 0, w - 1, 0);
  fill_rect(g, 0, h + 1, w - 1, h + 1);
  fill_rect(g, 0, 0, 0, h + 1);
  fill_rect(g, w - 1, 0, w - 1, h + 1);
  fill_rect(g, room_w + 1, 0, room_w + 1, h + 1);
  const int y0 = (h + 2 - door) / 2;
  fill_rect(g, room_w + 1, y0, room_w + 1, y0 + door - 1, 0);
  return g;
}

}  // namespace voronav::voronoi::testing
