#include "voronav/topology/edge_route.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

#include "voronav/voronoi/test_maps.hpp"

namespace voronav::topology {
namespace {

// Every edge's route joins its two centres through its crossing, one 8-neighbour step at a time,
// over free cells of its two regions, never cutting a blocked corner; returns the share of route
// cells on the diagram.
double check_routes(const TopologicalMap& m) {
  std::size_t cells = 0, on_diagram = 0;
  for (const TopoEdge& e : m.edges) {
    const std::vector<Cell> r = edge_route(m, e);
    EXPECT_FALSE(r.empty()) << "edge " << e.a << "-" << e.b;
    if (r.empty()) continue;
    EXPECT_EQ(r.front(), m.regions[static_cast<std::size_t>(e.a)].centre);
    EXPECT_EQ(r.back(), m.regions[static_cast<std::size_t>(e.b)].centre);
    EXPECT_NE(std::find(r.begin(), r.end(), e.midpoint), r.end());
    for (std::size_t k = 0; k < r.size(); ++k) {
      const Cell c = r[k];
      EXPECT_FALSE(m.blocked[c]) << c;
      EXPECT_TRUE(c == e.midpoint || m.region[c] == e.a || m.region[c] == e.b) << c;
      if (k > 0) {
        const Cell d = c - r[k - 1];
        EXPECT_TRUE(std::abs(d.x) <= 1 && std::abs(d.y) <= 1 && (d.x != 0 || d.y != 0)) << c;
        if (d.x != 0 && d.y != 0) {
          const Cell side1{r[k - 1].x + d.x, r[k - 1].y}, side2{r[k - 1].x, r[k - 1].y + d.y};
          EXPECT_FALSE(m.blocked[side1]) << "corner cut at " << c;
          EXPECT_FALSE(m.blocked[side2]) << "corner cut at " << c;
        }
      }
      ++cells;
      if (m.diagram[c]) ++on_diagram;
    }
  }
  return cells ? static_cast<double>(on_diagram) / static_cast<double>(cells) : 0.0;
}

TEST(EdgeRoute, TwoRoomsRouteRunsAlongTheDiagramThroughTheDoor) {
  const BinaryGrid g = voronoi::testing::two_rooms(30, 24, 4);
  const TopologicalMap m = build_topological_map(g);
  ASSERT_EQ(m.edges.size(), 1U);
  // Each room's medial axis runs through its centre to the door: the route is nearly all diagram.
  EXPECT_GT(check_routes(m), 0.9);
}

TEST(EdgeRoute, RandomRoomsRoutesFollowTheDiagramInsideTheirRegions) {
  std::size_t edges = 0;
  for (unsigned seed = 1; seed <= 12; ++seed) {
    const BinaryGrid g = voronoi::testing::random_room(seed, 64, 48, 12);
    const TopologicalMap m = build_topological_map(g);
    edges += m.edges.size();
    const double on_diagram = check_routes(m);
    // Along the diagram, not straight: straight legs (no off-diagram cost) give 15-30 % here.
    if (!m.edges.empty()) {
      EXPECT_GE(on_diagram, 0.8) << "seed " << seed;
    }
  }
  EXPECT_GT(edges, 0U);
}

TEST(EdgeRoute, EdgeWithUnknownRegionsHasNoRoute) {
  const TopologicalMap m = build_topological_map(voronoi::testing::two_rooms(30, 24, 4));
  TopoEdge e = m.edges.at(0);
  e.b = 7;
  EXPECT_TRUE(edge_route(m, e).empty());
}

}  // namespace
}  // namespace voronav::topology
