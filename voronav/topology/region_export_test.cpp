#include "voronav/topology/region_export.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>

#include "voronav/core/error.hpp"
#include "voronav/topology/segmentation.hpp"
#include "voronav/topology/topological_map.hpp"
#include "voronav/voronoi/test_maps.hpp"

namespace voronav::topology {
namespace {

TEST(RegionExport, LabelImageRoundTripBothFormats) {
  GridMap<std::int32_t> r(GridGeometry{7, 4, 0.5, {}}, -1);
  r[Cell{0, 0}] = 0;      // bottom-left cell -> last image row, first column
  r[Cell{6, 3}] = 300;    // top-right cell -> first image row, last column (id > 255)
  r[Cell{3, 1}] = 65534;  // the largest id that fits
  for (const char* name : {"labels.png", "labels.pgm"}) {
    const auto path = std::filesystem::temp_directory_path() / name;
    write_label_image(path, r);
    const auto img = read_label_image(path);
    ASSERT_EQ(img.size(), 4U);
    ASSERT_EQ(img[0].size(), 7U);
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 7; ++x)
        EXPECT_EQ(
            static_cast<int>(img[static_cast<std::size_t>(3 - y)][static_cast<std::size_t>(x)]),
            r[(Cell{x, y})] + 1)
            << name << " " << x << "," << y;
    std::filesystem::remove(path);
  }
  r[Cell{1, 1}] = 65535;
  EXPECT_THROW(write_label_image(std::filesystem::temp_directory_path() / "x.png", r), Error);
  EXPECT_THROW(write_label_image(std::filesystem::temp_directory_path() / "x.jpg", r), Error);
}

TEST(RegionExport, OutlinesEncloseTheRegionArea) {
  // A ring-shaped region (a hole in the middle) and an L next to it, at 0.1 m with an offset.
  GridGeometry geo{12, 9, 0.1, {}};
  geo.origin.position = {2.0, -1.0};
  GridMap<std::int32_t> r(geo, -1);
  for (int y = 1; y <= 6; ++y)
    for (int x = 1; x <= 6; ++x)
      if (!(x >= 3 && x <= 4 && y >= 3 && y <= 4)) r[Cell{x, y}] = 0;
  for (int y = 1; y <= 7; ++y)
    r[Cell{9, y}] = 1;
  r[Cell{10, 1}] = 1;
  r[Cell{11, 1}] = 1;
  const auto rings = region_outlines(r, 2);
  ASSERT_EQ(rings.size(), 2U);
  EXPECT_EQ(rings[0].size(), 2U);  // outer ring and hole
  EXPECT_EQ(rings[1].size(), 1U);
  EXPECT_EQ(rings[1][0].size(), 6U);  // an L has 6 corners
  double a0 = 0.0;
  for (const Ring& ring : rings[0])
    a0 += ring_area(ring);
  EXPECT_NEAR(a0, 32 * 0.01, 1e-9);
  EXPECT_NEAR(ring_area(rings[1][0]), 9 * 0.01, 1e-9);
  EXPECT_NEAR(rings[1][0][0].x, 2.0 + 0.9, 1e-9);  // world frame: origin + corner * resolution
}

TEST(Segmentation, IpaScoreHandComputed) {
  // Ground truth 30 x 10: rooms A (x < 15, 150 cells) and B (x >= 16, 140 cells) split by a wall
  // column at 15. Regions: 0 = x < 10 (100 cells: dropped, <= 100 px), 1 = 10 <= x < 30 (200
  // cells, including the wall column cells, which count against it).
  BinaryGrid gt(30, 10, 0);
  for (int y = 0; y < 10; ++y)
    gt[Cell{15, y}] = 1;
  GridMap<std::int32_t> reg(30, 10, -1);
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 30; ++x)
      reg[Cell{x, y}] = x < 10 ? 0 : 1;
  const SegmentationScores s = segmentation_scores_ipa(reg, gt, 100);
  EXPECT_EQ(s.rooms, 2);
  EXPECT_EQ(s.regions, 1);
  // Room A (150): best overlap with the kept region 1 = 50; room B (140 cells: x 16..29): 140.
  EXPECT_DOUBLE_EQ(s.recall, (50.0 / 150.0 + 140.0 / 140.0) / 2.0);
  EXPECT_DOUBLE_EQ(s.precision, 140.0 / 200.0);
  // 8-connectivity: two rooms touching at a corner are one room.
  BinaryGrid diag(22, 22, 1);
  for (int y = 0; y < 11; ++y)
    for (int x = 0; x < 11; ++x) {
      diag[Cell{x, y}] = 0;
      diag[Cell{x + 11, y + 11}] = 0;
    }
  GridMap<std::int32_t> one(22, 22, 0);
  EXPECT_EQ(segmentation_scores_ipa(one, diag, 100).rooms, 1);
  const BinaryGrid half = resample_nearest(diag, 11, 11);
  EXPECT_EQ(half.width(), 11);
  EXPECT_EQ(half[(Cell{2, 2})], 0);
  EXPECT_EQ(half[(Cell{8, 2})], 1);
}

TEST(TopologicalMap, NoRegionUnderTheMinimumAreaAndTouchingRegionsAreLinked) {
  for (std::uint32_t seed = 0; seed < 12; ++seed) {
    BinaryGrid g = voronoi::testing::random_room(seed, 80, 60, 6);
    // Free specks inside a thick wall block: isolated pockets under the minimum area.
    voronoi::testing::fill_rect(g, 30, 25, 40, 33);
    g[Cell{33, 28}] = 0;
    g[Cell{37, 30}] = 0;
    TopologyOptions o;
    o.min_region_area = 0.5;  // 0.1 m cells: 50 cells
    const TopologicalMap m = build_topological_map(g, o);
    for (const Region& r : m.regions)
      EXPECT_GE(r.area_m2, o.min_region_area) << seed;
    EXPECT_EQ(m.region[(Cell{33, 28})], -1);
    // Every pair of touching regions is joined by an edge.
    std::map<std::pair<int, int>, int> edges;
    for (const TopoEdge& e : m.edges)
      edges[{e.a, e.b}]++;
    for (int y = 0; y + 1 < g.height(); ++y)
      for (int x = 0; x + 1 < g.width(); ++x) {
        const int a = m.region[Cell{x, y}];
        for (const Cell q : {Cell{x + 1, y}, Cell{x, y + 1}}) {
          const int b = m.region[q];
          if (a < 0 || b < 0 || a == b) continue;
          EXPECT_TRUE(edges.contains({std::min(a, b), std::max(a, b)}))
              << seed << " " << a << "-" << b;
        }
      }
  }
}

}  // namespace
}  // namespace voronav::topology
