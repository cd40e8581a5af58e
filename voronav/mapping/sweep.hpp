// A simulated mapping sweep: a robot senses a ground-truth map from random free poses with a
// laser or a sonar ring and fuses every scan into an occupancy grid (seed 003, eq. 1-3). It is
// how `voronav map` and the demo build a map "from sensors" and measure it against the truth.
#pragma once

#include <cstdint>

#include "voronav/mapping/occupancy_map.hpp"
#include "voronav/mapping/range_simulation.hpp"

namespace voronav::mapping {

enum class SweepSensor { kLaser, kSonar };

struct SweepOptions {
  SweepSensor sensor = SweepSensor::kLaser;
  int poses = 100;            ///< number of sensing poses (>= 1)
  double range = 0.0;         ///< sensor max range [m]; 0 = the sensor's default
  double clearance = 0.3;     ///< poses keep at least this distance [m] from obstacles
  double noise_stddev = 0.0;  ///< laser range noise [m]
  std::uint64_t seed = 1;     ///< poses, headings and noise are drawn from this seed
};

struct SweepResult {
  OccupancyMap map;
  std::vector<Pose2> poses;  ///< where the robot sensed from
  CellAgreement agreement;   ///< of map.threshold() against the truth
};

/// Runs the sweep over `truth` (1 = blocked). Throws voronav::Error when poses < 1 or no free
/// cell keeps the requested clearance.
[[nodiscard]] SweepResult simulate_sweep(const BinaryGrid& truth, const SweepOptions& options = {});

}  // namespace voronav::mapping
