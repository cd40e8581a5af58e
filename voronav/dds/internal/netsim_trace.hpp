// What the processes of a multi-process netsim run actually did (issue #19): each robot process
// appends one JSON line per step to its trace file (its pose, the messages it sent and the route
// breaks it handled: Repair asked or executed), the world
// process one line per fault or obstacle change; read_netsim_traces() joins them into the
// sim::Recording the in-process run would have made, so the replay page and the ROS 2 bag show the
// DDS run itself (not an in-process re-run). Lines are flushed at once, so a killed process leaves
// its trace up to the step it died. Not installed (netsim_dds.hpp).
#pragma once

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "voronav/core/vec2.hpp"
#include "voronav/dds/netsim_dds.hpp"
#include "voronav/sim/netsim.hpp"

namespace voronav::dds::internal {

/// Appends JSON lines to a file (nothing when the path is empty).
class TraceFile {
 public:
  explicit TraceFile(const std::string& path);
  [[nodiscard]] bool on() const { return on_; }
  /// Robot: its pose at step k (time t), the messages it sent and the route breaks it handled
  /// (Repair asked or executed) since the last line.
  void robot_step(std::uint32_t k, double t, Vec2 p, const std::vector<sim::RecordedMessage>& sent,
                  const std::vector<sim::RecordedRepair>& repairs = {});
  /// Robot: the source's route at the end [m].
  void robot_route(const std::vector<Vec2>& route);
  /// World: an event (DdsEvent's fields).
  void event(const DdsEvent& e);

 private:
  void line(const std::string& s);
  std::ofstream f_;
  bool on_ = false;
};

/// Reads the trace files of `robots` robot processes and the world's. Steps: one per step any
/// robot reported, every robot at its last reported pose (a dead robot stays where it died).
/// Malformed lines (a process killed mid-write) are skipped.
void read_netsim_traces(const std::vector<std::string>& robot_files, const std::string& world_file,
                        const sim::NetSimScenario& scenario, sim::Recording& recording,
                        std::vector<DdsEvent>& events);

}  // namespace voronav::dds::internal
