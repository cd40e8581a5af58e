// The 4-sector reactive search controller of seed 004 (section 3.2, Table 1, Table 2): the front
// half of the laser scan is split into the sectors Left, Front-Left, Front-Right and Right; a
// sector is "occupied" when at least `counter_threshold` returns fall inside it within the
// detection distance; OBS_bits = (L, FL, FR, R) from MSB to LSB selects the next heading from
// Table 1. Behaviour rules of the paper: (1) slow down to obs_approach when something is seen,
// (2) turn away at obs_dist, (3) follow a wall seen at the side at desired_wf_dist, (4) return to
// random driving when the wall is lost for a while.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <random>
#include <string_view>

#include "voronav/robot/diff_drive.hpp"
#include "voronav/robot/laser.hpp"

namespace voronav::robot {

/// Next search direction of Table 1.
enum class Heading { kForward, kLeft, kRight, kForwardOrLeft };
[[nodiscard]] std::string_view to_string(Heading h);

/// Bit masks of OBS_bits (L is the MSB, R the LSB).
inline constexpr std::uint8_t kObsL = 0b1000, kObsFL = 0b0100, kObsFR = 0b0010, kObsR = 0b0001;

/// One row of Table 1 exactly as printed. `sic` marks the two rows whose heading turns toward
/// the obstacle (L_FL -> L, FR_R -> R); see docs/reproductions/exploration.md.
struct Table1Row {
  std::string_view state;
  std::uint8_t bits;
  Heading heading;
  bool sic;
};

/// Table 1 of seed 004 (L_F and F_R each cover two bit patterns, so 14 rows).
inline constexpr std::array<Table1Row, 14> kTable1 = {{
    {"CLEAR", 0b0000, Heading::kForward, false},
    {"L", 0b1000, Heading::kRight, false},
    {"R", 0b0001, Heading::kLeft, false},
    {"L_R", 0b1001, Heading::kForward, false},
    {"FL", 0b0100, Heading::kRight, false},
    {"FR", 0b0010, Heading::kLeft, false},
    {"F", 0b0110, Heading::kForwardOrLeft, false},
    {"L_FL", 0b1100, Heading::kLeft, true},
    {"FR_R", 0b0011, Heading::kRight, true},
    {"L_F", 0b1010, Heading::kRight, false},
    {"L_F", 0b1110, Heading::kRight, false},
    {"F_R", 0b0101, Heading::kLeft, false},
    {"F_R", 0b0111, Heading::kLeft, false},
    {"ALL", 0b1111, Heading::kRight, false},
}};

/// Which variant of Table 1 to drive with.
enum class Table1Variant {
  kPaper,      ///< the printed table (L_FL -> L, FR_R -> R)
  kCorrected,  ///< the two "sic" rows turned away from the obstacle (L_FL -> R, FR_R -> L)
};

/// Heading for a 4-bit OBS_bits value. The two patterns the paper does not list are completed
/// by turning toward the free front sector: 1011 (L, FR, R) -> L and 1101 (L, FL, R) -> R.
/// Throws voronav::Error for bits > 15.
[[nodiscard]] Heading table1_heading(std::uint8_t bits,
                                     Table1Variant variant = Table1Variant::kPaper);

/// Sector boundaries [rad] in the ROS convention (counter-clockwise positive). The paper prints
/// thetaR = 90 deg, thetaFR = 40 deg, thetaFL = -40 deg, thetaL = -90 deg (clockwise positive);
/// mirrored to REP-103 this is L = [40, 90] deg, FL = [0, 40], FR = [-40, 0], R = [-90, -40].
struct SectorOptions {
  double theta_L = 1.5707963267948966;    ///< outer edge of L [rad] (+90 deg)
  double theta_FL = 0.6981317007977318;   ///< L / FL boundary [rad] (+40 deg)
  double theta_FR = -0.6981317007977318;  ///< FR / R boundary [rad] (-40 deg)
  double theta_R = -1.5707963267948966;   ///< outer edge of R [rad] (-90 deg)
  int counter_threshold = 1;              ///< returns needed to call a sector occupied (Table 2)
};

/// Per-sector minimum range [m] (range_max when empty) and the count of returns within a
/// distance, in the order L, FL, FR, R.
struct SectorReadings {
  std::array<double, 4> min_range{};
  std::array<int, 4> count{};
};

/// Counts, per sector, the beams of `scan` with a return closer than `distance` [m].
[[nodiscard]] SectorReadings read_sectors(const LaserScan& scan, const SectorOptions& sectors,
                                          double distance);
/// OBS_bits for the returns closer than `distance` [m].
[[nodiscard]] std::uint8_t obs_bits(const LaserScan& scan, const SectorOptions& sectors,
                                    double distance);

/// What rule 2 does when no heading clears the front: the paper says only "avoid" (회피) at
/// obs_dist; we read it as a turn on the spot by Table 1 until the front sectors are clear within
/// obs_dist (kSpin). In clutter no 80 deg cone is clear within obs_dist in any direction and that
/// turn never ends (traced on willow, 16 robots, issue 14). kCorridor (ours, the default): after
/// turning escape_after_turn without a clear front, the robot turns to the heading whose
/// body-wide corridor is free the longest and drives out along it at obs_approach.
enum class AvoidEscape { kSpin, kCorridor };
[[nodiscard]] std::string_view to_string(AvoidEscape e);
/// "spin" / "corridor"; throws voronav::Error naming the accepted values.
[[nodiscard]] AvoidEscape parse_avoid_escape(std::string_view name);

/// Length [m] a disc of radius `half_width` can travel from the sensor along `bearing` [rad,
/// robot frame] before it touches a return of `scan` (capped at `cap`; 0 when it touches one now).
[[nodiscard]] double corridor_length(const LaserScan& scan, double bearing, double half_width,
                                     double cap);

/// Parameters of the controller (Table 2 values where the paper has them).
struct ReactiveControllerOptions {
  SectorOptions sectors;
  Table1Variant table = Table1Variant::kCorrected;  /// see Table1Variant; paper rows trap the robot
  double drive_velocity = 0.3;        ///< [m/s] normal driving (Table 2 drive_velocity)
  double obs_approach = 0.1;          ///< [m/s] speed when approaching an obstacle (Table 2)
  double obs_avoid = 0.3;             ///< [rad/s] turn rate while avoiding (Table 2)
  double approach_dist = 1.0;         ///< [m] an obstacle nearer than this in any sector slows down
  double obs_dist = 0.4;              ///< [m] front obstacle nearer than this: turn by Table 1
  double desired_wf_dist = 0.3;       ///< [m] wall-following distance (Table 2, printed "mm")
  double wall_detect_dist = 0.6;      ///< [m] side obstacle nearer than this starts wall following
  double wall_lost_time = 3.0;        ///< [s] wall not seen this long: back to random driving
  double wall_follow_timeout = 40.0;  ///< [s] leave a wall after this long (0 = never; not in
                                      ///< the paper: without it a robot circles the outer wall)
  double wf_gain = 1.5;               ///< [rad/s per m] wall-following distance gain
  double random_turn_rate = 0.4;      ///< [rad/s] max turn rate of random driving
  double random_period = 4.0;         ///< [s] a new random turn rate is drawn this often
  std::uint64_t seed = 1;             ///< random driving seed
  AvoidEscape avoid_escape = AvoidEscape::kCorridor;  ///< see AvoidEscape
  double escape_after_turn = 3.141592653589793;  ///< [rad] turned in avoid mode before escaping
  double escape_half_width = 0.16;  ///< [m] corridor half-width (body radius 0.12 + 4 cm)
  double escape_min_length = 0.15;  ///< [m] shorter corridors do not count (keep turning)
  double escape_max_length = 1.0;   ///< [m] an escape drives at most this far
  /// [s] kCorridor also escapes when the robot has not left a stuck_radius circle for this long
  /// (dithering between avoid turns and short wall-following moves in clutter; 0 = never).
  double stuck_time = 20.0;
  double stuck_radius = 0.5;  ///< [m]

  void validate() const;
};

enum class ControllerMode { kRandom, kAvoid, kWallFollowLeft, kWallFollowRight };
[[nodiscard]] std::string_view to_string(ControllerMode m);

/// The reactive controller: one update per scan, returns the velocity command.
class ReactiveController {
 public:
  explicit ReactiveController(const ReactiveControllerOptions& options = {});
  BodyVelocity update(const LaserScan& scan, double dt);
  [[nodiscard]] ControllerMode mode() const { return mode_; }
  [[nodiscard]] std::uint8_t last_bits() const { return last_bits_; }
  [[nodiscard]] const ReactiveControllerOptions& options() const { return options_; }
  /// Escapes started (AvoidEscape::kCorridor) since construction.
  [[nodiscard]] int escapes() const { return escapes_; }
  [[nodiscard]] bool escaping() const { return escape_heading_.has_value(); }

 private:
  ReactiveControllerOptions options_;
  std::mt19937_64 rng_;
  ControllerMode mode_ = ControllerMode::kRandom;
  std::optional<Heading> avoid_heading_;
  std::uint8_t last_bits_ = 0;
  double random_omega_ = 0.0;
  double random_timer_ = 0.0;
  double wall_lost_timer_ = 0.0;
  double wall_follow_timer_ = 0.0;
  double wall_cooldown_ = 0.0;            // [s] left during which walls do not start wall following
  double avoid_turned_ = 0.0;             // [rad] turned in the current avoid manoeuvre
  std::optional<double> escape_heading_;  // [rad, world] corridor escape under way
  double escape_left_ = 0.0;              // [m] still to drive on the escape
  int escapes_ = 0;
  Vec2 stuck_anchor_;         // where the robot has stayed since stuck_since_
  double stuck_clock_ = 0.0;  // [s] time since construction (sum of dt)
  double stuck_since_ = 0.0;
  bool start_escape(const LaserScan& scan);
};

}  // namespace voronav::robot
