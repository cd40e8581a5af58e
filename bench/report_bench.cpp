// Speed of the replay page pipeline (issue 9): recording -> JSON, JSON -> recording, recording ->
// page, for the synthetic example and for the real floor plan NLB.png (999 x 850 cells). Baseline
// in the same run: nlohmann::json writing the same occupancy as a plain array (what a naive format
// without run-length encoding would do). bench/run_report_bench.sh turns this into
// bench/results/report.md.
#include <benchmark/benchmark.h>

#include <nlohmann/json.hpp>
#include <string>

#include "voronav/io/map_loader.hpp"
#include "voronav/report/example_recording.hpp"
#include "voronav/report/replay_html.hpp"

namespace {

using voronav::report::Recording;

const Recording& example() {
  static const Recording r = voronav::report::make_example_recording();
  return r;
}

const Recording& floorplan() {
  static const Recording r = [] {
    Recording rec;
    rec.title = "NLB floor plan";
    rec.map =
        voronav::io::load_map(std::string(VORONAV_SOURCE_DIR) + "/data/floorplans/NLB.png").grid;
    return rec;
  }();
  return r;
}

const Recording& pick(int which) {
  return which == 0 ? example() : floorplan();
}

void BM_ToJson(benchmark::State& state) {
  const Recording& r = pick(static_cast<int>(state.range(0)));
  std::size_t bytes = 0;
  for (auto _ : state) {
    std::string s = voronav::report::to_json(r);
    bytes = s.size();
    benchmark::DoNotOptimize(s);
  }
  state.counters["bytes"] = static_cast<double>(bytes);
  state.counters["cells"] = static_cast<double>(r.map.size());
}

void BM_NaiveJsonMap(benchmark::State& state) {
  const Recording& r = pick(static_cast<int>(state.range(0)));
  std::size_t bytes = 0;
  for (auto _ : state) {
    nlohmann::json j = r.map.values();
    std::string s = j.dump();
    bytes = s.size();
    benchmark::DoNotOptimize(s);
  }
  state.counters["bytes"] = static_cast<double>(bytes);
  state.counters["cells"] = static_cast<double>(r.map.size());
}

void BM_FromJson(benchmark::State& state) {
  const Recording& r = pick(static_cast<int>(state.range(0)));
  const std::string text = voronav::report::to_json(r);
  for (auto _ : state) {
    Recording back = voronav::report::from_json(text);
    benchmark::DoNotOptimize(back);
  }
  state.counters["bytes"] = static_cast<double>(text.size());
  state.counters["cells"] = static_cast<double>(r.map.size());
}

void BM_RenderPage(benchmark::State& state) {
  const Recording& r = pick(static_cast<int>(state.range(0)));
  std::size_t bytes = 0;
  for (auto _ : state) {
    std::string page = voronav::report::render_replay_html(r);
    bytes = page.size();
    benchmark::DoNotOptimize(page);
  }
  state.counters["bytes"] = static_cast<double>(bytes);
  state.counters["cells"] = static_cast<double>(r.map.size());
}

// Argument 0: the example recording; 1: the NLB floor plan.
BENCHMARK(BM_NaiveJsonMap)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ToJson)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FromJson)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RenderPage)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
