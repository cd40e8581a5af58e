// The Voronoi tree of seed 004 (section 4.3, figures 5, 6, 8(e), 9; eq. 11): the vertices of
// the Voronoi diagram of feature points, clipped to the known free space, become tree nodes.
// The root is the vertex nearest the robots' start; every node has at most two children, the
// left one nearer to it; edge weights are Euclidean distances (eq. 11); leaves (nodes without
// children) are the goals. Robots travel the common trunk and split toward the leaves; with
// fewer robots than leaves, leaves are taken in order of distance (figure 9).
//
// Where the paper is silent we decide (docs/reproductions/exploration.md): the tree is the
// shortest-path tree of the clipped Voronoi graph from the root; a node with more than two
// children (the root, or a degenerate vertex) keeps the two nearest and hands each further child
// to the kept child nearest to it. Every tree edge carries a path checked against the map: the
// straight segment when it is free, else an A* path.
#pragma once

#include <cstddef>
#include <vector>

#include "voronav/core/occupancy.hpp"
#include "voronav/core/vec2.hpp"
#include "voronav/exploration/point_voronoi.hpp"

namespace voronav::exploration {

struct VoronoiTreeOptions {
  /// A graph edge whose straight segment is blocked is replaced by an A* path when that path is
  /// at most this many times longer than the segment; otherwise the edge is dropped (>= 1).
  double max_detour_factor = 2.0;
  /// Leaves whose edge to the parent is shorter than this are pruned, repeatedly [m]
  /// (0 = keep every vertex, as the paper).
  double prune_leaf_shorter_than = 0.0;
  /// The root is the kept vertex nearest the start within the largest connected part of the
  /// clipped graph (true), or the nearest kept vertex of all (false). The paper roots the tree at
  /// the start and does not say what happens when the vertex there is cut off; with false, paper
  /// world seed 15 rooted six trees (400-550 s) at a vertex with no usable edge: no leaf (issue
  /// 14).
  bool root_in_largest_component = true;

  void validate() const;
};

struct TreeNode {
  Vec2 position;           ///< [m]
  int parent = -1;         ///< -1 for the root
  int left = -1;           ///< nearer child, -1 if none
  int right = -1;          ///< farther child, -1 if none
  double weight = 0.0;     ///< Euclidean distance to the parent [m] (eq. 11)
  double depth = 0.0;      ///< sum of the weights from the root [m]
  std::vector<Vec2> path;  ///< checked path from the parent to this node (empty for the root)
  [[nodiscard]] bool is_leaf() const { return left < 0 && right < 0; }
};

struct VoronoiTree {
  std::vector<TreeNode> nodes;
  int root = -1;  ///< -1 when the tree is empty

  [[nodiscard]] bool empty() const { return root < 0; }
  /// Leaves (goals) in order of their distance from the root (depth, then index).
  [[nodiscard]] std::vector<int> leaves_by_distance() const;
  /// Node indices from `from` to `to` through their lowest common ancestor.
  [[nodiscard]] std::vector<int> node_route(int from, int to) const;
  /// Waypoints [m] from node `from` to node `to` along the checked edge paths.
  [[nodiscard]] std::vector<Vec2> waypoints(int from, int to) const;
};

/// The grid seed 004's tree lives on: cells not known to be blocked (free or unknown, ROS values
/// < 50) are passable; known obstacles are inflated by `radius` [m]. 1 = blocked, 0 = passable.
[[nodiscard]] BinaryGrid tree_grid(const OccupancyGrid& map, double radius);

/// True when every cell of the Bresenham line between the cells of a and b is free (0) in
/// `traversable`.
[[nodiscard]] bool segment_free(const BinaryGrid& traversable, Vec2 a, Vec2 b);

/// Builds the tree from the Voronoi diagram. `traversable`: 1 = blocked (the explorer: known
/// obstacles inflated by the robot radius), 0 = passable (the explorer: free or unknown);
/// vertices on blocked cells or off the grid are clipped away.
/// `start`: the robots' start [m]. Throws voronav::Error for a non-finite start or invalid options.
[[nodiscard]] VoronoiTree build_voronoi_tree(const PointVoronoi& voronoi,
                                             const BinaryGrid& traversable, Vec2 start,
                                             const VoronoiTreeOptions& options = {});

/// Dispatch (figure 9): leaf lists per robot. Leaves sorted by distance; robot i takes leaves
/// i, i + N, i + 2N, ... (N robots); with more robots than leaves, robot i takes leaf i mod L.
/// Throws voronav::Error for robots < 1.
[[nodiscard]] std::vector<std::vector<int>> dispatch_leaves(const VoronoiTree& tree, int robots);
/// The same rule for an explicit leaf order (e.g. a filtered leaves_by_distance()).
[[nodiscard]] std::vector<std::vector<int>> dispatch_leaves(const std::vector<int>& leaves,
                                                            int robots);

}  // namespace voronav::exploration
