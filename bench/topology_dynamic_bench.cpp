// Dynamic GVD (seed 003, DynamicGvd) on real maps: full build and per-change update cost, the
// measure of the dynamic brushfire GVD of Lau, Sprunk and Burgard (2013).
//   full/<map>    DynamicGvd full build (EDT + labels + raw diagram + thinning + pruning)
//   update/<map>  one iteration = 10 accumulated 3x3 obstacle insertions at random free places,
//                 then their removal in reverse order (20 calls of DynamicGvd::update);
//                 items = changes, so the time per change is 1 / items_per_second
// Maps: willow, warehouse (../shared/data/ros_maps), depot, turtlebot3_world (data/ros_maps),
// lab_intel (data/floorplans); maps that are missing are skipped. Counters of the update runs
// say which mechanism did the work: rows and row cells of the EDT, cells whose distance or site
// changed, cells the re-thinning and re-pruning examined, steps of the longest stored thinning
// run, label repartitions (merges/splits) per change, raw cells whose clearance changed and those
// of them that flip the clearance order of two raw neighbours (the thinning replays only these),
// changes that the re-thinnings after pruning left dormant and those woken up again.
// bench/topology_dynamic.sh turns the JSON output into bench/results/topology_dynamic.md.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "free_spots.hpp"
#include "voronav/core/occupancy.hpp"
#include "voronav/io/map_loader.hpp"
#include "voronav/voronoi/gvd.hpp"

namespace {

using namespace voronav;
namespace fs = std::filesystem;

fs::path find_map(const std::vector<std::string>& rels) {
  const fs::path src(VORONAV_SOURCE_DIR);
  for (const std::string& rel : rels)
    for (const fs::path& base :
         {src, src / "../../shared", fs::path("/work/shared"), src / "../shared"}) {
      const fs::path p = base / rel;
      if (fs::exists(p)) return p;
    }
  return {};
}

std::vector<Cell> random_spots(const BinaryGrid& map, std::uint32_t seed, std::size_t n) {
  return voronav::bench::free_3x3_spots(map, seed, n);
}

void full(benchmark::State& state, const BinaryGrid* map) {
  for (auto _ : state) {
    voronoi::DynamicGvd g(*map);
    benchmark::DoNotOptimize(g);
  }
  std::size_t free = 0;
  for (std::size_t i = 0; i < map->size(); ++i)
    free += (*map)[i] == 0;
  state.counters["cells"] = static_cast<double>(map->size());
  state.counters["free_cells"] = static_cast<double>(free);
}

void update(benchmark::State& state, const BinaryGrid* map) {
  voronoi::DynamicGvd g(*map);
  const std::vector<Cell> spots = random_spots(*map, 7, 200);
  if (spots.size() < 10) {
    state.SkipWithError("fewer than 10 free 3x3 places");
    return;
  }
  std::vector<voronoi::CellChange> changes(9);
  std::size_t k = 0;
  double rows = 0, row_cells = 0, skel = 0, repart = 0, changes_done = 0, steps = 0, dist = 0;
  double keys = 0, thin_keys = 0, dormant = 0, woken = 0;
  auto apply = [&](Cell c, bool add) {
    int n = 0;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        changes[static_cast<std::size_t>(n++)] = {c + Cell{dx, dy}, add};
    const voronoi::GvdUpdateStats st = g.update(changes);
    rows += static_cast<double>(st.recomputed_rows);
    row_cells += static_cast<double>(st.row_cells);
    skel += static_cast<double>(st.skeleton_work);
    repart += st.labels_repartitioned ? 1.0 : 0.0;
    steps += st.thinning_steps;
    dist += static_cast<double>(st.changed_distances);
    keys += static_cast<double>(st.key_changes);
    thin_keys += static_cast<double>(st.thin_key_changes);
    dormant += static_cast<double>(st.rethin_dormant);
    woken += static_cast<double>(st.rethin_woken);
    changes_done += 1.0;
  };
  for (auto _ : state) {
    std::vector<Cell> batch;
    for (int i = 0; i < 10; ++i)
      batch.push_back(spots[k++ % spots.size()]);
    for (const Cell c : batch)
      apply(c, true);
    for (auto it = batch.rbegin(); it != batch.rend(); ++it)
      apply(*it, false);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(changes_done));
  state.counters["rows_per_change"] = rows / changes_done;
  state.counters["row_cells_per_change"] = row_cells / changes_done;
  state.counters["skeleton_cells_per_change"] = skel / changes_done;
  state.counters["repartitions_per_change"] = repart / changes_done;
  state.counters["thinning_steps"] = steps / changes_done;
  state.counters["changed_distances_per_change"] = dist / changes_done;
  state.counters["key_changes_per_change"] = keys / changes_done;
  state.counters["thin_key_changes_per_change"] = thin_keys / changes_done;
  state.counters["rethin_dormant_per_change"] = dormant / changes_done;
  state.counters["rethin_woken_per_change"] = woken / changes_done;
}

}  // namespace

int main(int argc, char** argv) {
  struct Entry {
    std::string name;
    std::vector<std::string> rels;
  };
  const std::vector<Entry> entries = {
      {"willow", {"data/ros_maps/willow/willow-full-0.05.yaml"}},
      {"warehouse", {"data/ros_maps/warehouse/warehouse.yaml"}},
      {"depot", {"data/ros_maps/depot/depot.yaml"}},
      {"lab_intel", {"data/floorplans/lab_intel.png"}},
      {"turtlebot3_world", {"data/ros_maps/turtlebot3_world/map.yaml"}},
  };
  static std::vector<BinaryGrid> maps;
  maps.reserve(entries.size());
  for (const Entry& e : entries) {
    const fs::path p = find_map(e.rels);
    if (p.empty()) continue;
    maps.push_back(binarize(io::load_map(p).grid));
    const BinaryGrid* m = &maps.back();
    benchmark::RegisterBenchmark(("full/" + e.name).c_str(), full, m)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("update/" + e.name).c_str(), update, m)
        ->Unit(benchmark::kMillisecond);
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
