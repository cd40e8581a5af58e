#include "voronav/mapping/occupancy_map.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "voronav/core/cell_iterators.hpp"
#include "voronav/core/error.hpp"

namespace voronav::mapping {
namespace {

bool open_unit(double p) {
  return p > 0.0 && p < 1.0;
}

void check_probability(const char* name, double p, double lo, double hi) {
  if (!(p >= lo && p <= hi) || !std::isfinite(p))
    throw Error(name, 0,
                "expected a probability in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                    "], got " + std::to_string(p));
}

void check_options(const OccupancyMapOptions& o) {
  if (!open_unit(o.prior) || !open_unit(o.clamp_min) || !open_unit(o.clamp_max) ||
      !(o.clamp_min < o.prior && o.prior < o.clamp_max))
    throw Error("OccupancyMapOptions", 0,
                "expected 0 < clamp_min < prior < clamp_max < 1, got clamp_min=" +
                    std::to_string(o.clamp_min) + " prior=" + std::to_string(o.prior) +
                    " clamp_max=" + std::to_string(o.clamp_max));
}

void check_model(const SonarModelOptions& m) {
  if (!(m.half_angle > 0.0 && m.half_angle < std::numbers::pi / 2))
    throw Error("SonarModelOptions.half_angle", 0,
                "expected 0 < beta < pi/2 [rad], got " + std::to_string(m.half_angle));
  if (!(m.max_range > 0.0) || !std::isfinite(m.max_range))
    throw Error("SonarModelOptions.max_range", 0,
                "expected a positive range [m], got " + std::to_string(m.max_range));
  if (!(m.sigma >= 0.0) || !std::isfinite(m.sigma))
    throw Error("SonarModelOptions.sigma", 0,
                "expected sigma >= 0 [m], got " + std::to_string(m.sigma));
  check_probability("SonarModelOptions.p_occupied", m.p_occupied, 0.5, 0.999);
  check_probability("SonarModelOptions.p_empty", m.p_empty, 0.001, 0.5);
}

void check_model(const LaserModelOptions& m) {
  if (!(m.max_range > 0.0) || !std::isfinite(m.max_range))
    throw Error("LaserModelOptions.max_range", 0,
                "expected a positive range [m], got " + std::to_string(m.max_range));
  check_probability("LaserModelOptions.p_occupied", m.p_occupied, 0.5, 0.999);
  check_probability("LaserModelOptions.p_empty", m.p_empty, 0.001, 0.5);
}

}  // namespace

double logit(double p) {
  return std::log(p / (1.0 - p));
}
double logistic(double l) {
  return 1.0 / (1.0 + std::exp(-l));
}

double sonar_occupancy(double r, double d, double sigma, const SonarModelOptions& m) {
  if (d >= m.max_range) return r < m.max_range ? m.p_empty : 0.5;  // no echo: clear the cone
  if (r > d + 3.0 * sigma) return 0.5;                             // occluded (seed 003)
  // The paper's density p(d|r) (eq. 1) scaled to 1 at its peak.
  const double g = std::exp(-(r - d) * (r - d) / (2.0 * sigma * sigma));
  if (r <= d) return m.p_empty + (m.p_occupied - m.p_empty) * g;
  return 0.5 + (m.p_occupied - 0.5) * g;
}

OccupancyMap::OccupancyMap(GridGeometry geometry, const OccupancyMapOptions& options)
    : options_(options) {
  check_options(options);
  if (geometry.empty())
    throw Error("OccupancyMap", 0,
                "expected a non-empty grid, got " + std::to_string(geometry.width) + "x" +
                    std::to_string(geometry.height));
  if (!geometry.origin.is_finite()) throw Error("OccupancyMap", 0, "the origin is not finite");
  l_prior_ = static_cast<float>(logit(options.prior));
  l_min_ = static_cast<float>(logit(options.clamp_min));
  l_max_ = static_cast<float>(logit(options.clamp_max));
  log_odds_ = GridMap<float>(geometry, l_prior_);
}

double OccupancyMap::probability(Cell c) const {
  return logistic(static_cast<double>(log_odds_.at(c)));
}

bool OccupancyMap::observed(Cell c) const {
  return log_odds_.at(c) != l_prior_;
}

void OccupancyMap::update(Cell c, double p_occupied) {
  if (!log_odds_.contains(c)) return;
  if (!(p_occupied > 0.0 && p_occupied < 1.0))
    throw Error("OccupancyMap::update", 0,
                "expected a probability in (0, 1), got " + std::to_string(p_occupied));
  if (p_occupied == 0.5) return;
  float& l = log_odds_[c];
  const double v = static_cast<double>(l) + logit(p_occupied) - static_cast<double>(l_prior_);
  l = std::clamp(static_cast<float>(v), l_min_, l_max_);
}

void OccupancyMap::insert_sonar(const Pose2& sensor, double range, const SonarModelOptions& model) {
  check_model(model);
  if (!sensor.is_finite()) throw Error("insert_sonar", 0, "the sensor pose is not finite");
  if (std::isnan(range) || range < 0.0)
    throw Error("insert_sonar", 0, "expected a range >= 0 [m], got " + std::to_string(range));
  const GridGeometry& g = geometry();
  const double sigma = model.sigma > 0.0 ? model.sigma : g.resolution;
  const double d = std::min(range, model.max_range);
  const double reach = d >= model.max_range ? model.max_range : d + 3.0 * sigma;
  // Bounding box of the disc of radius `reach` around the sensor, in grid coordinates.
  const Vec2 centre = g.world_to_grid(sensor.position);
  const double rc = reach / g.resolution + 1.0;
  const int x0 = std::max(0, static_cast<int>(std::floor(centre.x - rc)));
  const int x1 = std::min(g.width - 1, static_cast<int>(std::floor(centre.x + rc)));
  const int y0 = std::max(0, static_cast<int>(std::floor(centre.y - rc)));
  const int y1 = std::min(g.height - 1, static_cast<int>(std::floor(centre.y + rc)));
  const double half_cell = 0.5 * g.resolution;
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const Cell c{x, y};
      const Vec2 rel = g.cell_center(c) - sensor.position;
      const double r = rel.norm();
      if (r > reach) continue;
      // The sensor's own cell is free; elsewhere only the cone +-beta around the axis.
      if (r > half_cell &&
          std::abs(wrap_angle(std::atan2(rel.y, rel.x) - sensor.yaw)) > model.half_angle)
        continue;
      update(c, sonar_occupancy(r, d, sigma, model));
    }
  }
}

void OccupancyMap::check_scan(const RangeScan& scan) const {
  if (scan.bearings.size() != scan.ranges.size())
    throw Error("RangeScan", 0,
                "bearings and ranges differ in size (" + std::to_string(scan.bearings.size()) +
                    " vs " + std::to_string(scan.ranges.size()) + ")");
  if (!scan.pose.is_finite()) throw Error("RangeScan", 0, "the sensor pose is not finite");
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    if (!std::isfinite(scan.bearings[i]))
      throw Error("RangeScan", 0, "bearing " + std::to_string(i) + " is not finite");
    if (std::isnan(scan.ranges[i]) || scan.ranges[i] < 0.0)
      throw Error("RangeScan", 0,
                  "range " + std::to_string(i) + ": expected >= 0 [m], got " +
                      std::to_string(scan.ranges[i]));
  }
}

void OccupancyMap::insert_scan(const RangeScan& scan, const SonarModelOptions& model) {
  check_scan(scan);
  for (std::size_t i = 0; i < scan.ranges.size(); ++i)
    insert_sonar({scan.pose.position, wrap_angle(scan.pose.yaw + scan.bearings[i])}, scan.ranges[i],
                 model);
}

void OccupancyMap::insert_laser_beam(Vec2 from, Vec2 dir, double range,
                                     const LaserModelOptions& m) {
  const GridGeometry& g = geometry();
  const bool hit = range < m.max_range;
  const double len = std::min(range, m.max_range);
  const auto a = g.world_to_cell(from);
  // A hair beyond the measured distance, so that an echo on a cell face lands in the cell behind
  // it.
  const auto b = g.world_to_cell(from + dir * (len + 1e-6 * g.resolution));
  if (!a || !b) return;
  // The walk ends where the beam leaves the grid: with a tiny resolution the range can span
  // millions of cells outside the map, which no update could touch.
  bool inside = false;
  for_each_line_cell(*a, *b, [&](Cell c) {
    if (!g.contains(c)) return !inside;
    inside = true;
    if (c == *b) {
      update(c, hit ? m.p_occupied : m.p_empty);
      return true;
    }
    update(c, m.p_empty);
    return true;
  });
}

void OccupancyMap::insert_scan(const RangeScan& scan, const LaserModelOptions& model) {
  check_model(model);
  check_scan(scan);
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    const double a = scan.pose.yaw + scan.bearings[i];
    insert_laser_beam(scan.pose.position, {std::cos(a), std::sin(a)}, scan.ranges[i], model);
  }
}

OccupancyGrid OccupancyMap::to_occupancy_grid() const {
  OccupancyGrid out(geometry(), kUnknown);
  const auto src = log_odds_.data();
  auto dst = out.data();
  for (std::size_t i = 0; i < src.size(); ++i) {
    if (src[i] == l_prior_) continue;
    const double p = logistic(static_cast<double>(src[i]));
    dst[i] = static_cast<std::int8_t>(std::lround(100.0 * p));
  }
  return out;
}

OccupancyGrid OccupancyMap::threshold(const ThresholdOptions& options) const {
  if (!(options.free_below <= options.occupied_above) || !(options.free_below >= 0.0) ||
      !(options.occupied_above <= 1.0))
    throw Error("ThresholdOptions", 0,
                "expected 0 <= free_below <= occupied_above <= 1, got " +
                    std::to_string(options.free_below) + ", " +
                    std::to_string(options.occupied_above));
  OccupancyGrid out(geometry(), kUnknown);
  const auto src = log_odds_.data();
  auto dst = out.data();
  for (std::size_t i = 0; i < src.size(); ++i) {
    const double p = logistic(static_cast<double>(src[i]));
    if (p < options.free_below)
      dst[i] = kFree;
    else if (p > options.occupied_above)
      dst[i] = kOccupied;
  }
  return out;
}

BinaryGrid OccupancyMap::to_binary(const ThresholdOptions& options) const {
  return binarize(threshold(options), {50, options.unknown_is_blocked});
}

}  // namespace voronav::mapping
