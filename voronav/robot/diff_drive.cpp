#include "voronav/robot/diff_drive.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "voronav/core/error.hpp"
#include "voronav/core/require.hpp"

namespace voronav::robot {
namespace {

void require_positive(double value, const char* name) {
  require_finite_positive(std::string("DiffDriveOptions.") + name, value);
}

void require_non_negative(double value, const char* name) {
  require_finite_nonneg(std::string("DiffDriveOptions.") + name, value);
}

double clamp_finite(double value, double limit) {
  if (!std::isfinite(value)) return 0.0;
  return std::clamp(value, -limit, limit);
}

}  // namespace

void DiffDriveOptions::validate() const {
  require_positive(wheel_distance, "wheel_distance");
  require_positive(wheel_radius, "wheel_radius");
  if (ticks_per_revolution <= 0)
    throw Error("DiffDriveOptions.ticks_per_revolution", 0,
                "expected a positive integer, got " + std::to_string(ticks_per_revolution));
  require_positive(body_radius, "body_radius");
  require_positive(max_linear_speed, "max_linear_speed");
  require_positive(max_angular_speed, "max_angular_speed");
  require_non_negative(slip_stddev, "slip_stddev");
  require_non_negative(encoder_noise_ticks, "encoder_noise_ticks");
}

BodyVelocity velocity_from_encoders(EncoderReading previous, EncoderReading current, double T,
                                    const DiffDriveOptions& options) {
  if (!(T > 0.0) || !std::isfinite(T))
    throw Error("velocity_from_encoders", 0, "T must be a positive finite time step [s]");
  const double degrees_per_tick = 360.0 / static_cast<double>(options.ticks_per_revolution);
  const double deg_l = static_cast<double>(current.left - previous.left) * degrees_per_tick;
  const double deg_r = static_cast<double>(current.right - previous.right) * degrees_per_tick;
  const double v_l = deg_l / T * std::numbers::pi / 180.0;           // eq. 1 [rad/s]
  const double v_r = deg_r / T * std::numbers::pi / 180.0;           // eq. 2
  const double V_l = v_l * options.wheel_radius;                     // eq. 3 [m/s]
  const double V_r = v_r * options.wheel_radius;                     // eq. 4
  return {(V_r + V_l) / 2.0, (V_r - V_l) / options.wheel_distance};  // eq. 5, 6
}

Pose2 runge_kutta_step(const Pose2& pose, BodyVelocity velocity, double T) {
  const double mid = pose.yaw + T * velocity.omega / 2.0;
  return {{pose.position.x + T * velocity.v * std::cos(mid),   // eq. 7
           pose.position.y + T * velocity.v * std::sin(mid)},  // eq. 8
          wrap_angle(pose.yaw + velocity.omega * T)};          // eq. 9
}

Odometry::Odometry(const DiffDriveOptions& options, Pose2 initial, EncoderReading initial_reading)
    : options_(options), pose_(initial), previous_(initial_reading) {
  options_.validate();
}

void Odometry::update(EncoderReading reading, double T) {
  last_velocity_ = velocity_from_encoders(previous_, reading, T, options_);
  pose_ = runge_kutta_step(pose_, last_velocity_, T);
  previous_ = reading;
}

bool disc_collides(const BinaryGrid& world, Vec2 center, double radius,
                   std::span<const Disc> others) {
  for (const Disc& d : others) {
    const double r = radius + d.radius;
    if ((d.center - center).squared_norm() < r * r) return true;
  }
  const GridGeometry& g = world.geometry();
  const Vec2 c = g.world_to_grid(center);
  const double rc = radius / g.resolution;
  if (!c.is_finite()) return true;
  const int x0 = static_cast<int>(std::floor(c.x - rc)),
            x1 = static_cast<int>(std::floor(c.x + rc));
  const int y0 = static_cast<int>(std::floor(c.y - rc)),
            y1 = static_cast<int>(std::floor(c.y + rc));
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const Cell cell{x, y};
      if (g.contains(cell) && world[cell] == 0) continue;
      // Distance from the centre to the cell square [x, x+1] x [y, y+1] (grid units).
      const double dx = std::max({static_cast<double>(x) - c.x, 0.0, c.x - (x + 1.0)});
      const double dy = std::max({static_cast<double>(y) - c.y, 0.0, c.y - (y + 1.0)});
      if (dx * dx + dy * dy < rc * rc) return true;
    }
  }
  return false;
}

DiffDriveRobot::DiffDriveRobot(const DiffDriveOptions& options, Pose2 start, std::uint64_t seed)
    : options_(options), true_pose_(start), odometry_(options, start), rng_(seed) {
  if (!start.is_finite()) throw Error("DiffDriveRobot", 0, "start pose must be finite");
}

void DiffDriveRobot::command(BodyVelocity cmd) {
  cmd_.v = clamp_finite(cmd.v, options_.max_linear_speed);
  cmd_.omega = clamp_finite(cmd.omega, options_.max_angular_speed);
}

EncoderReading DiffDriveRobot::encoders() const {
  const double tpr = static_cast<double>(options_.ticks_per_revolution);
  const auto ticks = [&](double angle) {
    return static_cast<std::int64_t>(std::llround(angle / (2.0 * std::numbers::pi) * tpr));
  };
  return {ticks(wheel_angle_left_), ticks(wheel_angle_right_)};
}

bool DiffDriveRobot::step(double dt, const BinaryGrid& world, std::span<const Disc> others) {
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw Error("DiffDriveRobot::step", 0, "dt must be a positive finite time step [s]");
  const double D = options_.wheel_distance, r = options_.wheel_radius;
  // Wheel rotation commanded (what the encoders see) ...
  const double dphi_l = (cmd_.v - cmd_.omega * D / 2.0) / r * dt;
  const double dphi_r = (cmd_.v + cmd_.omega * D / 2.0) / r * dt;
  // ... and the ground travel of each wheel, which slips.
  double s_l = dphi_l * r, s_r = dphi_r * r;
  if (options_.slip_stddev > 0.0) {
    std::normal_distribution<double> slip(0.0, options_.slip_stddev);
    s_l *= 1.0 + slip(rng_);
    s_r *= 1.0 + slip(rng_);
  }
  const double ds = (s_r + s_l) / 2.0, dtheta = (s_r - s_l) / D;
  // Exact arc motion of the ground truth.
  Pose2 next = true_pose_;
  if (std::abs(dtheta) < 1e-12) {
    next.position += Vec2{std::cos(true_pose_.yaw), std::sin(true_pose_.yaw)} * ds;
  } else {
    const double R = ds / dtheta;
    next.position.x += R * (std::sin(true_pose_.yaw + dtheta) - std::sin(true_pose_.yaw));
    next.position.y -= R * (std::cos(true_pose_.yaw + dtheta) - std::cos(true_pose_.yaw));
  }
  next.yaw = wrap_angle(true_pose_.yaw + dtheta);

  const bool moves = std::abs(ds) > 0.0;
  if (moves && disc_collides(world, next.position, options_.body_radius, others)) {
    ++collisions_;
    cmd_ = {};
    odometry_.update(encoders(), dt);  // wheels did not turn: odometry sees zero motion
    return false;
  }
  distance_ += std::abs(ds);
  true_pose_ = next;
  wheel_angle_left_ += dphi_l;
  wheel_angle_right_ += dphi_r;
  EncoderReading reading = encoders();
  if (options_.encoder_noise_ticks > 0.0) {
    std::normal_distribution<double> noise(0.0, options_.encoder_noise_ticks);
    reading.left += static_cast<std::int64_t>(std::llround(noise(rng_)));
    reading.right += static_cast<std::int64_t>(std::llround(noise(rng_)));
  }
  odometry_.update(reading, dt);
  return true;
}

}  // namespace voronav::robot
