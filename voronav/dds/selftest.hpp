// Multi-process checks of the DDS transport, with robots as separate processes (issue #8):
//  - run_echo(): one participant (robot `id` of `peers`) on a line of robots, `spacing_m` apart;
//    it publishes its pose, waits for the others, sends `rounds` broadcasts and `rounds` directed
//    messages to robot (id + 1) mod peers, and reports what it received (JSON on stdout);
//  - run_selftest(): launches `processes` echo processes (ProcessGroup), optionally kills one
//    mid-run and injects loss, and checks that every in-range message arrived exactly once,
//    nothing arrived from beyond range and no process hung.
// This is the machinery the one-process-per-robot run of the decentralized protocol (seed 000)
// reuses: the same launcher, config and transport, with the protocol in place of the echo.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "voronav/dds/process_launcher.hpp"

namespace voronav::dds {

struct EchoOptions {
  std::uint32_t id = 0;
  std::uint32_t peers = 2;         ///< robots 0..peers-1 take part (>= 2)
  int rounds = 5;                  ///< broadcasts and directed messages each robot sends (>= 1)
  double interval_s = 0.02;        ///< pause between rounds [s] (0 = as fast as possible)
  std::size_t payload_bytes = 64;  ///< size of each test payload [bytes] (>= 16)
  double spacing_m = 10.0;         ///< robot i stands at (i * spacing_m, 0) [m]
  double range_m = 25.0;           ///< radio range [m]; infinity = everyone hears everyone
  double loss = 0.0;               ///< injected loss probability at the receiver [0, 1]
  std::uint64_t seed = 1;
  std::uint32_t domain_id = 0;
  std::string partition = "voronav-echo";
  /// Cyclone config XML; empty = CYCLONEDDS_URI (as set by the selftest) or Cyclone defaults.
  std::string config_xml;
  int history_depth = 256;
  double startup_timeout_s = 10.0;  ///< wait for the other robots at most this long [s]
  double quiet_s = 1.0;             ///< after sending, stop when nothing arrived for this long [s]
  double timeout_s = 30.0;          ///< hard limit for the whole run [s]
};

/// Parses "--id 3 --peers 6 ..." (the flags of `voronav dds-echo`); throws voronav::Error.
[[nodiscard]] EchoOptions parse_echo_args(const std::vector<std::string>& args);
/// The flags that parse_echo_args() reads back to the same options (config_xml excluded).
[[nodiscard]] std::vector<std::string> echo_args(const EchoOptions& options);

/// Runs one echo participant; returns its JSON report (one line). Throws voronav::Error for bad
/// options. Progress lines go to stderr ("voronav-dds-echo <id>: round <r> sent").
[[nodiscard]] std::string run_echo(const EchoOptions& options);

struct SelftestOptions {
  std::uint32_t processes = 6;  ///< >= 2, <= 110 (participant indices of the loopback config)
  int rounds = 5;
  double interval_s = 0.02;
  std::size_t payload_bytes = 64;
  double spacing_m = 10.0;
  double range_m = 25.0;
  double loss = 0.0;
  std::uint64_t seed = 1;
  /// Robot whose process is killed (SIGKILL) after it sent its first round.
  std::optional<std::uint32_t> kill_id;
  /// DDS domain; default: derived from the process id (parallel selftests do not meet).
  std::optional<std::uint32_t> domain_id;
  double timeout_s = 60.0;  ///< for the whole group [s]
  double startup_timeout_s = 15.0;
  double quiet_s = 1.0;
  /// Program and leading arguments that run an echo participant; default: this executable
  /// with "dds-echo" (the voronav CLI).
  std::vector<std::string> echo_command;
  /// Directory for the generated Cyclone config; default: the system temp directory.
  std::string work_dir;
};

struct SelftestReport {
  bool passed = false;
  std::uint32_t processes = 0;
  double wall_s = 0.0;
  std::uint64_t expected = 0;   ///< in-range messages from senders that were not killed
  std::uint64_t delivered = 0;  ///< of those, delivered
  std::uint64_t out_of_range_delivered = 0;  ///< must be 0
  std::uint64_t duplicates = 0;              ///< must be 0
  std::uint64_t rejected = 0;                ///< malformed samples seen by the transports
  double latency_p50_ms = 0.0;               ///< median over receivers of their median latency
  double latency_p99_ms = 0.0;               ///< largest per-receiver 99th percentile
  double throughput_msgs_s = 0.0;       ///< payloads delivered per second, summed over receivers
  std::vector<std::string> violations;  ///< what failed, human-readable
  std::vector<ChildResult> children;
  std::string json;  ///< the whole report as JSON
};

/// Launches the echo processes, checks their reports and returns the verdict (never hangs:
/// bounded by timeout_s). Throws voronav::Error for bad options.
[[nodiscard]] SelftestReport run_selftest(const SelftestOptions& options);

}  // namespace voronav::dds
