// The exploration runner's right of way (issue 14; not installed): which robot backs off when
// the front guard stops a robot because of another robot (not a wall). Before issue 14's
// lab_intel trace only the higher index backed off; a robot that tailgated a lower-index robot
// held up by a door corner then boxed it in, neither moved for 60 s (8 robots, frontier, seed 4:
// stalled). With yield_to_held a robot also backs off from a robot in front of it that is held up
// itself (blocked while following its route and not backing off), whatever their indices, so the
// held-up robot gets room to turn away. A head-on pair still resolves by index: the higher index
// backs off at once, so the lower one never sees it held up and does not back off too.
// ExplorationOptions::unstick_right_of_way (stop 28): a robot on an unstick route (its way out of
// a spot where the progress watchdog found it) goes before the robots that are not on one,
// whatever their indices; among the rest the rules above hold. Without it the highest index in a
// crowd (willow, 16 robots, tree, seed 9 with unstick_retry: robot 15 among ten robots on their
// tree legs) backed off from every robot it met and stayed 60 s.
#pragma once

#include <cmath>

#include "voronav/core/pose2.hpp"
#include "voronav/core/vec2.hpp"

namespace voronav::exploration::internal {

/// The other robot as the right of way sees it.
struct RightOfWayPeer {
  int index = 0;
  Vec2 position;            ///< [m]
  bool held = false;        ///< following a route, its block clock > 0.5 s, and not backing off
  bool unsticking = false;  ///< on an unstick route (ExplorationOptions::unstick_right_of_way)
};

/// True when the robot `self_index` at `self`, stopped by the guard because of a robot, backs
/// off for `other`: the other is within `contact` [m] (the runner: two body radii + 0.3 m) and
/// has the lower index, or (yield_to_held) it is held up and lies in front (|bearing| < 0.9 rad,
/// the guard's half field of view + 0.2 rad). With `unstick_first`, when exactly one of the two is
/// on an unstick route (`self_unsticking`, other.unsticking), that one goes first: the other
/// backs off, whatever the indices.
[[nodiscard]] inline bool backs_off_for(int self_index, const Pose2& self,
                                        const RightOfWayPeer& other, double contact,
                                        bool yield_to_held, bool self_unsticking = false,
                                        bool unstick_first = false) {
  const Vec2 d = other.position - self.position;
  if (other.index == self_index || d.norm() >= contact) return false;
  if (unstick_first && self_unsticking != other.unsticking) return other.unsticking;
  if (other.index < self_index) return true;
  const double bearing = wrap_angle(std::atan2(d.y, d.x) - self.yaw);
  return yield_to_held && other.held && std::abs(bearing) < 0.9;
}

}  // namespace voronav::exploration::internal
