#include "voronav/robot/reactive_controller.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "voronav/core/error.hpp"

namespace voronav::robot {

std::string_view to_string(Heading h) {
  switch (h) {
    case Heading::kForward:
      return "F";
    case Heading::kLeft:
      return "L";
    case Heading::kRight:
      return "R";
    case Heading::kForwardOrLeft:
      return "F or L";
  }
  return "?";
}

std::string_view to_string(ControllerMode m) {
  switch (m) {
    case ControllerMode::kRandom:
      return "random";
    case ControllerMode::kAvoid:
      return "avoid";
    case ControllerMode::kWallFollowLeft:
      return "wall_follow_left";
    case ControllerMode::kWallFollowRight:
      return "wall_follow_right";
  }
  return "?";
}

std::string_view to_string(AvoidEscape e) {
  return e == AvoidEscape::kSpin ? "spin" : "corridor";
}

AvoidEscape parse_avoid_escape(std::string_view name) {
  if (name == "spin") return AvoidEscape::kSpin;
  if (name == "corridor") return AvoidEscape::kCorridor;
  throw Error("--avoid-escape", 0,
              "expected one of spin, corridor; got '" + std::string(name) + "'");
}

double corridor_length(const LaserScan& scan, double bearing, double half_width, double cap) {
  double len = cap;
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    if (!scan.hit(i)) continue;
    const double r = scan.ranges[i];
    const double a = scan.angle(i) - bearing;
    const double along = r * std::cos(a), lateral = r * std::sin(a);
    // A return level with the centre or behind it never comes closer as the disc moves on.
    if (std::abs(lateral) >= half_width || along <= 0.0) continue;
    const double enter = along - std::sqrt(half_width * half_width - lateral * lateral);
    len = std::min(len, std::max(0.0, enter));
  }
  return len;
}

Heading table1_heading(std::uint8_t bits, Table1Variant variant) {
  if (bits > 0b1111)
    throw Error("OBS_bits", 0, "expected a 4-bit value (0..15), got " + std::to_string(bits));
  for (const Table1Row& row : kTable1) {
    if (row.bits != bits) continue;
    if (row.sic && variant == Table1Variant::kCorrected)
      return row.heading == Heading::kLeft ? Heading::kRight : Heading::kLeft;
    return row.heading;
  }
  // Not in the paper: 1011 (free FL) -> L, 1101 (free FR) -> R.
  return bits == 0b1011 ? Heading::kLeft : Heading::kRight;
}

SectorReadings read_sectors(const LaserScan& scan, const SectorOptions& s, double distance) {
  SectorReadings out;
  out.min_range.fill(scan.range_max);
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    const double a = wrap_angle(scan.angle(i));
    int sector = -1;
    if (a <= s.theta_L && a > s.theta_FL)
      sector = 0;
    else if (a <= s.theta_FL && a >= 0.0)
      sector = 1;
    else if (a < 0.0 && a >= s.theta_FR)
      sector = 2;
    else if (a < s.theta_FR && a >= s.theta_R)
      sector = 3;
    if (sector < 0 || !scan.hit(i)) continue;
    const auto k = static_cast<std::size_t>(sector);
    const double r = scan.ranges[i];
    out.min_range[k] = std::min(out.min_range[k], r);
    if (r < distance) ++out.count[k];
  }
  return out;
}

std::uint8_t obs_bits(const LaserScan& scan, const SectorOptions& sectors, double distance) {
  const SectorReadings r = read_sectors(scan, sectors, distance);
  const int t = std::max(1, sectors.counter_threshold);
  std::uint8_t bits = 0;
  if (r.count[0] >= t) bits |= kObsL;
  if (r.count[1] >= t) bits |= kObsFL;
  if (r.count[2] >= t) bits |= kObsFR;
  if (r.count[3] >= t) bits |= kObsR;
  return bits;
}

void ReactiveControllerOptions::validate() const {
  const auto positive = [](double v, const char* name) {
    if (!(v > 0.0) || !std::isfinite(v))
      throw Error(std::string("ReactiveControllerOptions.") + name, 0,
                  "expected a positive finite number, got " + std::to_string(v));
  };
  positive(drive_velocity, "drive_velocity");
  positive(obs_approach, "obs_approach");
  positive(obs_avoid, "obs_avoid");
  positive(approach_dist, "approach_dist");
  positive(obs_dist, "obs_dist");
  positive(desired_wf_dist, "desired_wf_dist");
  positive(wall_detect_dist, "wall_detect_dist");
  positive(wall_lost_time, "wall_lost_time");
  positive(wf_gain, "wf_gain");
  positive(random_period, "random_period");
  positive(escape_after_turn, "escape_after_turn");
  positive(escape_half_width, "escape_half_width");
  positive(escape_min_length, "escape_min_length");
  positive(escape_max_length, "escape_max_length");
  positive(stuck_radius, "stuck_radius");
  if (!(stuck_time >= 0.0)) throw Error("ReactiveControllerOptions.stuck_time", 0, ">= 0");
  if (!(random_turn_rate >= 0.0))
    throw Error("ReactiveControllerOptions.random_turn_rate", 0, ">= 0");
  const SectorOptions& s = sectors;
  if (!(s.theta_L > s.theta_FL && s.theta_FL > 0.0 && 0.0 > s.theta_FR && s.theta_FR > s.theta_R))
    throw Error("SectorOptions", 0, "expected theta_L > theta_FL > 0 > theta_FR > theta_R");
  if (s.counter_threshold < 1) throw Error("SectorOptions.counter_threshold", 0, "expected >= 1");
}

ReactiveController::ReactiveController(const ReactiveControllerOptions& options)
    : options_(options), rng_(options.seed) {
  options_.validate();
}

// The heading (every 10 deg) whose body-wide corridor is free the longest; an escape along it
// starts when it is at least escape_min_length long.
bool ReactiveController::start_escape(const LaserScan& scan) {
  const ReactiveControllerOptions& o = options_;
  double best = 0.0, best_bearing = 0.0;
  for (int k = 0; k < 36; ++k) {
    const double b = wrap_angle(k * 0.17453292519943295);
    const double len = corridor_length(scan, b, o.escape_half_width, 2.0);
    if (len > best + 1e-9) {
      best = len;
      best_bearing = b;
    }
  }
  if (best < o.escape_min_length) return false;
  escape_heading_ = wrap_angle(scan.pose.yaw + best_bearing);
  escape_left_ = std::min(o.escape_max_length, best - 0.05);
  ++escapes_;
  return true;
}

BodyVelocity ReactiveController::update(const LaserScan& scan, double dt) {
  const ReactiveControllerOptions& o = options_;
  const std::uint8_t bits = obs_bits(scan, o.sectors, o.obs_dist);
  last_bits_ = bits;
  const SectorReadings near = read_sectors(scan, o.sectors, o.approach_dist);
  const bool front_seen = near.count[1] > 0 || near.count[2] > 0;
  const double v_nominal = front_seen ? o.obs_approach : o.drive_velocity;  // rule 1

  const auto turn = [&](Heading h) {
    return h == Heading::kRight ? -o.obs_avoid : h == Heading::kForward ? 0.0 : o.obs_avoid;
  };

  // AvoidEscape::kCorridor: a robot that stays on one spot (clutter: avoid turns and short
  // wall-following moves in turn) escapes too.
  stuck_clock_ += dt;
  if (distance(scan.pose.position, stuck_anchor_) > o.stuck_radius) {
    stuck_anchor_ = scan.pose.position;
    stuck_since_ = stuck_clock_;
  } else if (o.avoid_escape == AvoidEscape::kCorridor && o.stuck_time > 0.0 && !escape_heading_ &&
             stuck_clock_ - stuck_since_ > o.stuck_time) {
    stuck_since_ = stuck_clock_;
    start_escape(scan);
  }
  // AvoidEscape::kCorridor: drive out of clutter along the corridor chosen by start_escape.
  if (escape_heading_) {
    const double err = wrap_angle(*escape_heading_ - scan.pose.yaw);
    const double steer = std::clamp(2.0 * err, -o.obs_avoid, o.obs_avoid);
    if (std::abs(err) > 0.15) return {0.0, steer};
    const bool blocked = corridor_length(scan, 0.0, o.escape_half_width, 1.0) < 0.05;
    if (!blocked && escape_left_ > 0.0) {
      escape_left_ -= o.obs_approach * dt;
      return {o.obs_approach, steer};
    }
    escape_heading_.reset();  // done (or blocked): back to the rules
    avoid_turned_ = 0.0;
    mode_ = ControllerMode::kRandom;
    avoid_heading_.reset();
  }

  // Rule 2: an obstacle in front within obs_dist -> turn on the spot by Table 1 until the front
  // is clear. The heading is kept while turning, so the robot does not dither.
  if ((bits & (kObsFL | kObsFR)) != 0) {
    if (mode_ == ControllerMode::kAvoid && o.avoid_escape == AvoidEscape::kCorridor &&
        avoid_turned_ >= o.escape_after_turn) {
      // Turned that far and the front never cleared: escape along a corridor if there is one.
      avoid_turned_ = 0.0;
      if (start_escape(scan)) return {0.0, 0.0};
    }
    if (mode_ != ControllerMode::kAvoid || !avoid_heading_) {
      avoid_turned_ = 0.0;
      Heading h = table1_heading(bits, o.table);
      // "F or L" with both front sectors blocked: forward would hit, so L. A forward heading
      // with a blocked front (cannot come from Table 1 rows with FL/FR set) falls back to L.
      if (h == Heading::kForwardOrLeft || h == Heading::kForward) h = Heading::kLeft;
      avoid_heading_ = h;
    }
    mode_ = ControllerMode::kAvoid;
    avoid_turned_ += o.obs_avoid * dt;
    return {0.0, turn(*avoid_heading_)};
  }
  if (mode_ == ControllerMode::kAvoid) {
    mode_ = ControllerMode::kRandom;
    avoid_heading_.reset();
    avoid_turned_ = 0.0;
  }

  // Rule 3: a wall at the side starts wall following (the nearer side).
  const SectorReadings side = read_sectors(scan, o.sectors, o.wall_detect_dist);
  wall_cooldown_ -= dt;
  if (mode_ == ControllerMode::kRandom && wall_cooldown_ <= 0.0) {
    wall_follow_timer_ = 0.0;
    const bool left = side.count[0] > 0, right = side.count[3] > 0;
    if (left && (!right || side.min_range[0] <= side.min_range[3]))
      mode_ = ControllerMode::kWallFollowLeft;
    else if (right)
      mode_ = ControllerMode::kWallFollowRight;
    wall_lost_timer_ = 0.0;
  }
  if (mode_ == ControllerMode::kWallFollowLeft || mode_ == ControllerMode::kWallFollowRight) {
    const bool left = mode_ == ControllerMode::kWallFollowLeft;
    const double d = side.min_range[left ? 0 : 3];
    double omega = 0.0;
    if (d < o.wall_detect_dist) {
      wall_lost_timer_ = 0.0;
      const double err = d - o.desired_wf_dist;  // > 0: too far from the wall
      omega = std::clamp(o.wf_gain * err, -2.0 * o.obs_avoid, 2.0 * o.obs_avoid);
      if (!left) omega = -omega;
    } else {
      wall_lost_timer_ += dt;
      if (wall_lost_timer_ > o.wall_lost_time) mode_ = ControllerMode::kRandom;  // rule 4
    }
    wall_follow_timer_ += dt;
    if (o.wall_follow_timeout > 0.0 && wall_follow_timer_ > o.wall_follow_timeout) {
      // Leave the wall: turn away from it and ignore walls for a while.
      mode_ = ControllerMode::kRandom;
      wall_cooldown_ = 2.0 * o.random_period;
      random_omega_ = left ? -o.random_turn_rate : o.random_turn_rate;
      random_timer_ = o.random_period;
    }
    if (mode_ != ControllerMode::kRandom) return {v_nominal, omega};
  }

  // Side-only obstacles within obs_dist: steer by Table 1 (L -> R, R -> L, L_R -> F).
  if (bits != 0) return {v_nominal, turn(table1_heading(bits, o.table))};

  // Random driving: a new turn rate every random_period seconds.
  random_timer_ -= dt;
  if (random_timer_ <= 0.0) {
    std::uniform_real_distribution<double> u(-o.random_turn_rate, o.random_turn_rate);
    random_omega_ = u(rng_);
    random_timer_ = o.random_period;
  }
  return {v_nominal, random_omega_};
}

}  // namespace voronav::robot
