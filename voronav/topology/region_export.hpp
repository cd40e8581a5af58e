// Segmentation a user can take away: the region of every cell as a 16-bit label image (0 = no
// region, region id + 1 otherwise; same size and row order as the map image: the top image row
// is the highest cell row), and every region's outline as polygons in the world frame.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "voronav/core/grid_map.hpp"
#include "voronav/core/vec2.hpp"

namespace voronav::topology {

/// Writes `region` (id >= 0 per cell, -1 none) as a 16-bit grey image: .png (libpng, bit depth
/// 16) or .pgm (P5, maxval 65535, big-endian). Throws voronav::Error for another extension, more
/// than 65535 regions or a file that cannot be written.
void write_label_image(const std::filesystem::path& path, const GridMap<std::int32_t>& region);

/// Reads a label image written by write_label_image back (value per cell, 0 = none; 16-bit
/// PGM or 16/8-bit grey PNG). Throws voronav::Error naming the file when it cannot be read.
[[nodiscard]] std::vector<std::vector<std::uint16_t>> read_label_image(
    const std::filesystem::path& path);

/// The outlines of region `id`: closed rings of cell-corner points in the world frame [m], the
/// region on the left (outer rings counter-clockwise, holes clockwise), collinear corners
/// removed. The signed areas of the rings add up to the region's area.
using Ring = std::vector<Vec2>;
[[nodiscard]] std::vector<std::vector<Ring>> region_outlines(const GridMap<std::int32_t>& region,
                                                             int regions);

/// Signed area of a ring [m^2] (positive counter-clockwise).
[[nodiscard]] double ring_area(const Ring& ring);

}  // namespace voronav::topology
