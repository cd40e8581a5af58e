// One robot of an exploration run (run_exploration; not installed): its simulated body, its
// reactive controller and own map, and the state of whatever it is doing — a route to a
// frontier or tree leaf, tree legs still to drive, an unstick route, the block clock, the
// progress watchdog and stall watch, and the goals it gave up. Plain data; the team run
// (internal/team_run.hpp) changes it.
#pragma once

#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

#include "voronav/core/pose2.hpp"
#include "voronav/core/vec2.hpp"
#include "voronav/exploration/explorer.hpp"
#include "voronav/exploration/internal/block_clock.hpp"
#include "voronav/mapping/occupancy_map.hpp"
#include "voronav/robot/diff_drive.hpp"
#include "voronav/robot/reactive_controller.hpp"

namespace voronav::exploration::internal {

enum class AgentMode { kReactive, kFollow };

struct Agent {
  Agent(const ExplorationOptions& o, Pose2 start, std::uint64_t seed, const GridGeometry& g)
      : body(o.drive, start, seed),
        controller([&] {
          robot::ReactiveControllerOptions c =
              o.method == ExplorationMethod::kTree ? o.controller : o.frontier_controller;
          c.seed = seed;
          return c;
        }()),
        map(g) {}
  robot::DiffDriveRobot body;
  robot::ReactiveController controller;
  mapping::OccupancyMap map;
  AgentMode mode = AgentMode::kReactive;
  std::vector<Vec2> route;
  std::size_t next = 0;
  BlockClock block;  // wanted to drive forward but took no forward step (3 s rule)
  double since_progress = 0.0;
  double reactive_until = 0.0;  // [s] a deadlocked robot searches reactively until then
  std::optional<Vec2> goal;     // frontier goal
  std::vector<Vec2> blacklist;  // unreachable frontier goals
  std::vector<Vec2> soft_bans;  // goals given up when blocked or without progress (retry_banned)
  double ban_reset_t = -1e9;    // [s] when soft_bans were last cleared (retry_banned)
  bool on_tree = false;         // following a leg of a tree dispatch
  std::deque<std::vector<Vec2>> legs;  // tree legs still to drive, each ending at a leaf
  bool tree_done = false;              // its dispatched leaves are done (or given up)
  int tree_node = -1;      // the tree node of its last leaf (ExplorationOptions::nearest_leaf_next)
  bool goal_leaf = false;  // kTreeFrontier: the goal is a tree leaf
  double retry_at = 0.0;   // [s] TreeReplan::kFromRobots: next attempt
  Vec2 anchor;             // stall watch: where it has stayed since anchor_t
  double anchor_t = 0.0;
  Vec2 wd_anchor;  // progress watchdog (give up a goal when stuck)
  double wd_t = 0.0;
  double back_off_until = 0.0;  // [s] yields to a robot with a lower index until then
  bool stalled = false;
  bool idle_counted = false;   // ExplorationResult::idle_when_explored
  double leg_replan_t = -1e9;  // [s] last TreeLegReplan::kAroundRobots re-plan, and where
  Vec2 leg_replan_at;
  bool unsticking = false;     // following an unstick route (ExplorationOptions::unstick)
  bool guard_stopped = false;  // the front guard stopped it at its last route-following step
  bool escaping = false;       // its unstick route leaves the planning margin (margin_escape)
  // unstick_retry: it retries until retry_until (the next watchdog) while within stall_distance
  // of retry_anchor, where the watchdog fired; the next retry at next_retry.
  double retry_until = -1.0;  // [s]
  double next_retry = 0.0;    // [s]
  Vec2 retry_anchor;
};

}  // namespace voronav::exploration::internal
