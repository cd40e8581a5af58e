// Simulated range sensors over a ground-truth map: exact ray casting through the grid
// (Amanatides & Woo cell traversal), a laser scan, and a ring of sonars whose reading is the
// nearest echo inside the cone +-beta (seed 003, figure 1). Used to build maps from a simulated
// sweep (`voronav map`) and to compare the result with the ground truth (cell agreement).
#pragma once

#include <cstdint>
#include <numbers>
#include <vector>

#include "voronav/core/occupancy.hpp"
#include "voronav/mapping/occupancy_map.hpp"

namespace voronav::mapping {

/// Distance [m] from `origin` (world) along the direction `angle` [rad, world frame] to the
/// boundary of the first blocked cell of `world`, or max_range when none is closer. Leaving the
/// grid counts as no echo. Throws voronav::Error for non-finite input or max_range <= 0.
[[nodiscard]] double cast_ray(const BinaryGrid& world, Vec2 origin, double angle, double max_range);

struct LaserSimulationOptions {
  int beams = 360;  ///< number of readings, evenly over the fov (>= 1)
  double field_of_view = 2.0 * std::numbers::pi;  ///< [rad], (0, 2 pi]
  double max_range = 10.0;                        ///< [m]
  double noise_stddev = 0.0;                      ///< Gaussian range noise [m] (>= 0)
  std::uint64_t seed = 1;                         ///< noise seed (same seed, same scan)
};

/// A laser scan from `pose`; bearings from -fov/2 to +fov/2 (the whole circle when fov = 2 pi).
[[nodiscard]] RangeScan simulate_laser_scan(const BinaryGrid& world, const Pose2& pose,
                                            const LaserSimulationOptions& options = {});

struct SonarRingOptions {
  int sonars = 16;  ///< transducers evenly around the robot (>= 1)
  double half_angle = 12.5 * std::numbers::pi / 180.0;  ///< cone half angle beta [rad]
  double max_range = 5.0;                               ///< [m]
  int rays_per_cone = 9;  ///< rays cast across the cone; the reading is their minimum (>= 1)
};

/// One reading per sonar of a ring: the nearest echo in its cone (max_range when none).
[[nodiscard]] RangeScan simulate_sonar_ring(const BinaryGrid& world, const Pose2& pose,
                                            const SonarRingOptions& options = {});

struct CellAgreement {
  double agreement = 0.0;    ///< fraction of observed cells whose state equals the truth (0..1)
  double observed = 0.0;     ///< fraction of all cells the map knows (not unknown) (0..1)
  std::size_t compared = 0;  ///< number of observed cells
};

/// Compares a map (values 0..100, -1 unknown; >= 50 = occupied) with the ground truth
/// (1 = blocked). Throws voronav::Error when the sizes differ.
[[nodiscard]] CellAgreement cell_agreement(const OccupancyGrid& map, const BinaryGrid& truth);

}  // namespace voronav::mapping
