#include "voronav/dds/process_launcher.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <thread>

#include "voronav/core/error.hpp"

extern char** environ;

namespace voronav::dds {

std::string_view to_string(ChildStatus s) {
  switch (s) {
    case ChildStatus::kExited:
      return "exited";
    case ChildStatus::kSignaled:
      return "signaled";
    case ChildStatus::kKilled:
      return "killed";
    case ChildStatus::kTimedOut:
      return "timed_out";
    case ChildStatus::kFailedToStart:
      return "failed_to_start";
  }
  return "unknown";
}

namespace {
double now_s() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}
void close_fd(int& fd) {
  if (fd >= 0) ::close(fd);
  fd = -1;
}
}  // namespace

struct ProcessGroup::Child {
  ChildSpec spec;
  ChildResult result;
  int out_fd = -1;
  int err_fd = -1;
  bool running = false;
  bool kill_requested = false;
  ChildStatus kill_reason = ChildStatus::kKilled;
  double started_s = 0.0;
};

ProcessGroup::ProcessGroup(LaunchOptions options) : options_(options), start_s_(now_s()) {
  if (!(options_.timeout_s > 0.0) || !std::isfinite(options_.timeout_s))
    throw Error("timeout_s", 0, "expected a positive finite number of seconds");
  if (!(options_.term_grace_s >= 0.0) || !std::isfinite(options_.term_grace_s))
    throw Error("term_grace_s", 0, "expected a finite number of seconds >= 0");
}

ProcessGroup::~ProcessGroup() {
  for (auto& c : children_) {
    if (c.running) {
      ::kill(c.result.pid, SIGKILL);
      int ws = 0;
      while (::waitpid(c.result.pid, &ws, 0) < 0 && errno == EINTR) {
      }
      c.running = false;
    }
    close_fd(c.out_fd);
    close_fd(c.err_fd);
  }
}

std::size_t ProcessGroup::size() const {
  return children_.size();
}
bool ProcessGroup::running(std::size_t index) const {
  return index < children_.size() && children_[index].running;
}

const std::string& ProcessGroup::stdout_so_far(std::size_t index) const {
  if (index >= children_.size()) throw Error("index", 0, "no such child");
  return children_[index].result.stdout_text;
}
const std::string& ProcessGroup::stderr_so_far(std::size_t index) const {
  if (index >= children_.size()) throw Error("index", 0, "no such child");
  return children_[index].result.stderr_text;
}

std::size_t ProcessGroup::start(ChildSpec spec) {
  if (spec.argv.empty() || spec.argv[0].empty())
    throw Error("argv", 0, "expected the executable path as argv[0]");
  // Everything the child needs is prepared before fork(): between fork and exec only
  // async-signal-safe calls are allowed (the parent may have other threads, e.g. Cyclone's).
  std::vector<std::string> env_strings;
  for (char** e = environ; e != nullptr && *e != nullptr; ++e) {
    std::string kv(*e);
    const auto eq = kv.find('=');
    if (eq != std::string::npos && spec.env.count(kv.substr(0, eq)) != 0) continue;
    env_strings.push_back(std::move(kv));
  }
  for (const auto& [k, v] : spec.env)
    env_strings.push_back(k + "=" + v);
  std::vector<char*> envp;
  for (auto& s : env_strings)
    envp.push_back(s.data());
  envp.push_back(nullptr);
  std::vector<std::string> args = spec.argv;
  std::vector<char*> argv;
  for (auto& s : args)
    argv.push_back(s.data());
  argv.push_back(nullptr);

  int out_pipe[2], err_pipe[2], exec_pipe[2];
  if (::pipe2(out_pipe, O_CLOEXEC) != 0) throw Error("pipe2", 0, std::strerror(errno));
  if (::pipe2(err_pipe, O_CLOEXEC) != 0) {
    ::close(out_pipe[0]);
    ::close(out_pipe[1]);
    throw Error("pipe2", 0, std::strerror(errno));
  }
  if (::pipe2(exec_pipe, O_CLOEXEC) != 0) {
    for (int fd : {out_pipe[0], out_pipe[1], err_pipe[0], err_pipe[1]})
      ::close(fd);
    throw Error("pipe2", 0, std::strerror(errno));
  }

  Child c;
  c.spec = std::move(spec);
  c.result.name = c.spec.name;
  c.started_s = now_s();
  const pid_t pid = ::fork();
  if (pid < 0) {
    for (int fd : {out_pipe[0], out_pipe[1], err_pipe[0], err_pipe[1], exec_pipe[0], exec_pipe[1]})
      ::close(fd);
    throw Error("fork", 0, std::strerror(errno));
  }
  if (pid == 0) {
    // Child: stdin from /dev/null, stdout/stderr into the pipes, then exec.
    const int devnull = ::open("/dev/null", O_RDONLY);
    if (devnull >= 0) ::dup2(devnull, 0);
    ::dup2(out_pipe[1], 1);
    ::dup2(err_pipe[1], 2);
    // Do not leak the parent's descriptors (e.g. DDS sockets bound to discovery ports); the
    // exec-error pipe is kept open (it is close-on-exec).
    if (exec_pipe[1] > 3) ::close_range(3, static_cast<unsigned>(exec_pipe[1]) - 1, 0);
    ::close_range(static_cast<unsigned>(exec_pipe[1]) + 1, ~0U, 0);
    ::execve(argv[0], argv.data(), envp.data());
    const int err = errno;
    ssize_t ignored = ::write(exec_pipe[1], &err, sizeof err);
    (void)ignored;
    ::_exit(127);
  }
  ::close(out_pipe[1]);
  ::close(err_pipe[1]);
  ::close(exec_pipe[1]);
  c.result.pid = pid;
  c.out_fd = out_pipe[0];
  c.err_fd = err_pipe[0];
  c.running = true;
  // exec_pipe closes on a successful exec (CLOEXEC) or carries errno.
  int child_errno = 0;
  ssize_t n = 0;
  do {
    n = ::read(exec_pipe[0], &child_errno, sizeof child_errno);
  } while (n < 0 && errno == EINTR);
  ::close(exec_pipe[0]);
  if (n == static_cast<ssize_t>(sizeof child_errno)) {
    int ws = 0;
    while (::waitpid(pid, &ws, 0) < 0 && errno == EINTR) {
    }
    c.running = false;
    close_fd(c.out_fd);
    close_fd(c.err_fd);
    c.result.status = ChildStatus::kFailedToStart;
    c.result.stderr_text = "cannot execute " + c.spec.argv[0] + ": " + std::strerror(child_errno);
  }
  children_.push_back(std::move(c));
  return children_.size() - 1;
}

void ProcessGroup::kill(std::size_t index) {
  if (index >= children_.size()) throw Error("index", 0, "no such child");
  Child& c = children_[index];
  if (!c.running || c.kill_requested) return;
  c.kill_requested = true;
  c.kill_reason = ChildStatus::kKilled;
  ::kill(c.result.pid, SIGKILL);
}

void ProcessGroup::read_some(Child& c, int fd, std::string& into) {
  char buf[8192];
  const ssize_t n = ::read(fd, buf, sizeof buf);
  if (n <= 0) {
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) return;
    if (fd == c.out_fd) close_fd(c.out_fd);
    if (fd == c.err_fd) close_fd(c.err_fd);
    return;
  }
  const std::size_t room =
      into.size() < options_.max_output_bytes ? options_.max_output_bytes - into.size() : 0;
  const std::size_t take = std::min(room, static_cast<std::size_t>(n));
  into.append(buf, take);
  if (take < static_cast<std::size_t>(n)) c.result.output_truncated = true;
  if (!c.spec.kill_on_output.empty() && !c.kill_requested &&
      into.find(c.spec.kill_on_output) != std::string::npos) {
    c.kill_requested = true;
    c.kill_reason = ChildStatus::kKilled;
    ::kill(c.result.pid, SIGKILL);
  }
}

void ProcessGroup::reap(Child& c, int wstatus) {
  c.running = false;
  c.result.wall_s = now_s() - c.started_s;
  if (WIFEXITED(wstatus)) {
    c.result.status = ChildStatus::kExited;
    c.result.exit_code = WEXITSTATUS(wstatus);
  } else if (WIFSIGNALED(wstatus)) {
    c.result.signal = WTERMSIG(wstatus);
    c.result.status = c.kill_requested ? c.kill_reason : ChildStatus::kSignaled;
  }
  if (c.kill_requested && c.result.status == ChildStatus::kExited) {
    // Exited by itself just before the signal landed: report what really happened.
    c.kill_requested = false;
  }
}

bool ProcessGroup::poll(double timeout_s) {
  const double deadline = start_s_ + options_.timeout_s;
  const double until = std::min(now_s() + std::max(0.0, timeout_s), deadline);
  for (;;) {
    // Timed kills.
    const double t = now_s();
    for (auto& c : children_) {
      if (c.running && !c.kill_requested && c.spec.kill_after_s > 0.0 &&
          t - c.started_s >= c.spec.kill_after_s) {
        c.kill_requested = true;
        c.kill_reason = ChildStatus::kKilled;
        ::kill(c.result.pid, SIGKILL);
      }
    }
    std::vector<pollfd> fds;
    std::vector<std::pair<std::size_t, int>> owner;
    for (std::size_t i = 0; i < children_.size(); ++i) {
      for (int fd : {children_[i].out_fd, children_[i].err_fd}) {
        if (fd < 0) continue;
        fds.push_back(pollfd{fd, POLLIN, 0});
        owner.emplace_back(i, fd);
      }
    }
    const double left = until - now_s();
    const int wait_ms = static_cast<int>(std::clamp(left * 1000.0, 0.0, 20.0));
    if (!fds.empty()) {
      const int r = ::poll(fds.data(), fds.size(), wait_ms);
      if (r > 0) {
        for (std::size_t k = 0; k < fds.size(); ++k) {
          if ((fds[k].revents & (POLLIN | POLLHUP | POLLERR)) == 0) continue;
          Child& c = children_[owner[k].first];
          read_some(c, owner[k].second,
                    owner[k].second == c.out_fd ? c.result.stdout_text : c.result.stderr_text);
        }
      }
    } else if (wait_ms > 0) {
      std::this_thread::sleep_for(std::chrono::milliseconds(std::min(wait_ms, 5)));
    }
    // Reap. A child counts as finished once it exited and its pipes reached EOF (or it exited
    // and the pipes are drained as far as possible: grandchildren may keep them open).
    bool any_running = false;
    for (auto& c : children_) {
      if (!c.running) continue;
      int ws = 0;
      const pid_t r = ::waitpid(c.result.pid, &ws, WNOHANG);
      if (r == c.result.pid) {
        // Drain what is left without blocking.
        for (int fd : {c.out_fd, c.err_fd}) {
          if (fd < 0) continue;
          const int fl = ::fcntl(fd, F_GETFL);
          ::fcntl(fd, F_SETFL, fl | O_NONBLOCK);
        }
        for (int guard = 0; guard < 4096 && (c.out_fd >= 0 || c.err_fd >= 0); ++guard) {
          const std::size_t before = c.result.stdout_text.size() + c.result.stderr_text.size();
          if (c.out_fd >= 0) read_some(c, c.out_fd, c.result.stdout_text);
          if (c.err_fd >= 0) read_some(c, c.err_fd, c.result.stderr_text);
          if (c.result.stdout_text.size() + c.result.stderr_text.size() == before) break;
        }
        close_fd(c.out_fd);
        close_fd(c.err_fd);
        reap(c, ws);
      } else {
        any_running = true;
      }
    }
    if (!any_running) return true;
    if (now_s() >= until) return false;
  }
}

void ProcessGroup::stop_all(ChildStatus why) {
  for (auto& c : children_) {
    if (!c.running) continue;
    c.kill_requested = true;
    c.kill_reason = why;
    ::kill(c.result.pid, SIGTERM);
  }
  const double grace_end = now_s() + options_.term_grace_s;
  while (now_s() < grace_end) {
    bool any = false;
    for (auto& c : children_) {
      if (!c.running) continue;
      int ws = 0;
      if (::waitpid(c.result.pid, &ws, WNOHANG) == c.result.pid)
        reap(c, ws);
      else
        any = true;
    }
    if (!any) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  for (auto& c : children_) {
    if (!c.running) continue;
    ::kill(c.result.pid, SIGKILL);
    int ws = 0;
    while (::waitpid(c.result.pid, &ws, 0) < 0 && errno == EINTR) {
    }
    reap(c, ws);
  }
  for (auto& c : children_) {
    // Keep whatever output is buffered.
    for (int* fd : {&c.out_fd, &c.err_fd}) {
      if (*fd < 0) continue;
      const int fl = ::fcntl(*fd, F_GETFL);
      ::fcntl(*fd, F_SETFL, fl | O_NONBLOCK);
      read_some(c, *fd, fd == &c.out_fd ? c.result.stdout_text : c.result.stderr_text);
      close_fd(*fd);
    }
    if (c.kill_requested && c.result.status == ChildStatus::kSignaled) c.result.status = why;
  }
}

std::vector<ChildResult> ProcessGroup::wait_all(const std::function<void(ProcessGroup&)>& on_tick) {
  const double deadline = start_s_ + options_.timeout_s;
  for (;;) {
    if (poll(0.05)) break;
    if (now_s() >= deadline) {
      stop_all(ChildStatus::kTimedOut);
      break;
    }
    if (on_tick) on_tick(*this);
  }
  std::vector<ChildResult> out;
  out.reserve(children_.size());
  for (auto& c : children_)
    out.push_back(c.result);
  return out;
}

std::vector<ChildResult> run_processes(std::vector<ChildSpec> specs, const LaunchOptions& options) {
  ProcessGroup g(options);
  for (auto& s : specs)
    g.start(std::move(s));
  return g.wait_all();
}

std::string self_executable() {
  std::error_code ec;
  auto p = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec)
    throw Error("/proc/self/exe", 0, "cannot resolve the running executable: " + ec.message());
  return p.string();
}

}  // namespace voronav::dds
