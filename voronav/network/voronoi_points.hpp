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
#include <limits>
#include <memory>
#include <span>
#include <utility>
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
  std::size_t work = 0;              ///< pairs examined by the all-pairs search
  std::size_t candidates = 0;        ///< pairs actually compared (= work for the all-pairs one)
};

/// Multi-source Dijkstra over `points` with edges between points that continue each other,
/// weighted by Euclidean length. `start_cost[i]` (+inf = not a start) seeds each point.
/// Optional extra edges (e.g. straight moves a robot has checked in its own map).
using ExtraEdge = std::function<bool(std::size_t, std::size_t)>;

[[nodiscard]] PointSearch search_points(std::span<const VoronoiPoint> points,
                                        std::span<const double> start_cost, double robot_radius_m,
                                        const ExtraEdge& extra_edge = {});

/// Extra edges a caller can bound, so that the search need not compare every pair of points.
struct BoundedExtraEdges {
  ExtraEdge edge;  ///< may be empty
  /// When set, called for every pair the search asks edge() about (a caller counts the work of
  /// its checks here); edge() itself is then asked only when its answer can change the result
  /// (the move would lower the other point's cost, or tie it where a tie counts), so a costly
  /// check is skipped where it cannot matter. Same cost, parent and work as without it.
  std::function<void(std::size_t, std::size_t)> on_asked;
  /// edge(i, j) is false whenever the points are more than this far apart [m] (the caller
  /// guarantees it); +inf = no bound (the search then compares every pair).
  double max_distance_m = std::numeric_limits<double>::infinity();
  /// edge(i, j) is false unless both i and j are in [range_begin, range_end) (the caller
  /// guarantees it; e.g. a robot's own points): other points only look for continuing points.
  std::size_t range_begin = 0;
  std::size_t range_end = std::numeric_limits<std::size_t>::max();
  /// Pairs {i, j} that edge() is asked about at any distance (e.g. consecutive points of a
  /// driven trail); unordered, duplicates allowed.
  std::vector<std::pair<std::size_t, std::size_t>> unbounded_pairs;
};

/// The same search as above, with the same result (cost, parent and work, bit for bit), but the
/// candidates of each settled point come from a uniform grid of the points by position: a point
/// is only compared with points in the grid cells that can hold one that continues it (within
/// its (c - r) plus the largest (c - r) of all points) or that `extra.edge` may join (within
/// `extra.max_distance_m`), plus `extra.unbounded_pairs`; a grid cell is skipped when no point in
/// it can continue the settled one (its rectangle is farther than (c - r) plus the cell's largest
/// (c - r)), and edge() is asked only about pairs in its range or unbounded. Exact copies (same
/// position and clearance, clearance > r, outside the edge range and in no unbounded pair; merged
/// Searches repeat points) are searched as one point; every copy then gets the cost and parent
/// the all-pairs search gives it (ties included). `work` still counts the pairs the paper's
/// all-pairs search examines (n per settled point, n counting every copy), so the computation
/// metric (eq. 8-9) keeps its meaning; `candidates` counts the pairs actually compared.
[[nodiscard]] PointSearch search_points_bucketed(std::span<const VoronoiPoint> points,
                                                 std::span<const double> start_cost,
                                                 double robot_radius_m,
                                                 const BoundedExtraEdges& extra = {});

/// Whether a copy of a Search brings anything new (seed 000, Table 2 line 4, "IF (Receive New
/// Search Message)"; docs/reproductions/networked.md, "Table 2: which copy is new"): `done` is a
/// finished search over `points`; the copy adds the points `added` with start costs
/// `added_start`. The answer is what the search over `points` + `added` would give, without
/// running it: it `improves` when some point from `target_begin` on (the robot's own points, its
/// trail, the destination) would get a cost lower by more than `tolerance` (a point not reached
/// before counts). The added points join the others by continues() only, and the extra edges of
/// `done` (if any) join only points from `target_begin` on, so only a target that improves can
/// pass an improvement on through them. An incremental Dijkstra from the added points: only
/// points whose cost drops are expanded, an added point that is an exact copy (position,
/// clearance) of a point already held at no higher cost is skipped, and the check stops at the
/// first target that improves. `work` counts the pairs compared (eq. 8-9).
struct ImprovementCheck {
  bool improves = false;
  std::size_t work = 0;
};
/// The held points and their costs indexed once (a hash of exact points, a grid by position), so
/// that every copy heard until the robot's next search is checked against the same index.
class CopyCheck {
 public:
  /// Copies what it needs; throws voronav::Error when `done` does not match `points`.
  CopyCheck(std::span<const VoronoiPoint> points, const PointSearch& done, double robot_radius_m,
            std::size_t target_begin);
  [[nodiscard]] ImprovementCheck improves(std::span<const VoronoiPoint> added,
                                          std::span<const double> added_start,
                                          double tolerance) const;

 private:
  struct Index;
  std::shared_ptr<const Index> index_;
};
/// CopyCheck(points, done, robot_radius_m, target_begin).improves(added, added_start, tolerance).
[[nodiscard]] ImprovementCheck search_would_improve(std::span<const VoronoiPoint> points,
                                                    const PointSearch& done,
                                                    std::span<const VoronoiPoint> added,
                                                    std::span<const double> added_start,
                                                    double robot_radius_m, std::size_t target_begin,
                                                    double tolerance);

/// Chain of point indices ending at `last` by following parents.
[[nodiscard]] std::vector<std::size_t> trace_points(const PointSearch& s, std::size_t last);

/// Polyline length [m] (eq. 2: P = sum |O_{i+1} - O_i|).
[[nodiscard]] double route_length(std::span<const VoronoiPoint> route);

}  // namespace voronav::network
