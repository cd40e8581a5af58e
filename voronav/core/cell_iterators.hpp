// Cell iterators, the shared vocabulary for walking grids: the Bresenham line between two cells
// and the disc of cells around a centre. Each comes as a visitor (no allocation; the visitor may
// return false to stop early) and as a convenience returning a vector.
#pragma once

#include <cmath>
#include <concepts>
#include <cstdlib>
#include <vector>

#include "voronav/core/cell.hpp"

namespace voronav {

template <typename F>
concept CellVisitor = std::invocable<F&, Cell>;

namespace detail {
template <typename F>
bool visit_cell(F& f, Cell c) {
  if constexpr (std::is_same_v<std::invoke_result_t<F&, Cell>, bool>) {
    return f(c);
  } else {
    f(c);
    return true;
  }
}
}  // namespace detail

/// Visits the cells of the Bresenham line from a to b, both included, in order from a.
/// Returns false when the visitor stopped early.
template <CellVisitor F>
bool for_each_line_cell(Cell a, Cell b, F&& visit) {
  const int dx = std::abs(b.x - a.x), sx = a.x < b.x ? 1 : -1;
  const int dy = -std::abs(b.y - a.y), sy = a.y < b.y ? 1 : -1;
  int err = dx + dy;
  Cell c = a;
  while (true) {
    if (!detail::visit_cell(visit, c)) return false;
    if (c == b) return true;
    const int e2 = 2 * err;
    if (e2 >= dy) {
      err += dy;
      c.x += sx;
    }
    if (e2 <= dx) {
      err += dx;
      c.y += sy;
    }
  }
}

[[nodiscard]] inline std::vector<Cell> line_cells(Cell a, Cell b) {
  std::vector<Cell> out;
  out.reserve(static_cast<std::size_t>(std::max(std::abs(b.x - a.x), std::abs(b.y - a.y)) + 1));
  for_each_line_cell(a, b, [&](Cell c) { out.push_back(c); });
  return out;
}

/// Visits every cell whose centre lies within `radius` cells of the centre of `center`
/// (Euclidean), row by row. A negative or NaN radius visits nothing.
template <CellVisitor F>
bool for_each_disc_cell(Cell center, double radius, F&& visit) {
  if (!(radius >= 0.0)) return true;
  const int r = static_cast<int>(std::floor(radius));
  const double r2 = radius * radius;
  for (int dy = -r; dy <= r; ++dy) {
    const int half = static_cast<int>(std::floor(std::sqrt(std::max(0.0, r2 - dy * dy))));
    for (int dx = -half; dx <= half; ++dx)
      if (!detail::visit_cell(visit, Cell{center.x + dx, center.y + dy})) return false;
  }
  return true;
}

[[nodiscard]] inline std::vector<Cell> disc_cells(Cell center, double radius) {
  std::vector<Cell> out;
  for_each_disc_cell(center, radius, [&](Cell c) { out.push_back(c); });
  return out;
}

}  // namespace voronav
