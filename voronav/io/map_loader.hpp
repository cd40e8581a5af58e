// load_map: one entry point for every map file voronav reads, chosen by extension — ROS
// map_server YAML (.yaml/.yml), Moving AI (.map), plain floor-plan images (.png/.pgm). The format
// is returned too, because it decides the coordinate convention users speak (cells for .map
// files, metres for the others).
#pragma once

#include <filesystem>

#include "voronav/core/occupancy.hpp"
#include "voronav/io/floorplan.hpp"

namespace voronav::io {

enum class MapFormat { kRos, kMovingAi, kImage };

struct LoadedMap {
  OccupancyGrid grid;
  MapFormat format = MapFormat::kRos;
  std::filesystem::path source;
};

/// Loads any supported map; throws voronav::Error for a missing file, unknown extension or
/// malformed content.
[[nodiscard]] LoadedMap load_map(const std::filesystem::path& path,
                                 const FloorplanOptions& image_options = {});

[[nodiscard]] const char* to_string(MapFormat format);

}  // namespace voronav::io
