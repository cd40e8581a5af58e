#include "voronav/mapping/sweep.hpp"

#include <cmath>
#include <numbers>
#include <random>

#include "voronav/core/error.hpp"
#include "voronav/field/distance_transform.hpp"

namespace voronav::mapping {

SweepResult simulate_sweep(const BinaryGrid& truth, const SweepOptions& o) {
  if (o.poses < 1) throw Error("sweep poses", 0, "expected at least 1 pose");
  if (!(o.clearance >= 0) || !std::isfinite(o.clearance))
    throw Error("sweep clearance", 0, "expected a finite clearance >= 0 [m]");
  if (!(o.range >= 0) || !std::isfinite(o.range))
    throw Error("sweep range", 0, "expected a finite range >= 0 [m] (0 = sensor default)");
  const GridGeometry& geo = truth.geometry();
  const field::DistanceField df = field::distance_transform(truth, {.border_is_blocked = true});
  std::vector<Cell> candidates;
  const double min_d = o.clearance / geo.resolution;
  for (std::size_t i = 0; i < truth.size(); ++i)
    if (!truth[i] && std::sqrt(static_cast<double>(df.squared_distance[i])) >= min_d)
      candidates.push_back(geo.cell_at(i));
  if (candidates.empty())
    throw Error("--clearance", 0,
                "no free cell of the map keeps " + std::to_string(o.clearance) +
                    " m from obstacles (sweep clearance); give a smaller --clearance");
  std::mt19937_64 rng(o.seed);
  std::uniform_int_distribution<std::size_t> pick(0, candidates.size() - 1);
  std::uniform_real_distribution<double> yaw(-std::numbers::pi, std::numbers::pi);
  SweepResult out{OccupancyMap(geo), {}, {}};
  LaserSimulationOptions laser;
  laser.noise_stddev = o.noise_stddev;
  SonarRingOptions sonar;
  if (o.range > 0) laser.max_range = sonar.max_range = o.range;
  SonarModelOptions sonar_model;
  sonar_model.max_range = sonar.max_range;
  LaserModelOptions laser_model;
  laser_model.max_range = laser.max_range;
  for (int k = 0; k < o.poses; ++k) {
    const Pose2 pose{geo.cell_center(candidates[pick(rng)]), yaw(rng)};
    out.poses.push_back(pose);
    laser.seed = o.seed + static_cast<std::uint64_t>(k);
    if (o.sensor == SweepSensor::kLaser)
      out.map.insert_scan(simulate_laser_scan(truth, pose, laser), laser_model);
    else
      out.map.insert_scan(simulate_sonar_ring(truth, pose, sonar), sonar_model);
  }
  out.agreement = cell_agreement(out.map.threshold(), truth);
  return out;
}

}  // namespace voronav::mapping
