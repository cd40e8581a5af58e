// The lockstep options and the metrics JSON of the multi-process netsim run (netsim_dds.hpp).
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
#include "voronav/sim/robot_agent.hpp"
#include "voronav/sim/scenario_file.hpp"

namespace voronav::dds {

using nlohmann::json;
namespace fs = std::filesystem;
using namespace internal;

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
  json j = {{"success", m.success},
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
            {"route_found_by", std::string(sim::to_string(m.route_found_by))},
            {"route_robots", m.route_robots},
            {"paths_lost", m.paths_lost},
            {"paths_unacknowledged", m.paths_unacknowledged},
            {"paths_late", m.paths_late},
            {"repairs_executed", m.repairs_executed},
            {"repair_requests", m.repair_requests},
            {"source_repair_requests", m.source_repair_requests},
            {"repair_answers", m.repair_answers},
            {"changes_on_route", m.changes_on_route},
            {"changes_applied", m.changes_applied},
            {"point_searches", m.point_searches},
            {"search_copies_ignored", m.search_copies_ignored},
            {"sensing_walks", m.sensing_walks},
            {"sensing_walk_m", m.sensing_walk_m},
            {"repair_sense_walks", m.repair_sense_walks},
            {"repair_sense_walk_m", m.repair_sense_walk_m},
            {"repair_sense_answers", m.repair_sense_answers},
            {"route_used_sensing", m.route_used_sensing},
            {"relay_travel_m", m.relay_travel_m},
            {"simulated_s", m.simulated_s},
            {"wall_s", m.wall_s},
            {"robots", robots}};
  put_repair_trace(j, m);
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
    m.route_found_by = sim::parse_route_found_by(j.at("route_found_by").get<std::string>());
    m.route_robots = j.at("route_robots").get<int>();
    m.paths_lost = j.at("paths_lost").get<int>();
    m.paths_unacknowledged = j.value("paths_unacknowledged", 0);
    m.paths_late = j.value("paths_late", 0);
    m.repairs_executed = j.at("repairs_executed").get<int>();
    m.repair_requests = j.value("repair_requests", 0);
    m.source_repair_requests = j.value("source_repair_requests", 0);
    m.repair_answers = j.value("repair_answers", 0);
    get_repair_trace(j, m);
    m.changes_on_route = j.at("changes_on_route").get<int>();
    m.changes_applied = j.at("changes_applied").get<int>();
    m.point_searches = j.value("point_searches", std::uint64_t{0});
    m.search_copies_ignored = j.value("search_copies_ignored", std::uint64_t{0});
    m.sensing_walks = j.value("sensing_walks", 0);
    m.sensing_walk_m = j.value("sensing_walk_m", 0.0);
    m.repair_sense_walks = j.value("repair_sense_walks", 0);
    m.repair_sense_walk_m = j.value("repair_sense_walk_m", 0.0);
    m.repair_sense_answers = j.value("repair_sense_answers", 0);
    m.route_used_sensing = j.value("route_used_sensing", false);
    m.relay_travel_m = j.at("relay_travel_m").get<double>();
    m.simulated_s = j.at("simulated_s").get<double>();
    m.wall_s = j.at("wall_s").get<double>();
    for (const auto& r : j.at("robots"))
      m.robots.push_back(robot_metrics_from(r));
    return m;
  } catch (const json::exception& e) {
    throw Error("metrics", 0, std::string("malformed metrics JSON: ") + e.what());
  }
}

}  // namespace voronav::dds
