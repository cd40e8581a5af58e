// voronav demo: the README's first command. Runs the project's main capabilities on bundled real
// maps and writes pictures and summary.json into an output folder whose path it prints.
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "cli_common.hpp"
#include "command.hpp"
#include "plan_picture.hpp"
#include "voronav/io/movingai.hpp"
#include "voronav/io/ros_map.hpp"
#include "voronav/planning/astar.hpp"
#include "voronav/planning/bfs.hpp"
#include "voronav/planning/planner_factory.hpp"

namespace voronav::cli {
namespace {

namespace fs = std::filesystem;

struct DemoArgs {
  fs::path out = "demo-out";
  fs::path data;
  bool json = false;
};

/// Two free cells far apart in the largest reachable area: BFS from any free cell to its farthest
/// cell, then from there to the farthest again (a double sweep).
std::pair<Cell, Cell> far_apart_cells(const BinaryGrid& grid) {
  planning::BfsFlood bfs;
  Cell seed{-1, -1};
  std::size_t best_reach = 0;
  // Try a few seeds on a coarse lattice and keep the one reaching the most cells.
  const int step = std::max(1, std::min(grid.width(), grid.height()) / 8);
  for (int y = step / 2; y < grid.height(); y += step)
    for (int x = step / 2; x < grid.width(); x += step)
      if (grid[Cell{x, y}] == 0) {
        const std::size_t n = bfs.flood(grid, {x, y}, planning::Connectivity::k8);
        if (n > best_reach) {
          best_reach = n;
          seed = {x, y};
        }
      }
  if (best_reach == 0) throw Error("demo: the map has no free cell");
  auto farthest = [&](Cell from) {
    bfs.flood(grid, from, planning::Connectivity::k8);
    Cell best = from;
    std::int32_t d = -1;
    for (std::size_t i = 0; i < grid.size(); ++i) {
      const Cell c = grid.cell_at(i);
      if (bfs.steps(grid, c) > d) {
        d = bfs.steps(grid, c);
        best = c;
      }
    }
    return best;
  };
  const Cell a = farthest(seed);
  return {a, farthest(a)};
}

nlohmann::json plan_stage(const fs::path& data, const fs::path& out) {
  const fs::path yaml = data / "ros_maps" / "turtlebot3_world" / "map.yaml";
  const OccupancyGrid map = io::load_ros_map(yaml);
  const double radius = 0.105;  // TurtleBot3 Burger footprint radius [m]
  const BinaryGrid grid = planning::make_planning_grid(binarize(map), radius);
  const auto [start, goal] = far_apart_cells(grid);
  nlohmann::json j{{"map", "data/ros_maps/turtlebot3_world/map.yaml"},
                   {"size", {map.width(), map.height()}},
                   {"resolution_m", map.resolution()},
                   {"robot_radius_m", radius}};
  for (auto kind : {planning::PlannerKind::kAStar, planning::PlannerKind::kDijkstra}) {
    planning::PlannerOptions opt;
    opt.robot_radius = radius;
    opt.record_expanded = true;
    auto planner = planning::make_planner(kind, opt);
    const auto r = planner->plan(grid, start, goal);
    const std::string name(planner->name());
    const fs::path png = out / ("plan_" + name + ".png");
    save_plan_picture({map, grid, start, goal, &r, true}, png);
    if (kind == planning::PlannerKind::kAStar)
      save_plan_picture({map, grid, start, goal, &r, true}, out / "plan_astar.svg");
    const Vec2 sw = map.geometry().cell_center(start), gw = map.geometry().cell_center(goal);
    j[name] = {{"status", planning::to_string(r.status)},
               {"start_m", {sw.x, sw.y}},
               {"goal_m", {gw.x, gw.y}},
               {"length_m", r.length_cells * map.resolution()},
               {"expanded", r.expanded},
               {"time_ms", r.time_ms},
               {"picture", png.filename().string()}};
  }
  return j;
}

nlohmann::json scen_stage(const fs::path& data) {
  const fs::path map_path = data / "movingai" / "arena.map";
  const OccupancyGrid map = io::load_movingai_map(map_path);
  const auto queries = io::load_movingai_scen(map_path.string() + ".scen");
  const BinaryGrid grid = binarize(map);
  planning::AStarPlanner astar;
  std::size_t mismatches = 0, unsolved = 0;
  double ms = 0;
  for (const auto& q : queries) {
    const auto r = astar.plan(grid, io::movingai_to_cell(q.start_x, q.start_y, map.height()),
                              io::movingai_to_cell(q.goal_x, q.goal_y, map.height()));
    ms += r.time_ms;
    if (!r.ok())
      ++unsolved;
    else if (std::abs(r.length_cells - q.optimal_length) > 1e-4)
      ++mismatches;
  }
  return {{"map", "data/movingai/arena.map"},
          {"queries", queries.size()},
          {"mismatches", mismatches},
          {"unsolved", unsolved},
          {"mean_us", queries.empty() ? 0.0 : ms * 1000.0 / double(queries.size())}};
}

void run(const DemoArgs& a) {
  const fs::path data = a.data.empty() ? bundled_data_dir() : a.data;
  if (data.empty() || !fs::exists(data / "README.md"))
    throw Error("--data", 0, "bundled data folder not found; pass --data <repo>/data");
  fs::create_directories(a.out);
  const auto t0 = std::chrono::steady_clock::now();
  nlohmann::json summary;
  summary["plan"] = plan_stage(data, a.out);
  summary["scen"] = scen_stage(data);
  summary["total_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::ofstream(a.out / "summary.json") << summary.dump(2) << "\n";
  const fs::path where = fs::absolute(a.out).lexically_normal();
  if (a.json) {
    summary["out"] = where.string();
    print_json(summary);
    return;
  }
  const auto& p = summary["plan"];
  std::cout << "voronav demo\n"
            << "  plan on turtlebot3_world (" << p["size"][0] << "x" << p["size"][1]
            << ", robot radius " << p["robot_radius_m"] << " m):\n"
            << "    A*       length " << p["astar"]["length_m"] << " m, expanded "
            << p["astar"]["expanded"] << ", " << p["astar"]["time_ms"] << " ms\n"
            << "    Dijkstra length " << p["dijkstra"]["length_m"] << " m, expanded "
            << p["dijkstra"]["expanded"] << ", " << p["dijkstra"]["time_ms"] << " ms\n"
            << "  Moving AI arena: " << summary["scen"]["queries"] << " queries, "
            << summary["scen"]["mismatches"] << " mismatches, " << summary["scen"]["unsolved"]
            << " unsolved, " << summary["scen"]["mean_us"] << " us/query\n"
            << "output: " << where.string() << "\n";
}

void setup(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "demo", "Run the main capabilities on bundled maps; writes pictures and summary.json");
  auto args = std::make_shared<DemoArgs>();
  cmd->add_option("--out", args->out, "Output folder")->capture_default_str();
  cmd->add_option("--data", args->data, "Bundled data folder (default: the source tree's data/)");
  cmd->add_flag("--json", args->json, "Print summary.json to stdout");
  cmd->callback([args] { run(*args); });
}

const Command reg{{"demo", setup, 1}};

}  // namespace
}  // namespace voronav::cli
