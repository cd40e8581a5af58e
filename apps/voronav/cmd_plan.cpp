// voronav plan: one start-goal query on a map with a grid planner; text or JSON out, optional
// PNG/SVG picture.
#include <filesystem>
#include <iostream>

#include "cli_common.hpp"
#include "command.hpp"
#include "plan_picture.hpp"
#include "plan_ras.hpp"
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
};

void run(const PlanArgs& a) {
  const MapContext ctx = load_map_context(a.map, a.cells);
  const Cell start = ctx.to_cell(parse_point(a.start, "--start"), "--start");
  const Cell goal = ctx.to_cell(parse_point(a.goal, "--goal"), "--goal");
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
  if (a.json) {
    nlohmann::json path = nlohmann::json::array(), world = nlohmann::json::array();
    for (Cell c : r.path) {
      path.push_back(ctx.cell_json(c));
      const Vec2 w = ctx.map.grid.geometry().cell_center(c);
      world.push_back({w.x, w.y});
    }
    nlohmann::json out{{"status", planning::to_string(r.status)},
                       {"planner", planner->name()},
                       {"length", r.length_cells * res},
                       {"length_unit", "m"},
                       {"cells", r.length_cells},
                       {"expanded", r.expanded},
                       {"time_ms", r.time_ms},
                       {"path", path},
                       {"path_world", world}};
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
  auto* cmd = app.add_subcommand("plan", "Plan a path from start to goal on a map");
  auto args = std::make_shared<PlanArgs>();
  cmd->add_option("--map", args->map,
                  "Map file: ROS map .yaml, Moving AI .map, or a floor plan .png/.pgm")
      ->required();
  cmd->add_option("--start", args->start,
                  "Start X,Y: cells (x right, y down, as in .scen files) for .map files; "
                  "metres in the world frame for ROS and image maps (see --cells)")
      ->required();
  cmd->add_option("--goal", args->goal, "Goal X,Y, same frame as --start")->required();
  cmd->add_option("--planner", args->planner, "astar | dijkstra | ras | topo")
      ->capture_default_str();
  cmd->add_option("--connectivity", args->connectivity, "4 or 8 neighbours")
      ->check(CLI::IsMember({4, 8}))
      ->capture_default_str();
  cmd->add_option("--radius", args->radius,
                  "Robot radius [m]: cells closer than this to an obstacle are blocked")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_flag("--cells", args->cells,
                "Read --start/--goal as grid cells (row 0 at the bottom) for ROS/image maps");
  cmd->add_flag("--expanded", args->show_expanded, "Draw the expanded cells in the picture");
  cmd->add_option("--png", args->png, "Write a PNG picture of the map and path");
  cmd->add_option("--svg", args->svg, "Write an SVG picture of the map and path");
  cmd->add_flag("--json", args->json,
                "JSON output: status, length [m], cells (length in cells), expanded, time_ms, "
                "path (cells), path_world (m)");
  add_ras_options(cmd, args->ras);
  cmd->callback([args] { run(*args); });
}

const Command reg{{"plan", setup, 10}};

}  // namespace
}  // namespace voronav::cli
