// The networked-robot run of seed 000 with every robot its own process over Cyclone DDS (issue
// #8): `voronav robot` runs one sim::RobotAgent (its sensing and its share of the protocol) with a
// DdsTransport; `voronav netsim-world` is the world process (the clock, the obstacle changes, who
// is alive, the metrics); run_netsim_dds() launches them all and returns the same metrics as the
// in-process run (sim::run_netsim).
//
// Lockstep: the world process publishes Tick k once every live robot reported step k-1; each
// robot then runs the RobotAgent step (robot_agent.hpp): move, publish its pose stamped t_k and
// send what the move held back, wait for every live robot's pose of t_k and for every payload they
// sent up to step k-1 (the Tick says how many, by sequence number), hand those over in (send time,
// sender) order, communicate, apply the changes the Tick names, report. Range is checked with the
// poses at send time (DdsTransportOptions::range_at_send_time). With no loss, the same scenario
// gives the same route, the same messages and the same bytes as the simulated radio.
//
// Faults: a robot that does not report within `step_timeout_s` is declared dead (the others stop
// waiting for it; the protocol's retries and new Searches route around it); a robot that hears no
// Tick for `world_timeout_s` exits with kExitWorldLost; a restarted world (`resume`) takes the
// robots' last reports (transient-local) and goes on from there. Every wait has a timeout and
// every process exits with one of the statuses below.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "voronav/dds/process_launcher.hpp"
#include "voronav/sim/netsim.hpp"

namespace voronav::dds {

/// Exit statuses of the robot and world processes.
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailed = 1;        ///< an error (message on stderr)
inline constexpr int kExitUsage = 2;         ///< bad arguments or scenario
inline constexpr int kExitNoPeers = 3;       ///< discovery did not complete in time
inline constexpr int kExitWorldLost = 4;     ///< robot: no Tick for world_timeout_s
inline constexpr int kExitRobotsLost = 5;    ///< world: no robot reports any more
inline constexpr int kExitInjectedKill = 9;  ///< never returned: the process SIGKILLs itself

/// What the world process and the robots share to find each other.
struct LockstepLink {
  std::uint32_t domain_id = 0;
  std::string partition = "voronav-netsim";
  /// Cyclone config XML; empty = CYCLONEDDS_URI (set by the launcher) or Cyclone's defaults.
  std::string config_xml;
  double startup_timeout_s = 60.0;  ///< discovery of every process [s]
  double step_timeout_s = 10.0;     ///< world: a robot silent this long in one step is dead [s]
  double world_timeout_s = 30.0;    ///< robot: no Tick this long, the world is lost [s]
  double payload_timeout_s = 2.0;   ///< robot: wait this long for the packets a Tick announces [s]
  /// Throws voronav::Error naming the option (--domain, --step-timeout, ...) that is wrong.
  void validate() const;
};

struct RobotProcessOptions {
  std::uint32_t id = 0;
  std::string scenario_path;  ///< a netsim scenario file (sim/scenario_file.hpp)
  LockstepLink link;
  double loss = 0.0;  ///< injected at this robot's transport (receptions dropped) [0, 1]
  /// Fault injection: after reporting this step the process kills itself (SIGKILL).
  std::optional<std::uint32_t> die_at_step;
  /// When set, one JSON line per step is appended here: the pose and the messages sent
  /// (read back by run_netsim_dds with DdsRunOptions::record).
  std::string trace_path;
};

/// Runs one robot; returns the exit status. Prints its final report (JSON) on stdout, progress
/// and errors on stderr.
int run_robot_process(const RobotProcessOptions& options);

struct WorldProcessOptions {
  std::string scenario_path;
  LockstepLink link;
  /// Take over a run whose world process died: start from the robots' last reports.
  bool resume = false;
  /// Fault injection: after publishing this step's Tick the process kills itself (SIGKILL).
  std::optional<std::uint32_t> die_at_step;
  /// When set, one JSON line per event (robot declared dead, obstacle change, world restart)
  /// is appended here.
  std::string trace_path;
};

/// Runs the world process; returns the exit status. Prints the run's result (JSON: "metrics" as
/// sim::NetSimMetrics, "dead", "steps", "resumed_at") on stdout.
int run_world_process(const WorldProcessOptions& options);

/// Something that happened in a multi-process run, as the processes saw it.
struct DdsEvent {
  double t_s = 0.0;         ///< simulated time [s]
  std::uint32_t step = 0;   ///< lockstep step
  std::string kind;         ///< "killed", "dead", "change", "world_killed", "world_resumed"
  std::int64_t robot = -1;  ///< the robot concerned (-1: none)
  std::string detail;       ///< in words
};

struct DdsRunOptions {
  std::string scenario_path;
  /// Program and leading arguments of the CLI (default: this executable): the robots run as
  /// `<command> robot ...`, the world as `<command> netsim-world ...`.
  std::vector<std::string> command;
  LockstepLink link;
  double loss = 0.0;
  /// Fault injection: robot `kill_robot` dies after step `kill_at_step`.
  std::optional<std::uint32_t> kill_robot;
  std::uint32_t kill_at_step = 0;
  /// Fault injection: the world process dies after this step and a new one resumes the run.
  std::optional<std::uint32_t> world_restart_at_step;
  double timeout_s = 900.0;  ///< for the whole run [s]
  std::string work_dir;      ///< for the generated Cyclone config; default: the temp directory
  /// DDS domain; default derived from the process id (parallel runs do not meet).
  std::optional<std::uint32_t> domain_id;
  /// Record what the processes did (trace files in work_dir): DdsRunResult::recording/events.
  bool record = false;
};

struct DdsRunResult {
  bool ok = false;  ///< every process exited as expected and the world reported
  sim::NetSimMetrics metrics;
  std::vector<std::uint32_t> dead;  ///< robots the world declared dead
  int world_restarts = 0;
  std::uint32_t steps = 0;
  double wall_s = 0.0;
  std::string error;  ///< why not ok
  std::vector<ChildResult> children;
  /// With DdsRunOptions::record: every robot's pose per step, the messages each sent, the
  /// source's final route (as sim::NetSimOptions::record gives in process).
  sim::Recording recording;
  /// Faults and obstacle changes in step order (with record; "killed" is always there when
  /// a robot kill was injected).
  std::vector<DdsEvent> events;
};

/// Launches the world and one process per robot of the scenario and collects the result. Never
/// hangs (bounded by timeout_s). Throws voronav::Error for bad options.
[[nodiscard]] DdsRunResult run_netsim_dds(const DdsRunOptions& options);

/// sim::NetSimMetrics as the JSON object the CLI prints (also read back by run_netsim_dds).
[[nodiscard]] std::string metrics_to_json(const sim::NetSimMetrics& m);
[[nodiscard]] sim::NetSimMetrics metrics_from_json(const std::string& json);

}  // namespace voronav::dds
