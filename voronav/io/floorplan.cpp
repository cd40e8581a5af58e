#include "voronav/io/floorplan.hpp"

#include <cmath>

#include "voronav/core/error.hpp"
#include "voronav/io/image.hpp"

namespace voronav::io {

OccupancyGrid load_floorplan(const std::filesystem::path& path, const FloorplanOptions& o) {
  if (!(o.resolution > 0) || !std::isfinite(o.resolution))
    throw Error(path.string(), 0, "floor plan resolution must be a positive number [m/pixel]");
  if (o.occupied_below < 0 || o.free_from > 256 || o.occupied_below > o.free_from)
    throw Error(path.string(), 0,
                "floor plan thresholds: expected 0 <= occupied_below <= free_from <= 256");
  const GrayImage img = read_image(path);
  OccupancyGrid grid(GridGeometry{img.width, img.height, o.resolution, o.origin}, kUnknown);
  for (int j = 0; j < img.height; ++j)
    for (int x = 0; x < img.width; ++x) {
      const int v = img.at(x, j);
      grid[Cell{x, img.height - 1 - j}] =
          v < o.occupied_below ? kOccupied : (v >= o.free_from ? kFree : kUnknown);
    }
  return grid;
}

}  // namespace voronav::io
