// Coordination benchmark (seed 002) and the paper's experiments.
//  - Benchmarks: resolution of 3 robots with a fixed priority (paper: < 0.1 ms), the same including
//    building the network from the paths, EDF, and the GA on the section 5.1 random networks with
//    30 and 100 robots; a plain resolve() of the same network is the in-run baseline.
//  - `coordination_bench --repro [--runs R]` prints the markdown tables of
//    docs/reproductions/coordination.md: Table 4, figure 17 (urgent fraction) and figure 18 (GA
//    rounds and makespan / max travel time over R runs). bench/coordination_repro.py adds the
//    MAPF experiments (via the CLI) and writes bench/results/coordination.md.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "voronav/coordination/coordinator.hpp"
#include "voronav/coordination/internal/critical_moves.hpp"
#include "voronav/coordination/paper_networks.hpp"

namespace co = voronav::coordination;
using voronav::Vec2;

namespace {

std::vector<co::Agent> three_robots() {
  // Figure 11-like: three robots whose paths cross pairwise, speeds 1, 2, 1 m/s, radius 5 m.
  return {{1, co::TimedPath({{0, 50}, {100, 50}}, {1.0, co::kInfinity}), 5.0},
          {2, co::TimedPath({{50, 0}, {50, 100}, {60, 140}}, {2.0, co::kInfinity}), 5.0},
          {3, co::TimedPath({{0, 0}, {40, 40}, {90, 60}, {100, 100}}, {1.0, co::kInfinity}), 5.0}};
}

void BM_Resolve3FixedPriority(benchmark::State& state) {
  const auto agents = three_robots();
  const co::MdNetwork net = co::build_network(agents);
  const std::vector<int> order{0, 1, 2};
  for (auto _ : state)
    benchmark::DoNotOptimize(co::resolve(net, order));
}
BENCHMARK(BM_Resolve3FixedPriority);

void BM_NetworkAndResolve3(benchmark::State& state) {
  const auto agents = three_robots();
  const std::vector<int> order{0, 1, 2};
  for (auto _ : state) {
    const co::MdNetwork net = co::build_network(agents);
    benchmark::DoNotOptimize(co::resolve(net, order));
  }
}
BENCHMARK(BM_NetworkAndResolve3)->Unit(benchmark::kMicrosecond);

void BM_ResolveRandom(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const co::MdNetwork net = co::random_network(n, 3 * n, 1);
  std::vector<int> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  for (auto _ : state)
    benchmark::DoNotOptimize(co::resolve(net, order));
}
BENCHMARK(BM_ResolveRandom)->Arg(30)->Arg(100)->Unit(benchmark::kMicrosecond);

void BM_Edf(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const co::MdNetwork net = co::random_network(n, 3 * n, 1);
  for (auto _ : state)
    benchmark::DoNotOptimize(co::bottom_level_edf(net));
}
BENCHMARK(BM_Edf)->Arg(30)->Arg(100)->Unit(benchmark::kMicrosecond);

void BM_Ga(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const co::MdNetwork net = co::random_network(n, 2 * n, 1);
  co::SearchOptions so;
  so.edf_reduction = false;  // all n robots are searched ("n urgent agents")
  for (auto _ : state)
    benchmark::DoNotOptimize(co::search_priority(net, so));
}
BENCHMARK(BM_Ga)->Arg(30)->Arg(100)->Unit(benchmark::kMillisecond)->Iterations(1);

// One evaluation of the paper 3-opt's incremental resolution (MoveEvaluator::resolve_move, the
// GA's hot spot, issue #16): n robots, `points` shared points of the section 5.1 random network,
// a fixed random base order and 1,024 random segment moves (the paper's draw) evaluated in turn
// with the GA's cutoff (base makespan + 1e-9). Counters: robots resolved per move, moves cut.
void BM_MoveEvaluator(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const co::MdNetwork net = co::random_network(n, static_cast<int>(state.range(1)), 1);
  std::mt19937_64 rng(7);
  std::vector<int> base_order(static_cast<std::size_t>(n));
  std::iota(base_order.begin(), base_order.end(), 0);
  std::shuffle(base_order.begin(), base_order.end(), rng);
  const co::Resolution base = co::resolve(net, base_order);
  struct Move {
    std::vector<int> cand;
    int from, to;
  };
  std::vector<Move> moves;
  co::internal::SegmentMove mv;
  while (moves.size() < 1024) {
    if (!co::internal::random_segment_move(n, rng, mv)) continue;
    Move m;
    co::internal::apply_segment_move(base_order, mv, m.cand, m.from, m.to);
    moves.push_back(std::move(m));
  }
  co::MoveEvaluator ev(net);
  std::size_t k = 0, resolved = 0, cut = 0, count = 0;
  for (auto _ : state) {
    const Move& m = moves[k++ % moves.size()];
    const co::Resolution r =
        ev.resolve_move(base_order, base, m.cand, m.from, m.to, base.makespan + 1e-9);
    benchmark::DoNotOptimize(r.makespan);
    resolved += static_cast<std::size_t>(ev.last_resolved());
    cut += r.cut ? 1U : 0U;
    ++count;
  }
  state.counters["resolved_per_move"] =
      static_cast<double>(resolved) / static_cast<double>(std::max<std::size_t>(count, 1));
  state.counters["cut_fraction"] =
      static_cast<double>(cut) / static_cast<double>(std::max<std::size_t>(count, 1));
}
BENCHMARK(BM_MoveEvaluator)
    ->Args({30, 60})
    ->Args({100, 200})
    ->Args({100, 800})
    ->Unit(benchmark::kMicrosecond);

// The 3-opt neighbourhood (issue #16): the paper's random moves (order 0) against critical-first
// (order 1) and critical-delayed (order 2) on the section 5.1 random network of n robots and 2n
// points, network seed s; counters: the makespan reached and the orders evaluated.
void BM_GaOrder(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const co::MdNetwork net =
      co::random_network(n, 2 * n, static_cast<std::uint64_t>(state.range(1)));
  co::SearchOptions so;
  so.edf_reduction = false;
  const co::ThreeOptOrder orders[] = {co::ThreeOptOrder::kPaper, co::ThreeOptOrder::kCriticalFirst,
                                      co::ThreeOptOrder::kCriticalDelayed};
  so.ga.three_opt_order = orders[static_cast<std::size_t>(state.range(2))];
  co::SearchResult r;
  for (auto _ : state) {
    r = co::search_priority(net, so);
    benchmark::DoNotOptimize(r);
  }
  state.counters["makespan"] = r.resolution.makespan;
  state.counters["evaluations"] = static_cast<double>(r.evaluations);
}
BENCHMARK(BM_GaOrder)
    ->ArgsProduct({{30, 100}, {1, 2, 3, 4, 5, 6, 7, 8}, {0, 1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

double mean(const std::vector<double>& v) {
  return v.empty() ? 0.0 : std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}
double stddev(const std::vector<double>& v) {
  if (v.size() < 2) return 0.0;
  const double m = mean(v);
  double s = 0.0;
  for (const double x : v)
    s += (x - m) * (x - m);
  return std::sqrt(s / static_cast<double>(v.size() - 1));
}

void repro(int runs) {
  std::cout << "### Table 4: Bottom-level EDF on the derived 5-robot network\n\n";
  const co::MdNetwork t4 = co::table4_network();
  const co::EdfResult edf = co::bottom_level_edf(t4);
  std::cout
      << "| round | A1 | A2 | A3 | A4 | A5 | UG | removed |\n|---|---|---|---|---|---|---|---|\n";
  for (std::size_t k = 0; k < edf.rounds.size(); ++k) {
    const auto& r = edf.rounds[k];
    std::cout << "| " << k + 1;
    for (int i = 0; i < 5; ++i) {
      const double c = r.completion[static_cast<std::size_t>(i)];
      if (std::isnan(c)) {
        std::cout << " | –";
      } else {
        std::cout << " | " << c << "/" << edf.deadline - c;
      }
    }
    std::cout << " | {";
    for (std::size_t j = 0; j < r.urgent_group.size(); ++j) {
      std::cout << (j ? "," : "") << r.urgent_group[j] + 1;
    }
    std::cout << "} | A" << r.removed + 1 << " |\n";
  }
  std::cout << "\nPriority order (highest first): {";
  for (std::size_t j = 0; j < edf.order.size(); ++j)
    std::cout << (j ? "-" : "") << edf.order[j] + 1;
  const auto res = co::resolve(t4, edf.order);
  std::cout << "}, makespan " << res.makespan << " s; delays";
  for (int i = 0; i < 5; ++i)
    std::cout << " A" << i + 1 << "=" << res.delays[static_cast<std::size_t>(i)];
  co::SearchOptions ex;
  ex.kind = co::SearchKind::kExhaustive;
  ex.edf_reduction = false;
  std::cout << "; exhaustive optimum " << co::search_priority(t4, ex).resolution.makespan
            << " s\n\n";

  std::cout << "### Figure 17: fraction of urgent robots after EDF (" << runs << " runs each)\n\n";
  const std::vector<double> per_agent{0.5, 1.0, 1.5, 2.0, 2.5, 3.0};
  std::cout << "| N \\ boxes per robot, P/N (per-agent meetings = 2 P/N) |";
  for (const double x : per_agent)
    std::cout << " " << x << " |";
  std::cout << "\n|---|";
  for (std::size_t i = 0; i < per_agent.size(); ++i)
    std::cout << "---|";
  std::cout << "\n";
  for (int n = 20; n <= 50; n += 10) {
    std::cout << "| " << n << " |";
    for (const double x : per_agent) {
      std::vector<double> frac;
      for (int run = 0; run < runs; ++run) {
        const auto net = co::random_network(n, static_cast<int>(std::lround(x * n)),
                                            static_cast<std::uint64_t>(1000 * n + run));
        frac.push_back(static_cast<double>(co::bottom_level_edf(net).urgent_group.size()) / n);
      }
      std::printf(" %.2f ± %.2f |", mean(frac), stddev(frac));
      std::fflush(stdout);
    }
    std::cout << "\n";
  }

  std::cout << "\n### Figure 18: GA/3-opt on 30 urgent robots (" << runs << " runs)\n\n";
  std::vector<double> rounds, ratio, ms, edf_ratio;
  for (int run = 0; run < runs; ++run) {
    const auto net = co::random_network(30, 60, static_cast<std::uint64_t>(5000 + run));
    co::SearchOptions so;
    so.edf_reduction = false;
    so.ga.seed = static_cast<std::uint64_t>(run + 1);
    const auto t0 = std::chrono::steady_clock::now();
    const auto r = co::search_priority(net, so);
    ms.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    const double tmax = *std::max_element(net.travel_times().begin(), net.travel_times().end());
    rounds.push_back(r.rounds);
    ratio.push_back(r.resolution.makespan / tmax);
    edf_ratio.push_back(co::resolve(net, co::bottom_level_edf(net).order).makespan / tmax);
  }
  std::printf("| quantity | mean ± sd | paper |\n|---|---|---|\n");
  std::printf("| GA rounds until convergence | %.2f ± %.2f | 2.47 ± 0.96 |\n", mean(rounds),
              stddev(rounds));
  std::printf("| makespan / max travel time (GA) | %.3f ± %.3f | 1.05 ± 0.03 |\n", mean(ratio),
              stddev(ratio));
  std::printf("| makespan / max travel time (EDF order only) | %.3f ± %.3f | – |\n",
              mean(edf_ratio), stddev(edf_ratio));
  std::printf("| GA time [ms] | %.1f ± %.1f | – |\n\n", mean(ms), stddev(ms));
}

}  // namespace

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--repro") == 0) {
      int runs = 100;
      for (int j = 1; j + 1 < argc; ++j) {
        if (std::strcmp(argv[j], "--runs") == 0) runs = std::max(1, std::atoi(argv[j + 1]));
      }
      repro(runs);
      return 0;
    }
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
