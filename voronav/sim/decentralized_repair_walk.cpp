// The decentralized method of seed 000, beyond Tables 4-5 (issue #13, stop 28, option
// repair_sense_walk, on by default since stop 28): a relay goes and senses the break of the
// source's Repair on its behalf, as the relays of figure 18 go and sense a gap for the Search.
// Traced need: in 11 of 48 change runs no Repair executed, because no robot within repair_hops knew
// a way round the break, or because every answerer had not seen the change and its detour crossed
// it (docs/reproductions/networked.md, stops 22 and 25). The walking relay answers only from a map
// that holds the break as it is now.
#include <algorithm>
#include <vector>

#include "voronav/sim/agent_internal.hpp"
#include "voronav/sim/robot_agent.hpp"

namespace voronav::sim {

using namespace network;
using namespace agent_detail;

/// Whether this robot is the one that walks for the Repair it got in `h`: it heard it from the
/// source itself, carries no Path, and no other robot it hears is as near the source (ties: lower
/// id). One hand-off rule, as the Search's: each neighbour of the source decides from the positions
/// it hears, so at most one of the robots that hear each other walks.
bool RobotAgent::walks_for_repair(const Header& h) {
  const auto& r = r_;
  if (!opt().repair_sense_walk || is_source() || h.sender != source_id()) return false;
  // A Repair means the source has its route: a walk left from the Search (a bridge, a walk to
  // the destination) no longer serves it and gives way, and so does a walk for an earlier Repair
  // (the source asks anew from where it is now); a Path it carries back does not.
  if (r.walk == Walk::kBack || r.walk == Walk::kSense || r.pending) return false;
  std::optional<Vec2> src;
  const auto near = transport_.nearby(r.id);
  for (const auto& n : near)
    if (n.id == source_id()) src = n.position;
  if (!src) return false;
  const double mine = distance(r.pos, *src);
  for (const auto& n : near) {
    if (n.id == source_id() || n.id == r.id) continue;
    const double d = distance(n.position, *src);
    if (d < mine || (d == mine && n.id.value < r.id.value)) return false;
  }
  return true;
}

/// Starts the walk to the source's side of the break of `m` (the last route point before it),
/// when its planned way there is at most half of what it can drive in repair_sense_wait_s (the
/// other half is for sensing and walking round the break); a robot farther away does not walk
/// and says nothing, so the source waits only repair_timeout_s as without the option.
bool RobotAgent::start_repair_walk(const RepairMessage& m) {
  auto& r = r_;
  if (m.broken_from >= m.whole_path.size()) return false;
  const auto keep_waypoints = r.waypoints;
  const auto keep_wp = r.wp;
  if (!plan_walk(m.whole_path[m.broken_from].position)) return false;
  if (path_len(r.pos, r.waypoints) > 0.5 * opt().speed_mps * opt().repair_sense_wait_s) {
    r.waypoints = keep_waypoints;  // too far: it keeps what it was doing
    r.wp = keep_wp;
    return false;
  }
  repair_walk_ = m;
  repair_walk_phase_ = 0;
  repair_walk_until_ = now_ + opt().repair_sense_wait_s;
  r.walk = Walk::kRepair;
  r.walk_since_check = 0.0;
  r.walk_map_changed = false;
  ++report_.repair_sense_walks;
  send_sense_notice(kSenseWalking);  // the source waits for it (repair_sense_wait_s)
  NS_DEBUG("t=%.1f robot %u walks to sense the break at (%.1f,%.1f)\n", now_, r.id.value,
           m.whole_path[m.broken_from].position.x, m.whole_path[m.broken_from].position.y);
  return true;
}

/// Every metre its map changed and at the walk's end. Phase 0: once it has sensed the break
/// (within sensing range of the cells the Repair carried, or at the break), it answers with its
/// detour if it has one; at the break without one it walks on to the route point past the break
/// (phase 1, A* on its own map, unknown cells free), answering as soon as its points hold a
/// detour, or at that point with the way it drove (each step driven, so free).
void RobotAgent::repair_walk_progress(bool arrived) {
  auto& r = r_;
  if (!repair_walk_ || now_ + 1e-9 >= repair_walk_until_) {
    end_repair_walk();
    return;
  }
  const RepairMessage& m = *repair_walk_;
  if (repair_walk_phase_ == 0) {
    bool sensed = arrived;
    for (Vec2 q : m.blocked)
      sensed = sensed || distance(q, r.pos) <= opt().sensing_range_m;
    if (sensed) {
      const auto fixed = detour(m.whole_path, m.broken_from, m.broken_to);
      if (!fixed.empty()) {
        answer_sensed(fixed);
        return;
      }
    }
    if (!arrived) return;
    r.walk_trail = {r.pos};
    if (m.broken_to >= m.whole_path.size() || !plan_walk(m.whole_path[m.broken_to].position)) {
      send_sense_notice(kSenseGaveUp);
      end_repair_walk();
      return;
    }
    repair_walk_phase_ = 1;
    NS_DEBUG("t=%.1f robot %u knows no detour at the break: walks round it\n", now_, r.id.value);
    return;
  }
  const auto fixed = detour(m.whole_path, m.broken_from, m.broken_to);
  if (!fixed.empty()) {
    answer_sensed(fixed);
    return;
  }
  if (!arrived) return;
  const Vec2 from = m.whole_path[m.broken_from].position;
  const Vec2 to = m.whole_path[m.broken_to].position;
  if (r.walk_trail.empty() || distance(r.walk_trail.front(), from) > 0.5 ||
      distance(r.pos, to) > 0.5) {
    send_sense_notice(kSenseGaveUp);  // stopped short, or its trail broke: no way to tell
    end_repair_walk();
    return;
  }
  std::vector<VoronoiPoint> way(
      m.whole_path.begin(), m.whole_path.begin() + static_cast<std::ptrdiff_t>(m.broken_from) + 1);
  for (Vec2 p : r.walk_trail) {
    if (distance(p, from) < 1e-3 || distance(p, to) < 1e-3) continue;
    const double cl = clearance_at(r.map.grid(), p);
    way.push_back(
        VoronoiPoint{p, static_cast<float>(std::max(cl, opt().robot_radius_m + 0.05)), 0.0f});
  }
  way.insert(way.end(), m.whole_path.begin() + static_cast<std::ptrdiff_t>(m.broken_to),
             m.whole_path.end());
  answer_sensed(way);
}

/// Sends `fixed` (starting where the source stands) to the source as the answer to the Repair it
/// walked for, when the source is in radio range; ends the walk either way.
void RobotAgent::answer_sensed(const std::vector<VoronoiPoint>& fixed) {
  const RepairMessage m = *repair_walk_;
  end_repair_walk();
  const bool heard = neighbour_position(m.source).has_value();
  NS_DEBUG("t=%.1f robot %u answers the Repair from what it sensed (%zu points, source %s)\n", now_,
           r_.id.value, fixed.size(), heard ? "in range" : "out of range");
  if (!heard) return;
  PathMessage p;
  p.source = m.source;
  p.num = next_repair_num();
  p.relays = {m.source};
  p.whole_path = fixed;
  p.exit_index = kSensedAnswer;
  ++report_.repair_answers;
  ++report_.repair_sense_answers;
  log_repair(false, "sensed the break and answers the source's Repair (sensing walk)");
  send_reliable(m.source, p);
}

/// A notice to the source about the walk for its Repair (kSenseWalking, kSenseGaveUp), when the
/// source is in radio range: a Path message without points, whose num is the Repair's (with
/// the Repair-answer flag).
void RobotAgent::send_sense_notice(std::uint32_t what) {
  if (!repair_walk_) return;
  const RepairMessage& m = *repair_walk_;
  if (!neighbour_position(m.source)) return;
  PathMessage p;
  p.source = m.source;
  p.num = m.num | kRepairFlag;  // a Repair answer's flag: handled as one (on_repair_path)
  p.relays = {m.source};
  p.exit_index = what;
  send_reliable(m.source, p);
}

void RobotAgent::end_repair_walk() {
  auto& r = r_;
  repair_walk_.reset();
  repair_walk_until_ = -1.0;
  if (r.walk == Walk::kRepair) {
    r.walk = Walk::kIdle;
    r.waypoints.clear();
    r.wp = 0;
  }
}

}  // namespace voronav::sim
