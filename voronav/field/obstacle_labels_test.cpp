#include "voronav/field/obstacle_labels.hpp"

#include <gtest/gtest.h>

#include <random>

namespace voronav::field {
namespace {

TEST(ObstacleLabels, HandMadeComponents) {
  // . # . . #
  // . . # . #
  // # . . . .
  BinaryGrid g(5, 3, 0);
  g[Cell{1, 2}] = 1;
  g[Cell{2, 1}] = 1;  // diagonal to (1,2): same component
  g[Cell{4, 2}] = 1;
  g[Cell{4, 1}] = 1;
  g[Cell{0, 0}] = 1;
  const ObstacleLabels l = label_obstacles(g);
  EXPECT_EQ(l.count, 3);
  EXPECT_EQ(l.label[(Cell{0, 0})], 0);
  EXPECT_EQ(l.label[(Cell{2, 1})], l.label[(Cell{1, 2})]);
  EXPECT_EQ(l.label[(Cell{4, 1})], l.label[(Cell{4, 2})]);
  EXPECT_NE(l.label[(Cell{4, 1})], l.label[(Cell{2, 1})]);
  EXPECT_EQ(l.label[(Cell{3, 1})], kNoLabel);
}

TEST(ObstacleLabels, NeighboursShareLabelsOnRandomMaps) {
  std::mt19937 rng(7);
  for (int seed = 0; seed < 20; ++seed) {
    BinaryGrid g(30, 20, 0);
    std::bernoulli_distribution b(0.3);
    for (std::size_t i = 0; i < g.size(); ++i)
      g[i] = b(rng) ? 1 : 0;
    const ObstacleLabels l = label_obstacles(g);
    for (std::size_t i = 0; i < g.size(); ++i) {
      const Cell c = g.cell_at(i);
      ASSERT_EQ(g[i] != 0, l.label[i] != kNoLabel);
      if (!g[i]) continue;
      EXPECT_GE(l.label[i], 0);
      EXPECT_LT(l.label[i], l.count);
      for (const Cell d : kNeighbours8)
        if (g.contains(c + d) && g[c + d]) {
          EXPECT_EQ(l.label[c + d], l.label[i]);
        }
    }
  }
  EXPECT_EQ(label_obstacles(BinaryGrid{}).count, 0);
}

}  // namespace
}  // namespace voronav::field
