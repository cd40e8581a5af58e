#include "voronav/voronoi/labeled_voronoi.hpp"

#include <gtest/gtest.h>

#include <cstdio>

#include "voronav/core/error.hpp"
#include "voronav/voronoi/gvd.hpp"
#include "voronav/voronoi/test_maps.hpp"

namespace voronav::voronoi {
namespace {

using testing::fill_rect;

TEST(EdgeCodes, TheEightShapesAndNoise) {
  BinaryGrid g(GridGeometry{12, 7, 1.0, {}}, 0);
  fill_rect(g, 2, 2, 4, 4);  // a 3x3 block
  fill_rect(g, 7, 3, 9, 3);  // a one-cell-thick wall
  g[Cell{11, 6}] = 1;        // a lone cell in the corner
  const GridMap<std::uint8_t> c = edge_codes(g, false);
  EXPECT_EQ(c[(Cell{0, 0})], 1);   // free
  EXPECT_EQ(c[(Cell{3, 3})], 2);   // interior
  EXPECT_EQ(c[(Cell{4, 3})], 5);   // free side E
  EXPECT_EQ(c[(Cell{3, 4})], 6);   // N
  EXPECT_EQ(c[(Cell{2, 3})], 7);   // W
  EXPECT_EQ(c[(Cell{3, 2})], 8);   // S
  EXPECT_EQ(c[(Cell{4, 4})], 9);   // NE corner
  EXPECT_EQ(c[(Cell{2, 4})], 10);  // NW
  EXPECT_EQ(c[(Cell{2, 2})], 11);  // SW
  EXPECT_EQ(c[(Cell{4, 2})], 12);  // SE
  EXPECT_EQ(c[(Cell{8, 3})], 3);   // thin wall: noise
  EXPECT_EQ(c[(Cell{7, 3})], 4);   // its tip: noise
                                  // The lone cell in the corner is free on W and S only (outside is
                                  // not free): a SW corner.
  EXPECT_EQ(c[(Cell{11, 6})], 11);
  EXPECT_EQ(edge_codes(g, true)[(Cell{11, 6})], 11);
  g[Cell{11, 6}] = 0;
  g[Cell{10, 5}] = 1;  // a lone cell inside: free on all four sides
  EXPECT_EQ(edge_codes(g, true)[(Cell{10, 5})], 4);
}

TEST(LabeledVoronoi, TimeStampIsTheFourConnectedClearance) {
  // A walled rectangle without obstacles inside: each cell is reached from the nearest wall.
  BinaryGrid g(GridGeometry{21, 13, 0.1, {}}, 0);
  fill_rect(g, 0, 0, 20, 0);
  fill_rect(g, 0, 12, 20, 12);
  fill_rect(g, 0, 0, 0, 12);
  fill_rect(g, 20, 0, 20, 12);
  const LabeledVoronoi v = build_labeled_voronoi(g);
  for (int y = 1; y < 12; ++y)
    for (int x = 1; x < 20; ++x)
      EXPECT_EQ(v.time[(Cell{x, y})], std::min({x, y, 20 - x, 12 - y})) << x << "," << y;
  EXPECT_EQ(v.time[(Cell{0, 5})], 0);
  EXPECT_EQ(v.steps, 6);
  // The diagram holds the centre line y = 6 between x = 6 and 14.
  for (int x = 6; x <= 14; ++x)
    EXPECT_EQ(v.diagram[(Cell{x, 6})], 1) << x;
}

TEST(LabeledVoronoi, CorridorCentreLineMatchesTheEdtDiagram) {
  BinaryGrid odd(GridGeometry{20, 7, 0.1, {}}, 0);
  fill_rect(odd, 0, 0, 19, 0);
  fill_rect(odd, 0, 6, 19, 6);
  CaVoronoiOptions o;
  o.border_is_blocked = false;
  const LabeledVoronoi v = build_labeled_voronoi(odd, o);
  for (int x = 0; x < 20; ++x)
    EXPECT_EQ(v.diagram[(Cell{x, 3})], 1) << x;
  EXPECT_EQ(v.time[(Cell{5, 3})], 3);
  // The paper's edge-code labels separate the two walls too (codes N and S differ).
  o.labels = CaLabels::kEdgeCode;
  o.site_separation = 1e9;
  const LabeledVoronoi e = build_labeled_voronoi(odd, o);
  for (int x = 2; x < 18; ++x)
    EXPECT_EQ(e.vor[(Cell{x, 3})], 1) << x;
}

// The documented tolerance (docs/reproductions/topology.md): on rectilinear rooms at least 90 %
// of the cellular-automaton diagram lies within 2 cells of the EDT diagram (both unpruned) and
// the other way round. The CA measures 4-connected distance, so its bisectors bend away from
// the Euclidean ones where walls are not parallel.
TEST(LabeledVoronoi, AgreesWithTheEdtDiagramWithinTolerance) {
  double worst_a = 1.0, worst_b = 1.0, sum_a = 0.0, sum_b = 0.0;
  const int n = 25;
  for (int seed = 0; seed < n; ++seed) {
    const BinaryGrid g = testing::random_room(static_cast<std::uint32_t>(seed), 60, 44, 5);
    GvdOptions go;
    go.spur_clearance_ratio = 0.0;
    const GeneralizedVoronoi edt = build_gvd(g, go);
    const LabeledVoronoi ca = build_labeled_voronoi(g);
    const DiagramAgreement a = compare_diagrams(ca.diagram, edt.diagram, 2.0);
    worst_a = std::min(worst_a, a.a_in_b);
    worst_b = std::min(worst_b, a.b_in_a);
    sum_a += a.a_in_b;
    sum_b += a.b_in_a;
  }
  std::printf("CA in EDT: mean %.3f worst %.3f; EDT in CA: mean %.3f worst %.3f\n", sum_a / n,
              worst_a, sum_b / n, worst_b);
  EXPECT_GT(sum_a / n, 0.9);
  EXPECT_GT(sum_b / n, 0.9);
  EXPECT_GT(worst_a, 0.75);
  EXPECT_GT(worst_b, 0.75);
}

TEST(LabeledVoronoi, CompareDiagramsHandComputed) {
  BinaryGrid a(10, 1, 0), b(10, 1, 0);
  a[Cell{0, 0}] = a[Cell{5, 0}] = 1;
  b[Cell{1, 0}] = 1;
  const DiagramAgreement r = compare_diagrams(a, b, 1.0);
  EXPECT_EQ(r.a_cells, 2U);
  EXPECT_DOUBLE_EQ(r.a_in_b, 0.5);
  EXPECT_DOUBLE_EQ(r.b_in_a, 1.0);
  EXPECT_THROW((void)compare_diagrams(a, BinaryGrid(3, 1, 0), 1.0), Error);
  EXPECT_THROW((void)compare_diagrams(a, b, -1.0), Error);
}

TEST(LabeledVoronoi, EmptyAndInvalid) {
  EXPECT_TRUE(build_labeled_voronoi(BinaryGrid{}).vor.empty());
  const LabeledVoronoi none =
      build_labeled_voronoi(BinaryGrid(5, 5, 0), {.border_is_blocked = false});
  EXPECT_EQ(none.steps, 0);
  EXPECT_EQ(none.time[(Cell{2, 2})], -1);
  CaVoronoiOptions o;
  o.site_separation = -1;
  EXPECT_THROW((void)build_labeled_voronoi(BinaryGrid(3, 3, 0), o), Error);
}

}  // namespace
}  // namespace voronav::voronoi
