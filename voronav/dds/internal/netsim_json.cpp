#include "voronav/dds/internal/netsim_json.hpp"

namespace voronav::dds::internal {

using nlohmann::json;

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

void put_repair_trace(json& j, const sim::SourceRepairTrace& t) {
  sim::SourceRepairTrace::fields([&](const char* name, auto member) { j[name] = t.*member; });
}

void get_repair_trace(const json& j, sim::SourceRepairTrace& t) {
  sim::SourceRepairTrace::fields([&](const char* name, auto member) {
    t.*member = j.value(name, 0);  // absent in files written before the counter existed
  });
}

json agent_report_json(const sim::AgentReport& a) {
  json j = {{"metrics", robot_metrics_json(a.metrics)},
            {"search_attempts", a.search_attempts},
            {"repairs", a.repairs},
            {"replans", a.replans},
            {"corrupt_packets", a.corrupt_packets},
            {"arrived", a.arrived},
            {"route_time_s", a.route_time_s},
            {"arrival_time_s", a.arrival_time_s},
            {"route_length_m", a.route_length_m},
            {"found_by", std::string(sim::to_string(a.found_by))},
            {"route_robots", a.route_robots},
            {"paths_lost", a.paths_lost},
            {"paths_unacknowledged", a.paths_unacknowledged},
            {"paths_late", a.paths_late},
            {"repairs_executed", a.repairs_executed},
            {"repair_requests", a.repair_requests},
            {"repair_answers", a.repair_answers},
            {"changes_on_route", a.changes_on_route},
            {"point_searches", a.point_searches},
            {"search_copies_ignored", a.search_copies_ignored},
            {"sensing_walks", a.sensing_walks},
            {"sensing_walk_m", a.sensing_walk_m},
            {"repair_sense_walks", a.repair_sense_walks},
            {"repair_sense_walk_m", a.repair_sense_walk_m},
            {"repair_sense_answers", a.repair_sense_answers},
            {"route_used_sensing", a.route_used_sensing}};
  put_repair_trace(j, a);
  return j;
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
  a.found_by = sim::parse_route_found_by(j.at("found_by").get<std::string>());
  a.route_robots = j.at("route_robots").get<int>();
  a.paths_lost = j.at("paths_lost").get<int>();
  a.paths_unacknowledged = j.value("paths_unacknowledged", 0);
  a.paths_late = j.value("paths_late", 0);
  a.repairs_executed = j.at("repairs_executed").get<int>();
  a.repair_requests = j.value("repair_requests", 0);
  a.repair_answers = j.value("repair_answers", 0);
  get_repair_trace(j, a);
  a.changes_on_route = j.at("changes_on_route").get<int>();
  a.point_searches = j.value("point_searches", 0);
  a.search_copies_ignored = j.value("search_copies_ignored", 0);
  a.sensing_walks = j.value("sensing_walks", 0);
  a.sensing_walk_m = j.value("sensing_walk_m", 0.0);
  a.repair_sense_walks = j.value("repair_sense_walks", 0);
  a.repair_sense_walk_m = j.value("repair_sense_walk_m", 0.0);
  a.repair_sense_answers = j.value("repair_sense_answers", 0);
  a.route_used_sensing = j.value("route_used_sensing", false);
  return a;
}

}  // namespace voronav::dds::internal
