// Plain floor-plan images (white free, black walls), such as the room-segmentation benchmark
// maps: any PGM or PNG becomes an occupancy grid with a chosen resolution. A pixel darker than
// `occupied_below` is occupied, one at least `free_from` bright is free, anything in between
// unknown; the defaults make every pixel either free or occupied (a binary plan).
#pragma once

#include <filesystem>

#include "voronav/core/occupancy.hpp"

namespace voronav::io {

struct FloorplanOptions {
  double resolution = 0.05;  ///< [m/pixel]
  Pose2 origin{};            ///< world pose of the lower-left pixel's corner
  int occupied_below = 128;  ///< grey < this -> occupied
  int free_from = 128;       ///< grey >= this -> free (values in between: unknown)
};

[[nodiscard]] OccupancyGrid load_floorplan(const std::filesystem::path& image,
                                           const FloorplanOptions& options = {});

}  // namespace voronav::io
