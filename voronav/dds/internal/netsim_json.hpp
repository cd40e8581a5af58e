// JSON of one robot's metrics (sim::RobotMetrics, sim::AgentReport) as the robot processes of
// the multi-process netsim run send them to the world process in their final report (not
// installed; netsim_dds.hpp).
#pragma once

#include <nlohmann/json.hpp>

#include "voronav/sim/robot_agent.hpp"

namespace voronav::dds::internal {

[[nodiscard]] nlohmann::json robot_metrics_json(const sim::RobotMetrics& m);
/// Throws nlohmann::json::exception on a missing or mistyped field.
[[nodiscard]] sim::RobotMetrics robot_metrics_from(const nlohmann::json& j);
/// Adds / reads the source's Repair counters (every field of sim::SourceRepairTrace, by name; a
/// missing one reads as 0).
void put_repair_trace(nlohmann::json& j, const sim::SourceRepairTrace& t);
void get_repair_trace(const nlohmann::json& j, sim::SourceRepairTrace& t);
[[nodiscard]] nlohmann::json agent_report_json(const sim::AgentReport& a);
/// Throws nlohmann::json::exception on a missing or mistyped field.
[[nodiscard]] sim::AgentReport agent_report_from(const nlohmann::json& j);

}  // namespace voronav::dds::internal
