// Scale runs of the networked-robot protocols (seed 000, issue item 9): the decentralized method
// and the centralized baseline with 6, 12, 100 and 1000 robots on office worlds whose robot
// density is that of a paper scenario (docs/reproductions/networked.md, "Scale"). Reports
// simulated seconds per wall second, traffic and messages per robot, success and route time as
// counters; bench/run_netsim_bench.sh turns them into bench/results/networked.md.
//
//   netsim_bench [google benchmark flags]        the default set (6..100 robots, both methods)
//   netsim_bench --case ROBOTS SIZE_M METHOD [LIMIT_S] [SEED] [defaults] [KEY=VALUE...]
//                                                 one run, one JSON line on stdout; KEY is one of
//                                                 the scale options of NetSimOptions or loss;
//                                                 `defaults` starts from the default options
//                                                 instead of NetSimOptions::scale_options()
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "voronav/sim/scenarios.hpp"

namespace {

using voronav::sim::Method;

/// World side [m] for `robots` robots at the density of `robots_ref` robots in `side_ref` m.
double side_for(int robots, int robots_ref, double side_ref) {
  return side_ref * std::sqrt(static_cast<double>(robots) / robots_ref);
}

voronav::sim::NetSimMetrics run_case(
    int robots, double size_m, Method method, double limit_s, std::uint64_t seed,
    voronav::sim::NetSimOptions o = voronav::sim::NetSimOptions{}.scale_options()) {
  const auto sc = voronav::sim::make_scale_run(robots, size_m, seed);
  o.method = method;
  o.time_limit_s = limit_s;
  return voronav::sim::run_netsim(sc, o).metrics;
}

/// KEY=VALUE overrides of the scale options (ablations), applied after scale_options().
bool set_option(voronav::sim::NetSimOptions& o, const std::string& kv) {
  const auto eq = kv.find('=');
  if (eq == std::string::npos) return false;
  const std::string k = kv.substr(0, eq);
  const double v = std::atof(kv.c_str() + eq + 1);
  if (k == "search_timeout_s") {
    o.search_timeout_s = v;
  } else if (k == "search_timeout_per_m") {
    o.search_timeout_per_m = v;
  } else if (k == "search_activity_s") {
    o.search_activity_s = v;
  } else if (k == "keep_bridge_on_new_search") {
    o.keep_bridge_on_new_search = v != 0.0;
  } else if (k == "source_straight_start") {
    o.source_straight_start = v != 0.0;
  } else if (k == "frontier_by_points") {
    o.frontier_by_points = v != 0.0;
  } else if (k == "walk_replan_whole_map") {
    o.walk_replan_whole_map = v != 0.0;
  } else if (k == "loss") {
    o.radio.loss = v;
  } else {
    return false;
  }
  return true;
}

void BM_NetsimScale(benchmark::State& state) {
  const int robots = static_cast<int>(state.range(0));
  const auto method = state.range(1) == 0 ? Method::kCentralized : Method::kDecentralized;
  // range(2): 3 = scenario 3's density (12 robots / 40 x 40 m, the paper's densest),
  //           4 = scenario 4's (12 robots / 80 x 80 m, sparse stress case).
  const double size_m = side_for(robots, 12, state.range(2) == 3 ? 40.0 : 80.0);
  voronav::sim::NetSimMetrics m;
  for (auto _ : state) {
    m = run_case(robots, size_m, method, 600.0, 1);
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
    ->ArgsProduct({{12, 100}, {0, 1}, {3}})
    ->ArgNames({"robots", "decentralized", "density"})
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

int run_one(int argc, char** argv) {
  if (argc < 5) {
    std::fprintf(stderr,
                 "usage: %s --case ROBOTS SIZE_M METHOD [LIMIT_S] [SEED] [defaults] "
                 "[KEY=VALUE...]\n",
                 argv[0]);
    return 2;
  }
  const int robots = std::atoi(argv[2]);
  const double size_m = std::atof(argv[3]);
  const Method method = voronav::sim::parse_method(argv[4]);
  const double limit_s = argc > 5 ? std::atof(argv[5]) : 600.0;
  const std::uint64_t seed = argc > 6 ? std::strtoull(argv[6], nullptr, 10) : 1;
  auto o = voronav::sim::NetSimOptions{}.scale_options();
  int first_option = 7;
  if (argc > 7 && std::string(argv[7]) == "defaults") {
    o = voronav::sim::NetSimOptions{};
    first_option = 8;
  }
  for (int i = first_option; i < argc; ++i)
    if (!set_option(o, argv[i])) {
      std::fprintf(stderr, "unknown option %s\n", argv[i]);
      return 2;
    }
  const auto m = run_case(robots, size_m, method, limit_s, seed, o);
  const double n = robots;
  std::printf(
      "{\"robots\": %d, \"world_m\": %.1f, \"method\": \"%s\", \"seed\": %llu, \"success\": %s, "
      "\"route_time_s\": %.1f, \"arrival_time_s\": %.1f, \"simulated_s\": %.1f, \"wall_s\": %.2f, "
      "\"sim_s_per_wall_s\": %.3f, \"traffic_bytes_per_robot\": %.1f, "
      "\"messages_per_robot\": %.2f, \"search_attempts\": %d, \"travel_m\": %.1f, "
      "\"max_robot_cpu_s\": %.3f, \"route_found_by\": \"%s\", \"route_robots\": %d, "
      "\"paths_lost\": %d, \"route_length_m\": %.1f, \"source_travel_m\": %.1f, "
      "\"repairs_executed\": %d, \"changes_on_route\": %d, \"options\": \"%s\"}\n",
      robots, size_m, std::string(voronav::sim::to_string(method)).c_str(),
      static_cast<unsigned long long>(seed), m.success ? "true" : "false", m.route_time_s,
      m.arrival_time_s, m.simulated_s, m.wall_s, m.wall_s > 0 ? m.simulated_s / m.wall_s : 0.0,
      static_cast<double>(m.traffic_bytes) / n, static_cast<double>(m.messages) / n,
      m.search_attempts, m.travel_m, m.max_robot_cpu_s,
      std::string(voronav::sim::to_string(m.route_found_by)).c_str(), m.route_robots, m.paths_lost,
      m.route_length_m, m.source_travel_m, m.repairs_executed, m.changes_on_route,
      first_option == 8 ? "defaults" : "scale");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "--case") return run_one(argc, argv);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
