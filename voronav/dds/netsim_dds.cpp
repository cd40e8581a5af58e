#include "voronav/dds/netsim_dds.hpp"

#include <dds/dds.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>
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
#include "voronav/sim/robot_agent.hpp"
#include "voronav/sim/scenario_file.hpp"
#include "voronav_dds.h"

namespace voronav::dds {

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

constexpr std::uint16_t kVersion = voronav_dds_kWireVersion;
constexpr std::uint8_t kReady = 1, kDone = 2, kFinal = 3, kFailedReport = 4;

std::shared_ptr<spdlog::logger> log() {
  static std::shared_ptr<spdlog::logger> l = [] {
    if (auto existing = spdlog::get("voronav_netsim_dds")) return existing;
    return spdlog::stderr_color_mt("voronav_netsim_dds");
  }();
  return l;
}

double steady_s() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

dds_duration_t ns(double s) {
  return static_cast<dds_duration_t>(std::llround(std::max(0.0, s) * 1e9));
}

dds_entity_t must(dds_entity_t e, const char* what) {
  if (e < 0)
    throw Error(
        "cyclonedds", 0,
        std::string(what) + " failed: " + dds_strretcode(e) + " (" + std::to_string(e) + ")");
  return e;
}

[[noreturn]] void die_now() {
  std::fflush(nullptr);
  std::raise(SIGKILL);
  std::abort();
}

// ---- JSON of the metrics ----------------------------------------------------------------------
json robot_metrics_json(const sim::RobotMetrics& m) {
  json types = json::array();
  for (const auto& t : m.sent_by_type)
    types.push_back({t.messages, t.bytes});
  return {{"sent_by_type", types},      {"work", m.work},
          {"cpu_s", m.cpu_s},           {"travel_m", m.travel_m},
          {"sent_bytes", m.sent_bytes}, {"sent_messages", m.sent_messages}};
}
sim::RobotMetrics robot_metrics_from(const json& j) {
  sim::RobotMetrics m;
  m.work = j.at("work").get<std::uint64_t>();
  m.cpu_s = j.at("cpu_s").get<double>();
  m.travel_m = j.at("travel_m").get<double>();
  m.sent_bytes = j.at("sent_bytes").get<std::uint64_t>();
  m.sent_messages = j.at("sent_messages").get<std::uint64_t>();
  const auto& types = j.at("sent_by_type");
  for (std::size_t t = 0; t < m.sent_by_type.size() && t < types.size(); ++t) {
    m.sent_by_type[t].messages = types[t].at(0).get<std::uint64_t>();
    m.sent_by_type[t].bytes = types[t].at(1).get<std::uint64_t>();
  }
  return m;
}

json agent_report_json(const sim::AgentReport& a) {
  return {{"metrics", robot_metrics_json(a.metrics)},
          {"search_attempts", a.search_attempts},
          {"repairs", a.repairs},
          {"replans", a.replans},
          {"corrupt_packets", a.corrupt_packets},
          {"arrived", a.arrived},
          {"route_time_s", a.route_time_s},
          {"arrival_time_s", a.arrival_time_s},
          {"route_length_m", a.route_length_m}};
}
sim::AgentReport agent_report_from(const json& j) {
  sim::AgentReport a;
  a.metrics = robot_metrics_from(j.at("metrics"));
  a.search_attempts = j.at("search_attempts").get<int>();
  a.repairs = j.at("repairs").get<int>();
  a.replans = j.at("replans").get<int>();
  a.corrupt_packets = j.at("corrupt_packets").get<std::uint64_t>();
  a.arrived = j.at("arrived").get<bool>();
  a.route_time_s = j.at("route_time_s").get<double>();
  a.arrival_time_s = j.at("arrival_time_s").get<double>();
  a.route_length_m = j.at("route_length_m").get<double>();
  return a;
}

// ---- the control topics -----------------------------------------------------------------------
struct ReportMsg {
  std::uint32_t id = 0;
  std::uint32_t step = 0;
  std::uint8_t kind = 0;
  std::uint64_t seq = 0, prev_seq = 0;
  std::uint32_t changes_applied = 0;
  double route_time_s = -1.0;
  bool arrived = false;
  std::string detail;
};
struct TickMsg {
  std::uint32_t step = 0;
  bool stop = false;
  double first_route_s = -1.0;
  std::vector<std::uint8_t> alive;
  std::vector<std::uint64_t> seq;
  std::vector<std::uint32_t> changes;
};

dds_qos_t* control_qos() {
  dds_qos_t* q = dds_create_qos();
  dds_qset_reliability(q, DDS_RELIABILITY_RELIABLE, ns(1.0));
  dds_qset_history(q, DDS_HISTORY_KEEP_LAST, 1);
  dds_qset_durability(q, DDS_DURABILITY_TRANSIENT_LOCAL);
  dds_qset_ignorelocal(q, DDS_IGNORELOCAL_PARTICIPANT);
  return q;
}

/// Tick/Report endpoints on a participant (the robot's DdsTransport participant, or the world's
/// own). The world writes Ticks and reads Reports; a robot the other way round.
class ControlLink {
 public:
  ControlLink(dds_entity_t participant, const std::string& partition, bool world) : world_(world) {
    tick_topic_ = must(
        dds_create_topic(participant, &voronav_dds_Tick_desc, "voronav_tick", nullptr, nullptr),
        "dds_create_topic(tick)");
    report_topic_ = must(
        dds_create_topic(participant, &voronav_dds_Report_desc, "voronav_report", nullptr, nullptr),
        "dds_create_topic(report)");
    dds_qos_t* pq = dds_create_qos();
    dds_qset_partition1(pq, partition.c_str());
    pub_ = must(dds_create_publisher(participant, pq, nullptr), "dds_create_publisher");
    sub_ = must(dds_create_subscriber(participant, pq, nullptr), "dds_create_subscriber");
    dds_delete_qos(pq);
    dds_qos_t* q = control_qos();
    writer_ = must(dds_create_writer(pub_, world ? tick_topic_ : report_topic_, q, nullptr),
                   "dds_create_writer(control)");
    reader_ = must(dds_create_reader(sub_, world ? report_topic_ : tick_topic_, q, nullptr),
                   "dds_create_reader(control)");
    dds_delete_qos(q);
    waitset_ = must(dds_create_waitset(participant), "dds_create_waitset");
    const dds_entity_t rc =
        must(dds_create_readcondition(reader_, DDS_ANY_STATE), "dds_create_readcondition");
    must(dds_waitset_attach(waitset_, rc, reader_), "dds_waitset_attach");
  }

  void write(const TickMsg& t) {
    voronav_dds_Tick s{};
    s.version = kVersion;
    s.step = t.step;
    s.stop = t.stop;
    s.first_route_s = t.first_route_s;
    auto alive = t.alive;
    auto seq = t.seq;
    auto changes = t.changes;
    s.alive._buffer = alive.data();
    s.alive._length = s.alive._maximum = static_cast<std::uint32_t>(alive.size());
    s.seq._buffer = seq.data();
    s.seq._length = s.seq._maximum = static_cast<std::uint32_t>(seq.size());
    s.changes._buffer = changes.data();
    s.changes._length = s.changes._maximum = static_cast<std::uint32_t>(changes.size());
    const dds_return_t rc = dds_write(writer_, &s);
    if (rc != DDS_RETCODE_OK) must(rc, "dds_write(tick)");
  }

  void write(const ReportMsg& r) {
    voronav_dds_Report s{};
    s.version = kVersion;
    s.id = r.id;
    s.step = r.step;
    s.kind = r.kind;
    s.seq = r.seq;
    s.prev_seq = r.prev_seq;
    s.changes_applied = r.changes_applied;
    s.route_time_s = r.route_time_s;
    s.arrived = r.arrived;
    std::string detail = r.detail;
    s.detail = detail.data();
    const dds_return_t rc = dds_write(writer_, &s);
    if (rc != DDS_RETCODE_OK) must(rc, "dds_write(report)");
  }

  /// Takes every available Tick; the newest valid one, if any.
  std::optional<TickMsg> take_tick() {
    std::optional<TickMsg> out;
    for (;;) {
      void* buf[8] = {};
      dds_sample_info_t si[8];
      const dds_return_t n = dds_take(reader_, buf, si, 8, 8);
      if (n <= 0) break;
      for (dds_return_t i = 0; i < n; ++i) {
        if (!si[i].valid_data) continue;
        const auto* s = static_cast<const voronav_dds_Tick*>(buf[i]);
        if (s->version != kVersion || s->alive._length != s->seq._length) {
          log()->error("rejected a malformed tick (version {}, {} alive flags, {} seqs)",
                       s->version, s->alive._length, s->seq._length);
          continue;
        }
        TickMsg t;
        t.step = s->step;
        t.stop = s->stop;
        t.first_route_s = s->first_route_s;
        t.alive.assign(s->alive._buffer, s->alive._buffer + s->alive._length);
        t.seq.assign(s->seq._buffer, s->seq._buffer + s->seq._length);
        t.changes.assign(s->changes._buffer, s->changes._buffer + s->changes._length);
        if (!out || t.step >= out->step) out = std::move(t);
      }
      dds_return_loan(reader_, buf, n);
    }
    return out;
  }

  /// Takes every available Report.
  std::vector<ReportMsg> take_reports() {
    std::vector<ReportMsg> out;
    for (;;) {
      void* buf[32] = {};
      dds_sample_info_t si[32];
      const dds_return_t n = dds_take(reader_, buf, si, 32, 32);
      if (n <= 0) break;
      for (dds_return_t i = 0; i < n; ++i) {
        if (!si[i].valid_data) continue;
        const auto* s = static_cast<const voronav_dds_Report*>(buf[i]);
        if (s->version != kVersion || s->kind < kReady || s->kind > kFailedReport) {
          log()->error("rejected a malformed report (version {}, kind {})", s->version, s->kind);
          continue;
        }
        ReportMsg r;
        r.id = s->id;
        r.step = s->step;
        r.kind = s->kind;
        r.seq = s->seq;
        r.prev_seq = s->prev_seq;
        r.changes_applied = s->changes_applied;
        r.route_time_s = s->route_time_s;
        r.arrived = s->arrived;
        r.detail = s->detail ? s->detail : "";
        out.push_back(std::move(r));
      }
      dds_return_loan(reader_, buf, n);
    }
    return out;
  }

  void wait(double timeout_s) { dds_waitset_wait(waitset_, nullptr, 0, ns(timeout_s)); }
  std::size_t matched_writers() const {
    dds_subscription_matched_status_t st{};
    if (dds_get_subscription_matched_status(reader_, &st) < 0) return 0;
    return st.current_count;
  }
  std::size_t matched_readers() const {
    dds_publication_matched_status_t st{};
    if (dds_get_publication_matched_status(writer_, &st) < 0) return 0;
    return st.current_count;
  }
  void flush(double timeout_s) { dds_wait_for_acks(writer_, ns(timeout_s)); }

 private:
  bool world_;
  dds_entity_t tick_topic_ = 0, report_topic_ = 0, pub_ = 0, sub_ = 0, writer_ = 0, reader_ = 0,
               waitset_ = 0;
};

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

dds_entity_t participant_for(const LockstepLink& link, dds_entity_t& domain) {
  domain = 0;
  if (!link.config_xml.empty())
    domain = must(dds_create_domain(link.domain_id, link.config_xml.c_str()), "dds_create_domain");
  return must(dds_create_participant(link.domain_id, nullptr, nullptr), "dds_create_participant");
}

}  // namespace

void LockstepLink::validate() const {
  if (domain_id > 230)
    throw Error("--domain", 0, "expected 0..230, got " + std::to_string(domain_id));
  if (partition.empty()) throw Error("--partition", 0, "expected a non-empty partition name");
  auto positive = [](double v, const char* name) {
    if (!(v > 0.0) || !std::isfinite(v))
      throw Error(name, 0,
                  "expected a positive finite number of seconds, got " + std::to_string(v));
  };
  positive(startup_timeout_s, "--startup-timeout");
  positive(step_timeout_s, "--step-timeout");
  positive(world_timeout_s, "--world-timeout");
  positive(payload_timeout_s, "payload_timeout_s");
}

std::string metrics_to_json(const sim::NetSimMetrics& m) {
  json by_type = json::object();
  for (const auto& [k, c] : m.by_type)
    by_type[k] = {{"messages", c.messages}, {"bytes", c.bytes}};
  json robots = json::array();
  for (const auto& r : m.robots)
    robots.push_back(robot_metrics_json(r));
  const json j = {{"success", m.success},
                  {"route_time_s", m.route_time_s},
                  {"arrival_time_s", m.arrival_time_s},
                  {"travel_m", m.travel_m},
                  {"source_travel_m", m.source_travel_m},
                  {"route_length_m", m.route_length_m},
                  {"traffic_bytes", m.traffic_bytes},
                  {"messages", m.messages},
                  {"computation", m.computation},
                  {"max_robot_computation", m.max_robot_computation},
                  {"cpu_s", m.cpu_s},
                  {"max_robot_cpu_s", m.max_robot_cpu_s},
                  {"by_type", by_type},
                  {"alpha_bytes", m.alpha_bytes},
                  {"beta_bytes", m.beta_bytes},
                  {"gamma_bytes", m.gamma_bytes},
                  {"search_attempts", m.search_attempts},
                  {"repairs", m.repairs},
                  {"replans", m.replans},
                  {"corrupt_packets", m.corrupt_packets},
                  {"simulated_s", m.simulated_s},
                  {"wall_s", m.wall_s},
                  {"robots", robots}};
  return j.dump();
}

sim::NetSimMetrics metrics_from_json(const std::string& text) {
  try {
    const json j = json::parse(text);
    sim::NetSimMetrics m;
    m.success = j.at("success").get<bool>();
    m.route_time_s = j.at("route_time_s").get<double>();
    m.arrival_time_s = j.at("arrival_time_s").get<double>();
    m.travel_m = j.at("travel_m").get<double>();
    m.source_travel_m = j.at("source_travel_m").get<double>();
    m.route_length_m = j.at("route_length_m").get<double>();
    m.traffic_bytes = j.at("traffic_bytes").get<std::uint64_t>();
    m.messages = j.at("messages").get<std::uint64_t>();
    m.computation = j.at("computation").get<std::uint64_t>();
    m.max_robot_computation = j.at("max_robot_computation").get<std::uint64_t>();
    m.cpu_s = j.at("cpu_s").get<double>();
    m.max_robot_cpu_s = j.at("max_robot_cpu_s").get<double>();
    for (const auto& [k, v] : j.at("by_type").items())
      m.by_type[k] = {v.at("messages").get<std::uint64_t>(), v.at("bytes").get<std::uint64_t>()};
    m.alpha_bytes = j.at("alpha_bytes").get<double>();
    m.beta_bytes = j.at("beta_bytes").get<double>();
    m.gamma_bytes = j.at("gamma_bytes").get<double>();
    m.search_attempts = j.at("search_attempts").get<int>();
    m.repairs = j.at("repairs").get<int>();
    m.replans = j.at("replans").get<int>();
    m.corrupt_packets = j.at("corrupt_packets").get<std::uint64_t>();
    m.simulated_s = j.at("simulated_s").get<double>();
    m.wall_s = j.at("wall_s").get<double>();
    for (const auto& r : j.at("robots"))
      m.robots.push_back(robot_metrics_from(r));
    return m;
  } catch (const json::exception& e) {
    throw Error("metrics", 0, std::string("malformed metrics JSON: ") + e.what());
  }
}

// ---- one robot --------------------------------------------------------------------------------
int run_robot_process(const RobotProcessOptions& o) {
  o.link.validate();
  if (!(o.loss >= 0.0 && o.loss <= 1.0))
    throw Error("--loss", 0, "expected a probability in [0, 1], got " + std::to_string(o.loss));
  const auto file = sim::load_netsim_scenario(o.scenario_path);
  const auto& sc = file.scenario;
  const auto& opts = file.options;
  sc.validate();
  opts.validate();
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
  sim::AgentContext ctx{&sc, &opts, &truth, nullptr};
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
    report(kDone, step);
    if (o.die_at_step && *o.die_at_step == step) {
      std::cerr << who << ": killing itself after step " << step << " (fault injection)\n";
      die_now();
    }
  }
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

// ---- the world --------------------------------------------------------------------------------
int run_world_process(const WorldProcessOptions& o) {
  o.link.validate();
  const auto file = sim::load_netsim_scenario(o.scenario_path);
  const auto& sc = file.scenario;
  const auto& opts = file.options;
  sc.validate();
  opts.validate();
  const auto n = static_cast<std::uint32_t>(sc.robots.size());
  const double wall0 = steady_s();
  dds_entity_t domain = 0;
  const dds_entity_t participant = participant_for(o.link, domain);
  struct Closer {
    dds_entity_t p, d;
    ~Closer() {
      dds_delete(p);
      if (d > 0) dds_delete(d);
    }
  } closer{participant, domain};
  ControlLink link(participant, o.link.partition, true);
  std::map<std::uint32_t, ReportMsg> last;  // newest report per robot
  std::vector<std::uint8_t> alive(n, 1);
  std::vector<std::uint32_t> dead;
  auto collect = [&](double timeout_s, const std::function<bool()>& enough) {
    const double deadline = steady_s() + timeout_s;
    for (;;) {
      for (auto& r : link.take_reports()) {
        if (r.id >= n) {
          log()->error("report from robot {} (the scenario has {})", r.id, n);
          continue;
        }
        auto it = last.find(r.id);
        if (it == last.end() || r.kind == kFinal || r.kind == kFailedReport ||
            r.step >= it->second.step)
          last[r.id] = r;
      }
      if (enough()) return true;
      if (steady_s() >= deadline) return false;
      link.wait(0.02);
    }
  };
  auto has = [&](std::uint32_t j, std::uint8_t kind, std::uint32_t step) {
    auto it = last.find(j);
    if (it == last.end()) return false;
    if (it->second.kind == kFinal || it->second.kind == kFailedReport) return kind <= kFinal;
    return it->second.kind >= kind && it->second.step >= step;
  };
  auto declare_dead = [&](std::uint32_t j, const std::string& why) {
    if (!alive[j]) return;
    alive[j] = 0;
    dead.push_back(j);
    std::cerr << "voronav-world: robot " << j << " declared dead (" << why << ")\n";
  };
  std::uint32_t step = 0;  // the last step every live robot completed
  std::uint32_t resumed_at = 0;
  if (!o.resume) {
    const bool ok = collect(o.link.startup_timeout_s, [&] {
      for (std::uint32_t j = 0; j < n; ++j)
        if (!has(j, kReady, 0)) return false;
      return link.matched_readers() >= n;
    });
    if (!ok) {
      std::size_t ready = 0;
      for (std::uint32_t j = 0; j < n; ++j)
        ready += has(j, kReady, 0) ? 1 : 0;
      std::cerr << "voronav-world: " << ready << " of " << n << " robots ready after "
                << o.link.startup_timeout_s << " s\n";
      TickMsg stop;
      stop.stop = true;
      stop.alive = alive;
      stop.seq.assign(n, 0);
      link.write(stop);
      link.flush(1.0);
      return kExitNoPeers;
    }
    TickMsg t0;
    t0.step = 0;
    t0.alive = alive;
    t0.seq.assign(n, 0);
    link.write(t0);
    collect(o.link.step_timeout_s, [&] {
      for (std::uint32_t j = 0; j < n; ++j)
        if (alive[j] && !has(j, kDone, 0)) return false;
      return true;
    });
    for (std::uint32_t j = 0; j < n; ++j)
      if (!has(j, kDone, 0)) declare_dead(j, "no report of the start");
  } else {
    // Take over: every robot's last report (transient-local), those silent are dead.
    collect(o.link.step_timeout_s, [&] { return last.size() == n && link.matched_readers() >= n; });
    std::uint32_t top = 0;
    for (std::uint32_t j = 0; j < n; ++j) {
      if (!last.count(j) || last[j].kind == kFailedReport || last[j].kind == kFinal)
        declare_dead(j, "no report when the world resumed");
      else
        top = std::max(top, last[j].step);
    }
    // Robots one step behind still need Tick `top`; then everyone is at `top`.
    bool behind = false;
    for (std::uint32_t j = 0; j < n; ++j)
      if (alive[j] && last[j].step + 1 == top) behind = true;
    step = behind ? top - 1 : top;
    resumed_at = step;
    std::cerr << "voronav-world: resuming after step " << step << "\n";
  }
  const int steps = static_cast<int>(std::ceil(opts.time_limit_s / opts.dt_s));
  const auto source = static_cast<std::uint32_t>(sc.source);
  auto source_arrived = [&] { return last.count(source) && last[source].arrived; };
  while (static_cast<int>(step) < steps && alive[source] && !source_arrived()) {
    const std::uint32_t k = step + 1;
    TickMsg t;
    t.step = k;
    t.alive = alive;
    t.seq.assign(n, 0);
    std::uint32_t applied = 0;
    for (std::uint32_t j = 0; j < n; ++j) {
      if (!alive[j]) continue;
      const auto& r = last[j];
      // Its last payload by the end of step k-1.
      t.seq[j] = r.step >= k ? r.prev_seq : r.seq;
      applied = std::max(applied, r.changes_applied);
    }
    t.first_route_s = last[source].route_time_s;
    for (std::size_t c : sim::changes_due(sc, t.first_route_s, k * opts.dt_s, applied))
      t.changes.push_back(static_cast<std::uint32_t>(c));
    link.write(t);
    if (o.die_at_step && *o.die_at_step == k) {
      link.flush(1.0);
      std::cerr << "voronav-world: killing itself after tick " << k << " (fault injection)\n";
      die_now();
    }
    const bool all = collect(o.link.step_timeout_s, [&] {
      for (std::uint32_t j = 0; j < n; ++j)
        if (alive[j] && !has(j, kDone, k)) return false;
      return true;
    });
    if (!all)
      for (std::uint32_t j = 0; j < n; ++j)
        if (alive[j] && !has(j, kDone, k))
          declare_dead(j, "no report of step " + std::to_string(k) + " within " +
                              std::to_string(o.link.step_timeout_s) + " s");
    step = k;
    if (std::count(alive.begin(), alive.end(), 1) == 0) {
      std::cerr << "voronav-world: no robot left\n";
      return kExitRobotsLost;
    }
  }
  TickMsg stop;
  stop.step = step + 1;
  stop.stop = true;
  stop.alive = alive;
  stop.seq.assign(n, 0);
  link.write(stop);
  collect(o.link.step_timeout_s + 5.0, [&] {
    for (std::uint32_t j = 0; j < n; ++j)
      if (alive[j] && !(last.count(j) && last[j].kind == kFinal)) return false;
    return true;
  });
  std::vector<sim::AgentReport> reports(n);
  json per_robot = json::array();
  for (std::uint32_t j = 0; j < n; ++j) {
    if (!(last.count(j) && last[j].kind == kFinal)) {
      if (alive[j]) declare_dead(j, "no final report");
      continue;
    }
    try {
      const json rj = json::parse(last[j].detail);
      reports[j] = agent_report_from(rj);
      per_robot.push_back(rj);
    } catch (const json::exception& e) {
      std::cerr << "voronav-world: malformed final report of robot " << j << ": " << e.what()
                << "\n";
      declare_dead(j, "malformed final report");
    }
  }
  auto m = sim::aggregate_metrics(reports, sc.source, opts.method);
  m.simulated_s = step * opts.dt_s;
  m.wall_s = steady_s() - wall0;
  std::sort(dead.begin(), dead.end());
  const json out = {{"metrics", json::parse(metrics_to_json(m))},
                    {"dead", dead},
                    {"steps", step},
                    {"resumed_at", resumed_at},
                    {"robots", per_robot}};
  std::cout << out.dump() << "\n";
  return kExitOk;
}

// ---- the launcher -----------------------------------------------------------------------------
DdsRunResult run_netsim_dds(const DdsRunOptions& o) {
  if (o.scenario_path.empty()) throw Error("scenario", 0, "a scenario file is required");
  o.link.validate();
  if (!(o.timeout_s > 0.0) || !std::isfinite(o.timeout_s))
    throw Error("--dds-timeout", 0, "expected a positive finite number of seconds");
  if (!(o.loss >= 0.0 && o.loss <= 1.0))
    throw Error("--loss", 0, "expected a probability in [0, 1]");
  const auto file = sim::load_netsim_scenario(o.scenario_path);  // errors before any process
  const auto n = static_cast<std::uint32_t>(file.scenario.robots.size());
  if (n + 1 > 110)
    throw Error("scenario", 0,
                std::to_string(n) +
                    " robots: at most 109 robot processes per machine (the "
                    "loopback config has 120 participant slots)");
  if (o.kill_robot && *o.kill_robot >= n) throw Error("--kill-robot", 0, "no such robot");
  const double t0 = steady_s();
  const fs::path dir = o.work_dir.empty() ? fs::temp_directory_path() : fs::path(o.work_dir);
  fs::create_directories(dir);
  static int counter = 0;
  const std::string tag = std::to_string(::getpid()) + "-" + std::to_string(++counter);
  const fs::path config = dir / ("voronav-netsim-" + tag + ".xml");
  write_cyclone_config(config, CycloneConfigOptions{});
  struct Remove {
    fs::path p;
    ~Remove() {
      std::error_code ec;
      fs::remove(p, ec);
    }
  } remove{config};
  const std::uint32_t domain =
      o.domain_id.value_or(1 + static_cast<std::uint32_t>(::getpid()) % 200);
  const std::string partition = "netsim-" + tag;
  std::vector<std::string> cmd = o.command;
  if (cmd.empty()) cmd = {self_executable()};
  auto common = [&](std::vector<std::string> a) {
    for (auto s : {std::string("--scenario"), o.scenario_path, std::string("--domain"),
                   std::to_string(domain), std::string("--partition"), partition,
                   std::string("--startup-timeout"), std::to_string(o.link.startup_timeout_s),
                   std::string("--step-timeout"), std::to_string(o.link.step_timeout_s)})
      a.push_back(s);
    return a;
  };
  auto spec = [&](const std::string& name, std::vector<std::string> args) {
    ChildSpec s;
    s.name = name;
    s.argv = cmd;
    s.argv.insert(s.argv.end(), args.begin(), args.end());
    s.env["CYCLONEDDS_URI"] = cyclone_uri_for(config);
    return s;
  };
  LaunchOptions lo;
  lo.timeout_s = o.timeout_s;
  ProcessGroup group(lo);
  auto world_args = [&](bool resume) {
    auto a = common({"netsim-world"});
    if (resume) a.push_back("--resume");
    if (!resume && o.world_restart_at_step) {
      a.push_back("--die-at-step");
      a.push_back(std::to_string(*o.world_restart_at_step));
    }
    return a;
  };
  std::size_t world = group.start(spec("world", world_args(false)));
  for (std::uint32_t i = 0; i < n; ++i) {
    auto a = common({"robot", "--id", std::to_string(i), "--transport", "dds"});
    if (o.loss > 0.0) {
      a.push_back("--loss");
      a.push_back(std::to_string(o.loss));
    }
    if (o.kill_robot && *o.kill_robot == i) {
      a.push_back("--die-at-step");
      a.push_back(std::to_string(o.kill_at_step));
    }
    group.start(spec("robot " + std::to_string(i), a));
  }
  DdsRunResult res;
  const double deadline = t0 + o.timeout_s;
  for (;;) {
    const bool none = group.poll(0.05);
    if (!group.running(world)) {
      const auto& err = group.stderr_so_far(world);
      const bool injected = err.find("(fault injection)") != std::string::npos;
      if (injected && res.world_restarts == 0 && group.stdout_so_far(world).empty()) {
        ++res.world_restarts;
        world = group.start(spec("world (resumed)", world_args(true)));
        continue;
      }
    }
    if (none || steady_s() >= deadline) break;
  }
  res.children = group.wait_all();
  res.wall_s = steady_s() - t0;
  const auto& w = res.children[world];
  if (!w.ok()) {
    res.error = "world process: " + std::string(to_string(w.status)) + " (exit " +
                std::to_string(w.exit_code) + "): " + w.stderr_text.substr(0, 2000);
    return res;
  }
  try {
    const json j = json::parse(w.stdout_text);
    res.metrics = metrics_from_json(j.at("metrics").dump());
    res.dead = j.at("dead").get<std::vector<std::uint32_t>>();
    res.steps = j.at("steps").get<std::uint32_t>();
  } catch (const std::exception& e) {
    res.error = std::string("world process output: ") + e.what();
    return res;
  }
  res.ok = true;
  for (std::size_t i = 0; i < res.children.size(); ++i) {
    if (i == world) continue;
    const auto& c = res.children[i];
    const bool injected_kill = c.status == ChildStatus::kSignaled && c.signal == SIGKILL;
    if (!c.ok() && !injected_kill && c.name.rfind("world", 0) != 0) {
      res.ok = false;
      res.error += c.name + ": " + std::string(to_string(c.status)) + " (exit " +
                   std::to_string(c.exit_code) + ") " + c.stderr_text.substr(0, 500) + "\n";
    }
  }
  return res;
}

}  // namespace voronav::dds
