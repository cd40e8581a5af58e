// ProcessGroup: starts N child processes (fork/exec), captures each one's stdout (its JSON report)
// and stderr, enforces one deadline for the whole group, kills a child on demand (fault tests:
// a robot process dies mid-run) and reaps every child, so a multi-process run never hangs and
// every process ends with a clear status. Used by `voronav dds-selftest` and meant for the
// one-process-per-robot launcher of the networked-robots issue (`voronav netsim --transport dds`).
// POSIX only (fork, execve, poll, waitpid).
#pragma once

#include <sys/types.h>
#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace voronav::dds {

struct ChildSpec {
  std::string name;               ///< label in results and logs
  std::vector<std::string> argv;  ///< argv[0] is the executable path (no PATH search)
  /// Extra or overriding environment variables; the rest of the parent's environment is kept.
  std::map<std::string, std::string> env;
  /// Kill the child (SIGKILL) this long after start [s]; <= 0 = never.
  double kill_after_s = 0.0;
  /// Kill the child (SIGKILL) as soon as its stdout or stderr contains this text; empty = never.
  std::string kill_on_output;
};

struct LaunchOptions {
  /// Deadline for the whole group [s]: children still running then are killed (kTimedOut).
  double timeout_s = 60.0;
  /// Between SIGTERM and SIGKILL when a child is stopped at the deadline [s].
  double term_grace_s = 0.5;
  /// Output kept per stream and child [bytes]; the rest is discarded (and flagged).
  std::size_t max_output_bytes = 16u << 20;
};

enum class ChildStatus {
  kExited,         ///< exited by itself; see exit_code
  kSignaled,       ///< died of a signal nobody in the group sent
  kKilled,         ///< killed on request (kill(), kill_after_s, kill_on_output)
  kTimedOut,       ///< still running at the group deadline, then killed
  kFailedToStart,  ///< exec failed (error in stderr_text)
};
[[nodiscard]] std::string_view to_string(ChildStatus s);

struct ChildResult {
  std::string name;
  pid_t pid = -1;
  ChildStatus status = ChildStatus::kFailedToStart;
  int exit_code = -1;  ///< when kExited
  int signal = 0;      ///< when killed or signaled
  std::string stdout_text;
  std::string stderr_text;
  bool output_truncated = false;
  double wall_s = 0.0;  ///< from start to exit [s]

  [[nodiscard]] bool ok() const { return status == ChildStatus::kExited && exit_code == 0; }
};

class ProcessGroup {
 public:
  explicit ProcessGroup(LaunchOptions options = {});
  /// Kills (SIGKILL) and reaps every child still running.
  ~ProcessGroup();
  ProcessGroup(const ProcessGroup&) = delete;
  ProcessGroup& operator=(const ProcessGroup&) = delete;

  /// Starts a child; returns its index. Throws voronav::Error for an empty argv. An executable
  /// that cannot be run gives a child with kFailedToStart, not an exception.
  std::size_t start(ChildSpec spec);
  /// Sends SIGKILL to child `index` now (no effect once it has exited); result status kKilled.
  void kill(std::size_t index);
  [[nodiscard]] bool running(std::size_t index) const;
  /// What child `index` wrote so far (e.g. to act on a progress line).
  [[nodiscard]] const std::string& stdout_so_far(std::size_t index) const;
  [[nodiscard]] const std::string& stderr_so_far(std::size_t index) const;
  [[nodiscard]] std::size_t size() const;
  /// Collects output and exits for at most `timeout_s` [s] (and never past the group deadline);
  /// returns true when no child is running any more.
  bool poll(double timeout_s);
  /// Runs poll() until every child has exited or the group deadline passed (then stops the rest);
  /// `on_tick` is called between polls (e.g. to kill a child at a chosen moment).
  std::vector<ChildResult> wait_all(const std::function<void(ProcessGroup&)>& on_tick = {});

 private:
  struct Child;
  void reap(Child& c, int wstatus);
  void read_some(Child& c, int fd, std::string& into);
  void stop_all(ChildStatus why);
  LaunchOptions options_;
  double start_s_;
  std::vector<Child> children_;
};

/// Convenience: starts every spec, waits (ProcessGroup::wait_all) and returns the results in order.
[[nodiscard]] std::vector<ChildResult> run_processes(std::vector<ChildSpec> specs,
                                                     const LaunchOptions& options = {});

/// Path of the running executable (/proc/self/exe), for launching copies of oneself.
[[nodiscard]] std::string self_executable();

}  // namespace voronav::dds
