// Simulated laser range finder (seed 004, section 3.2): ray casting in the world grid with the
// ROS sensor_msgs/LaserScan conventions: beam i points at angle_min + i * angle_increment [rad],
// counter-clockwise from the robot's +x axis; a beam that hits nothing within range_max reports
// range_max (the paper substitutes Max_range for readings beyond the detection range).
#pragma once

#include <cstdint>
#include <random>
#include <span>
#include <vector>

#include "voronav/core/occupancy.hpp"
#include "voronav/core/pose2.hpp"
#include "voronav/robot/diff_drive.hpp"

namespace voronav::robot {

/// Laser parameters. Table 2 prints Max_range = 300 "mm" and Min_range = 0; 0.3 m cannot see a
/// 20 x 20 m world, so we read it as 3.0 m (a typical short-range LRF such as the TurtleBot3's
/// LDS-01 reaches 3.5 m) and document the choice in docs/reproductions/exploration.md.
struct LaserOptions {
  int beams = 360;                           ///< number of beams over the field of view
  double field_of_view = 6.283185307179586;  ///< [rad]; 2 pi = full circle
  double range_min = 0.0;                    ///< [m] (Table 2 Min_range)
  double range_max = 3.0;                    ///< [m] (Table 2 Max_range, see above)
  double noise_stddev = 0.0;                 ///< Gaussian range noise [m]; 0 = exact

  /// Throws voronav::Error naming the field for invalid values.
  void validate() const;
};

/// A scan in the ROS LaserScan layout.
struct LaserScan {
  double angle_min = 0.0;        ///< [rad] angle of beam 0 in the sensor frame
  double angle_increment = 0.0;  ///< [rad] between beams (> 0: counter-clockwise)
  double range_min = 0.0;        ///< [m]
  double range_max = 0.0;        ///< [m]
  std::vector<float> ranges;     ///< [m]; == range_max: no return
  Pose2 pose;                    ///< world pose of the sensor when the scan was taken

  [[nodiscard]] double angle(std::size_t i) const {
    return angle_min + static_cast<double>(i) * angle_increment;
  }
  /// True when beam i returned an obstacle (range < range_max).
  [[nodiscard]] bool hit(std::size_t i) const {
    return ranges[i] < static_cast<float>(range_max) && ranges[i] >= static_cast<float>(range_min);
  }
  /// World position of the end of beam i.
  [[nodiscard]] Vec2 endpoint(std::size_t i) const;
};

/// Distance [m] from `origin` along `angle` (world frame) to the first blocked cell of `world`
/// or disc in `others`, exact for grid cells (Amanatides-Woo traversal); max_range when nothing
/// is hit. Cells outside the grid are free (the world is assumed walled).
[[nodiscard]] double cast_ray(const BinaryGrid& world, Vec2 origin, double angle, double max_range,
                              std::span<const Disc> others = {});

/// A full scan from `pose`. `rng` is used only when options.noise_stddev > 0.
[[nodiscard]] LaserScan cast_scan(const BinaryGrid& world, const Pose2& pose,
                                  const LaserOptions& options, std::span<const Disc> others = {},
                                  std::mt19937_64* rng = nullptr);

}  // namespace voronav::robot
