// A robot's step in an exploration run: its command (reactive search, or route following with
// the front guard and right of way), the footprint safety check, its motion, then the progress
// watchdog and the stall watch (internal/team_run.hpp).
#include <algorithm>
#include <cmath>

#include "voronav/exploration/internal/right_of_way.hpp"
#include "voronav/exploration/internal/team_run.hpp"
#include "voronav/robot/laser.hpp"

namespace voronav::exploration::internal {

// Act: every robot's command for this step, then its motion to the step's end.
void TeamRun::act(double t) {
  for (std::size_t i = 0; i < agents.size(); ++i) {
    Agent& a = *agents[i];
    others.clear();
    for (std::size_t j = 0; j < agents.size(); ++j)
      if (j != i) others.push_back({agents[j]->body.true_pose().position, body});
    const Pose2 pose = a.body.true_pose();
    robot::BodyVelocity cmd;
    const bool was_guard_stopped = a.guard_stopped;
    a.guard_stopped = false;
    if (a.mode == AgentMode::kFollow && t < a.reactive_until) {
      cmd = a.controller.update(robot::cast_scan(blocked, pose, o.laser, others, &rng), o.dt);
    } else if (a.mode == AgentMode::kFollow) {
      cmd = follow(i, t, was_guard_stopped);
    } else {
      cmd = a.controller.update(robot::cast_scan(blocked, pose, o.laser, others, &rng), o.dt);
    }
    a.body.command(cmd);
    // Footprint safety (as a check of the scan points around the footprint would do): a
    // command that would touch an obstacle within the next few steps becomes a turn on the spot.
    if (cmd.v != 0.0) {
      const double ahead = std::copysign(std::min(0.1, std::abs(cmd.v) * 3.0 * o.dt), cmd.v);
      const Vec2 next = pose.position + Vec2{std::cos(pose.yaw), std::sin(pose.yaw)} * ahead;
      if (robot::disc_collides(blocked, next, body + 0.01, others)) {
        cmd.v = 0.0;
        if (cmd.omega == 0.0) cmd.omega = o.controller.obs_avoid;
        a.block.on_step_refused(o.dt);
      } else if (cmd.v > 0.0) {
        // Only a forward step that is taken ends a block, for every method: not a step the
        // guard lets through (its 13 beams may see a clear front while the footprint check
        // refuses) and not a new route. Either reset kept a robot standing still with the 3 s
        // block rule never firing: a tree leg until the 20 s watchdog (willow, 16 robots,
        // tree), and tree-frontier robots whose allocation changed goal every 2 s in a doorway
        // jam for 60 s and more (issue 14, fifth pass).
        a.block.on_forward_step_taken();
      }
    }
    a.body.command(cmd);
    a.body.step(o.dt, blocked, others);
    watch(i, t);
  }
}

// Route following (seed 004 and the frontier methods alike): robot i advances past reached
// waypoints and steers to the next; the front guard stops it, and a stopped robot may back off.
robot::BodyVelocity TeamRun::follow(std::size_t i, double t, bool was_guard_stopped) {
  Agent& a = *agents[i];
  const Pose2 pose = a.body.true_pose();
  robot::BodyVelocity cmd;
  // Waypoint following: advance past reached waypoints, steer to the farthest visible one.
  // A margin escape ends on its exit cell (kCornerReach), not 0.3 m short of it, where the
  // robot would still be in the margin.
  const double tolerance = a.escaping ? kCornerReach : o.goal_tolerance;
  while (a.next < a.route.size() && distance(pose.position, a.route[a.next]) < tolerance) {
    // FrontGuard::kCorridor: no cutting a corner of the route where the body would not
    // clear the wall (internal/front_guard.hpp); drive on to the waypoint instead.
    if (o.guard == FrontGuard::kCorridor && a.next + 1 < a.route.size() &&
        distance(pose.position, a.route[a.next]) > kCornerReach &&
        !line_clear(blocked, pose.position, a.route[a.next + 1], body))
      break;
    ++a.next;
    a.since_progress = 0.0;
  }
  if (a.next >= a.route.size()) {
    if (a.goal_leaf && a.goal) {
      // A leaf is visited once: reached (or its route ended short of it) it is done.
      if (distance(pose.position, *a.goal) < 2.0 * o.goal_tolerance) {
        ++result.leaves_reached;
        log_event(t, a, "leaf");
      }
      a.blacklist.push_back(*a.goal);
    } else if (a.goal && distance(pose.position, *a.goal) < 2.0 * o.goal_tolerance) {
      // A frontier still there once the robot stands on its target cannot be observed
      // from here (unknown cells walled in, e.g. in clutter): not this robot's goal again.
      // Chasing it again kept a robot circling on one spot (willow, 16 robots).
      a.blacklist.push_back(*a.goal);
      // ExplorationOptions::share_bans: nor any robot's (same map, same laser), when the
      // frontier is still there at the next allocation.
      if (o.share_bans) team_bans.reached(*a.goal, t);
    }
    a.goal.reset();
    a.goal_leaf = false;
    if (a.on_tree) {
      finish_leg(a, t);
    } else if (a.unsticking) {
      end_unstick(a, t);
    } else {
      a.mode = AgentMode::kReactive;
    }
    cmd = {};
  } else {
    const Vec2 target = a.route[a.next];
    const double e =
        wrap_angle(std::atan2(target.y - pose.position.y, target.x - pose.position.x) - pose.yaw);
    cmd.omega = std::clamp(1.5 * e, -o.drive.max_angular_speed, o.drive.max_angular_speed);
    cmd.v = std::abs(e) > 0.6 ? 0.0 : o.controller.drive_velocity * std::cos(e);
    // Guard: a robot right in front, or a wall (ExplorationOptions::guard: anything in the
    // cone, or a wall on the route's swept corridor; internal/front_guard.hpp) -> stop.
    const GuardVerdict gv = cmd.v > 0.0 ? front_guard(guard_rule, blocked, pose, a.route, a.next,
                                                      others, body, guard_laser)
                                        : GuardVerdict{};
    if (gv.stop && !was_guard_stopped)
      ++(gv.by_robot ? result.guard_robot_stops : result.guard_wall_stops);
    a.guard_stopped = gv.stop;
    if (gv.stop) {
      cmd.v = 0.0;
      a.block.on_step_refused(o.dt);
      // Right of way: blocked by a robot with a lower index (not by a wall), this robot
      // backs off for a moment so that a jam in a doorway dissolves.
      // ExplorationOptions::yield_to_held: also from a robot in front that is held up
      // itself (internal/right_of_way.hpp).
      // ExplorationOptions::unstick_right_of_way: a robot on an unstick route goes first.
      const bool unstick_first = o.unstick_right_of_way && o.method == ExplorationMethod::kTree;
      if (gv.by_robot)
        for (std::size_t j = 0; j < agents.size(); ++j) {
          const Agent& b = *agents[j];
          const RightOfWayPeer peer{
              static_cast<int>(j), b.body.true_pose().position,
              b.mode == AgentMode::kFollow && b.block.blocked_for() > 0.5 && t >= b.back_off_until,
              b.unsticking};
          if (backs_off_for(static_cast<int>(i), pose, peer, 2.0 * body + 0.3, o.yield_to_held,
                            a.unsticking, unstick_first)) {
            if (j > i && t >= a.back_off_until) {
              if (unstick_first && b.unsticking && !a.unsticking)
                ++result.unstick_yields;
              else
                ++result.yields;
            }
            a.back_off_until = t + 2.0;
          }
        }
    }
    if (t < a.back_off_until) cmd = {-0.1, 0.0};
    a.since_progress += o.dt;
    if (a.block.fires() || a.since_progress > 30.0) {
      // Deadlock or no progress: search reactively for a while, then drop the goal (banned
      // for this robot). Banning only goals without progress for 30 s, not blocked ones,
      // was tried (issue 14, fifth pass): depot seed 8 (frontier) then reached 99.5 %
      // instead of 96.3 %, but willow seed 2 (16 robots, frontier) stalled 4 robots.
      a.reactive_until = t + 5.0;
      a.block.on_fired();
      a.since_progress = 0.0;
      if (a.unsticking) {
        end_unstick(a, t);
      } else if (!a.on_tree) {
        if (a.goal) a.soft_bans.push_back(*a.goal);
        a.goal.reset();
        a.route.clear();
        a.mode = AgentMode::kReactive;
      } else if (o.tree_leg_replan == TreeLegReplan::kAroundRobots && replan_leg(i, t)) {
        a.reactive_until = 0.0;  // a new leg around the robots in the way
      } else {
        ++a.next;  // skip the waypoint that cannot be reached
      }
    }
  }
  return cmd;
}

void TeamRun::watch(std::size_t i, double t) {
  Agent& a = *agents[i];
  const Vec2 now = a.body.true_pose().position;
  // ExplorationOptions::unstick_retry: after a watchdog, until the robot has left that spot or
  // the next watchdog, a robot without a route tries the unstick again every retry period.
  if (t < a.retry_until) {
    if (distance(now, a.retry_anchor) > o.stall_distance) {
      a.retry_until = -1.0;  // it got away
    } else if (t >= a.next_retry && !a.unsticking) {
      a.next_retry = t + o.unstick_retry_period;
      if (unstick(i, t, true)) ++result.unstick_retries;
    }
  }
  // Progress watchdog: a robot that has not left a stall_distance circle for a third of
  // stall_time gives up its goal (tree leaf or frontier) and searches reactively for a while.
  if (distance(now, a.wd_anchor) > o.stall_distance) {
    a.wd_anchor = now;
    a.wd_t = t;
  } else if (t - a.wd_t > o.stall_time / 3.0) {
    watchdog_fires(i, t, now);
  }
  // Stall watch: idle (within stall_distance of one spot) for stall_time while reachable
  // unknown space remains; idle when none remains is counted apart (its work is done).
  if (distance(now, a.anchor) > o.stall_distance) {
    a.anchor = now;
    a.anchor_t = t;
  } else if (!a.stalled && t - a.anchor_t > o.stall_time) {
    if (unknown_space_remains(t)) {
      a.stalled = true;
      ++result.stalled_robots;
      if (o.method != ExplorationMethod::kTree && !team_has_target) ++result.stalled_without_target;
      log_event(t, a, "stalled");
    } else if (!a.idle_counted) {
      // None remains, and none will again (unknown_space_remains()): not a stall, ever.
      a.idle_counted = true;
      ++result.idle_when_explored;
      log_event(t, a, "idle");
    }
  }
}

// The progress watchdog fired for robot i at `now`: it gives its goal up, searches reactively for
// 10 s, and first leaves the planning margin or drives to open space where the options say so.
void TeamRun::watchdog_fires(std::size_t i, double t, Vec2 now) {
  Agent& a = *agents[i];
  a.wd_anchor = now;
  a.wd_t = t;
  ++result.watchdog_events;
  log_event(t, a, "watchdog");
  const bool had_goal = a.mode == AgentMode::kFollow;
  if (a.on_tree) {
    finish_leg(a, t);
  } else if (a.mode == AgentMode::kFollow) {
    if (a.goal) a.soft_bans.push_back(*a.goal);
    a.goal.reset();
    a.route.clear();
    a.mode = AgentMode::kReactive;
    a.unsticking = false;
  }
  a.reactive_until = t + 10.0;
  if (o.disperse_neighbours && o.method == ExplorationMethod::kTree) disperse_around(i, t);
  if (o.clear_way_out && o.method == ExplorationMethod::kTree) clear_way_out(i, t);
  // ExplorationOptions::unstick_retry: it tries again until it has left this spot.
  if (o.unstick_retry && o.unstick && o.method == ExplorationMethod::kTree) {
    a.retry_until = t + o.stall_time / 3.0;
    a.retry_anchor = now;
    a.next_retry = t + o.unstick_retry_period;
  }
  // ExplorationOptions::margin_escape: inside the planning margin, out of it first.
  if (o.margin_escape && margin_escape(a, t, now)) {
    leaving.clear();
    return;
  }
  if (o.method == ExplorationMethod::kTree ? o.unstick : o.frontier_unstick) {
    unstick(i, t, true);
  } else if (o.idle_unstick && !had_goal && o.method != ExplorationMethod::kTree) {
    // ExplorationOptions::idle_unstick: a goalless robot moves to open space.
    if (unstick(i, t, true)) ++result.idle_unsticks;
  }
  leaving.clear();
}

}  // namespace voronav::exploration::internal
