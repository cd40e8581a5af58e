// voronav scen: runs the queries of a Moving AI .map.scen file (all, the first N, or a range) and
// compares each found length with the file's optimal length at the precision the file printed
// (io::matches_optimal). Queries starting on water are searched on the water grid (the format's
// 'W' rule); a scenario whose map-size columns differ from the map runs on the map scaled to them.
// Exit code 1 on any mismatch or unsolved query.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>

#include "cli_common.hpp"
#include "command.hpp"
#include "voronav/io/movingai.hpp"
#include "voronav/planning/planner_factory.hpp"

namespace voronav::cli {
namespace {

struct ScenArgs {
  std::filesystem::path map, scen, per_query;
  std::string planner = "astar";
  int connectivity = 8;
  double tolerance = 1e-4;
  std::size_t first = 0;
  std::string range;
  bool json = false;
};

/// The land and water grids of the map at one size (scaled when the .scen says so).
struct SizedMap {
  io::MovingAiTerrain terrain;
  BinaryGrid land, water;
};

std::pair<std::size_t, std::size_t> query_span(const ScenArgs& a, std::size_t n) {
  if (a.first > 0) return {0, std::min(a.first, n)};
  if (a.range.empty()) return {0, n};
  const std::size_t colon = a.range.find(':');
  auto bad = [&] {
    return Error("--range", 0,
                 "expected A:B (0-based query indices, B exclusive, A < B <= " + std::to_string(n) +
                     "), got '" + a.range + "'");
  };
  if (colon == std::string::npos) throw bad();
  std::size_t lo = 0, hi = 0;
  try {
    std::size_t used = 0;
    lo = std::stoul(a.range.substr(0, colon), &used);
    if (used != colon) throw bad();
    const std::string rest = a.range.substr(colon + 1);
    hi = std::stoul(rest, &used);
    if (used != rest.size()) throw bad();
  } catch (const std::logic_error&) {
    throw bad();
  }
  if (lo >= hi || hi > n) throw bad();
  return {lo, hi};
}

void run(const ScenArgs& a) {
  const io::MovingAiTerrain terrain = io::load_movingai_terrain(a.map);
  const OccupancyGrid map = io::load_movingai_map(a.map);
  const auto queries = io::load_movingai_scen(a.scen);
  io::check_scen_fits(queries, map, a.scen, /*allow_scaling=*/true);
  const auto [lo, hi] = query_span(a, queries.size());
  planning::PlannerOptions opt;
  opt.connectivity = a.connectivity == 4 ? planning::Connectivity::k4 : planning::Connectivity::k8;
  auto planner = planning::make_planner(planning::parse_planner_kind(a.planner), opt);

  std::ofstream csv;
  if (!a.per_query.empty()) {
    csv.open(a.per_query);
    if (!csv) throw Error("--per-query", 0, "cannot write '" + a.per_query.string() + "'");
    csv << "id,length,expected,expanded,us\n";
    csv.precision(10);
  }
  // Grids per map size; std::map keeps their addresses stable (planners cache per-map data).
  std::map<std::pair<int, int>, SizedMap> sized;
  auto grids_for = [&](int w, int h) -> const SizedMap& {
    auto it = sized.find({w, h});
    if (it != sized.end()) return it->second;
    SizedMap s;
    s.terrain = (w == terrain.cells.width() && h == terrain.cells.height())
                    ? terrain
                    : io::scale_movingai_terrain(terrain, w, h);
    s.land = s.terrain.traversable(false);
    s.water = s.terrain.traversable(true);
    return sized.emplace(std::pair{w, h}, std::move(s)).first->second;
  };

  std::size_t mismatches = 0, unsolved = 0, expanded = 0, water = 0, scaled = 0;
  double planning_ms = 0.0, preprocess_ms = 0.0;
  nlohmann::json failures = nlohmann::json::array();
  const auto t0 = std::chrono::steady_clock::now();
  for (std::size_t i = lo; i < hi; ++i) {
    const auto& q = queries[i];
    const SizedMap& m = grids_for(q.map_width, q.map_height);
    if (q.map_width != map.width() || q.map_height != map.height()) ++scaled;
    const Cell s = io::movingai_to_cell(q.start_x, q.start_y, q.map_height);
    const Cell g = io::movingai_to_cell(q.goal_x, q.goal_y, q.map_height);
    const bool on_water = m.terrain.is_water(s);
    water += on_water ? 1 : 0;
    const auto r = planner->plan(on_water ? m.water : m.land, s, g);
    planning_ms += r.time_ms;
    preprocess_ms += r.preprocess_ms;
    expanded += r.expanded;
    const bool ok = r.ok();
    const bool match = ok && io::matches_optimal(q, r.length_cells, a.tolerance);
    if (!ok)
      ++unsolved;
    else if (!match)
      ++mismatches;
    if (csv.is_open())
      csv << i << ',' << (ok ? r.length_cells : -1.0) << ',' << q.optimal_length << ','
          << r.expanded << ',' << r.time_ms * 1000.0 << '\n';
    if ((!ok || !match) && failures.size() < 20)
      failures.push_back({{"id", i},
                          {"line", q.line},
                          {"start", {q.start_x, q.start_y}},
                          {"goal", {q.goal_x, q.goal_y}},
                          {"status", planning::to_string(r.status)},
                          {"found", r.length_cells},
                          {"optimal", q.optimal_length},
                          {"allowed", std::max(a.tolerance, q.optimal_rounding)}});
  }
  if (csv.is_open() && !csv)
    throw Error("--per-query", 0, "write to '" + a.per_query.string() + "' failed");
  const double total_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  const std::size_t n = hi - lo;
  const double mean_us = n == 0 ? 0.0 : planning_ms * 1000.0 / double(n);
  if (a.json) {
    print_json({{"map", a.map.filename().string()},
                {"planner", planner->name()},
                {"queries", n},
                {"first_id", lo},
                {"end_id", hi},
                {"queries_in_file", queries.size()},
                {"mismatches", mismatches},
                {"unsolved", unsolved},
                {"water_queries", water},
                {"scaled_queries", scaled},
                {"expanded_total", expanded},
                {"expanded_mean", n == 0 ? 0.0 : double(expanded) / double(n)},
                {"mean_us", mean_us},
                {"preprocess_ms", preprocess_ms},
                {"total_ms", total_ms},
                {"failures", failures}});
  } else {
    std::cout << a.map.filename().string() << ": " << n << " queries, " << mismatches
              << " mismatches, " << unsolved << " unsolved, mean " << mean_us << " us/query, "
              << expanded << " expanded (" << planner->name();
    if (preprocess_ms > 0) std::cout << ", preprocessing " << preprocess_ms << " ms";
    std::cout << ")\n";
    for (const auto& f : failures)
      std::cout << "  " << f.dump() << "\n";
  }
  if (mismatches > 0 || unsolved > 0) exit_code() = 1;
}

void setup(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "scen", "Run the queries of a Moving AI .scen file and compare with the optimal lengths");
  auto args = std::make_shared<ScenArgs>();
  cmd->add_option("--map", args->map, "Moving AI .map file")->required()->check(CLI::ExistingFile);
  cmd->add_option("--scen", args->scen, "Moving AI .map.scen file")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--planner", args->planner, "astar | dijkstra | ras | jps | jps+")
      ->capture_default_str();
  cmd->add_option("--connectivity", args->connectivity,
                  "4 or 8 (the .scen optimal lengths assume 8)")
      ->check(CLI::IsMember({4, 8}))
      ->capture_default_str();
  cmd->add_option("--tolerance", args->tolerance,
                  "Allowed |found - optimal| in cells (at least one unit in the last significant "
                  "digit of the file's optimal-length column, counting 6 digits)")
      ->check(non_negative())
      ->capture_default_str();
  auto* first = cmd->add_option("--first", args->first, "Run only the first N queries")
                    ->check(CLI::PositiveNumber);
  cmd->add_option("--range", args->range,
                  "Run queries A..B-1 (0-based ids as in --per-query), e.g. 100:200")
      ->excludes(first);
  cmd->add_option("--per-query", args->per_query,
                  "Write a CSV row per query: id, length, expected, expanded, us");
  cmd->add_flag("--json", args->json,
                "JSON output: queries, mismatches, unsolved, expanded_total, mean_us, "
                "preprocess_ms, total_ms, failures");
  cmd->callback([args] { run(*args); });
}

const Command reg{{"scen", setup, 20}};

}  // namespace
}  // namespace voronav::cli
