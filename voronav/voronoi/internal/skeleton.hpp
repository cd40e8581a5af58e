// Skeleton helpers shared by the EDT diagram and the cellular-automaton diagram: thinning by
// removal of simple cells and spur pruning, on a padded row-major raster (the outer ring is never
// part of the skeleton, so neighbour access needs no bounds checks).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace voronav::voronoi::internal {

struct PaddedRaster {
  int width = 0;   // padded width
  int height = 0;  // padded height
  // Offsets of the 8 neighbours in Yokoi order: E, NE, N, NW, W, SW, S, SE.
  [[nodiscard]] std::ptrdiff_t offset(int k) const {
    static constexpr int dx[8] = {1, 1, 0, -1, -1, -1, 0, 1};
    static constexpr int dy[8] = {0, 1, 1, 1, 0, -1, -1, -1};
    return static_cast<std::ptrdiff_t>(dy[k]) * width + dx[k];
  }
};

/// Number of skeleton cells among the 8 neighbours of i.
int skeleton_degree(const std::vector<std::uint8_t>& skel, const PaddedRaster& r, std::size_t i);
inline int skeleton_degree(const std::uint8_t* skel, const PaddedRaster& r, std::size_t i) {
  int n = 0;
  for (int k = 0; k < 8; ++k)
    n += skel[static_cast<std::ptrdiff_t>(i) + r.offset(k)] != 0;
  return n;
}

/// Yokoi 8-connectivity number of cell i (1 = simple cell: removing it keeps the topology).
int yokoi8(const std::vector<std::uint8_t>& skel, const PaddedRaster& r, std::size_t i);

/// Removes simple, non-end cells in the given order, pass after pass, until nothing changes.
void thin(std::vector<std::uint8_t>& skel, const PaddedRaster& r,
          const std::vector<std::size_t>& order);

/// Removes spurs: branches from an end cell to a junction shorter than
/// threshold(junction index) [in the same unit as the step lengths, 1 and sqrt 2 per step].
/// Returns the number of removed cells.
std::size_t prune_spurs(std::vector<std::uint8_t>& skel, const PaddedRaster& r,
                        const std::function<double(std::size_t)>& threshold);

}  // namespace voronav::voronoi::internal
