// Voronoi points (seed 000, section 3.4, figures 20–21): a robot compresses its local map into a
// few points instead of sending cells. The local map is binarized with unknown = blocked, so the
// free space is what the robot has actually sensed; its exact EDT (field::distance_transform)
// gives the generalized Voronoi diagram as the cells whose nearest obstacle sites lie far apart
// (ridge of the distance field). Skeleton cells with clearance > robot radius are thinned
// greedily (largest clearance first) into **open points**; the others into **close points**.
//
// Each open point carries its clearance c: the disc of radius c around it is known free. Two open
// points p, q are connected ("q continues p", Table 2) when |p - q| <= (c_p - r) + (c_q - r):
// then every point of the segment pq is the centre of a robot disc (radius r) inside one of the
// two free discs, so the straight move is collision free. This is how robots check continuity
// from points alone, without each other's maps. (Decision: the paper does not define
// "continues"; this is the geometric rule that makes the point route drivable.)
#pragma once

#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include "voronav/core/occupancy.hpp"
#include "voronav/network/messages.hpp"

namespace voronav::network {

struct VoronoiPointsOptions {
  double robot_radius_m = 0.2;  ///< r [m]; a point is open when clearance > r + one cell
  /// Two neighbouring cells are on the Voronoi diagram when their nearest sites are at least this
  /// far apart [cells] (2 = the sites are not neighbours).
  double min_site_separation_cells = 2.5;
  /// Close points are thinned to at most one per this spacing [m].
  double close_point_spacing_m = 1.0;
};

struct VoronoiPoints {
  std::vector<VoronoiPoint> open;
  std::vector<Vec2> close;
  std::size_t cells_processed = 0;  ///< work: cells of the local map handled (EDT + skeleton)
};

/// Computes the open and close points of `local_map` (kFree / kOccupied / kUnknown, world
/// georeferenced by its geometry). Throws voronav::Error for a negative or NaN robot radius.
[[nodiscard]] VoronoiPoints make_voronoi_points(const OccupancyGrid& local_map,
                                                const VoronoiPointsOptions& options = {});

/// Clearance [m] of a world point in `local_map` (unknown = blocked): distance from the point's
/// cell centre to the nearest blocked cell centre minus half a cell; 0 outside the map or blocked.
[[nodiscard]] double clearance_at(const OccupancyGrid& local_map, Vec2 world);

/// The continuity rule above: true when the straight move between p and q is collision free for
/// a robot of radius r by the two points' free discs.
[[nodiscard]] bool continues(const VoronoiPoint& p, const VoronoiPoint& q, double robot_radius_m);

/// Result of a shortest-path search over points.
struct PointSearch {
  std::vector<double> cost;          ///< per point, +inf when unreached
  std::vector<std::int32_t> parent;  ///< previous point, or -1 for a start
  std::size_t work = 0;              ///< pairs examined
};

/// Multi-source Dijkstra over `points` with edges between points that continue each other,
/// weighted by Euclidean length. `start_cost[i]` (+inf = not a start) seeds each point.
/// Optional extra edges (e.g. straight moves a robot has checked in its own map).
using ExtraEdge = std::function<bool(std::size_t, std::size_t)>;

[[nodiscard]] PointSearch search_points(std::span<const VoronoiPoint> points,
                                        std::span<const double> start_cost, double robot_radius_m,
                                        const ExtraEdge& extra_edge = {});

/// Chain of point indices ending at `last` by following parents.
[[nodiscard]] std::vector<std::size_t> trace_points(const PointSearch& s, std::size_t last);

/// Polyline length [m] (eq. 2: P = sum |O_{i+1} - O_i|).
[[nodiscard]] double route_length(std::span<const VoronoiPoint> route);

}  // namespace voronav::network
