#include "voronav/io/map_loader.hpp"

#include <algorithm>
#include <cctype>
#include <system_error>

#include "voronav/core/error.hpp"
#include "voronav/io/movingai.hpp"
#include "voronav/io/ros_map.hpp"

namespace voronav::io {

const char* to_string(MapFormat format) {
  switch (format) {
    case MapFormat::kRos:
      return "ros";
    case MapFormat::kMovingAi:
      return "movingai";
    case MapFormat::kImage:
      return "image";
  }
  return "?";
}

LoadedMap load_map(const std::filesystem::path& path, const FloorplanOptions& image_options) {
  std::error_code ec;  // no throw for names the file system refuses (too long, ...)
  if (!std::filesystem::exists(path, ec))
    throw Error(path.string(), 0,
                "map file not found" + (ec ? " (" + ec.message() + ")" : std::string()));
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".yaml" || ext == ".yml") return {read_ros_map(path).grid, MapFormat::kRos, path};
  if (ext == ".map") return {load_movingai_map(path), MapFormat::kMovingAi, path};
  if (ext == ".png" || ext == ".pgm")
    return {load_floorplan(path, image_options), MapFormat::kImage, path};
  throw Error(
      path.string(), 0,
      "unknown map format '" + ext +
          "': expected .yaml (ROS map_server), .map (Moving AI), or a .png/.pgm floor plan");
}

}  // namespace voronav::io
