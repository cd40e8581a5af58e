#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "voronav/core/error.hpp"
#include "voronav/mapping/occupancy_map.hpp"
#include "voronav/mapping/range_simulation.hpp"

namespace voronav::mapping {
namespace {

constexpr double kPi = std::numbers::pi;

GridGeometry geometry(int w, int h, double res) {
  return GridGeometry{w, h, res, {}};
}

// A room of w x h cells with a one-cell wall all around and a pillar.
BinaryGrid room(int w, int h) {
  BinaryGrid g(GridGeometry{w, h, 0.1, {}}, 0);
  for (int x = 0; x < w; ++x)
    g[Cell{x, 0}] = g[Cell{x, h - 1}] = 1;
  for (int y = 0; y < h; ++y)
    g[Cell{0, y}] = g[Cell{w - 1, y}] = 1;
  for (int y = h / 2 - 2; y <= h / 2 + 2; ++y)
    for (int x = w / 3 - 2; x <= w / 3 + 2; ++x)
      g[Cell{x, y}] = 1;
  return g;
}

TEST(OccupancyMap, StartsAtThePriorAndUnknown) {
  OccupancyMap m(geometry(10, 5, 0.1));
  EXPECT_DOUBLE_EQ(m.probability({3, 2}), 0.5);
  EXPECT_FALSE(m.observed({3, 2}));
  const OccupancyGrid g = m.to_occupancy_grid();
  for (auto v : g.values())
    EXPECT_EQ(v, kUnknown);
}

TEST(OccupancyMap, BayesUpdateMatchesEquationTwo) {
  OccupancyMap m(geometry(4, 4, 0.1), {0.5, 0.01, 0.99});
  m.update({1, 1}, 0.7);
  EXPECT_NEAR(m.probability({1, 1}), 0.7, 1e-6);
  m.update({1, 1}, 0.7);
  // eq. 2: 0.7*0.7 / (0.7*0.7 + 0.3*0.3)
  EXPECT_NEAR(m.probability({1, 1}), 0.49 / 0.58, 1e-6);
  m.update({1, 1}, 0.4);
  const double p = 0.49 / 0.58;
  EXPECT_NEAR(m.probability({1, 1}), p * 0.4 / (p * 0.4 + (1 - p) * 0.6), 1e-6);
  m.update({1, 1}, 0.5);  // an uninformative reading changes nothing
  EXPECT_NEAR(m.probability({1, 1}), p * 0.4 / (p * 0.4 + (1 - p) * 0.6), 1e-6);
  EXPECT_TRUE(m.observed({1, 1}));
  EXPECT_FALSE(m.observed({0, 0}));
}

TEST(OccupancyMap, NonHalfPriorIsRespected) {
  OccupancyMap m(geometry(2, 2, 1.0), {0.3, 0.01, 0.99});
  EXPECT_NEAR(m.probability({0, 0}), 0.3, 1e-6);
  m.update({0, 0}, 0.3);  // measurement equal to the prior: no information
  EXPECT_NEAR(m.probability({0, 0}), 0.3, 1e-6);
}

TEST(OccupancyMap, ClampsSoThatACellCanBeCleared) {
  OccupancyMap m(geometry(3, 3, 0.1));
  for (int i = 0; i < 100; ++i)
    m.update({1, 1}, 0.9);
  EXPECT_NEAR(m.probability({1, 1}), 0.97, 1e-5);
  for (int i = 0; i < 4; ++i)
    m.update({1, 1}, 0.2);
  EXPECT_LT(m.probability({1, 1}), 0.5);
  for (int i = 0; i < 100; ++i)
    m.update({1, 1}, 0.1);
  EXPECT_NEAR(m.probability({1, 1}), 0.12, 1e-5);
}

TEST(OccupancyMap, RejectsBadInput) {
  EXPECT_THROW(OccupancyMap(geometry(0, 3, 0.1)), Error);
  EXPECT_THROW(OccupancyMap(geometry(3, 3, 0.1), {0.5, 0.6, 0.9}), Error);
  EXPECT_THROW(OccupancyMap(geometry(3, 3, 0.1), {std::nan(""), 0.1, 0.9}), Error);
  OccupancyMap m(geometry(3, 3, 0.1));
  EXPECT_THROW(m.update({1, 1}, 1.0), Error);
  EXPECT_THROW(m.update({1, 1}, std::nan("")), Error);
  EXPECT_NO_THROW(m.update({7, 7}, 0.9));  // outside: ignored
  EXPECT_THROW((void)m.probability({7, 7}), Error);
  EXPECT_THROW(m.insert_sonar({}, std::nan("")), Error);
  EXPECT_THROW(m.insert_sonar({}, -1.0), Error);
  EXPECT_THROW(m.insert_sonar({{std::nan(""), 0.0}, 0.0}, 1.0), Error);
  SonarModelOptions bad;
  bad.half_angle = 0.0;
  EXPECT_THROW(m.insert_sonar({}, 1.0, bad), Error);
  RangeScan scan{{}, {0.0, 1.0}, {1.0}};
  EXPECT_THROW(m.insert_scan(scan, LaserModelOptions{}), Error);
  scan.ranges.push_back(std::nan(""));
  EXPECT_THROW(m.insert_scan(scan, LaserModelOptions{}), Error);
  EXPECT_THROW((void)m.threshold({0.8, 0.2}), Error);
}

TEST(SonarModel, GaussianAroundTheEchoAndHalfWhenOccluded) {
  SonarModelOptions m;
  const double sigma = 0.1;
  EXPECT_DOUBLE_EQ(sonar_occupancy(2.0, 2.0, sigma, m), m.p_occupied);
  EXPECT_NEAR(sonar_occupancy(0.5, 2.0, sigma, m), m.p_empty, 1e-12);
  EXPECT_DOUBLE_EQ(sonar_occupancy(2.31, 2.0, sigma, m), 0.5);  // behind the echo
  // One sigma before the echo: p_empty + (p_occ - p_empty) e^{-1/2}
  EXPECT_NEAR(sonar_occupancy(1.9, 2.0, sigma, m),
              m.p_empty + (m.p_occupied - m.p_empty) * std::exp(-0.5), 1e-12);
  EXPECT_NEAR(sonar_occupancy(2.1, 2.0, sigma, m), 0.5 + (m.p_occupied - 0.5) * std::exp(-0.5),
              1e-12);
  // No echo: the cone is empty up to the max range and unknown beyond.
  EXPECT_DOUBLE_EQ(sonar_occupancy(4.0, 5.0, sigma, m), m.p_empty);
  EXPECT_DOUBLE_EQ(sonar_occupancy(5.5, 5.0, sigma, m), 0.5);
}

TEST(SonarModel, InsertionFollowsTheCone) {
  // 10 m x 10 m at 0.1 m; sensor at the centre looking along +x, echo at 2 m.
  OccupancyMap m(geometry(100, 100, 0.1));
  const Pose2 sensor{{5.05, 5.05}, 0.0};
  m.insert_sonar(sensor, 2.0);
  const auto cell = [&](double x, double y) { return *m.geometry().world_to_cell({x, y}); };
  EXPECT_GT(m.probability(cell(7.05, 5.05)), 0.85);  // at the echo, on the axis
  EXPECT_LT(m.probability(cell(6.05, 5.05)), 0.35);  // before the echo: empty
  EXPECT_LT(m.probability(cell(5.05, 5.05)), 0.5);   // the sensor's own cell
  EXPECT_FALSE(m.observed(cell(7.65, 5.05)));        // occluded: still 0.5
  EXPECT_FALSE(m.observed(cell(5.05, 6.05)));        // 90 deg off the axis
  EXPECT_FALSE(m.observed(cell(3.05, 5.05)));        // behind the sensor
  // Inside the cone at 10 deg off the axis: the arc at 2 m is occupied too.
  const double a = 10.0 * kPi / 180.0;
  EXPECT_GT(m.probability(cell(5.05 + 2.0 * std::cos(a), 5.05 + 2.0 * std::sin(a))), 0.6);
  // Outside the cone at 20 deg: untouched.
  const double b = 20.0 * kPi / 180.0;
  EXPECT_FALSE(m.observed(cell(5.05 + 2.0 * std::cos(b), 5.05 + 2.0 * std::sin(b))));
}

TEST(LaserModel, BeamClearsAndEndCellIsOccupied) {
  OccupancyMap m(geometry(50, 10, 0.1));
  RangeScan scan{{{0.55, 0.55}, 0.0}, {0.0}, {3.0}};
  m.insert_scan(scan, LaserModelOptions{});
  for (int x = 5; x < 35; ++x)
    EXPECT_LT(m.probability({x, 5}), 0.5) << x;
  EXPECT_GT(m.probability({35, 5}), 0.5);
  EXPECT_FALSE(m.observed({36, 5}));
  EXPECT_FALSE(m.observed({20, 6}));
  // A max-range reading only clears.
  OccupancyMap n(geometry(50, 10, 0.1));
  n.insert_scan(RangeScan{{{0.55, 0.55}, 0.0}, {0.0}, {std::numeric_limits<double>::infinity()}},
                LaserModelOptions{2.0});
  EXPECT_LT(n.probability({25, 5}), 0.5);
  for (int x = 0; x < 50; ++x)
    EXPECT_LE(n.probability({x, 5}), 0.5);
}

TEST(CastRay, HandComputedDistances) {
  BinaryGrid w(GridGeometry{20, 20, 0.5, {}}, 0);
  w[Cell{10, 3}] = 1;
  // From the centre of cell (2,3), along +x: the blocked cell's face is at x = 10 cells.
  EXPECT_NEAR(cast_ray(w, {2.5 * 0.5, 3.5 * 0.5}, 0.0, 100.0), (10.0 - 2.5) * 0.5, 1e-9);
  EXPECT_NEAR(cast_ray(w, {2.5 * 0.5, 3.5 * 0.5}, 0.0, 2.0), 2.0, 1e-12);    // max range
  EXPECT_DOUBLE_EQ(cast_ray(w, {2.5 * 0.5, 3.5 * 0.5}, kPi, 100.0), 100.0);  // leaves the grid
  // Diagonal: from (5.5, 5.5) at 45 deg towards a block at (8, 8): enters at corner (8, 8).
  w[Cell{8, 8}] = 1;
  EXPECT_NEAR(cast_ray(w, {5.5 * 0.5, 5.5 * 0.5}, kPi / 4, 100.0), 2.5 * std::sqrt(2.0) * 0.5,
              1e-9);
  EXPECT_THROW((void)cast_ray(w, {0, 0}, std::nan(""), 1.0), Error);
  EXPECT_THROW((void)cast_ray(w, {0, 0}, 0.0, 0.0), Error);
}

TEST(CastRay, RotatedOriginIsRespected) {
  // Grid rotated by 90 deg: grid +x is world +y.
  BinaryGrid w(GridGeometry{10, 10, 1.0, {{0.0, 0.0}, kPi / 2}}, 0);
  w[Cell{7, 2}] = 1;
  const Vec2 from = w.geometry().cell_center({2, 2});
  EXPECT_NEAR(cast_ray(w, from, kPi / 2, 50.0), 4.5, 1e-9);
}

TEST(Simulation, LaserSweepReproducesTheRoom) {
  const BinaryGrid truth = room(60, 40);
  OccupancyMap m(truth.geometry());
  for (int i = 0; i < 6; ++i) {
    const Pose2 pose{{0.6 + 0.8 * i, 2.0}, 0.3 * i};
    LaserSimulationOptions o;
    o.beams = 720;
    m.insert_scan(simulate_laser_scan(truth, pose, o), LaserModelOptions{});
  }
  const CellAgreement a = cell_agreement(m.threshold(), truth);
  EXPECT_GT(a.agreement, 0.97);
  EXPECT_GT(a.observed, 0.6);
}

TEST(Simulation, SonarSweepReproducesTheRoom) {
  const BinaryGrid truth = room(60, 40);
  OccupancyMap m(truth.geometry());
  for (int i = 0; i < 30; ++i) {
    const Pose2 pose{{0.5 + 0.17 * i, 1.0 + 0.06 * i}, 0.1 * i};
    m.insert_scan(simulate_sonar_ring(truth, pose, {}), SonarModelOptions{});
  }
  const OccupancyGrid t = m.threshold();
  const CellAgreement a = cell_agreement(t, truth);
  // The wide cone and sigma = cell size (seed 003) thicken walls by about a cell towards the
  // sensor, so agreement is lower than with a laser, but no wall is ever seen as free.
  EXPECT_GT(a.agreement, 0.6);
  EXPECT_GT(a.observed, 0.3);
  std::size_t false_free = 0, walls_seen = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (truth[i] == 0 || t[i] < 0) continue;
    ++walls_seen;
    if (t[i] < 50) ++false_free;
  }
  EXPECT_GT(walls_seen, 50U);
  EXPECT_EQ(false_free, 0U);
}

TEST(Simulation, NoiseIsDeterministicPerSeed) {
  const BinaryGrid truth = room(40, 40);
  LaserSimulationOptions o;
  o.noise_stddev = 0.05;
  const auto a = simulate_laser_scan(truth, {{2.0, 2.0}, 0.0}, o);
  const auto b = simulate_laser_scan(truth, {{2.0, 2.0}, 0.0}, o);
  o.seed = 2;
  const auto c = simulate_laser_scan(truth, {{2.0, 2.0}, 0.0}, o);
  EXPECT_EQ(a.ranges, b.ranges);
  EXPECT_NE(a.ranges, c.ranges);
  o.beams = 0;
  EXPECT_THROW((void)simulate_laser_scan(truth, {}, o), Error);
}

TEST(CellAgreement, CountsOnlyObservedCells) {
  OccupancyGrid map(GridGeometry{2, 2, 1.0, {}}, kUnknown);
  BinaryGrid truth(GridGeometry{2, 2, 1.0, {}}, 0);
  truth[Cell{1, 1}] = 1;
  map[Cell{0, 0}] = 0;    // right
  map[Cell{1, 1}] = 100;  // right
  map[Cell{1, 0}] = 100;  // wrong
  const auto a = cell_agreement(map, truth);
  EXPECT_EQ(a.compared, 3U);
  EXPECT_NEAR(a.agreement, 2.0 / 3.0, 1e-12);
  EXPECT_NEAR(a.observed, 0.75, 1e-12);
  EXPECT_THROW((void)cell_agreement(map, BinaryGrid(GridGeometry{3, 2, 1.0, {}}, 0)), Error);
}

TEST(OccupancyMap, ThresholdAndBinary) {
  OccupancyMap m(geometry(3, 1, 1.0));
  m.update({0, 0}, 0.2);
  m.update({1, 0}, 0.9);
  const OccupancyGrid t = m.threshold();
  EXPECT_EQ(t[(Cell{0, 0})], kFree);
  EXPECT_EQ(t[(Cell{1, 0})], kOccupied);
  EXPECT_EQ(t[(Cell{2, 0})], kUnknown);
  const BinaryGrid b = m.to_binary();
  EXPECT_EQ(b[(Cell{0, 0})], 0);
  EXPECT_EQ(b[(Cell{1, 0})], 1);
  EXPECT_EQ(b[(Cell{2, 0})], 1);
  ThresholdOptions open;
  open.unknown_is_blocked = false;
  EXPECT_EQ(m.to_binary(open)[(Cell{2, 0})], 0);
  EXPECT_EQ(m.to_occupancy_grid()[(Cell{0, 0})], 20);
  EXPECT_EQ(m.to_occupancy_grid()[(Cell{1, 0})], 90);
}

}  // namespace
}  // namespace voronav::mapping
