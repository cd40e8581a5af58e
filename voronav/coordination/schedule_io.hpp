// Schedules as files (JSON or YAML by extension, the same fields): per robot the id, radius,
// limits, start delay, arrival and the timed path; plus the presence rules and the summary.
// read_schedule() + verify_schedule() check any schedule independently (voronav validate-schedule).
//
//   {"format": "voronav-schedule", "version": 1, "at_start": "wait", "at_goal": "stay",
//    "makespan": 23.2, "sum_of_arrivals": 43.2, "valid": true,
//    "agents": [{"id": 1, "radius": 0.5, "v_max": 1.0, "a_max": null, "delay": 0.0,
//                "arrival": 20.0, "path": [[-10, 0], [10, 0]]}, ...]}
// a_max null = instantaneous acceleration.
// SIPP schedules give each agent "waypoints": [[t, x, y], ...] (constant velocity between them,
// equal points = a wait) instead of moving along "path" after "delay"; "path" is then the
// geometric path and "delay" the first waypoint's time (informative). An optional "map" names the
// map file (relative to the schedule file) that validate-schedule checks the discs against.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "voronav/coordination/trajectory.hpp"

namespace voronav::coordination {

struct Schedule {
  std::vector<Agent> agents;
  std::vector<double> delays;  ///< [s], one per agent
  AtStart at_start = AtStart::kWait;
  AtGoal at_goal = AtGoal::kStay;
  bool valid = false;  ///< what the writer claimed (informative; re-check with verify_schedule)
  /// Per agent timed waypoints (SIPP); empty = every agent follows its path after its delay.
  std::vector<std::vector<TimedWaypoint>> waypoints;
  std::string map;  ///< map file as written in the schedule (empty = none)
};

/// Every agent's trajectory under the schedule's presence conventions.
[[nodiscard]] std::vector<Trajectory> trajectories(const Schedule& s);

[[nodiscard]] std::string schedule_to_json(const Schedule& s);
[[nodiscard]] std::string schedule_to_yaml(const Schedule& s);
/// Parses JSON or YAML text (YAML is a superset of JSON); `source` names it in errors.
[[nodiscard]] Schedule parse_schedule(const std::string& text, const std::string& source);
/// Writes .json, .yaml or .yml; throws voronav::Error otherwise.
void write_schedule(const std::filesystem::path& path, const Schedule& s);
[[nodiscard]] Schedule read_schedule(const std::filesystem::path& path);

[[nodiscard]] AtStart parse_at_start(const std::string& s);
[[nodiscard]] AtGoal parse_at_goal(const std::string& s);
[[nodiscard]] const char* to_string(AtStart s);
[[nodiscard]] const char* to_string(AtGoal g);

}  // namespace voronav::coordination
