// Inputs of the coordination method (seed 002 assumes a global offline path planner gives every
// robot a fixed path): a scenario YAML file (map + robots with start, goal, radius, v_max, a_max
// and an optional explicit path) and the MAPF benchmark (map + .scen, the first k rows are k
// robots). Paths are planned with the grid planner (A* on the map inflated by each robot's
// radius). Following the paper's assumption that no path passes through another robot's start or
// goal, the planner first tries with those discs (radius r_i + r_j + node spacing) blocked and
// falls back to the plain map.
//
// Scenario YAML:
//   map: arena.map              # relative to the scenario file; optional when every robot has a
//   path coordinates: cells | world  # default: cells for Moving AI maps (x right, y down), else
//   world [m] at_start: wait | appear     # default wait at_goal: stay | leave       # default stay
//   node_spacing: 0             # [m], 0 = automatic
//   robots:
//     - {id: 1, start: [x, y], goal: [x, y], radius: 0.5, v_max: 1.0, a_max: 2.0}
//     - {id: 2, path: [[x, y], [x, y], ...], radius: 0.4}   # explicit path in world metres
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "voronav/coordination/collision_map.hpp"
#include "voronav/io/map_loader.hpp"

namespace voronav::coordination {

struct RobotSpec {
  int id = 0;
  std::optional<Vec2> start, goal;  ///< in the scenario's coordinates
  std::vector<Vec2> path;           ///< explicit path [m, world]; empty = plan one
  double radius = 0.5;              ///< [m]
  MotionLimits limits;
  int line = 0;  ///< line in the source file, for error messages
};

struct Scenario {
  std::filesystem::path source;
  std::optional<io::LoadedMap> map;
  bool cell_coordinates = false;  ///< start/goal are cells (Moving AI: x right, y down)
  std::vector<RobotSpec> robots;
  CollisionMapOptions map_options;
};

/// Reads a scenario YAML file; throws voronav::Error naming the file, line and field.
[[nodiscard]] Scenario load_scenario(const std::filesystem::path& path);

/// The first `k` rows of a MAPF .scen file on `map_path` as robots of `radius` [cells = m on
/// Moving AI maps], v_max 1, instantaneous acceleration.
[[nodiscard]] Scenario load_mapf(const std::filesystem::path& map_path,
                                 const std::filesystem::path& scen_path, int k,
                                 double radius = 0.5);

struct PlannedAgents {
  std::vector<Agent> agents;
  int fallback_paths = 0;  ///< robots whose path had to cross another robot's start or goal
};

/// Plans every robot's path (explicit paths are kept). Throws voronav::Error when a start or goal
/// is blocked or unreachable.
[[nodiscard]] PlannedAgents plan_agents(const Scenario& scenario);

}  // namespace voronav::coordination
