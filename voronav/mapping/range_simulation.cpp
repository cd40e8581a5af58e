#include "voronav/mapping/range_simulation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "voronav/core/error.hpp"

namespace voronav::mapping {

double cast_ray(const BinaryGrid& world, Vec2 origin, double angle, double max_range) {
  if (!origin.is_finite() || !std::isfinite(angle))
    throw Error("cast_ray", 0, "the ray origin and angle must be finite");
  if (!(max_range > 0.0) || !std::isfinite(max_range))
    throw Error("cast_ray", 0, "expected max_range > 0 [m], got " + std::to_string(max_range));
  const GridGeometry& g = world.geometry();
  if (world.empty()) return max_range;
  const Vec2 p = g.world_to_grid(origin);
  const Vec2 d = rotate({std::cos(angle), std::sin(angle)}, -g.origin.yaw);
  const double t_max = max_range / g.resolution;  // in cells
  int x = static_cast<int>(std::floor(p.x));
  int y = static_cast<int>(std::floor(p.y));
  const int step_x = d.x > 0 ? 1 : -1;
  const int step_y = d.y > 0 ? 1 : -1;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const double dt_x = d.x != 0.0 ? std::abs(1.0 / d.x) : kInf;
  const double dt_y = d.y != 0.0 ? std::abs(1.0 / d.y) : kInf;
  double t_x = d.x != 0.0 ? ((d.x > 0 ? (x + 1 - p.x) : (p.x - x)) * dt_x) : kInf;
  double t_y = d.y != 0.0 ? ((d.y > 0 ? (y + 1 - p.y) : (p.y - y)) * dt_y) : kInf;
  double t = 0.0;
  while (t <= t_max) {
    const Cell c{x, y};
    if (!g.contains(c)) {
      // Outside the grid: stop once the ray moves away from it for good.
      const bool leaving = (x < 0 && step_x < 0) || (x >= g.width && step_x > 0) ||
                           (y < 0 && step_y < 0) || (y >= g.height && step_y > 0);
      if (leaving) return max_range;
    } else if (world[c] != 0) {
      return std::min(max_range, t * g.resolution);
    }
    if (t_x < t_y) {
      t = t_x;
      t_x += dt_x;
      x += step_x;
    } else {
      t = t_y;
      t_y += dt_y;
      y += step_y;
    }
  }
  return max_range;
}

RangeScan simulate_laser_scan(const BinaryGrid& world, const Pose2& pose,
                              const LaserSimulationOptions& o) {
  if (o.beams < 1) throw Error("LaserSimulationOptions.beams", 0, "expected >= 1");
  if (!(o.field_of_view > 0.0 && o.field_of_view <= 2.0 * std::numbers::pi + 1e-12))
    throw Error("LaserSimulationOptions.field_of_view", 0,
                "expected (0, 2 pi] [rad], got " + std::to_string(o.field_of_view));
  if (!(o.noise_stddev >= 0.0) || !std::isfinite(o.noise_stddev))
    throw Error("LaserSimulationOptions.noise_stddev", 0, "expected >= 0 [m]");
  if (!pose.is_finite()) throw Error("simulate_laser_scan", 0, "the pose is not finite");
  RangeScan scan;
  scan.pose = pose;
  scan.bearings.resize(static_cast<std::size_t>(o.beams));
  scan.ranges.resize(static_cast<std::size_t>(o.beams));
  const bool full = o.field_of_view >= 2.0 * std::numbers::pi - 1e-12;
  const double step =
      full ? o.field_of_view / o.beams : (o.beams > 1 ? o.field_of_view / (o.beams - 1) : 0.0);
  const double first = o.beams > 1 || full ? -o.field_of_view / 2 : 0.0;
  std::mt19937_64 rng(o.seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  for (int i = 0; i < o.beams; ++i) {
    const double b = first + step * i;
    double r = cast_ray(world, pose.position, pose.yaw + b, o.max_range);
    if (o.noise_stddev > 0.0 && r < o.max_range)
      r = std::clamp(r + o.noise_stddev * noise(rng), 0.0, o.max_range);
    scan.bearings[static_cast<std::size_t>(i)] = b;
    scan.ranges[static_cast<std::size_t>(i)] = r;
  }
  return scan;
}

RangeScan simulate_sonar_ring(const BinaryGrid& world, const Pose2& pose,
                              const SonarRingOptions& o) {
  if (o.sonars < 1 || o.rays_per_cone < 1)
    throw Error("SonarRingOptions", 0, "expected sonars >= 1 and rays_per_cone >= 1");
  if (!(o.half_angle > 0.0 && o.half_angle < std::numbers::pi / 2))
    throw Error("SonarRingOptions.half_angle", 0, "expected 0 < beta < pi/2 [rad]");
  if (!pose.is_finite()) throw Error("simulate_sonar_ring", 0, "the pose is not finite");
  RangeScan scan;
  scan.pose = pose;
  for (int s = 0; s < o.sonars; ++s) {
    const double axis = 2.0 * std::numbers::pi * s / o.sonars;
    double r = o.max_range;
    for (int k = 0; k < o.rays_per_cone; ++k) {
      const double off = o.rays_per_cone == 1
                             ? 0.0
                             : -o.half_angle + 2.0 * o.half_angle * k / (o.rays_per_cone - 1);
      r = std::min(r, cast_ray(world, pose.position, pose.yaw + axis + off, o.max_range));
    }
    scan.bearings.push_back(axis);
    scan.ranges.push_back(r);
  }
  return scan;
}

CellAgreement cell_agreement(const OccupancyGrid& map, const BinaryGrid& truth) {
  if (map.width() != truth.width() || map.height() != truth.height())
    throw Error("cell_agreement", 0,
                "the map is " + std::to_string(map.width()) + "x" + std::to_string(map.height()) +
                    " but the truth is " + std::to_string(truth.width()) + "x" +
                    std::to_string(truth.height()));
  CellAgreement out;
  std::size_t same = 0;
  for (std::size_t i = 0; i < map.size(); ++i) {
    if (map[i] < 0) continue;
    ++out.compared;
    if ((map[i] >= 50) == (truth[i] != 0)) ++same;
  }
  out.observed = map.empty() ? 0.0 : static_cast<double>(out.compared) / map.size();
  out.agreement = out.compared == 0 ? 0.0 : static_cast<double>(same) / out.compared;
  return out;
}

}  // namespace voronav::mapping
