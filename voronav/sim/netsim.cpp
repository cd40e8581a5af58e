#include "voronav/sim/netsim.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include <memory>

#include "voronav/core/error.hpp"
#include "voronav/core/stepper.hpp"
#include "voronav/sim/robot_agent.hpp"
#include "voronav/sim/world.hpp"

namespace voronav::sim {

using namespace network;

std::string_view to_string(Method m) {
  return m == Method::kCentralized ? "centralized" : "decentralized";
}

Method parse_method(std::string_view s) {
  if (s == "centralized") return Method::kCentralized;
  if (s == "decentralized") return Method::kDecentralized;
  throw Error("method", 0,
              "expected 'centralized' or 'decentralized', got '" + std::string(s) + "'");
}

void NetSimScenario::validate() const {
  if (world.empty()) throw Error("scenario.world", 0, "the world map is empty");
  if (robots.empty()) throw Error("scenario.robots", 0, "at least one robot is needed");
  if (source >= robots.size()) throw Error("scenario.source", 0, "source index out of range");
  auto check = [&](Vec2 p, const std::string& what) {
    const auto c = world.geometry().world_to_cell(p);
    if (!p.is_finite() || !c || !world.contains(*c))
      throw Error(what, 0, "position is outside the map");
    if (world[*c] != kFree) throw Error(what, 0, "position is inside an obstacle");
  };
  for (std::size_t i = 0; i < robots.size(); ++i)
    check(robots[i], "scenario.robots[" + std::to_string(i) + "]");
  check(destination, "scenario.destination");
  for (const auto& ch : changes) {
    if (!(ch.after_route_s >= 0.0) || !std::isfinite(ch.after_route_s))
      throw Error("scenario.changes", 0, "after_route_s must be a finite number >= 0");
    if (!std::isfinite(ch.at_s) || !std::isfinite(ch.centralized_at_s))
      throw Error("scenario.changes", 0,
                  "at_s and centralized_at_s must be finite numbers (< 0: unused)");
    for (Cell c : ch.cells)
      if (!world.contains(c)) throw Error("scenario.changes", 0, "change cell outside the map");
  }
}

void NetSimOptions::validate() const {
  auto pos = [](double v, const char* n) {
    if (!(v > 0.0) || !std::isfinite(v))
      throw Error(std::string("netsim.") + n, 0,
                  "expected a positive finite number, got " + std::to_string(v));
  };
  pos(sensing_range_m, "sensing_range_m");
  pos(speed_mps, "speed_mps");
  pos(dt_s, "dt_s");
  pos(time_limit_s, "time_limit_s");
  pos(search_timeout_s, "search_timeout_s");
  pos(link_timeout_s, "link_timeout_s");
  pos(collect_s, "collect_s");
  pos(repair_timeout_s, "repair_timeout_s");
  // At most 1e9 steps (the rule both simulators share, core/stepper.hpp).
  (void)step_count(dt_s, time_limit_s, "netsim.dt_s", "netsim.time_limit_s");
  if (!(robot_radius_m >= 0.0) || !std::isfinite(robot_radius_m))
    throw Error("netsim.robot_radius_m", 0, "expected a finite number >= 0");
  if (!(search_timeout_per_m >= 0.0) || !std::isfinite(search_timeout_per_m))
    throw Error("netsim.search_timeout_per_m", 0, "expected a finite number >= 0");
  if (!(search_activity_s >= 0.0) || !std::isfinite(search_activity_s))
    throw Error("netsim.search_activity_s", 0, "expected a finite number >= 0");
  if (!(repair_resend_s >= 0.0) || !std::isfinite(repair_resend_s))
    throw Error("netsim.repair_resend_s", 0, "expected a finite number >= 0");
  if (!(repair_sense_wait_s >= 0.0) || !std::isfinite(repair_sense_wait_s))
    throw Error("netsim.repair_sense_wait_s", 0, "expected a finite number >= 0");
  if (!(repair_rejoin_m >= 0.0) || !std::isfinite(repair_rejoin_m))
    throw Error("netsim.repair_rejoin_m", 0, "expected a finite number >= 0");
  if (!(path_wait_s >= 0.0) || !std::isfinite(path_wait_s))
    throw Error("netsim.path_wait_s", 0, "expected a finite number >= 0");
  if (max_search_attempts < 1 || link_retries < 0 || hop_limit < 1 || hop_limit > 255 ||
      repair_hops < 1 || repair_expand_hops < 0 || repair_expand_hops > 255)
    throw Error("netsim", 0, "attempts/retries/hop limits out of range");
  radio.validate();
}

NetSimOptions NetSimOptions::scale_options() const {
  NetSimOptions o = *this;
  o.search_timeout_per_m = 2.5;
  o.search_activity_s = 30.0;
  o.keep_bridge_on_new_search = true;
  o.source_straight_start = true;
  o.walk_replan_whole_map = true;
  return o;
}

namespace {

RadioOptions radio_opts(const NetSimOptions& o) {
  RadioOptions r = o.radio;
  r.seed = o.radio.seed ^ (o.seed * 0x9E3779B97F4A7C15ull);
  return r;
}

}  // namespace

ChangeBox apply_change(BinaryGrid& truth, const ObstacleChange& change) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  ChangeBox box{{kInf, kInf}, {-kInf, -kInf}};
  for (Cell c : change.cells) {
    truth[c] = change.value >= 50 ? 1 : 0;
    const Vec2 w = truth.geometry().cell_center(c);
    box.lo = {std::min(box.lo.x, w.x), std::min(box.lo.y, w.y)};
    box.hi = {std::max(box.hi.x, w.x), std::max(box.hi.y, w.y)};
  }
  return box;
}

std::vector<std::size_t> changes_due(const NetSimScenario& scenario, double first_route_s,
                                     double now_s, std::size_t applied, Method method) {
  std::vector<std::size_t> out;
  for (std::size_t i = applied; i < scenario.changes.size(); ++i) {
    const auto& c = scenario.changes[i];
    const double at =
        method == Method::kCentralized && c.centralized_at_s >= 0.0 ? c.centralized_at_s : c.at_s;
    if (at >= 0.0) {
      if (now_s + 1e-9 < at) break;
    } else if (first_route_s < 0.0 || now_s + 1e-9 < first_route_s + c.after_route_s) {
      break;
    }
    out.push_back(i);
  }
  return out;
}

NetSimResult run_netsim(const NetSimScenario& scenario, const NetSimOptions& options) {
  scenario.validate();
  options.validate();
  const auto wall0 = std::chrono::steady_clock::now();
  SimRadio radio(radio_opts(options));
  BinaryGrid truth = binarize(scenario.world);
  NetSimResult res;
  auto& rec = res.recording;
  AgentContext ctx{&scenario, &options, &truth, options.record ? &rec.messages : nullptr,
                   options.record ? &rec.repairs : nullptr};
  std::vector<std::unique_ptr<RobotAgent>> agents;
  for (std::size_t i = 0; i < scenario.robots.size(); ++i)
    agents.push_back(std::make_unique<RobotAgent>(ctx, RobotId{static_cast<std::uint32_t>(i)},
                                                  scenario.robots[i], radio));
  RobotAgent& source = *agents[scenario.source];
  if (options.record) rec.world = scenario.world.geometry();
  auto snapshot_at_route = [&] {
    if (!options.record || !rec.maps_at_route.empty() || source.first_route_s() < 0.0) return;
    for (auto& a : agents) {
      rec.maps_at_route.push_back(a->local_map().grid());
      rec.open_points_at_route.push_back(a->open_points());
    }
  };
  // The shared loop (core/stepper.hpp): sense -> decide -> move -> record each step. Step 0
  // senses with begin() and starts the method at t = 0; RobotAgent::move() senses at the end of
  // its move to t_{k+1} (the step a robot process runs, robot_agent.hpp), so that is the sensing
  // at t_{k+1} and the sense phase of later steps has nothing left to do. Decide at t_k > 0: the
  // robots handle the packets and timers (communicate), then the obstacle changes due by the
  // first route time known before the move to t_k (a robot process learns it from the world
  // process then); after the last step the robots handle that step's packets once more (finish).
  const Stepper clock(options.dt_s, options.time_limit_s, "netsim.dt_s", "netsim.time_limit_s");
  std::size_t applied = 0;
  double first_route = -1.0;
  const auto handle = [&](double now) {
    for (auto& a : agents)
      a->communicate(now);
    for (std::size_t i : changes_due(scenario, first_route, now, applied, options.method)) {
      const auto box = apply_change(truth, scenario.changes[i]);
      applied = i + 1;
      for (auto& a : agents)
        a->world_changed(now, box.lo, box.hi);
    }
    snapshot_at_route();
  };
  Stepper::Phases phases;
  phases.sense = [&](const Stepper::Step& s) {
    if (s.k == 0)
      for (auto& a : agents)
        a->begin();
  };
  phases.decide = [&](const Stepper::Step& s) {
    if (s.k > 0) return handle(s.t);
    for (auto& a : agents)
      a->start();
    snapshot_at_route();
  };
  phases.move = [&](const Stepper::Step& s) {
    radio.set_time(s.t_end);
    first_route = source.first_route_s();
    for (auto& a : agents)
      a->move(s.t_end);
    for (auto& a : agents)
      a->flush();
  };
  phases.record = [&](const Stepper::Step& s) {
    if (!options.record) return;
    RecordedStep st{s.t_end, {}};
    for (const auto& a : agents)
      st.positions.push_back(a->position());
    rec.steps.push_back(std::move(st));
  };
  phases.done = [&] { return source.arrived(); };
  phases.finish = handle;
  const double now = clock.run(phases).t_end;
  std::vector<AgentReport> reports;
  for (const auto& a : agents)
    reports.push_back(a->report());
  res.metrics = aggregate_metrics(reports, scenario.source, options.method);
  res.metrics.simulated_s = now;
  res.metrics.changes_applied = static_cast<int>(applied);
  res.metrics.wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  if (options.record) {
    for (auto& a : agents) {
      rec.final_local_maps.push_back(a->local_map().grid());
      rec.open_points.push_back(a->open_points());
    }
    rec.route = source.route();
  }
  return res;
}

}  // namespace voronav::sim
