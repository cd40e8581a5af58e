// Pose2: position [m] and heading yaw [rad, counter-clockwise from +x] in the plane.
// compose/inverse follow the usual SE(2) rules, so a pose maps local points into the world.
#pragma once

#include <cmath>
#include <numbers>
#include <ostream>

#include "voronav/core/vec2.hpp"

namespace voronav {

/// Wraps an angle to (-pi, pi].
[[nodiscard]] inline double wrap_angle(double a) {
  a = std::remainder(a, 2.0 * std::numbers::pi);
  return a <= -std::numbers::pi ? a + 2.0 * std::numbers::pi : a;
}

struct Pose2 {
  Vec2 position;
  double yaw = 0.0;

  /// Maps a point given in this pose's frame into the parent frame.
  [[nodiscard]] Vec2 transform(Vec2 local) const { return position + rotate(local, yaw); }
  /// Maps a point given in the parent frame into this pose's frame.
  [[nodiscard]] Vec2 inverse_transform(Vec2 world) const { return rotate(world - position, -yaw); }
  /// this ∘ other: `other` expressed in this frame, returned in the parent frame.
  [[nodiscard]] Pose2 compose(const Pose2& other) const {
    return {transform(other.position), wrap_angle(yaw + other.yaw)};
  }
  [[nodiscard]] Pose2 inverse() const { return {rotate(-position, -yaw), wrap_angle(-yaw)}; }
  [[nodiscard]] bool is_finite() const { return position.is_finite() && std::isfinite(yaw); }
  friend bool operator==(const Pose2&, const Pose2&) = default;
};

inline std::ostream& operator<<(std::ostream& os, const Pose2& p) {
  return os << '(' << p.position.x << ", " << p.position.y << ", " << p.yaw << ')';
}

}  // namespace voronav
