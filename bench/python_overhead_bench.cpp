// The C++ side of the Python-overhead benchmark (bench/python_overhead.py): mean time per query of
// A* on an even sample of den520d's .scen queries, planned on a prebuilt BinaryGrid with one
// reused planner, exactly as the Python script plans the same sample through voronav.Planner.
// The script runs both in alternating rounds and writes bench/results/python.md.
//
// Environment: VORONAV_MOVINGAI_DIR (else ../shared/data/movingai or ../../shared/data/movingai
// beside the repository, else /work/shared/data/movingai), VORONAV_BENCH_MAP (default den520d),
// VORONAV_BENCH_SAMPLE (queries, default 200).
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "voronav/core/error.hpp"
#include "voronav/io/movingai.hpp"
#include "voronav/planning/astar.hpp"

namespace fs = std::filesystem;
using namespace voronav;

namespace {

fs::path data_dir() {
  if (const char* env = std::getenv("VORONAV_MOVINGAI_DIR")) return env;
  const fs::path src(VORONAV_SOURCE_DIR);
  for (const fs::path& p :
       {src / ".." / "shared" / "data" / "movingai",
        src / ".." / ".." / "shared" / "data" / "movingai", fs::path("/work/shared/data/movingai")})
    if (fs::exists(p)) return p;
  return src / "data" / "movingai";
}

/// Every k-th query so that `sample` queries of all buckets remain (the Python script's rule).
std::vector<io::MovingAiQuery> sample_queries(const std::vector<io::MovingAiQuery>& all,
                                              std::size_t sample) {
  std::vector<io::MovingAiQuery> out;
  const std::size_t step = std::max<std::size_t>(1, all.size() / std::max<std::size_t>(1, sample));
  for (std::size_t i = 0; i < all.size() && out.size() < sample; i += step)
    out.push_back(all[i]);
  return out;
}

void BM_MovingAiQuery(benchmark::State& state) {
  const char* name_env = std::getenv("VORONAV_BENCH_MAP");
  const std::string name = name_env ? name_env : "den520d";
  const char* sample_env = std::getenv("VORONAV_BENCH_SAMPLE");
  const std::size_t sample = sample_env ? std::stoul(sample_env) : 200;
  const fs::path dir = data_dir();
  const OccupancyGrid map = io::load_movingai_map(dir / (name + ".map"));
  const auto queries = sample_queries(io::load_movingai_scen(dir / (name + ".map.scen")), sample);
  const BinaryGrid grid = binarize(map);
  planning::AStarPlanner planner;
  double length = 0.0;
  for (auto _ : state) {
    for (const auto& q : queries) {
      const auto r = planner.plan(grid, io::movingai_to_cell(q.start_x, q.start_y, map.height()),
                                  io::movingai_to_cell(q.goal_x, q.goal_y, map.height()));
      length += r.length_cells;
    }
  }
  benchmark::DoNotOptimize(length);
  state.counters["queries"] = static_cast<double>(queries.size());
}
BENCHMARK(BM_MovingAiQuery)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
