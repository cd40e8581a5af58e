// Planner benchmark on the Moving AI maps: mean time per scenario query for A*, Dijkstra, JPS,
// JPS+ (tables built before timing; the build time is its own counter) and a plain BFS flood of
// the whole map from the same start (the memory-bound floor of any search that touches the whole
// map), all measured in the same run; A*, JPS and JPS+ in alternating rounds
// ($VORONAV_BENCH_ROUNDS, default 3). bench/run_planning_bench.sh turns the JSON output into
// bench/results/planning.md with the JPS speed-ups over A* and the A*/BFS ratio per map.
//
// Maps are read from $VORONAV_MOVINGAI_DIR, else ../shared/data/movingai beside the repo, else
// the bundled data/movingai.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <vector>

#include "voronav/io/movingai.hpp"
#include "voronav/planning/astar.hpp"
#include "voronav/planning/bfs.hpp"
#include "voronav/planning/jps.hpp"

namespace fs = std::filesystem;
using namespace voronav;

namespace {

struct MapCase {
  std::string name;
  BinaryGrid grid;
  std::vector<std::pair<Cell, Cell>> queries;
};

fs::path data_dir() {
  if (const char* env = std::getenv("VORONAV_MOVINGAI_DIR")) return env;
  const fs::path shared = fs::path(VORONAV_SOURCE_DIR) / ".." / "shared" / "data" / "movingai";
  if (fs::exists(shared)) return shared;
  return fs::path(VORONAV_SOURCE_DIR) / "data" / "movingai";
}

std::vector<std::shared_ptr<MapCase>> load_cases(std::size_t max_queries) {
  std::vector<std::shared_ptr<MapCase>> out;
  std::vector<fs::path> maps;
  for (const auto& e : fs::directory_iterator(data_dir()))
    if (e.path().extension() == ".map" && fs::exists(e.path().string() + ".scen"))
      maps.push_back(e.path());
  std::sort(maps.begin(), maps.end());
  for (const auto& m : maps) {
    auto c = std::make_shared<MapCase>();
    c->name = m.stem().string();
    c->grid = binarize(io::load_movingai_map(m));
    const auto scen = io::load_movingai_scen(m.string() + ".scen");
    // An even sample over all buckets (short and long queries alike).
    const std::size_t step = std::max<std::size_t>(1, scen.size() / max_queries);
    for (std::size_t i = 0; i < scen.size(); i += step) {
      const auto& q = scen[i];
      c->queries.emplace_back(io::movingai_to_cell(q.start_x, q.start_y, c->grid.height()),
                              io::movingai_to_cell(q.goal_x, q.goal_y, c->grid.height()));
    }
    out.push_back(std::move(c));
  }
  return out;
}

void run_planner(benchmark::State& state, const MapCase& c, planning::GridPlanner& planner) {
  std::size_t expanded = 0;
  if (auto* jps = dynamic_cast<planning::JpsPlanner*>(&planner)) {
    // Per-map data (bit-packed map; JPS+ tables) built once, outside the timed loop.
    state.counters["build_ms"] = jps->prepare(c.grid);
  }
  for (auto _ : state) {
    for (const auto& [s, g] : c.queries) {
      const auto r = planner.plan(c.grid, s, g);
      expanded += r.expanded;
      benchmark::DoNotOptimize(r.length_cells);
    }
  }
  const double n = static_cast<double>(state.iterations() * c.queries.size());
  state.counters["us_per_query"] =
      benchmark::Counter(n, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["expanded_per_query"] = static_cast<double>(expanded) / n;
  state.counters["queries"] = static_cast<double>(c.queries.size());
}

void run_bfs(benchmark::State& state, const MapCase& c) {
  planning::BfsFlood bfs;
  std::size_t reached = 0;
  for (auto _ : state)
    for (const auto& q : c.queries)
      reached += bfs.flood(c.grid, q.first, planning::Connectivity::k8);
  const double n = static_cast<double>(state.iterations() * c.queries.size());
  state.counters["us_per_query"] =
      benchmark::Counter(n, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["expanded_per_query"] = static_cast<double>(reached) / n;
  state.counters["queries"] = static_cast<double>(c.queries.size());
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t max_queries = 200;
  if (const char* env = std::getenv("VORONAV_BENCH_QUERIES")) max_queries = std::stoul(env);
  const auto cases = load_cases(max_queries);
  if (cases.empty()) {
    std::cerr << "planning_bench: no .map with .map.scen found in " << data_dir() << "\n";
    return 2;
  }
  // A*, JPS and JPS+ run in `rounds` alternating rounds over all maps (run_planning_bench.sh
  // keeps each one's fastest round), so a load change on the machine hits all three alike.
  int rounds = 3;
  if (const char* env = std::getenv("VORONAV_BENCH_ROUNDS")) rounds = std::max(1, std::atoi(env));
  for (int round = 0; round < rounds; ++round)
    for (const auto& c : cases) {
      benchmark::RegisterBenchmark(("astar/" + c->name).c_str(), [c](benchmark::State& s) {
        planning::AStarPlanner p;
        run_planner(s, *c, p);
      })->Unit(benchmark::kMillisecond);
      benchmark::RegisterBenchmark(("jps/" + c->name).c_str(), [c](benchmark::State& s) {
        planning::JpsPlanner p;
        run_planner(s, *c, p);
      })->Unit(benchmark::kMillisecond);
      benchmark::RegisterBenchmark(("jps+/" + c->name).c_str(), [c](benchmark::State& s) {
        planning::JpsPlusPlanner p;
        run_planner(s, *c, p);
      })->Unit(benchmark::kMillisecond);
    }
  for (const auto& c : cases) {
    benchmark::RegisterBenchmark(("dijkstra/" + c->name).c_str(), [c](benchmark::State& s) {
      planning::DijkstraPlanner p;
      run_planner(s, *c, p);
    })->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("bfs/" + c->name).c_str(), [c](benchmark::State& s) {
      run_bfs(s, *c);
    })->Unit(benchmark::kMillisecond);
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
