// Rendering speed: a 1000x1000-cell occupancy map with a path, written as PNG, against the cost
// of only filling the raster (the floor any picture of that map pays), measured in the same run.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <filesystem>
#include <random>

#include "voronav/render/figure.hpp"

namespace {

using namespace voronav;

OccupancyGrid random_map(int side) {
  OccupancyGrid g(GridGeometry{side, side, 0.05, {}}, kFree);
  std::mt19937 rng(1);
  for (std::size_t i = 0; i < g.size(); ++i)
    g[i] = rng() % 10 == 0 ? kOccupied : kFree;
  return g;
}

void BM_RenderPng(benchmark::State& state) {
  const OccupancyGrid map = random_map(static_cast<int>(state.range(0)));
  std::vector<Cell> path;
  for (int i = 0; i < map.width(); ++i)
    path.push_back({i, i});
  const auto out = std::filesystem::temp_directory_path() /
                   ("voronav_render_bench_" + std::to_string(::getpid()) + ".png");
  for (auto _ : state) {
    render::Figure fig(map.geometry(), {.pixels_per_cell = 1.0, .title = "render bench"});
    fig.occupancy(map);
    fig.path(path, render::colors::kBlue);
    fig.save(out);
  }
  std::filesystem::remove(out);
}
BENCHMARK(BM_RenderPng)->Arg(1000)->Unit(benchmark::kMillisecond);

void BM_RasterOnly(benchmark::State& state) {
  const OccupancyGrid map = random_map(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    std::vector<std::uint32_t> px(map.size());
    for (std::size_t i = 0; i < map.size(); ++i)
      px[i] = map[i] == kFree ? 0xffffffffu : 0xff000000u;
    benchmark::DoNotOptimize(px.data());
  }
}
BENCHMARK(BM_RasterOnly)->Arg(1000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
