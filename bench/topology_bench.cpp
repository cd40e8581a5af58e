// Speed of the seed-003 pipeline on a real ROS map (willow, 1165 x 945 at 0.05 m, from
// ../shared/data when present, else the bundled depot map; override with VORONAV_TOPO_MAP):
//   edt         field::distance_transform, the baseline every ratio is measured against
//   gvd_full    voronoi::DynamicGvd full build (EDT + labels + raw diagram + thinning + pruning)
//   gvd_nothin  the same without thinning/pruning
//   ca          the paper's labeled Voronoi by cellular automaton
//   topology    topology::build_topological_map (diagram, critical points, regions, graph)
//   incr_3x3    DynamicGvd::update for a 3x3 block appearing/disappearing at a random free place
// Counters: ns_per_cell (of the whole map) so maps of any size compare.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <random>

#include "free_spots.hpp"
#include "voronav/field/distance_transform.hpp"
#include "voronav/io/map_loader.hpp"
#include "voronav/topology/topological_map.hpp"
#include "voronav/voronoi/gvd.hpp"
#include "voronav/voronoi/labeled_voronoi.hpp"

namespace {

using namespace voronav;

const BinaryGrid& bench_map() {
  static const BinaryGrid grid = [] {
    namespace fs = std::filesystem;
    std::vector<fs::path> candidates;
    if (const char* env = std::getenv("VORONAV_TOPO_MAP")) candidates.emplace_back(env);
    candidates.emplace_back(fs::path(VORONAV_SOURCE_DIR) /
                            "../../shared/data/ros_maps/willow/willow-full-0.05.yaml");
    candidates.emplace_back("/work/shared/data/ros_maps/willow/willow-full-0.05.yaml");
    candidates.emplace_back(fs::path(VORONAV_SOURCE_DIR) / "data/ros_maps/depot/depot.yaml");
    for (const auto& p : candidates)
      if (fs::exists(p)) return binarize(io::load_map(p).grid);
    return BinaryGrid(200, 200, 0);
  }();
  return grid;
}

void set_counters(benchmark::State& state) {
  const double cells = static_cast<double>(bench_map().size());
  state.counters["cells"] = cells;
  state.counters["ns_per_cell"] =
      benchmark::Counter(cells * static_cast<double>(state.iterations()) * 1e-9,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_Edt(benchmark::State& state) {
  for (auto _ : state)
    benchmark::DoNotOptimize(field::distance_transform(bench_map(), {.border_is_blocked = true}));
  set_counters(state);
}

void BM_GvdFull(benchmark::State& state) {
  for (auto _ : state) {
    voronoi::DynamicGvd g(bench_map());
    benchmark::DoNotOptimize(g);
  }
  set_counters(state);
}

void BM_GvdNoThin(benchmark::State& state) {
  voronoi::GvdOptions o;
  o.thin = false;
  for (auto _ : state) {
    voronoi::DynamicGvd g(bench_map(), o);
    benchmark::DoNotOptimize(g);
  }
  set_counters(state);
}

void BM_Ca(benchmark::State& state) {
  for (auto _ : state)
    benchmark::DoNotOptimize(voronoi::build_labeled_voronoi(bench_map()));
  set_counters(state);
}

void BM_Topology(benchmark::State& state) {
  for (auto _ : state)
    benchmark::DoNotOptimize(topology::build_topological_map(bench_map()));
  set_counters(state);
}

void BM_Incremental3x3(benchmark::State& state) {
  const BinaryGrid& map = bench_map();
  voronoi::DynamicGvd g(map);
  const std::vector<Cell> spots = voronav::bench::free_3x3_spots(map, 7, 64, 100000);
  std::size_t k = 0;
  bool add = true;
  std::vector<voronoi::CellChange> changes(9);
  for (auto _ : state) {
    const Cell c = spots[k % spots.size()];
    int n = 0;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        changes[static_cast<std::size_t>(n++)] = {c + Cell{dx, dy}, add};
    benchmark::DoNotOptimize(g.update(changes));
    if (!add) ++k;
    add = !add;
  }
  set_counters(state);
}

BENCHMARK(BM_Edt)->Name("edt")->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GvdFull)->Name("gvd_full")->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GvdNoThin)->Name("gvd_nothin")->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Ca)->Name("ca")->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Topology)->Name("topology")->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Incremental3x3)->Name("incr_3x3")->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
