// Tests of feature points, the Voronoi of points and the Voronoi tree (seed 004, section 4).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "voronav/core/error.hpp"
#include "voronav/exploration/feature_points.hpp"
#include "voronav/exploration/point_voronoi.hpp"
#include "voronav/exploration/voronoi_tree.hpp"
#include "voronav/robot/laser.hpp"

namespace voronav::exploration {
namespace {

// An open 10 x 10 m world (0.05 m cells, origin at 0) with one axis-aligned block.
BinaryGrid block_world(double x0, double y0, double x1, double y1) {
  BinaryGrid g(GridGeometry{200, 200, 0.05, {}}, 0);
  for (int y = 0; y < 200; ++y)
    for (int x = 0; x < 200; ++x) {
      const Vec2 c = g.geometry().cell_center({x, y});
      if (c.x > x0 && c.x < x1 && c.y > y0 && c.y < y1) g[Cell{x, y}] = 1;
    }
  return g;
}

TEST(FeaturePoints, CornersOfAKnownRectangle) {
  const BinaryGrid world = block_world(4.0, 4.0, 6.0, 5.0);
  const Vec2 corners[] = {{4.0, 4.0}, {6.0, 4.0}, {6.0, 5.0}, {4.0, 5.0}};
  robot::LaserOptions lo;
  lo.beams = 720;
  lo.range_max = 4.0;
  FeatureMap map;
  // Robots look at the block from eight places around it.
  for (int k = 0; k < 8; ++k) {
    const double a = k * std::numbers::pi / 4 + 0.2;
    const Pose2 pose{{5.0 + 2.5 * std::cos(a), 4.5 + 2.2 * std::sin(a)}, a};
    const robot::LaserScan scan = robot::cast_scan(world, pose, lo);
    const auto pts = extract_feature_points(scan);
    EXPECT_FALSE(pts.empty());
    map.add(pts);
  }
  // Every corner is found, and every feature point is a corner (tolerance 0.15 m: 3 cells).
  for (const Vec2& c : corners) {
    double best = 1e9;
    for (const FeaturePoint& p : map.points()) {
      best = std::min(best, distance(p.position, c));
    }
    EXPECT_LT(best, 0.15) << c;
  }
  for (const FeaturePoint& p : map.points()) {
    double best = 1e9;
    for (const Vec2& c : corners)
      best = std::min(best, distance(p.position, c));
    EXPECT_LT(best, 0.15) << p.position << " " << to_string(p.kind);
  }
  EXPECT_EQ(map.size(), 4u);
}

TEST(FeaturePoints, VCornerFacingTheRobotIsACorner) {
  const BinaryGrid world = block_world(4.0, 4.0, 6.0, 6.0);
  robot::LaserOptions lo;
  lo.range_max = 5.0;
  // Looking at the corner (4, 4) along the diagonal: both faces visible, V-shaped ranges.
  const auto scan = robot::cast_scan(world, {{2.5, 2.5}, std::numbers::pi / 4}, lo);
  const auto pts = extract_feature_points(scan);
  int corners = 0;
  for (const auto& p : pts)
    if (p.kind == FeatureKind::kCorner) {
      ++corners;
      EXPECT_LT(distance(p.position, {4.0, 4.0}), 0.1);
    }
  EXPECT_EQ(corners, 1);
}

TEST(FeaturePoints, RoundObstacleGivesAUStart) {
  BinaryGrid world(GridGeometry{200, 200, 0.05, {}}, 0);
  for (int y = 0; y < 200; ++y)
    for (int x = 0; x < 200; ++x)
      if (distance(world.geometry().cell_center({x, y}), {5.0, 5.0}) < 1.0) world[Cell{x, y}] = 1;
  robot::LaserOptions lo;
  lo.beams = 720;
  lo.range_max = 5.0;
  const auto pts = extract_feature_points(robot::cast_scan(world, {{2.0, 5.0}, 0.0}, lo));
  ASSERT_EQ(pts.size(), 1u);
  EXPECT_EQ(pts[0].kind, FeatureKind::kUStart);
  // The U starts at a silhouette point of the disc: on the circle, tangent from the robot.
  EXPECT_NEAR(distance(pts[0].position, {5.0, 5.0}), 1.0, 0.1);
}

TEST(FeaturePoints, EmptyAndInvalidScans) {
  robot::LaserScan scan;
  EXPECT_TRUE(extract_feature_points(scan).empty());
  scan.angle_min = -1;
  scan.angle_increment = 0.01;
  scan.range_max = 3;
  scan.ranges.assign(200, std::nanf(""));
  EXPECT_TRUE(extract_feature_points(scan).empty());
  scan.ranges.assign(200, 3.0f);  // all max range: nothing seen
  EXPECT_TRUE(extract_feature_points(scan).empty());
  FeaturePointOptions bad;
  bad.merge_tolerance = -1;
  EXPECT_THROW((void)extract_feature_points(scan, bad), Error);
  EXPECT_THROW(FeatureMap{bad}, Error);
}

TEST(FeatureMap, MergesWithinToleranceOnly) {
  FeatureMap m;  // tolerance 0.3 m
  m.add({{1.0, 1.0}, FeatureKind::kEdge, 1});
  m.add({{1.2, 1.0}, FeatureKind::kCorner, 1});
  m.add({{2.0, 1.0}, FeatureKind::kEdge, 1});
  m.add({{std::nan(""), 0.0}, FeatureKind::kEdge, 1});
  ASSERT_EQ(m.size(), 2u);
  EXPECT_NEAR(m.points()[0].position.x, 1.1, 1e-12);
  EXPECT_EQ(m.points()[0].observations, 2);
  EXPECT_EQ(m.points()[0].kind, FeatureKind::kCorner);
  EXPECT_EQ(m.positions(2).size(), 1u);
}

TEST(PointVoronoi, HandComputedVertices) {
  // Right triangle: one vertex at the circumcentre, the midpoint of the hypotenuse.
  const Vec2 tri[] = {{0, 0}, {4, 0}, {0, 3}};
  const PointVoronoi v = voronoi_of_points(tri);
  ASSERT_EQ(v.vertices.size(), 1u);
  EXPECT_NEAR(v.vertices[0].x, 2.0, 1e-9);
  EXPECT_NEAR(v.vertices[0].y, 1.5, 1e-9);
  EXPECT_TRUE(v.edges.empty());
  // Two triangles sharing an edge: points (0,0), (2,0), (1,2), (1,-2).
  const Vec2 kite[] = {{0, 0}, {2, 0}, {1, 2}, {1, -2}};
  const PointVoronoi k = voronoi_of_points(kite);
  ASSERT_EQ(k.vertices.size(), 2u);
  // Circumcentres: (1, 0.75) and (1, -0.75); one finite edge between them.
  std::vector<double> ys{k.vertices[0].y, k.vertices[1].y};
  std::sort(ys.begin(), ys.end());
  EXPECT_NEAR(ys[0], -0.75, 1e-9);
  EXPECT_NEAR(ys[1], 0.75, 1e-9);
  EXPECT_NEAR(k.vertices[0].x, 1.0, 1e-9);
  ASSERT_EQ(k.edges.size(), 1u);
  // Collinear points: no vertex. Duplicates are merged.
  const Vec2 line[] = {{0, 0}, {1, 0}, {2, 0}, {2, 0}};
  const PointVoronoi l = voronoi_of_points(line);
  EXPECT_TRUE(l.vertices.empty());
  EXPECT_EQ(l.sites.size(), 3u);
  // Bad input.
  const Vec2 nan_pt[] = {{0, 0}, {std::nan(""), 1}};
  EXPECT_THROW((void)voronoi_of_points(nan_pt), Error);
  const Vec2 huge[] = {{0, 0}, {1e7, 1}};
  EXPECT_THROW((void)voronoi_of_points(huge), Error);
  EXPECT_TRUE(voronoi_of_points(std::span<const Vec2>{}).vertices.empty());
}

TEST(PointVoronoi, VerticesAreEmptyCircleCentres) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 10.0);
  for (int trial = 0; trial < 10; ++trial) {
    std::vector<Vec2> pts(40);
    for (auto& p : pts)
      p = {u(rng), u(rng)};
    const PointVoronoi v = voronoi_of_points(pts);
    EXPECT_GT(v.vertices.size(), 20u);
    for (const Vec2& c : v.vertices) {
      std::vector<double> d;
      for (const Vec2& s : v.sites)
        d.push_back(distance(c, s));
      std::sort(d.begin(), d.end());
      // At least three sites at the same (smallest) distance: no site inside the circle.
      EXPECT_NEAR(d[0], d[2], 1e-6);
    }
  }
}

// Tree over random points in an open world.
VoronoiTree random_tree(std::uint64_t seed, const BinaryGrid& world, Vec2 start) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.5, 9.5);
  std::vector<Vec2> pts(30);
  for (auto& p : pts)
    p = {u(rng), u(rng)};
  return build_voronoi_tree(voronoi_of_points(pts), world, start);
}

TEST(VoronoiTree, Invariants) {
  const BinaryGrid world = block_world(4.0, 4.0, 6.0, 6.0);
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const Vec2 start{1.0, 1.0};
    const VoronoiTree t = random_tree(seed, world, start);
    ASSERT_FALSE(t.empty());
    const TreeNode& root = t.nodes[static_cast<std::size_t>(t.root)];
    EXPECT_EQ(root.parent, -1);
    int leaves = 0;
    for (std::size_t i = 0; i < t.nodes.size(); ++i) {
      const TreeNode& n = t.nodes[i];
      // The root is the node nearest the start.
      EXPECT_GE(distance(n.position, start) + 1e-12, distance(root.position, start));
      // No node inside the block (clipped to free space).
      EXPECT_FALSE(n.position.x > 4.0 && n.position.x < 6.0 && n.position.y > 4.0 &&
                   n.position.y < 6.0);
      // <= 2 children, left nearer.
      if (n.left >= 0 && n.right >= 0) {
        EXPECT_LE(distance(t.nodes[static_cast<std::size_t>(n.left)].position, n.position),
                  distance(t.nodes[static_cast<std::size_t>(n.right)].position, n.position));
      }
      if (n.right >= 0) {
        EXPECT_GE(n.left, 0);
      }
      for (int c : {n.left, n.right}) {
        if (c >= 0) {
          EXPECT_EQ(t.nodes[static_cast<std::size_t>(c)].parent, static_cast<int>(i));
        }
      }
      if (n.parent >= 0) {
        const TreeNode& p = t.nodes[static_cast<std::size_t>(n.parent)];
        EXPECT_NEAR(n.weight, distance(p.position, n.position), 1e-12);  // eq. 11
        EXPECT_NEAR(n.depth, p.depth + n.weight, 1e-9);
        // The edge path is checked against the map.
        ASSERT_GE(n.path.size(), 2u);
        EXPECT_EQ(n.path.front(), p.position);
        EXPECT_EQ(n.path.back(), n.position);
        for (std::size_t k = 1; k < n.path.size(); ++k)
          EXPECT_TRUE(segment_free(world, n.path[k - 1], n.path[k]));
        // Connected to the root without cycles.
        int hops = 0;
        for (int a = static_cast<int>(i); a != t.root && hops <= static_cast<int>(t.nodes.size());
             a = t.nodes[static_cast<std::size_t>(a)].parent)
          ++hops;
        EXPECT_LE(hops, static_cast<int>(t.nodes.size()));
      }
      if (n.is_leaf() && static_cast<int>(i) != t.root) ++leaves;
    }
    // Leaves are exactly the goals, sorted by distance.
    const auto goals = t.leaves_by_distance();
    EXPECT_EQ(static_cast<int>(goals.size()), leaves);
    for (std::size_t k = 1; k < goals.size(); ++k)
      EXPECT_LE(t.nodes[static_cast<std::size_t>(goals[k - 1])].depth,
                t.nodes[static_cast<std::size_t>(goals[k])].depth);
  }
}

TEST(VoronoiTree, HandBuiltTreeAndRoutes) {
  // Kite points: vertices (1, 0.75) and (1, -0.75); start near the lower one.
  const BinaryGrid world(GridGeometry{100, 100, 0.05, {{-2.5, -2.5}, 0.0}}, 0);
  const Vec2 kite[] = {{0, 0}, {2, 0}, {1, 2}, {1, -2}};
  const VoronoiTree t = build_voronoi_tree(voronoi_of_points(kite), world, {1.0, -2.0});
  ASSERT_EQ(t.nodes.size(), 2u);
  const TreeNode& root = t.nodes[static_cast<std::size_t>(t.root)];
  EXPECT_NEAR(root.position.y, -0.75, 1e-9);
  ASSERT_EQ(t.leaves_by_distance().size(), 1u);
  const int leaf = t.leaves_by_distance()[0];
  EXPECT_NEAR(t.nodes[static_cast<std::size_t>(leaf)].weight, 1.5, 1e-9);
  const auto wp = t.waypoints(t.root, leaf);
  ASSERT_EQ(wp.size(), 2u);
  const auto back = t.waypoints(leaf, t.root);
  EXPECT_EQ(back.front(), wp.back());
  EXPECT_EQ(back.back(), wp.front());
}

TEST(VoronoiTree, BlockedSegmentsUseThePlanner) {
  // A wall between two vertices: the edge path bends around it.
  BinaryGrid world(GridGeometry{100, 100, 0.05, {{-2.5, -2.5}, 0.0}}, 0);
  for (int x = 30; x < 70; ++x)
    world[Cell{x, 50}] = 1;  // y = 0 from x = -1 to 1
  const Vec2 kite[] = {{-1.5, 0}, {1.5, 0}, {0, 2}, {0, -2}};
  const PointVoronoi v = voronoi_of_points(kite);
  const VoronoiTree t = build_voronoi_tree(v, world, {0.0, -2.0}, {.max_detour_factor = 3.0});
  ASSERT_EQ(t.nodes.size(), 2u);
  const int leaf = t.leaves_by_distance().at(0);
  const auto& path = t.nodes[static_cast<std::size_t>(leaf)].path;
  EXPECT_GT(path.size(), 2u);
  for (std::size_t k = 1; k < path.size(); ++k)
    EXPECT_TRUE(segment_free(world, path[k - 1], path[k]));
  // With no detour allowed the edge is dropped: the tree is the root alone.
  const VoronoiTree strict = build_voronoi_tree(v, world, {0.0, -2.0}, {.max_detour_factor = 1.0});
  EXPECT_EQ(strict.nodes.size(), 1u);
  EXPECT_TRUE(strict.leaves_by_distance().empty());
}

TEST(VoronoiTree, RootInTheLargestPartWhenTheNearestVertexIsCutOff) {
  // Paper world seed 15 (issue 14): the vertex nearest the start had no usable edge, so six trees
  // in a row were its root alone, without a leaf. Here a wall ring around the vertex nearest the
  // start cuts it off; the rest of the graph stays connected.
  const Vec2 pts[] = {{0.0, 0.0}, {3.1, 0.2}, {6.0, -0.1}, {0.2, 3.0},  {3.0, 3.3},
                      {6.2, 2.9}, {1.6, 1.3}, {4.4, 1.7},  {0.6, -2.3}, {4.8, -1.6}};
  const PointVoronoi v = voronoi_of_points(pts);
  const Vec2 start{1.5, -0.2};
  std::size_t v0 = 0;
  for (std::size_t i = 1; i < v.vertices.size(); ++i)
    if (distance(v.vertices[i], start) < distance(v.vertices[v0], start)) v0 = i;
  BinaryGrid world(GridGeometry{200, 200, 0.05, {{-2.5, -4.0}, 0.0}}, 0);
  for (std::size_t k = 0; k < world.size(); ++k) {
    const double d = distance(world.geometry().cell_center(world.cell_at(k)), v.vertices[v0]);
    if (d > 0.2 && d < 0.35) world[k] = 1;
  }
  ASSERT_FALSE(world[*world.geometry().world_to_cell(v.vertices[v0])]);
  const VoronoiTree cut = build_voronoi_tree(v, world, start, {.root_in_largest_component = false});
  EXPECT_EQ(cut.nodes.size(), 1u);  // the old rule: the cut-off vertex alone
  EXPECT_TRUE(cut.leaves_by_distance().empty());
  const VoronoiTree t = build_voronoi_tree(v, world, start);
  EXPECT_GT(t.nodes.size(), 4u);
  EXPECT_GE(t.leaves_by_distance().size(), 2u);
  EXPECT_GT(distance(t.nodes[static_cast<std::size_t>(t.root)].position, v.vertices[v0]), 0.4);
}

TEST(Dispatch, LeavesByDistanceAsFigure9) {
  const BinaryGrid world(GridGeometry{200, 200, 0.05, {}}, 0);
  const VoronoiTree t = random_tree(5, world, {1.0, 1.0});
  const auto leaves = t.leaves_by_distance();
  ASSERT_GE(leaves.size(), 4u);
  // 2 robots: leaves in pairs by distance.
  const auto two = dispatch_leaves(t, 2);
  ASSERT_EQ(two.size(), 2u);
  for (std::size_t k = 0; k < leaves.size(); ++k)
    EXPECT_EQ(two[k % 2][k / 2], leaves[k]);
  // As many robots as leaves: all leaves at once.
  const auto all = dispatch_leaves(t, static_cast<int>(leaves.size()));
  for (std::size_t i = 0; i < leaves.size(); ++i) {
    ASSERT_EQ(all[i].size(), 1u);
    EXPECT_EQ(all[i][0], leaves[i]);
  }
  // More robots than leaves: wrap around.
  const auto many = dispatch_leaves(t, static_cast<int>(leaves.size()) + 1);
  EXPECT_EQ(many.back()[0], leaves[0]);
  EXPECT_THROW((void)dispatch_leaves(t, 0), Error);
  // Every route starts with the common trunk at the root.
  for (int leaf : leaves)
    EXPECT_EQ(t.node_route(t.root, leaf).front(), t.root);
}

}  // namespace
}  // namespace voronav::exploration
