// The lockstep control topics of the multi-process netsim run (netsim_dds.hpp; not installed):
// the world process writes Ticks ("start step k", who is alive, how many payloads each robot sent,
// which obstacle changes are due) and reads Reports; a robot the other way round. Both topics are
// reliable, keep-last 1 and transient-local (a restarted world reads every robot's last report).
// Malformed samples are logged and skipped.
#pragma once

#include <dds/dds.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace voronav::dds::internal {

/// Report kinds (IDL Report::kind).
inline constexpr std::uint8_t kReady = 1, kDone = 2, kFinal = 3, kFailedReport = 4;

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

/// Throws voronav::Error naming the Cyclone call when `e` is an error code.
dds_entity_t must(dds_entity_t e, const char* what);
/// Seconds to a Cyclone duration (>= 0).
dds_duration_t to_duration(double seconds);
/// The steady clock [s] (timeouts).
double steady_s();
/// Fault injection: flushes stdio and SIGKILLs this process (no clean-up, no goodbye).
[[noreturn]] void die_now();

class ControlLink {
 public:
  /// Endpoints on `participant` (a robot's DdsTransport participant, or the world's own) in
  /// `partition`; `world` selects the side.
  ControlLink(dds_entity_t participant, const std::string& partition, bool world);
  void write(const TickMsg& t);
  void write(const ReportMsg& r);
  /// Takes every available Tick; the newest valid one, if any (robot side).
  std::optional<TickMsg> take_tick();
  /// Takes every available Report (world side).
  std::vector<ReportMsg> take_reports();
  /// Waits until a sample is there or the timeout [s] passed.
  void wait(double timeout_s);
  /// Matched readers of our writer.
  [[nodiscard]] std::size_t matched_readers() const;
  /// Waits at most timeout_s [s] for our samples to be acknowledged.
  void flush(double timeout_s);

 private:
  template <typename Sample, typename F>
  void take_all(F&& on_sample);
  dds_entity_t writer_ = 0, reader_ = 0, waitset_ = 0;
};

}  // namespace voronav::dds::internal
