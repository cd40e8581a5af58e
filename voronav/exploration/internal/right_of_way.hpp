// The exploration runner's right of way (issue 14; not installed): which robot backs off when
// the front guard stops a robot because of another robot (not a wall). Before issue 14's
// lab_intel trace only the higher index backed off; a robot that tailgated a lower-index robot
// held up by a door corner then boxed it in, neither moved for 60 s (8 robots, frontier, seed 4:
// stalled). With yield_to_held a robot also backs off from a robot in front of it that is held up
// itself (blocked while following its route and not backing off), whatever their indices, so the
// held-up robot gets room to turn away. A head-on pair still resolves by index: the higher index
// backs off at once, so the lower one never sees it held up and does not back off too.
#pragma once

#include <cmath>

#include "voronav/core/pose2.hpp"
#include "voronav/core/vec2.hpp"

namespace voronav::exploration::internal {

/// The other robot as the right of way sees it.
struct RightOfWayPeer {
  int index = 0;
  Vec2 position;      ///< [m]
  bool held = false;  ///< following a route, its block clock > 0.5 s, and not backing off
};

/// True when the robot `self_index` at `self`, stopped by the guard because of a robot, backs
/// off for `other`: the other is within `contact` [m] (the runner: two body radii + 0.3 m) and
/// has the lower index, or (yield_to_held) it is held up and lies in front (|bearing| < 0.9 rad,
/// the guard's half field of view + 0.2 rad).
[[nodiscard]] inline bool backs_off_for(int self_index, const Pose2& self,
                                        const RightOfWayPeer& other, double contact,
                                        bool yield_to_held) {
  const Vec2 d = other.position - self.position;
  if (other.index == self_index || d.norm() >= contact) return false;
  if (other.index < self_index) return true;
  const double bearing = wrap_angle(std::atan2(d.y, d.x) - self.yaw);
  return yield_to_held && other.held && std::abs(bearing) < 0.9;
}

}  // namespace voronav::exploration::internal
