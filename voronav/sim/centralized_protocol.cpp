// The centralized baseline of seed 000: the source floods a Request, every robot answers with an
// Ack holding its whole local map, the source plans A* over the merged map and replans on changes.
#include "voronav/sim/robot_agent.hpp"

#include <algorithm>
#include <cmath>

#include "voronav/core/error.hpp"
#include "voronav/planning/astar.hpp"
#include "voronav/sim/agent_internal.hpp"

namespace voronav::sim {

using namespace network;
using namespace agent_detail;

// ---- centralized baseline ---------------------------------------------------------------------
void RobotAgent::start_request() {
  auto& s = r_;
  ++report_.search_attempts;
  const std::uint32_t num = ++search_num_;
  s.req_num = num;
  collecting_ = true;
  last_ack_ = now_;
  broadcast(RequestMessage{s.id, num}, 0);
}

void RobotAgent::on(const Header& h, const RequestMessage& m) {
  auto& r = r_;
  if (is_source() || m.source != source_id()) return;
  if (r.req_num != kNone && m.num <= r.req_num) return;
  r.req_num = m.num;
  r.parent = h.sender;
  if (h.hops + 1 < opt().hop_limit) broadcast(m, static_cast<std::uint8_t>(h.hops + 1));
  report_.metrics.work += r.map.grid().size();  // serialising the map
  send_reliable(r.parent, AckMessage{m.source, m.num, r.id, r.map.grid()});
}

void RobotAgent::on(const Header&, const AckMessage& m) {
  auto& r = r_;
  if (!is_source()) {
    if (r.parent != kBroadcast) send_reliable(r.parent, m);  // relay toward the source
    return;
  }
  // Merge the received local map into the source's map.
  const auto& wg = scen().world;
  const auto& g = m.local_map.geometry();
  const auto off = wg.geometry().world_to_cell(g.cell_center(Cell{0, 0}));
  if (!off) return;
  timed([&] {
    for (int y = 0; y < g.height; ++y)
      for (int x = 0; x < g.width; ++x) {
        const std::int8_t v = m.local_map[Cell{x, y}];
        const Cell w = *off + Cell{x, y};
        if (v != kUnknown && wg.contains(w) && r.map.at(w) != v) r.map.set(w, v);
      }
    return 0;
  });
  report_.metrics.work += m.local_map.size();
  last_ack_ = now_;
}

void RobotAgent::on(const Header&, const NotifyMessage& m) {
  auto& r = r_;
  if (!is_source()) {
    if (r.parent != kBroadcast) send_reliable(r.parent, m);
    return;
  }
  ++report_.repairs;
  log_repair(false, "learns the route is blocked and asks for the maps again");
  if (!collecting_) start_request();
}

void RobotAgent::on(const Header&, const LinkAckMessage&) {}

void RobotAgent::plan_central() {
  auto& s = r_;
  const auto& wg = scen().world.geometry();
  const auto a = wg.world_to_cell(s.pos), b = wg.world_to_cell(scen().destination);
  ++report_.replans;
  const auto result = timed([&] {
    BinaryGrid bin = binarize(s.map.grid(), BinarizeOptions{.unknown_is_blocked = false});
    BinaryGrid pg = planning::make_planning_grid(bin, opt().robot_radius_m);
    const Cell la = *a - s.map.offset(), lb = *b - s.map.offset();
    pg[la] = 0;
    pg[lb] = 0;
    planning::AStarPlanner planner;
    auto r = planner.plan(pg, la, lb);
    for (auto& c : r.path)
      c = c + s.map.offset();
    return r;
  });
  report_.metrics.work += s.map.grid().size() * 3 + result.expanded;
  if (!result.ok()) {
    s.waypoints.clear();
    return;
  }
  s.waypoints.clear();
  for (std::size_t i = 1; i < result.path.size(); ++i)
    s.waypoints.push_back(wg.cell_center(result.path[i]));
  s.waypoints.push_back(scen().destination);
  s.wp = 0;
  if (report_.route_time_s < 0.0) {
    report_.found_by = RouteFoundBy::kSourceAlone;  // it plans by itself over the maps it got
    report_.route_time_s = now_;
    report_.route_length_m = path_len(s.pos, s.waypoints);
  }
}

void RobotAgent::check_central_path() {
  auto& s = r_;
  if (collecting_ || s.waypoints.empty()) return;
  for (std::size_t i = s.wp; i < s.waypoints.size(); ++i) {
    if (distance(s.waypoints[i], s.pos) > opt().sensing_range_m + 0.5) break;
    const Vec2 from = i == s.wp ? s.pos : s.waypoints[i - 1];
    if (segment_blocked(from, s.waypoints[i])) {
      plan_central();
      return;
    }
  }
}

}  // namespace voronav::sim
