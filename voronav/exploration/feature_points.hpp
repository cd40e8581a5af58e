// Feature points of obstacles from laser scans (seed 004, section 4.1, figure 4): a rectangular
// obstacle shows a V-shaped range profile whose minimum is a corner; a round obstacle shows a
// U-shape whose start is the feature point. We find the V corners as the convex break points of
// an iterative end-point fit (split-and-merge) of each contiguous run of returns, and the starts
// of runs (where the obstacle's silhouette begins next to a no-return or a far return) as the
// U starts / silhouette corners. Points from many scans and robots are merged within a tolerance.
#pragma once

#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "voronav/core/vec2.hpp"
#include "voronav/robot/laser.hpp"

namespace voronav::exploration {

enum class FeatureKind {
  kCorner,  ///< V-shaped range minimum: a convex corner of a polygonal obstacle
  kUStart,  ///< start of a U-shaped (round) run of returns
  kEdge,    ///< start or end of a straight run: a silhouette corner of an obstacle
};
[[nodiscard]] std::string_view to_string(FeatureKind k);

struct FeaturePoint {
  Vec2 position;  ///< world [m]
  FeatureKind kind = FeatureKind::kCorner;
  int observations = 1;  ///< how many detections were merged into it
};

struct FeaturePointOptions {
  /// Neighbouring returns farther apart than this + 3 beam spacings belong to different runs [m].
  double break_distance = 0.15;
  /// Split tolerance of the end-point fit [m] (a grid world is a staircase: >= 1 cell).
  double split_tolerance = 0.06;
  /// A break point turning by more than this is a corner [rad] (30 deg).
  double min_corner_angle = 0.5235987755982988;
  /// Segments of the fit shorter than this do not make a corner [m] (staircase noise).
  double min_segment_length = 0.15;
  /// Half width of the window in which a corner's turn is measured locally [m]: an arc of
  /// radius R turns by only about corner_window / R there.
  double corner_window = 0.25;
  /// Runs with fewer returns are ignored (noise, thin posts).
  int min_run_points = 4;
  /// Run ends at a range above this fraction of range_max may be cut by the range, not by the
  /// obstacle, so they are not features (0..1).
  double max_range_fraction = 0.9;
  /// Detections within this distance are merged into one feature point [m].
  double merge_tolerance = 0.3;

  void validate() const;
};

/// Feature points of one scan (world coordinates, using scan.pose). NaN or infinite ranges count
/// as no return. Throws voronav::Error for invalid options.
[[nodiscard]] std::vector<FeaturePoint> extract_feature_points(
    const robot::LaserScan& scan, const FeaturePointOptions& options = {});

/// The team's feature points, merged across robots and time: a detection within
/// merge_tolerance of a known point refines it (running mean), otherwise it is added.
class FeatureMap {
 public:
  explicit FeatureMap(const FeaturePointOptions& options = {});
  void add(const FeaturePoint& p);
  void add(std::span<const FeaturePoint> points);
  [[nodiscard]] const std::vector<FeaturePoint>& points() const { return points_; }
  /// Points seen at least `min_observations` times.
  [[nodiscard]] std::vector<Vec2> positions(int min_observations = 1) const;
  [[nodiscard]] std::size_t size() const { return points_.size(); }

 private:
  FeaturePointOptions options_;
  std::vector<FeaturePoint> points_;
};

}  // namespace voronav::exploration
