// Cell: integer grid index (x = column, y = row; row 0 is the bottom row in world terms).
// A distinct type from Vec2 (world metres) so that cell and world coordinates cannot be swapped.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <ostream>

namespace voronav {

struct Cell {
  int x = 0;
  int y = 0;

  friend constexpr Cell operator+(Cell a, Cell b) { return {a.x + b.x, a.y + b.y}; }
  friend constexpr Cell operator-(Cell a, Cell b) { return {a.x - b.x, a.y - b.y}; }
  friend constexpr bool operator==(Cell a, Cell b) = default;
  friend constexpr auto operator<=>(Cell a, Cell b) = default;
};

inline std::ostream& operator<<(std::ostream& os, Cell c) {
  return os << '[' << c.x << ", " << c.y << ']';
}

/// The 8 neighbour offsets: 4 straight ones first (E, N, W, S), then the diagonals.
inline constexpr Cell kNeighbours8[8] = {{1, 0},  {0, 1},  {-1, 0}, {0, -1},
                                         {1, 1},  {-1, 1}, {-1, -1}, {1, -1}};

}  // namespace voronav

template <>
struct std::hash<voronav::Cell> {
  std::size_t operator()(voronav::Cell c) const noexcept {
    return std::hash<std::uint64_t>{}((static_cast<std::uint64_t>(static_cast<std::uint32_t>(c.x))
                                       << 32) |
                                      static_cast<std::uint32_t>(c.y));
  }
};
