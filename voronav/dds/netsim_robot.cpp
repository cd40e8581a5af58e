// One robot process of the multi-process netsim run (netsim_dds.hpp): a sim::RobotAgent over
// DdsTransport, stepped in lockstep with the world process.
#include "voronav/dds/netsim_dds.hpp"

#include <dds/dds.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <functional>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <thread>

#include "voronav/core/error.hpp"
#include "voronav/dds/cyclone_config.hpp"
#include "voronav/dds/dds_transport.hpp"
#include "voronav/dds/internal/lockstep_control.hpp"
#include "voronav/dds/internal/netsim_json.hpp"
#include "voronav/dds/internal/netsim_trace.hpp"
#include "voronav/sim/robot_agent.hpp"
#include "voronav/sim/scenario_file.hpp"

namespace voronav::dds {

namespace {

using nlohmann::json;
namespace fs = std::filesystem;
using namespace internal;

/// The agent's view of the network in a robot process: sends go straight to DDS; receive()
/// hands over the packets the lockstep loop released for this step.
class LockstepTransport final : public network::Transport {
 public:
  explicit LockstepTransport(DdsTransport& dds) : dds_(dds) {}
  void send(network::RobotId from, network::RobotId to,
            std::span<const std::uint8_t> bytes) override {
    dds_.send(from, to, bytes);
  }
  void broadcast(network::RobotId from, std::span<const std::uint8_t> bytes) override {
    dds_.broadcast(from, bytes);
  }
  std::vector<network::Packet> receive(network::RobotId) override {
    auto out = std::move(due_);
    due_.clear();
    return out;
  }
  void update_position(network::RobotId id, Vec2 position) override {
    dds_.update_position(id, position);
  }
  std::vector<network::Neighbour> nearby(network::RobotId self) override {
    return dds_.nearby(self);
  }

  /// Pulls what DDS has into the buffer.
  void pull() {
    for (auto& p : dds_.receive(dds_.self()))
      buffer_.push_back(std::move(p));
  }
  /// Releases the buffered packets sent before `before_s`, in (send time, sender) order (per
  /// sender the send order is kept): the order the simulated radio delivers in.
  void release(double before_s) {
    std::vector<network::Packet> later;
    for (auto& p : buffer_)
      (p.sent_at_s < before_s - 1e-9 ? due_ : later).push_back(std::move(p));
    buffer_ = std::move(later);
    std::stable_sort(due_.begin(), due_.end(), [](const auto& a, const auto& b) {
      if (a.sent_at_s != b.sent_at_s) return a.sent_at_s < b.sent_at_s;
      return a.from < b.from;
    });
  }

 private:
  DdsTransport& dds_;
  std::vector<network::Packet> buffer_, due_;
};

}  // namespace

using nlohmann::json;
namespace fs = std::filesystem;
using namespace internal;

// ---- one robot --------------------------------------------------------------------------------
int run_robot_process(const RobotProcessOptions& o) {
  o.link.validate();
  if (!(o.loss >= 0.0 && o.loss <= 1.0))
    throw Error("--loss", 0, "expected a probability in [0, 1], got " + std::to_string(o.loss));
  const auto file = sim::load_netsim_scenario(o.scenario_path);
  const auto& sc = file.scenario;
  const auto& opts = file.options;
  const auto n = static_cast<std::uint32_t>(sc.robots.size());
  if (o.id >= n)
    throw Error("--id", 0,
                "robot " + std::to_string(o.id) + " does not exist: the scenario has " +
                    std::to_string(n) + " robots (0.." + std::to_string(n - 1) + ")");
  if (!(opts.radio.latency_s > 0.0))
    throw Error(o.scenario_path, 0, "radio.latency_s must be > 0 for robot processes");
  double clock_now = 0.0;
  DdsTransportOptions to;
  to.self = network::RobotId{o.id};
  to.domain_id = o.link.domain_id;
  to.config_xml = o.link.config_xml;
  to.partition = o.link.partition;
  to.radio_range_m = opts.radio.range_m;
  to.range_at_send_time = true;
  to.pose_max_age_s = 0.75 * opts.dt_s;  // live robots publish every step; the dead do not
  to.loss_probability = o.loss;
  to.loss_seed = opts.seed ^ (0x51ED27ull * (o.id + 1));
  to.history_depth = 8192;
  to.max_payload_bytes = 8u << 20;
  to.max_blocking_s = 5.0;
  to.close_timeout_s = 2.0;
  to.clock = [&clock_now] { return clock_now; };
  DdsTransport dds(to);
  ControlLink link(static_cast<dds_entity_t>(dds.participant_handle()), o.link.partition, false);
  LockstepTransport net(dds);
  BinaryGrid truth = binarize(sc.world);
  TraceFile trace(o.trace_path);
  if (!o.trace_path.empty() && !trace.on())
    throw Error(o.trace_path, 0, "cannot write the trace file");
  std::vector<sim::RecordedMessage> sent;    // since the last trace line
  std::vector<sim::RecordedRepair> repairs;  // route breaks handled, since the last trace line
  sim::AgentContext ctx{&sc, &opts, &truth, trace.on() ? &sent : nullptr,
                        trace.on() ? &repairs : nullptr};
  sim::RobotAgent agent(ctx, network::RobotId{o.id}, sc.robots[o.id], net);
  const std::string who = "voronav-robot " + std::to_string(o.id);

  ReportMsg rep;
  rep.id = o.id;
  auto report = [&](std::uint8_t kind, std::uint32_t step, std::string detail = {}) {
    rep.kind = kind;
    rep.prev_seq = rep.seq;
    rep.seq = dds.last_seq_sent();
    rep.step = step;
    rep.route_time_s = agent.first_route_s();
    rep.arrived = agent.arrived();
    rep.detail = std::move(detail);
    link.write(rep);
  };

  agent.begin();  // pose stamped 0, first sensing
  if (!dds.wait_for_peers(n - 1, o.link.startup_timeout_s)) {
    std::cerr << who << ": discovery incomplete after " << o.link.startup_timeout_s << " s ("
              << dds.known_robots().size() << " of " << n - 1 << " robots)\n";
    report(kFailedReport, 0, "discovery incomplete");
    link.flush(1.0);
    return kExitNoPeers;
  }
  report(kReady, 0);
  std::uint32_t step = 0;
  bool started = false;
  const double dt = opts.dt_s;
  std::uint64_t missing_waits = 0;
  for (;;) {
    // The next Tick (a newer step, or stop).
    std::optional<TickMsg> tick;
    const double deadline = steady_s() + o.link.world_timeout_s;
    while (!tick) {
      if (auto t = link.take_tick(); t && (t->stop || t->step > step || (!started && t->step == 0)))
        tick = std::move(t);
      else if (steady_s() >= deadline)
        break;
      else
        link.wait(0.05);
      // Keep our report visible (a restarted world reads it).
    }
    if (!tick) {
      std::cerr << who << ": no tick from the world process for " << o.link.world_timeout_s
                << " s after step " << step << "; giving up\n";
      return kExitWorldLost;
    }
    if (tick->stop) break;
    if (tick->alive.size() != n) {
      std::cerr << who << ": tick for " << tick->alive.size() << " robots, scenario has " << n
                << "\n";
      return kExitFailed;
    }
    if (tick->step == 0) {
      agent.start();
      trace.robot_step(0, 0.0, agent.position(), sent, repairs);
      sent.clear();
      repairs.clear();
      started = true;
      report(kDone, 0);
      continue;
    }
    started = true;
    if (tick->step != step + 1) {
      std::cerr << who << ": tick " << tick->step << " after step " << step << "\n";
      return kExitFailed;
    }
    step = tick->step;
    const double now = step * dt;
    std::vector<network::RobotId> alive;
    for (std::uint32_t j = 0; j < n; ++j)
      if (tick->alive[j] && j != o.id) alive.push_back(network::RobotId{j});
    clock_now = now - dt / 2;  // during the move, neighbours are where they were at t_{k-1}
    agent.move(now);
    clock_now = now;
    agent.flush();
    // Everyone's pose of t_k, then every packet announced up to step k-1.
    if (!dds.wait_for_poses(alive, now, o.link.payload_timeout_s)) ++missing_waits;
    const double until = steady_s() + o.link.payload_timeout_s;
    for (;;) {
      net.pull();
      bool all = true;
      for (auto j : alive)
        if (dds.last_seq_from(j) < tick->seq[j.value]) all = false;
      if (all) break;
      if (steady_s() >= until) {
        ++missing_waits;
        break;
      }
      std::this_thread::sleep_for(std::chrono::microseconds(100));
    }
    net.release(now);
    agent.communicate(now);
    for (std::uint32_t c : tick->changes) {
      if (c >= sc.changes.size() || c < rep.changes_applied) continue;
      const auto box = sim::apply_change(truth, sc.changes[c]);
      rep.changes_applied = c + 1;
      agent.world_changed(now, box.lo, box.hi);
    }
    trace.robot_step(step, now, agent.position(), sent, repairs);
    sent.clear();
    repairs.clear();
    report(kDone, step);
    if (o.die_at_step && *o.die_at_step == step) {
      std::cerr << who << ": killing itself after step " << step << " (fault injection)\n";
      die_now();
    }
  }
  if (o.id == sc.source) trace.robot_route(agent.route());
  const auto a = agent.report();
  json j = agent_report_json(a);
  j["id"] = o.id;
  j["steps"] = step;
  j["missing_waits"] = missing_waits;
  j["transport"] = {{"delivered", dds.stats().delivered},
                    {"dropped_range", dds.stats().dropped_range},
                    {"dropped_loss", dds.stats().dropped_loss},
                    {"rejected", dds.stats().rejected}};
  report(kFinal, step, j.dump());
  link.flush(2.0);
  dds.flush(1.0);
  std::cout << j.dump() << "\n";
  return kExitOk;
}

}  // namespace voronav::dds
