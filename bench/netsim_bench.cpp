// Scale runs of the networked-robot protocols (seed 000, issue item 9): the decentralized method
// (and the centralized baseline) with 100 and 1000 robots on office worlds of the same robot
// density as scenario 3 (12 robots in 40 x 40 m). Reports simulated seconds per wall second and
// traffic per robot as counters; bench/run_netsim_bench.sh turns them into bench/results.
#include <benchmark/benchmark.h>

#include "voronav/sim/scenarios.hpp"

namespace {

using voronav::sim::Method;

void BM_NetsimScale(benchmark::State& state) {
  const int robots = static_cast<int>(state.range(0));
  const auto method = state.range(1) == 0 ? Method::kCentralized : Method::kDecentralized;
  const double size_m = 40.0 * std::sqrt(robots / 12.0);
  const auto sc = voronav::sim::make_scale_run(robots, size_m, 1);
  voronav::sim::NetSimOptions o;
  o.method = method;
  o.time_limit_s = 600.0;
  voronav::sim::NetSimMetrics m;
  for (auto _ : state) {
    m = voronav::sim::run_netsim(sc, o).metrics;
    benchmark::DoNotOptimize(m.traffic_bytes);
  }
  state.counters["robots"] = robots;
  state.counters["world_m"] = size_m;
  state.counters["success"] = m.success ? 1 : 0;
  state.counters["simulated_s"] = m.simulated_s;
  state.counters["sim_s_per_wall_s"] = m.wall_s > 0 ? m.simulated_s / m.wall_s : 0.0;
  state.counters["traffic_bytes_per_robot"] = static_cast<double>(m.traffic_bytes) / robots;
  state.counters["messages_per_robot"] = static_cast<double>(m.messages) / robots;
  state.counters["route_time_s"] = m.route_time_s;
  state.counters["max_robot_cpu_s"] = m.max_robot_cpu_s;
}

BENCHMARK(BM_NetsimScale)
    ->ArgsProduct({{12, 100}, {0, 1}})
    ->ArgNames({"robots", "decentralized"})
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();
