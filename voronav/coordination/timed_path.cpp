#include "voronav/coordination/timed_path.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "voronav/core/error.hpp"

namespace voronav::coordination {

TimedPath::TimedPath(std::vector<Vec2> nodes, MotionLimits limits)
    : nodes_(std::move(nodes)), limits_(limits) {
  if (nodes_.empty()) throw Error("path", 0, "a path needs at least one node");
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    if (!nodes_[i].is_finite()) {
      throw Error("path", 0, "node " + std::to_string(i) + " is not a finite point");
    }
  }
  if (!(limits_.v_max > 0.0) || !std::isfinite(limits_.v_max)) {
    throw Error("v_max", 0,
                "expected a positive finite speed, got " + std::to_string(limits_.v_max));
  }
  if (!(limits_.a_max > 0.0)) {
    throw Error(
        "a_max", 0,
        "expected a positive acceleration (or infinity), got " + std::to_string(limits_.a_max));
  }
  cumulative_.resize(nodes_.size(), 0.0);
  for (std::size_t i = 1; i < nodes_.size(); ++i) {
    cumulative_[i] = cumulative_[i - 1] + distance(nodes_[i - 1], nodes_[i]);
  }
  const double len = length();
  const double v = limits_.v_max;
  const double a = limits_.a_max;
  if (std::isinf(a)) {
    v_peak_ = v;
    t_accel_ = 0.0;
    travel_time_ = len / v;
  } else if (len >= v * v / a) {  // trapezoid: accelerate, cruise, decelerate
    v_peak_ = v;
    t_accel_ = v / a;
    travel_time_ = len / v + v / a;
  } else {  // triangle: never reaches v_max
    v_peak_ = std::sqrt(a * len);
    t_accel_ = v_peak_ / a;
    travel_time_ = 2.0 * t_accel_;
  }
}

double TimedPath::arc_at(double t) const {
  const double len = length();
  if (!(t > 0.0)) return 0.0;  // also NaN
  if (t >= travel_time_) return len;
  if (t_accel_ <= 0.0) return std::min(len, v_peak_ * t);
  const double a = limits_.a_max;
  if (t < t_accel_) return 0.5 * a * t * t;
  const double s_accel = 0.5 * v_peak_ * t_accel_;
  const double t_decel = travel_time_ - t_accel_;
  if (t <= t_decel) return s_accel + v_peak_ * (t - t_accel_);
  const double r = travel_time_ - t;
  return std::clamp(len - 0.5 * a * r * r, 0.0, len);
}

double TimedPath::time_at_arc(double s) const {
  const double len = length();
  if (!(s > 0.0)) return 0.0;
  if (s >= len) return travel_time_;
  if (t_accel_ <= 0.0) return s / v_peak_;
  const double a = limits_.a_max;
  const double s_accel = 0.5 * v_peak_ * t_accel_;
  if (s < s_accel) return std::sqrt(2.0 * s / a);
  if (s <= len - s_accel) return t_accel_ + (s - s_accel) / v_peak_;
  return travel_time_ - std::sqrt(2.0 * std::max(0.0, len - s) / a);
}

double TimedPath::speed(double t) const {
  if (!(t > 0.0) || t >= travel_time_) return 0.0;
  if (t_accel_ <= 0.0) return v_peak_;
  const double a = limits_.a_max;
  if (t < t_accel_) return a * t;
  if (t <= travel_time_ - t_accel_) return v_peak_;
  return a * (travel_time_ - t);
}

Vec2 TimedPath::point_at_arc(double s) const {
  if (nodes_.size() == 1 || !(s > 0.0)) return nodes_.front();
  if (s >= length()) return nodes_.back();
  const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), s);
  const auto i = static_cast<std::size_t>(it - cumulative_.begin());  // 1 <= i < size
  const double seg = cumulative_[i] - cumulative_[i - 1];
  const double lambda = seg > 0.0 ? (s - cumulative_[i - 1]) / seg : 0.0;
  return nodes_[i - 1] + (nodes_[i] - nodes_[i - 1]) * lambda;
}

std::vector<Vec2> resample(const TimedPath& path, double spacing, std::vector<double>* arcs) {
  if (!(spacing > 0.0) || !std::isfinite(spacing)) {
    throw Error("node_spacing", 0,
                "expected a positive finite spacing, got " + std::to_string(spacing));
  }
  const auto& nodes = path.nodes();
  const auto& cum = path.cumulative();
  // Checked before the loop: a tiny spacing on a long path would allocate without bound.
  constexpr double kMaxNodes = 1e6;
  if (!cum.empty() && !(cum.back() / spacing + static_cast<double>(nodes.size()) <= kMaxNodes)) {
    throw Error("node_spacing", 0,
                "a spacing of " + std::to_string(spacing) + " m cuts a " +
                    std::to_string(cum.back()) + " m path into more than 1000000 nodes; " +
                    "use a larger node_spacing");
  }
  std::vector<Vec2> out{nodes.front()};
  std::vector<double> s_out{0.0};
  for (std::size_t i = 1; i < nodes.size(); ++i) {
    const double seg = cum[i] - cum[i - 1];
    if (seg <= 0.0) continue;
    const auto pieces = static_cast<int>(std::ceil(seg / spacing - 1e-12));
    for (int k = 1; k <= pieces; ++k) {
      const double f = static_cast<double>(k) / pieces;
      out.push_back(nodes[i - 1] + (nodes[i] - nodes[i - 1]) * f);
      s_out.push_back(cum[i - 1] + seg * f);
    }
  }
  if (arcs != nullptr) *arcs = std::move(s_out);
  return out;
}

}  // namespace voronav::coordination
