// OccupancyMap: a probabilistic occupancy grid built from range sensors (seed 003, section II).
// Each cell holds the log-odds l = log(P/(1-P)) of being occupied. The paper's recursive Bayesian
// update (seed 003, eq. 2-3) with the inverse sensor model P(OCC|d) becomes an addition in
// log-odds: l_t = l_{t-1} + logit(P(OCC|d_t)) - logit(prior), which is numerically safe; the
// prior is 0.5 (l = 0) everywhere and the value is clamped so that a cell can change its mind.
//
// Sensor models:
//  - sonar (seed 003, eq. 1): inside the cone +-beta of the beam axis, a cell at range r from the
//    sensor gets an occupancy shaped by the Gaussian p(d|r) = exp(-(r-d)^2/(2 sigma^2)) /
//    (sqrt(2 pi) sigma) with sigma = cell size; cells well before d are empty, cells behind the
//    echo (occluded, r > d + 3 sigma) keep probability 0.5, i.e. are not updated.
//  - laser: one thin beam per reading, traced cell by cell (Bresenham): the cells it crosses are
//    empty, the end cell is occupied; a max-range reading only clears.
#pragma once

#include <cstdint>
#include <numbers>
#include <span>
#include <vector>

#include "voronav/core/grid_map.hpp"
#include "voronav/core/occupancy.hpp"
#include "voronav/core/pose2.hpp"

namespace voronav::mapping {

struct OccupancyMapOptions {
  /// Prior probability of occupancy of every cell (seed 003: 0.5) (0..1 exclusive).
  double prior = 0.5;
  /// The probability is clamped to [clamp_min, clamp_max] after every update, so that a cell
  /// seen occupied many times can still be cleared (0 < clamp_min < prior < clamp_max < 1).
  double clamp_min = 0.12;
  double clamp_max = 0.97;
};

/// Inverse model of a sonar (seed 003, eq. 1 and figure 1).
struct SonarModelOptions {
  /// Half opening angle beta of the cone [rad] (a Polaroid 6500 transducer: about 12.5 deg).
  double half_angle = 12.5 * std::numbers::pi / 180.0;
  /// Readings at or beyond this range [m] are "no echo": the cone is cleared up to max_range.
  double max_range = 5.0;
  /// sigma of the Gaussian [m]; 0 = the cell size (seed 003).
  double sigma = 0.0;
  /// Occupancy probability at the peak of the Gaussian (r = d) (0.5..1).
  double p_occupied = 0.9;
  /// Occupancy probability of the cells well before the echo (0..0.5).
  double p_empty = 0.3;
};

/// Inverse model of a laser range finder beam.
struct LaserModelOptions {
  /// Readings at or beyond this range [m] are "no return": the beam only clears.
  double max_range = 10.0;
  double p_occupied = 0.85;  ///< probability given to the end cell (0.5..1)
  double p_empty = 0.35;     ///< probability given to the crossed cells (0..0.5)
};

/// A set of range readings taken from one sensor pose. bearings[i] [rad] is the beam direction in
/// the sensor frame, ranges[i] [m] the measured distance (>= max_range or +inf = no echo).
struct RangeScan {
  Pose2 pose;  ///< sensor pose in the world [m, rad]
  std::vector<double> bearings;
  std::vector<double> ranges;
};

/// Thresholds from probability to the discrete ROS values (0 free, 100 occupied, -1 unknown).
struct ThresholdOptions {
  double free_below = 0.35;      ///< P < this -> free (0)
  double occupied_above = 0.65;  ///< P > this -> occupied (100); in between -> unknown (-1)
  /// For to_binary(): whether unknown cells are blocked.
  bool unknown_is_blocked = true;
};

class OccupancyMap {
 public:
  /// Throws voronav::Error for an empty/invalid geometry or inconsistent options.
  explicit OccupancyMap(GridGeometry geometry, const OccupancyMapOptions& options = {});

  [[nodiscard]] const GridGeometry& geometry() const { return log_odds_.geometry(); }
  [[nodiscard]] const OccupancyMapOptions& options() const { return options_; }
  /// The raw log-odds grid (0 = prior 0.5).
  [[nodiscard]] const GridMap<float>& log_odds() const { return log_odds_; }
  /// P(OCC) of a cell (checked: throws voronav::Error outside the grid).
  [[nodiscard]] double probability(Cell c) const;
  /// Whether any measurement changed the cell away from the prior.
  [[nodiscard]] bool observed(Cell c) const;

  /// One Bayesian update (seed 003, eq. 2) of a cell with the measured P(OCC|d) (0..1).
  /// p = 0.5 leaves the cell unchanged. Cells outside the grid are ignored.
  void update(Cell c, double p_occupied);

  /// Inserts one sonar reading from a sensor pose (beam axis = pose yaw). Throws voronav::Error
  /// for a non-finite pose, a negative or NaN range, or invalid options.
  void insert_sonar(const Pose2& sensor, double range, const SonarModelOptions& model = {});
  /// Inserts every reading of a scan with the sonar model (the bearing rotates the beam axis).
  void insert_scan(const RangeScan& scan, const SonarModelOptions& model);
  /// Inserts every reading of a scan with the laser beam model.
  void insert_scan(const RangeScan& scan, const LaserModelOptions& model);

  /// ROS occupancy values: -1 where never observed, else round(100 P).
  [[nodiscard]] OccupancyGrid to_occupancy_grid() const;
  /// ROS values thresholded to 0 / 100 / -1.
  [[nodiscard]] OccupancyGrid threshold(const ThresholdOptions& options = {}) const;
  /// 1 = blocked (occupied, and unknown when unknown_is_blocked), 0 = free.
  [[nodiscard]] BinaryGrid to_binary(const ThresholdOptions& options = {}) const;

 private:
  void check_scan(const RangeScan& scan) const;
  void insert_laser_beam(Vec2 from, Vec2 dir, double range, const LaserModelOptions& m);

  OccupancyMapOptions options_;
  float l_prior_ = 0.0F, l_min_ = 0.0F, l_max_ = 0.0F;
  GridMap<float> log_odds_;
};

/// logit(p) = log(p / (1 - p)).
[[nodiscard]] double logit(double p);
/// The inverse of logit.
[[nodiscard]] double logistic(double l);

/// The sonar inverse sensor model, exposed for tests and plots: P(OCC) of a cell at range r [m]
/// on the beam axis for a reading d [m] with Gaussian sigma [m]; 0.5 for occluded cells.
[[nodiscard]] double sonar_occupancy(double r, double d, double sigma,
                                     const SonarModelOptions& model);

}  // namespace voronav::mapping
