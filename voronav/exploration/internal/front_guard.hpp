// The exploration runner's front guard (issue 14, stop 21; not installed): whether a robot
// driving forward along its route stops this step, and whether a robot or a wall stopped it (the
// right of way acts only on robots). Two rules (ExplorationOptions::guard):
//  * kCone (before stop 21): a 13-beam laser over +-0.7 rad, 1 m; stop when any beam (wall or
//    robot) is shorter than body + 0.12 m. Routes are planned on cells whose centres keep
//    body + clearance (0.22 m) from occupied cell centres, so a legal route may pass a wall corner
//    0.14-0.16 m from its surface (a diagonal past a corner cell, or a (2, 1) cell offset): the
//    cone then stops the robot on a corner beside, not on, its route. Traced on lab_intel (door
//    jam), depot (bans from the 3 s block rule at clutter) and willow (16 robots, frontier seed 1:
//    a crowd of four robots at (33.5, 5) m, one stalled), issue 14 stop 19.
//  * kCorridor (ours): robots are dynamic obstacles and stop the robot as before (a beam that a
//    robot cuts short, within body + 0.12 m); a wall stops it only when the robot's disc of radius
//    body + 0.01 m (the runner's footprint check uses the same) swept along the next 0.12 m of its
//    route would touch it and come nearer to it than the robot is now. A route that keeps the body
//    clear of the walls is driven; a wall on the route (seen only now, e.g. in space that was
//    unknown when the route was planned) still stops it. A route is only legal as planned: a robot
//    that switched to its next waypoint 0.3 m (the waypoint tolerance) before a corner cut the
//    corner on a line the planner never checked (willow, 16 robots, frontier seed 2: 351 of 437
//    wall stops were more than 0.05 m off the route). So with kCorridor the runner switches to
//    the next waypoint early only when line_clear() says the straight line there is clear too;
//    else the robot drives on to within kCornerReach of the waypoint.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include "voronav/core/occupancy.hpp"
#include "voronav/core/pose2.hpp"
#include "voronav/core/vec2.hpp"
#include "voronav/robot/diff_drive.hpp"
#include "voronav/robot/laser.hpp"

namespace voronav::exploration::internal {

enum class GuardRule { kCone, kCorridor };

struct GuardVerdict {
  bool stop = false;
  bool by_robot = false;  ///< a robot (not a wall) stopped it: the right of way applies
};

inline constexpr double kGuardReach = 0.12;      ///< [m] in front of the body
inline constexpr double kCorridorMargin = 0.01;  ///< [m] added to the body radius (footprint check)
inline constexpr double kCornerReach = 0.08;  ///< [m] a waypoint is reached this near (kCorridor)

/// Distance [m] from p to the nearest blocked cell square of `world` (cells off the map count as
/// blocked, as in robot::disc_collides), searched up to `cap` [m]; `cap` when none is nearer.
[[nodiscard]] inline double wall_clearance(const BinaryGrid& world, Vec2 p, double cap) {
  const GridGeometry& g = world.geometry();
  const Vec2 c = g.world_to_grid(p);
  const double rc = cap / g.resolution;
  double best2 = rc * rc;
  const int x0 = static_cast<int>(std::floor(c.x - rc)),
            x1 = static_cast<int>(std::floor(c.x + rc));
  const int y0 = static_cast<int>(std::floor(c.y - rc)),
            y1 = static_cast<int>(std::floor(c.y + rc));
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const Cell cell{x, y};
      if (g.contains(cell) && world[cell] == 0) continue;
      const double dx = std::max({static_cast<double>(x) - c.x, 0.0, c.x - (x + 1.0)});
      const double dy = std::max({static_cast<double>(y) - c.y, 0.0, c.y - (y + 1.0)});
      best2 = std::min(best2, dx * dx + dy * dy);
    }
  return std::sqrt(best2) * g.resolution;
}

/// Points every `step` [m] along the polyline from `from` through route[next], route[next + 1],
/// ... up to `length` [m] (the last point at `length`, or at the route's end when shorter).
[[nodiscard]] inline std::vector<Vec2> route_ahead(Vec2 from, std::span<const Vec2> route,
                                                   std::size_t next, double length, double step) {
  std::vector<Vec2> out;
  double walked = 0.0, next_at = step;
  Vec2 a = from;
  for (std::size_t k = next; k < route.size() && walked < length; ++k) {
    const Vec2 b = route[k];
    const double seg = distance(a, b);
    for (; seg > 0.0 && next_at <= std::min(walked + seg, length) + 1e-9; next_at += step)
      out.push_back(a + (b - a) * ((next_at - walked) / seg));
    walked += seg;
    a = b;
  }
  // The route ends within `length`: its end is the last point.
  if (walked < length && next < route.size() && (out.empty() || distance(out.back(), a) > 1e-9))
    out.push_back(a);
  return out;
}

/// The wall rule of kCorridor: true when the robot's disc (body + kCorridorMargin) at each of
/// `ahead` (points on its way from `from`) either keeps its radius from every wall or is no nearer
/// to one than it is at `from` (a robot already near a wall may drive along or away from it).
[[nodiscard]] inline bool swept_clear(const BinaryGrid& world, Vec2 from,
                                      std::span<const Vec2> ahead, double body) {
  const double r = body + kCorridorMargin, cap = r + 0.02;
  const double now = wall_clearance(world, from, cap);
  for (const Vec2 p : ahead) {
    const double c = wall_clearance(world, p, cap);
    if (c < r && c < now - 1e-3) return false;
  }
  return true;
}

/// The shortest range of `scan` (its range_max when every beam is longer).
[[nodiscard]] inline double nearest_range(const robot::LaserScan& scan) {
  double front = scan.range_max;
  for (float r : scan.ranges)
    front = std::min(front, static_cast<double>(r));
  return front;
}

/// True when the robot's disc (body + kCorridorMargin) swept along the straight line from `from`
/// to `to` keeps clear of the walls by front_guard's wall rule (it never comes within the disc's
/// radius of a wall and nearer than it is at `from`).
[[nodiscard]] inline bool line_clear(const BinaryGrid& world, Vec2 from, Vec2 to, double body) {
  const std::vector<Vec2> line{to};
  return swept_clear(world, from, route_ahead(from, line, 0, distance(from, to), 0.03), body);
}

/// The guard's verdict for a robot at `pose` that wants to drive forward towards route[next]
/// (`others`: the other robots' discs; `laser`: the guard's 13-beam laser; `body` [m]).
[[nodiscard]] inline GuardVerdict front_guard(GuardRule rule, const BinaryGrid& world,
                                              const Pose2& pose, std::span<const Vec2> route,
                                              std::size_t next, std::span<const robot::Disc> others,
                                              double body, const robot::LaserOptions& laser) {
  const double stop_at = body + kGuardReach;
  const robot::LaserScan all = robot::cast_scan(world, pose, laser, others);
  const double front = nearest_range(all);
  GuardVerdict v;
  if (rule == GuardRule::kCone) {
    if (front >= stop_at) return v;
    v.stop = true;
    v.by_robot = nearest_range(robot::cast_scan(world, pose, laser, {})) > front + 0.05;
    return v;
  }
  // kCorridor. Robots: the beams that a robot cuts short (shorter than without the robots).
  if (front < stop_at) {
    const robot::LaserScan walls = robot::cast_scan(world, pose, laser, {});
    for (std::size_t k = 0; k < all.ranges.size(); ++k)
      if (all.ranges[k] < walls.ranges[k] && all.ranges[k] < stop_at) v.by_robot = true;
  }
  // Walls: the disc swept along the route ahead.
  if (!swept_clear(world, pose.position, route_ahead(pose.position, route, next, kGuardReach, 0.02),
                   body)) {
    v.stop = true;
    v.by_robot = false;  // the wall would stop it anyway: no back-off
    return v;
  }
  v.stop = v.by_robot;
  return v;
}

}  // namespace voronav::exploration::internal
