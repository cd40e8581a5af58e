// Speed of the seed 004 building blocks, as ratios against a baseline measured in the same run:
// our exact grid ray casting (robot::cast_scan, Amanatides-Woo) against the mapping module's
// simulated laser (mapping::simulate_laser_scan) on the paper's world; feature extraction per
// scan; Boost.Polygon Voronoi of N points; tree construction on the paper's world.
// Run: build/default/bin/exploration_bench
#include <benchmark/benchmark.h>

#include <random>

#include "voronav/exploration/explorer.hpp"
#include "voronav/exploration/feature_points.hpp"
#include "voronav/exploration/point_voronoi.hpp"
#include "voronav/exploration/voronoi_tree.hpp"
#include "voronav/mapping/range_simulation.hpp"
#include "voronav/planning/grid_planner.hpp"
#include "voronav/robot/laser.hpp"

namespace {

using namespace voronav;

const BinaryGrid& world() {
  static const BinaryGrid w = binarize(exploration::paper_world(0.05));
  return w;
}

void BM_CastScan(benchmark::State& state) {
  robot::LaserOptions o;
  o.beams = 360;
  o.range_max = 3.0;
  double yaw = 0.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(robot::cast_scan(world(), {{7.0, 8.5}, yaw}, o));
    yaw += 0.1;
  }
}
BENCHMARK(BM_CastScan);

void BM_BaselineMappingLaser(benchmark::State& state) {
  mapping::LaserSimulationOptions o;
  o.beams = 360;
  o.max_range = 3.0;
  double yaw = 0.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(mapping::simulate_laser_scan(world(), {{7.0, 8.5}, yaw}, o));
    yaw += 0.1;
  }
}
BENCHMARK(BM_BaselineMappingLaser);

void BM_FeaturePoints(benchmark::State& state) {
  robot::LaserOptions o;
  o.beams = 360;
  const robot::LaserScan scan = robot::cast_scan(world(), {{7.0, 8.5}, 0.3}, o);
  for (auto _ : state)
    benchmark::DoNotOptimize(exploration::extract_feature_points(scan));
}
BENCHMARK(BM_FeaturePoints);

void BM_VoronoiOfPoints(benchmark::State& state) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0.0, 20.0);
  std::vector<Vec2> pts(static_cast<std::size_t>(state.range(0)));
  for (auto& p : pts)
    p = {u(rng), u(rng)};
  for (auto _ : state)
    benchmark::DoNotOptimize(exploration::voronoi_of_points(pts));
  state.SetComplexityN(state.range(0));
}
BENCHMARK(BM_VoronoiOfPoints)->Arg(100)->Arg(1000)->Arg(10000)->Complexity();

void BM_VoronoiTree(benchmark::State& state) {
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> u(0.5, 19.5);
  std::vector<Vec2> pts(100);
  for (auto& p : pts)
    p = {u(rng), u(rng)};
  const exploration::PointVoronoi v = exploration::voronoi_of_points(pts);
  const BinaryGrid trav = planning::make_planning_grid(world(), 0.22);
  for (auto _ : state)
    benchmark::DoNotOptimize(exploration::build_voronoi_tree(v, trav, {2.0, 2.0}));
}
BENCHMARK(BM_VoronoiTree);

}  // namespace

BENCHMARK_MAIN();
