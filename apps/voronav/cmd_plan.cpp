// voronav plan: one start-goal query on a map with a grid planner; text or JSON out, optional
// PNG/SVG picture.
#include <cmath>
#include <filesystem>
#include <iostream>

#include "cli_common.hpp"
#include "command.hpp"
#include "plan_picture.hpp"
#include "plan_ras.hpp"
#include "voronav/bag/command_bags.hpp"
#include "voronav/planning/failure_hint.hpp"
#include "voronav/planning/planner_factory.hpp"
#include "voronav/topology/topo_planner.hpp"

namespace voronav::cli {
namespace {

struct PlanArgs {
  std::filesystem::path map;
  std::string start, goal;
  std::string planner = "astar";
  int connectivity = 8;
  double radius = 0.0;
  bool cells = false;
  bool show_expanded = false;
  std::filesystem::path png, svg;
  bool json = false;
  RasCliArgs ras;
  std::filesystem::path mcap;
};

void run(const PlanArgs& a) {
  const MapContext ctx = load_map_context(a.map, a.cells);
  const Vec2 start_in = parse_point(a.start, "--start"), goal_in = parse_point(a.goal, "--goal");
  const Cell start = ctx.to_cell(start_in, "--start");
  const Cell goal = ctx.to_cell(goal_in, "--goal");
  planning::PlannerOptions opt;
  opt.connectivity = a.connectivity == 4 ? planning::Connectivity::k4 : planning::Connectivity::k8;
  opt.robot_radius = a.radius;
  opt.record_expanded = a.show_expanded;
  const BinaryGrid grid = planning::make_planning_grid(binarize(ctx.map.grid), a.radius);
  // "topo": A* over the topological graph (seed 003), expanded to a grid path through the doors.
  std::unique_ptr<planning::GridPlanner> planner =
      a.planner == "topo" ? std::make_unique<topology::TopologicalPlanner>(opt)
                          : planning::make_planner(planning::parse_planner_kind(a.planner), opt,
                                                   to_ras_options(a.ras));
  const planning::PlanResult r = planner->plan(grid, start, goal);
  const auto* ras = dynamic_cast<const planning::RasPlanner*>(planner.get());

  const double res = ctx.map.grid.resolution();
  // A start or goal within the radius of a wall, or a door too narrow for the radius: say so.
  const planning::FailureHint hint =
      r.status == planning::PlanStatus::kStartOccupied ||
              r.status == planning::PlanStatus::kGoalOccupied ||
              r.status == planning::PlanStatus::kUnreachable
          ? planning::explain_failure(binarize(ctx.map.grid), ctx.map.grid.geometry(), start, goal,
                                      a.radius)
          : planning::FailureHint{};
  if (!a.png.empty() || !a.svg.empty()) {
    PlanPicture pic{ctx.map.grid, grid, start, goal, &r, a.radius > 0};
    for (const auto& out : {a.png, a.svg}) {
      if (out.empty()) continue;
      if (ras != nullptr) {
        save_ras_picture(pic, *ras, out);
      } else {
        save_plan_picture(pic, out, std::string(planner->name()),
                          ctx.map.format == io::MapFormat::kMovingAi ? "cells" : "m");
      }
    }
  }
  if (!a.mcap.empty()) {
    std::vector<Vec2> world;
    for (Cell c : r.path)
      world.push_back(ctx.map.grid.geometry().cell_center(c));
    const auto& geo = ctx.map.grid.geometry();
    bag::write_plan_bag(a.mcap, ctx.map.grid, geo.cell_center(start), geo.cell_center(goal), world,
                        std::string(planner->name()));
  }
  if (a.json) {
    nlohmann::json path = nlohmann::json::array(), world = nlohmann::json::array();
    nlohmann::json poses = nlohmann::json::array();
    const auto& geo = ctx.map.grid.geometry();
    double yaw = 0.0;  // heading of the next segment (the last pose keeps the previous one)
    for (std::size_t i = 0; i < r.path.size(); ++i) {
      path.push_back(ctx.cell_json(r.path[i]));
      const Vec2 w = geo.cell_center(r.path[i]);
      world.push_back({w.x, w.y});
      if (i + 1 < r.path.size()) {
        const Vec2 d = geo.cell_center(r.path[i + 1]) - w;
        yaw = std::atan2(d.y, d.x);
      }
      poses.push_back(pose_json({w, yaw}, false));
    }
    const double start_yaw = poses.empty() ? 0.0 : poses.front()["yaw"].get<double>();
    const double goal_yaw = poses.empty() ? 0.0 : poses.back()["yaw"].get<double>();
    nlohmann::json out{{"status", planning::to_string(r.status)},
                       {"planner", planner->name()},
                       {"length", r.length_cells * res},
                       {"length_unit", "m"},
                       {"cells", r.length_cells},
                       {"expanded", r.expanded},
                       {"time_ms", r.time_ms},
                       {"preprocess_ms", r.preprocess_ms},
                       {"path", path},
                       {"path_world", world},
                       // issue 19: frames, units and inputs named (docs/ros.md)
                       {"frame_id", "map"},
                       {"cell_frame", ctx.cell_frame()},
                       {"length_m", r.length_cells * res},
                       {"length_cells", r.length_cells},
                       {"start", pose_json({geo.cell_center(start), start_yaw})},
                       {"goal", pose_json({geo.cell_center(goal), goal_yaw})},
                       {"poses", poses},
                       {"input",
                        {{"map", a.map.string()},
                         {"start", {start_in.x, start_in.y}},
                         {"goal", {goal_in.x, goal_in.y}},
                         {"units", ctx.cell_coordinates ? "cells" : "m"},
                         {"cell_frame", ctx.cell_frame()},
                         {"radius_m", a.radius},
                         {"connectivity", a.connectivity}}}};
    if (ras != nullptr) add_ras_json(out, *ras, ctx);
    if (!hint.text.empty()) out["hint"] = hint.text;
    print_json(out);
  } else {
    std::cout << "status:   " << planning::to_string(r.status) << "\n";
    if (r.ok()) {
      std::cout << "length:   " << r.length_cells * res << " m (" << r.length_cells
                << " cells, octile)\n"
                << "steps:    " << (r.path.size() - 1) << "\n";
    }
    if (ras != nullptr) print_ras_text(*ras);
    std::cout << "expanded: " << r.expanded << "\n"
              << "time:     " << r.time_ms << " ms\n";
  }
  if (!hint.text.empty() && !a.json) std::cout << "hint:     " << hint.text << "\n";
  if (!r.ok()) exit_code() = 1;
}

void setup(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "plan",
      "Plan a path from start to goal on a map: A*, Dijkstra, jump point search, a path along "
      "the topological map, or RAS (Kwak & Lim, 'Random Access Sequence path planning with "
      "distribution density', 2006)");
  auto args = std::make_shared<PlanArgs>();
  cmd->add_option("--map", args->map,
                  "Map file: ROS map .yaml, Moving AI .map, or a floor plan .png/.pgm")
      ->required();
  cmd->add_option("--start", args->start,
                  "Start X,Y: cells (x right, y down, as in .scen files) for .map files; "
                  "metres in the world frame for ROS and image maps (see --cells)")
      ->required();
  cmd->add_option("--goal", args->goal, "Goal X,Y, same frame as --start")->required();
  cmd->add_option("--planner", args->planner, "astar | dijkstra | ras | jps | jps+ | topo")
      ->capture_default_str();
  cmd->add_option("--connectivity", args->connectivity, "4 or 8 neighbours")
      ->check(CLI::IsMember({4, 8}))
      ->capture_default_str();
  cmd->add_option("--radius", args->radius,
                  "Robot radius [m]: cells closer than this to an obstacle are blocked")
      ->check(non_negative())
      ->capture_default_str();
  cmd->add_flag("--cells", args->cells,
                "Read --start/--goal as grid cells (row 0 at the bottom) for ROS/image maps");
  cmd->add_flag("--expanded", args->show_expanded, "Draw the expanded cells in the picture");
  cmd->add_option("--png", args->png, "Write a PNG picture of the map and path");
  cmd->add_option("--svg", args->svg, "Write an SVG picture of the map and path");
  cmd->add_flag("--json", args->json,
                "JSON output: status, length [m], cells (length in cells), expanded, time_ms, "
                "path (cells), path_world (m), frame_id, cell_frame, length_m, start/goal/poses "
                "{x, y, yaw}, input (docs/ros.md)");
  add_ras_options(cmd, args->ras);
  cmd->add_option("--mcap", args->mcap,
                  "Write the run as a ROS 2 bag (MCAP): /map, /plan, /tf, /robots (docs/ros.md)");
  cmd->callback([args] { run(*args); });
}

const Command reg{{"plan", setup, 10}};

}  // namespace
}  // namespace voronav::cli
