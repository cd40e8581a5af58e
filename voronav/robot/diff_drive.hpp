// Differential-drive robot with wheel encoders and dead-reckoning odometry (seed 004, eq. 1-9).
// The simulated robot keeps its ground-truth pose separately from the odometry estimate, so that
// optional wheel slip and encoder noise make the odometry drift as on a real robot; the paper
// assumes neither (defaults are noise free). Collisions with the world stop the robot and are
// counted, never silently ignored.
#pragma once

#include <cstdint>
#include <random>
#include <span>

#include "voronav/core/occupancy.hpp"
#include "voronav/core/pose2.hpp"
#include "voronav/core/vec2.hpp"

namespace voronav::robot {

/// Geometry, limits and noise of a differential-drive robot. Defaults: the paper's robot
/// (radius 0.12 m, drive 0.3 m/s; seed 004 Table 2) with TurtleBot-like wheels (the paper gives
/// no D or r values).
struct DiffDriveOptions {
  double wheel_distance = 0.20;      ///< D [m], distance between the wheels (eq. 6)
  double wheel_radius = 0.033;       ///< r [m] (eq. 3-4)
  int ticks_per_revolution = 4096;   ///< encoder resolution [ticks/rev]
  double body_radius = 0.12;         ///< collision disc radius [m] (Table 2 robot_radius)
  double max_linear_speed = 0.3;     ///< |v| limit [m/s]
  double max_angular_speed = 1.0;    ///< |omega| limit [rad/s]
  double slip_stddev = 0.0;          ///< relative wheel slip per step (std dev, fraction) [-]
  double encoder_noise_ticks = 0.0;  ///< encoder noise per reading (std dev) [ticks]

  /// Throws voronav::Error naming the offending field for non-positive or non-finite values.
  void validate() const;
};

/// Cumulative wheel encoder counts [ticks].
struct EncoderReading {
  std::int64_t left = 0;
  std::int64_t right = 0;
};

/// Linear velocity v [m/s] and angular velocity omega [rad/s] of the body.
struct BodyVelocity {
  double v = 0.0;
  double omega = 0.0;
};

/// Eq. 1-6: body velocity from two encoder readings taken T seconds apart. The paper's encoder
/// values are in degrees (eq. 1: (E_c - E_p)/T * pi/180); ticks are converted to degrees with
/// 360 / ticks_per_revolution. Throws voronav::Error for T <= 0 or non-finite T.
[[nodiscard]] BodyVelocity velocity_from_encoders(EncoderReading previous, EncoderReading current,
                                                  double T, const DiffDriveOptions& options);

/// Eq. 7-9: one second-order Runge-Kutta step of the unicycle model with time step T [s]:
/// x += T v cos(theta + T omega / 2), y += T v sin(theta + T omega / 2), theta += omega T.
[[nodiscard]] Pose2 runge_kutta_step(const Pose2& pose, BodyVelocity velocity, double T);

/// Dead-reckoning odometry from encoder readings (eq. 1-9).
class Odometry {
 public:
  Odometry(const DiffDriveOptions& options, Pose2 initial, EncoderReading initial_reading = {});
  /// Integrates the motion between the previous reading and `reading`, taken T [s] later.
  void update(EncoderReading reading, double T);
  [[nodiscard]] const Pose2& pose() const { return pose_; }
  [[nodiscard]] BodyVelocity last_velocity() const { return last_velocity_; }

 private:
  DiffDriveOptions options_;
  Pose2 pose_;
  EncoderReading previous_;
  BodyVelocity last_velocity_;
};

/// A disc obstacle other than the static world (another robot) [m].
struct Disc {
  Vec2 center;
  double radius = 0.0;
};

/// True when a disc of `radius` at `center` overlaps a blocked cell of `world` (cells outside
/// the grid count as blocked) or one of `others`.
[[nodiscard]] bool disc_collides(const BinaryGrid& world, Vec2 center, double radius,
                                 std::span<const Disc> others = {});

/// The simulated robot: ground-truth kinematics (exact arc motion), wheel encoders and odometry.
class DiffDriveRobot {
 public:
  /// Throws voronav::Error for invalid options or a non-finite start pose.
  DiffDriveRobot(const DiffDriveOptions& options, Pose2 start, std::uint64_t seed = 0);

  /// Sets the commanded velocity; clamped to the speed and turn-rate limits (NaN -> 0).
  void command(BodyVelocity cmd);
  [[nodiscard]] BodyVelocity commanded() const { return cmd_; }

  /// Advances by dt [s]. If the new pose would overlap `world` or `others`, the robot stays
  /// where it was, its command is zeroed, the collision counter increases and false is returned.
  bool step(double dt, const BinaryGrid& world, std::span<const Disc> others = {});

  [[nodiscard]] const Pose2& true_pose() const { return true_pose_; }
  [[nodiscard]] const Pose2& odometry_pose() const { return odometry_.pose(); }
  [[nodiscard]] EncoderReading encoders() const;
  [[nodiscard]] int collisions() const { return collisions_; }
  /// Ground-truth path length travelled [m].
  [[nodiscard]] double distance_travelled() const { return distance_; }
  [[nodiscard]] const DiffDriveOptions& options() const { return options_; }

 private:
  DiffDriveOptions options_;
  Pose2 true_pose_;
  BodyVelocity cmd_;
  double wheel_angle_left_ = 0.0;  // true cumulative wheel angles [rad]
  double wheel_angle_right_ = 0.0;
  Odometry odometry_;
  std::mt19937_64 rng_;
  int collisions_ = 0;
  double distance_ = 0.0;
};

}  // namespace voronav::robot
