// ROS map_server maps: a YAML file (image, resolution, origin [x, y, yaw], negate,
// occupied_thresh, free_thresh, mode) next to a PGM or PNG image, read and written with the pixel
// rules of the ROS 2 map_server (nav2_map_server map_io): image row j is map row H-1-j; the
// occupancy of a pixel is occ = 1 - shade/255 (or shade/255 with negate); trinary:
// occ > occupied_thresh -> occupied, occ < free_thresh -> free, else unknown; scale: the same but
// values in between are scaled to 1..99 and transparent pixels are unknown; raw: the pixel value
// itself (0..100), anything else unknown. Saving writes 254 free, 0 occupied, 205 unknown.
#pragma once

#include <filesystem>
#include <string>

#include "voronav/core/occupancy.hpp"
#include "voronav/io/image.hpp"

namespace voronav::io {

enum class RosMapMode { kTrinary, kScale, kRaw };

struct RosMapMetadata {
  std::filesystem::path image;  ///< as written in the YAML (relative to the YAML's folder)
  double resolution = 0.05;     ///< [m/cell]
  Pose2 origin;                 ///< pose of the lower-left pixel's corner [m, m, rad]
  bool negate = false;
  double occupied_thresh = 0.65;
  double free_thresh = 0.25;
  RosMapMode mode = RosMapMode::kTrinary;
};

struct RosMap {
  OccupancyGrid grid;
  RosMapMetadata metadata;
};

/// Loads a ROS map YAML and its image. Throws voronav::Error with the file and line of anything
/// malformed (missing key, bad number, threshold out of range, missing or unreadable image).
[[nodiscard]] RosMap read_ros_map(const std::filesystem::path& yaml_path);
[[nodiscard]] inline OccupancyGrid load_ros_map(const std::filesystem::path& yaml_path) {
  return read_ros_map(yaml_path).grid;
}

/// Converts an image (top row first) into an occupancy grid by the map_server rules above.
[[nodiscard]] OccupancyGrid image_to_occupancy(const GrayImage& image,
                                               const RosMapMetadata& metadata);

struct SaveRosMapOptions {
  RosMapMode mode = RosMapMode::kTrinary;
  double occupied_thresh = 0.65;
  /// 0.196 (ROS 1 map_saver's value) rather than ROS 2's 0.25, so that the unknown shade 205
  /// (occ = 0.196) reads back as unknown instead of free: save + load is the identity.
  double free_thresh = 0.196;
  /// Image format by extension of this name (".pgm" or ".png"); empty: <yaml stem>.pgm.
  std::string image_name{};
};

/// Writes `grid` as a YAML + image pair the way map_saver does. Returns the image path.
std::filesystem::path save_ros_map(const OccupancyGrid& grid,
                                   const std::filesystem::path& yaml_path,
                                   const SaveRosMapOptions& options = {});

[[nodiscard]] const char* to_string(RosMapMode mode);

}  // namespace voronav::io
