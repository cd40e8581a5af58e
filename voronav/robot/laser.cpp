#include "voronav/robot/laser.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "voronav/core/error.hpp"

namespace voronav::robot {

void LaserOptions::validate() const {
  if (beams <= 0)
    throw Error("LaserOptions.beams", 0, "expected a positive count, got " + std::to_string(beams));
  if (!(field_of_view > 0.0) || field_of_view > 2.0 * std::numbers::pi + 1e-9)
    throw Error("LaserOptions.field_of_view", 0, "expected (0, 2 pi] rad");
  if (!(range_min >= 0.0) || !std::isfinite(range_min))
    throw Error("LaserOptions.range_min", 0, "expected a finite number >= 0");
  if (!(range_max > range_min) || !std::isfinite(range_max))
    throw Error("LaserOptions.range_max", 0, "expected a finite number > range_min");
  if (!(noise_stddev >= 0.0) || !std::isfinite(noise_stddev))
    throw Error("LaserOptions.noise_stddev", 0, "expected a finite number >= 0");
}

Vec2 LaserScan::endpoint(std::size_t i) const {
  const double a = pose.yaw + angle(i);
  return pose.position + Vec2{std::cos(a), std::sin(a)} * static_cast<double>(ranges[i]);
}

double cast_ray(const BinaryGrid& world, Vec2 origin, double angle, double max_range,
                std::span<const Disc> others) {
  const Vec2 dir{std::cos(angle), std::sin(angle)};
  double best = max_range;
  // Discs (other robots): nearest positive root of |origin + t dir - c|^2 = r^2.
  for (const Disc& d : others) {
    const Vec2 oc = origin - d.center;
    const double b = dot(oc, dir), c = oc.squared_norm() - d.radius * d.radius;
    const double disc = b * b - c;
    if (disc < 0.0) continue;
    const double t = -b - std::sqrt(disc);
    if (t >= 0.0 && t < best) best = t;
  }
  const GridGeometry& g = world.geometry();
  if (g.empty()) return best;
  // Traverse in grid units; the grid may be rotated by origin.yaw.
  const Vec2 p = g.world_to_grid(origin);
  const Vec2 d = rotate(dir, -g.origin.yaw);
  const double res = g.resolution;
  const double t_limit = best / res;  // in grid units
  int cx = static_cast<int>(std::floor(p.x)), cy = static_cast<int>(std::floor(p.y));
  const int step_x = d.x > 0 ? 1 : -1, step_y = d.y > 0 ? 1 : -1;
  constexpr double inf = std::numeric_limits<double>::infinity();
  const double delta_x = d.x != 0.0 ? std::abs(1.0 / d.x) : inf;
  const double delta_y = d.y != 0.0 ? std::abs(1.0 / d.y) : inf;
  double t_max_x = d.x > 0 ? (cx + 1.0 - p.x) * delta_x : d.x < 0 ? (p.x - cx) * delta_x : inf;
  double t_max_y = d.y > 0 ? (cy + 1.0 - p.y) * delta_y : d.y < 0 ? (p.y - cy) * delta_y : inf;
  double t = 0.0;
  while (t <= t_limit) {
    const Cell c{cx, cy};
    if (g.contains(c) && world[c] != 0) return std::min(best, t * res);
    if (t_max_x < t_max_y) {
      t = t_max_x;
      t_max_x += delta_x;
      cx += step_x;
    } else {
      t = t_max_y;
      t_max_y += delta_y;
      cy += step_y;
    }
  }
  return best;
}

LaserScan cast_scan(const BinaryGrid& world, const Pose2& pose, const LaserOptions& options,
                    std::span<const Disc> others, std::mt19937_64* rng) {
  options.validate();
  if (!pose.is_finite()) throw Error("cast_scan", 0, "pose must be finite");
  LaserScan scan;
  const bool full = options.field_of_view >= 2.0 * std::numbers::pi - 1e-9;
  scan.angle_increment =
      full ? options.field_of_view / options.beams
           : (options.beams > 1 ? options.field_of_view / (options.beams - 1) : 0.0);
  scan.angle_min = full ? -std::numbers::pi : -options.field_of_view / 2.0;
  scan.range_min = options.range_min;
  scan.range_max = options.range_max;
  scan.pose = pose;
  scan.ranges.resize(static_cast<std::size_t>(options.beams));
  std::normal_distribution<double> noise(0.0, options.noise_stddev);
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    double r = cast_ray(world, pose.position, pose.yaw + scan.angle(i), options.range_max, others);
    if (r < options.range_max && options.noise_stddev > 0.0 && rng != nullptr)
      r = std::clamp(r + noise(*rng), options.range_min, options.range_max - 1e-6);
    scan.ranges[i] = static_cast<float>(r);
  }
  return scan;
}

}  // namespace voronav::robot
