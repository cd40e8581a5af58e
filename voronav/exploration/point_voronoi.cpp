#include "voronav/exploration/point_voronoi.hpp"

#include <algorithm>
#include <boost/polygon/point_data.hpp>
#include <boost/polygon/voronoi.hpp>
#include <cmath>
#include <limits>
#include <string>

#include "voronav/core/error.hpp"

namespace voronav::exploration {

PointVoronoi voronoi_of_points(std::span<const Vec2> points, const PointVoronoiOptions& options) {
  if (!(options.scale > 0.0) || !std::isfinite(options.scale))
    throw Error("PointVoronoiOptions.scale", 0, "expected a positive finite number");
  using IPoint = boost::polygon::point_data<int>;
  std::vector<IPoint> ipts;
  ipts.reserve(points.size());
  constexpr double kLimit = static_cast<double>(std::numeric_limits<int>::max() / 2);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec2 p = points[i];
    if (!p.is_finite())
      throw Error("voronoi_of_points", 0, "point " + std::to_string(i) + " is not finite");
    const double x = std::round(p.x * options.scale), y = std::round(p.y * options.scale);
    if (std::abs(x) > kLimit || std::abs(y) > kLimit)
      throw Error("voronoi_of_points", 0,
                  "point " + std::to_string(i) + " is out of range for scale " +
                      std::to_string(options.scale));
    ipts.emplace_back(static_cast<int>(x), static_cast<int>(y));
  }
  std::sort(ipts.begin(), ipts.end(), [](const IPoint& a, const IPoint& b) {
    return a.x() != b.x() ? a.x() < b.x() : a.y() < b.y();
  });
  ipts.erase(std::unique(ipts.begin(), ipts.end()), ipts.end());

  PointVoronoi out;
  for (const IPoint& p : ipts)
    out.sites.push_back({p.x() / options.scale, p.y() / options.scale});
  if (ipts.size() < 2) return out;

  boost::polygon::voronoi_diagram<double> vd;
  boost::polygon::construct_voronoi(ipts.begin(), ipts.end(), &vd);
  std::size_t index = 0;
  for (const auto& v : vd.vertices()) {
    v.color(index++);
    out.vertices.push_back({v.x() / options.scale, v.y() / options.scale});
  }
  for (const auto& e : vd.edges()) {
    if (!e.is_primary() || !e.is_finite()) continue;
    if (&e > e.twin()) continue;  // each undirected edge once
    const auto a = static_cast<std::size_t>(e.vertex0()->color());
    const auto b = static_cast<std::size_t>(e.vertex1()->color());
    if (a != b) out.edges.emplace_back(a, b);
  }
  return out;
}

}  // namespace voronav::exploration
