// voronav scen: runs every query of a Moving AI .map.scen file and compares the found length with
// the file's optimal length (tolerance 1e-4). Exit code 1 on any mismatch or unsolved query.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>

#include "cli_common.hpp"
#include "command.hpp"
#include "voronav/io/movingai.hpp"
#include "voronav/planning/planner_factory.hpp"

namespace voronav::cli {
namespace {

struct ScenArgs {
  std::filesystem::path map, scen;
  std::string planner = "astar";
  int connectivity = 8;
  double tolerance = 1e-4;
  bool json = false;
};

void run(const ScenArgs& a) {
  const OccupancyGrid map = io::load_movingai_map(a.map);
  const auto queries = io::load_movingai_scen(a.scen);
  const BinaryGrid grid = binarize(map);
  planning::PlannerOptions opt;
  opt.connectivity = a.connectivity == 4 ? planning::Connectivity::k4 : planning::Connectivity::k8;
  auto planner = planning::make_planner(planning::parse_planner_kind(a.planner), opt);

  io::check_scen_fits(queries, map, a.scen);
  std::size_t mismatches = 0, unsolved = 0;
  double planning_ms = 0.0;
  nlohmann::json failures = nlohmann::json::array();
  const auto t0 = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const auto& q = queries[i];
    const Cell s = io::movingai_to_cell(q.start_x, q.start_y, map.height());
    const Cell g = io::movingai_to_cell(q.goal_x, q.goal_y, map.height());
    const auto r = planner->plan(grid, s, g);
    planning_ms += r.time_ms;
    const bool ok = r.ok();
    // The file prints the optimal length with 3 or 8 decimals: allow one unit in the last one.
    const bool match = ok && std::abs(r.length_cells - q.optimal_length) <=
                                 std::max(a.tolerance, q.optimal_rounding + 1e-12);
    if (!ok)
      ++unsolved;
    else if (!match)
      ++mismatches;
    if ((!ok || !match) && failures.size() < 20)
      failures.push_back({{"line", q.line},
                          {"start", {q.start_x, q.start_y}},
                          {"goal", {q.goal_x, q.goal_y}},
                          {"status", planning::to_string(r.status)},
                          {"found", r.length_cells},
                          {"optimal", q.optimal_length}});
  }
  const double total_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  const double mean_us = queries.empty() ? 0.0 : planning_ms * 1000.0 / double(queries.size());
  if (a.json) {
    print_json({{"map", a.map.filename().string()},
                {"planner", planner->name()},
                {"queries", queries.size()},
                {"mismatches", mismatches},
                {"unsolved", unsolved},
                {"mean_us", mean_us},
                {"total_ms", total_ms},
                {"failures", failures}});
  } else {
    std::cout << a.map.filename().string() << ": " << queries.size() << " queries, " << mismatches
              << " mismatches, " << unsolved << " unsolved, mean " << mean_us << " us/query ("
              << planner->name() << ")\n";
    for (const auto& f : failures)
      std::cout << "  " << f.dump() << "\n";
  }
  if (mismatches > 0 || unsolved > 0) exit_code() = 1;
}

void setup(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "scen", "Run every query of a Moving AI .scen file and compare with the optimal lengths");
  auto args = std::make_shared<ScenArgs>();
  cmd->add_option("--map", args->map, "Moving AI .map file")->required()->check(CLI::ExistingFile);
  cmd->add_option("--scen", args->scen, "Moving AI .map.scen file")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--planner", args->planner, "astar | dijkstra")->capture_default_str();
  cmd->add_option("--connectivity", args->connectivity,
                  "4 or 8 (the .scen optimal lengths assume 8)")
      ->check(CLI::IsMember({4, 8}))
      ->capture_default_str();
  cmd->add_option("--tolerance", args->tolerance,
                  "Allowed |found - optimal| in cells (at least the rounding of the file's "
                  "optimal-length column)")
      ->check(non_negative())
      ->capture_default_str();
  cmd->add_flag("--json", args->json,
                "JSON output: queries, mismatches, unsolved, mean_us, total_ms, failures");
  cmd->callback([args] { run(*args); });
}

const Command reg{{"scen", setup, 20}};

}  // namespace
}  // namespace voronav::cli
