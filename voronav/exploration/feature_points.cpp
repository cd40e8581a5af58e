#include "voronav/exploration/feature_points.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "voronav/core/error.hpp"

namespace voronav::exploration {
namespace {

double point_line_distance(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double len = ab.norm();
  if (len < 1e-12) return distance(p, a);
  return std::abs(cross(ab, p - a)) / len;
}

// Iterative end-point fit: indices of the break points of pts[lo..hi] (lo and hi included).
void split(std::span<const Vec2> pts, std::size_t lo, std::size_t hi, double tol,
           std::vector<std::size_t>& out) {
  double worst = -1.0;
  std::size_t at = lo;
  for (std::size_t i = lo + 1; i < hi; ++i) {
    const double d = point_line_distance(pts[i], pts[lo], pts[hi]);
    if (d > worst) {
      worst = d;
      at = i;
    }
  }
  if (worst > tol) {
    split(pts, lo, at, tol, out);
    out.push_back(at);
    split(pts, at, hi, tol, out);
  }
}

}  // namespace

std::string_view to_string(FeatureKind k) {
  switch (k) {
    case FeatureKind::kCorner:
      return "corner";
    case FeatureKind::kUStart:
      return "u_start";
    case FeatureKind::kEdge:
      return "edge";
  }
  return "?";
}

void FeaturePointOptions::validate() const {
  const auto positive = [](double v, const char* name) {
    if (!(v > 0.0) || !std::isfinite(v))
      throw Error(std::string("FeaturePointOptions.") + name, 0,
                  "expected a positive finite number, got " + std::to_string(v));
  };
  positive(break_distance, "break_distance");
  positive(split_tolerance, "split_tolerance");
  positive(min_corner_angle, "min_corner_angle");
  positive(min_segment_length, "min_segment_length");
  positive(corner_window, "corner_window");
  positive(merge_tolerance, "merge_tolerance");
  if (min_run_points < 2) throw Error("FeaturePointOptions.min_run_points", 0, "expected >= 2");
  if (!(max_range_fraction > 0.0 && max_range_fraction <= 1.0))
    throw Error("FeaturePointOptions.max_range_fraction", 0, "expected (0, 1]");
}

std::vector<FeaturePoint> extract_feature_points(const robot::LaserScan& scan,
                                                 const FeaturePointOptions& o) {
  o.validate();
  std::vector<FeaturePoint> out;
  const std::size_t n = scan.ranges.size();
  if (n < 2 || !scan.pose.is_finite() || !(scan.angle_increment > 0.0)) return out;
  const auto valid = [&](std::size_t i) {
    const float r = scan.ranges[i];
    return std::isfinite(r) && scan.hit(i);
  };
  const bool cyclic =
      std::abs(scan.angle_increment * static_cast<double>(n) - 2.0 * std::numbers::pi) < 1e-6;
  const double spacing = scan.angle_increment;
  const auto joined = [&](std::size_t i, std::size_t j) {
    if (!valid(i) || !valid(j)) return false;
    const double r = std::max(scan.ranges[i], scan.ranges[j]);
    return distance(scan.endpoint(i), scan.endpoint(j)) < o.break_distance + 3.0 * r * spacing;
  };
  // Start after a break so that runs do not wrap around the start of a cyclic scan.
  std::size_t start = 0;
  if (cyclic) {
    bool found = false;
    for (std::size_t i = 0; i < n && !found; ++i)
      if (!joined((i + n - 1) % n, i)) {
        start = i;
        found = true;
      }
  }
  const double far_range = o.max_range_fraction * scan.range_max;
  std::vector<Vec2> pts;
  std::vector<std::size_t> beam;
  std::size_t k = 0;
  while (k < n) {
    const std::size_t i0 = (start + k) % n;
    if (!valid(i0)) {
      ++k;
      continue;
    }
    pts.clear();
    beam.clear();
    std::size_t len = 0;
    do {
      const std::size_t i = (start + k + len) % n;
      pts.push_back(scan.endpoint(i));
      beam.push_back(i);
      ++len;
    } while (k + len < n && joined((start + k + len - 1) % n, (start + k + len) % n));
    k += len;
    if (static_cast<int>(pts.size()) < o.min_run_points) continue;

    // V corners: convex break points of the end-point fit.
    std::vector<std::size_t> bp{0};
    split(pts, 0, pts.size() - 1, o.split_tolerance, bp);
    bp.push_back(pts.size() - 1);
    int corners = 0;
    for (std::size_t b = 1; b + 1 < bp.size(); ++b) {
      const Vec2 a = pts[bp[b - 1]], c = pts[bp[b]], d = pts[bp[b + 1]];
      if (distance(a, c) < o.min_segment_length || distance(c, d) < o.min_segment_length) continue;
      const Vec2 u = c - a, v = d - c;
      const double turn = std::abs(std::atan2(cross(u, v), dot(u, v)));
      if (turn < o.min_corner_angle) continue;
      // The turn must also be sharp locally (within a corner window on each side): a polygon fit
      // of an arc turns at its break points, but the arc itself turns only a little there.
      std::size_t ia = bp[b], ib = bp[b];
      while (ia > 0 && distance(pts[ia - 1], c) <= o.corner_window)
        --ia;
      while (ib + 1 < pts.size() && distance(pts[ib + 1], c) <= o.corner_window)
        ++ib;
      const Vec2 lu = c - pts[ia], lv = pts[ib] - c;
      if (std::abs(std::atan2(cross(lu, lv), dot(lu, lv))) < o.min_corner_angle) continue;
      // Convex toward the sensor: the corner lies on the sensor's side of the chord a-d.
      const double side_c = cross(d - a, c - a), side_s = cross(d - a, scan.pose.position - a);
      if (side_c * side_s <= 0.0) continue;
      out.push_back({c, FeatureKind::kCorner, 1});
      ++corners;
    }
    // Run ends where the obstacle's silhouette begins: next to a no-return or a farther return
    // that does not continue the same wall.
    const double chord = distance(pts.front(), pts.back());
    double deviation = 0.0;
    for (const Vec2& p : pts)
      deviation = std::max(deviation, point_line_distance(p, pts.front(), pts.back()));
    const bool round = corners == 0 && bp.size() > 3 && deviation > 0.1 * chord;
    const auto silhouette = [&](std::size_t end_beam, bool before) {
      if (scan.ranges[end_beam] > far_range) return false;
      if (!cyclic && ((before && end_beam == 0) || (!before && end_beam == n - 1))) return false;
      const std::size_t nb = before ? (end_beam + n - 1) % n : (end_beam + 1) % n;
      if (valid(nb) && scan.ranges[nb] <= scan.ranges[end_beam]) return false;  // occluded
      // Next to a no-return: if the run's last piece of wall, continued straight, would still be
      // hit by the neighbouring beam within range, the obstacle really ends here; otherwise the
      // run is only cut by the range (a wall seen at a grazing angle) and this is no feature.
      const std::size_t m = std::min<std::size_t>(pts.size() - 1, 3);
      const Vec2 e = before ? pts.front() : pts.back();
      const Vec2 inner = before ? pts[m] : pts[pts.size() - 1 - m];
      const Vec2 wall = e - inner;
      const double a = scan.pose.yaw + scan.angle(nb);
      const Vec2 dir{std::cos(a), std::sin(a)};
      const double denom = cross(dir, wall);
      if (std::abs(denom) < 1e-12) return false;
      // Ray origin + s dir meets the line e + u wall: s = cross(e - origin, wall) / cross(dir,
      // wall).
      const double s_hit = cross(e - scan.pose.position, wall) / denom;
      if (!valid(nb)) return s_hit > 0.0 && s_hit < far_range;
      // A farther return on the continuation of the same wall (a grazing wall whose returns are
      // spaced more than break_distance) is no obstacle end either.
      const double r_nb = scan.ranges[nb];
      return !(s_hit > 0.0 && std::abs(s_hit - r_nb) < o.break_distance + 0.1 * r_nb);
    };
    if (len >= n) continue;  // one closed run around the robot: no ends
    if (silhouette(beam.front(), true))
      out.push_back({pts.front(), round ? FeatureKind::kUStart : FeatureKind::kEdge, 1});
    if (!round && silhouette(beam.back(), false))
      out.push_back({pts.back(), FeatureKind::kEdge, 1});
  }
  return out;
}

FeatureMap::FeatureMap(const FeaturePointOptions& options) : options_(options) {
  options_.validate();
}

void FeatureMap::add(const FeaturePoint& p) {
  if (!p.position.is_finite()) return;
  FeaturePoint* best = nullptr;
  double best_d = options_.merge_tolerance;
  for (FeaturePoint& q : points_) {
    const double d = distance(q.position, p.position);
    if (d <= best_d) {
      best_d = d;
      best = &q;
    }
  }
  if (best == nullptr) {
    points_.push_back(p);
    return;
  }
  const double w = static_cast<double>(best->observations);
  best->position = (best->position * w + p.position) / (w + 1.0);
  ++best->observations;
  // A corner seen once stays a corner: it is the most specific kind.
  if (p.kind == FeatureKind::kCorner) best->kind = FeatureKind::kCorner;
}

void FeatureMap::add(std::span<const FeaturePoint> points) {
  for (const FeaturePoint& p : points)
    add(p);
}

std::vector<Vec2> FeatureMap::positions(int min_observations) const {
  std::vector<Vec2> out;
  for (const FeaturePoint& p : points_)
    if (p.observations >= min_observations) out.push_back(p.position);
  return out;
}

}  // namespace voronav::exploration
