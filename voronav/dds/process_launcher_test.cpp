// Tests of the process launcher (with /bin/sh children) and of the multi-process selftest: this
// test binary doubles as the echo participant ("<binary> dds-echo --id ..."), so the tests need
// no other executable.
#include "voronav/dds/process_launcher.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>

#include "voronav/core/error.hpp"
#include "voronav/dds/selftest.hpp"

namespace voronav::dds {
namespace {

// When started as "<this binary> dds-echo ARGS", run one echo participant before gtest starts.
struct EchoHook {
  EchoHook() {
    std::ifstream f("/proc/self/cmdline", std::ios::binary);
    const std::string all((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    std::vector<std::string> args;
    std::size_t start = 0;
    for (std::size_t i = 0; i < all.size(); ++i) {
      if (all[i] == '\0') {
        args.push_back(all.substr(start, i - start));
        start = i + 1;
      }
    }
    if (args.size() < 2 || args[1] != "dds-echo") return;
    int code = 0;
    try {
      const std::string out = run_echo(parse_echo_args({args.begin() + 2, args.end()}));
      std::fputs(out.c_str(), stdout);
      std::fputc('\n', stdout);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "dds-echo: error: %s\n", e.what());
      code = 2;
    }
    std::fflush(stdout);
    std::fflush(stderr);
    std::_Exit(code);
  }
};
const EchoHook echo_hook;

ChildSpec sh(const std::string& name, const std::string& script) {
  ChildSpec s;
  s.name = name;
  s.argv = {"/bin/sh", "-c", script};
  return s;
}

TEST(ProcessGroup, CollectsOutputAndExitCodes) {
  LaunchOptions lo;
  lo.timeout_s = 10.0;
  std::vector<ChildSpec> specs;
  specs.push_back(sh("ok", "echo '{\"a\": 1}'; echo note >&2"));
  specs.push_back(sh("three", "exit 3"));
  auto env = sh("env", "echo \"$VORONAV_TEST_VAR\"");
  env.env["VORONAV_TEST_VAR"] = "hello from env";
  specs.push_back(env);
  const auto r = run_processes(specs, lo);
  ASSERT_EQ(r.size(), 3u);
  EXPECT_TRUE(r[0].ok());
  EXPECT_EQ(r[0].stdout_text, "{\"a\": 1}\n");
  EXPECT_EQ(r[0].stderr_text, "note\n");
  EXPECT_EQ(r[1].status, ChildStatus::kExited);
  EXPECT_EQ(r[1].exit_code, 3);
  EXPECT_FALSE(r[1].ok());
  EXPECT_EQ(r[2].stdout_text, "hello from env\n");
}

TEST(ProcessGroup, ChildInheritsNoOtherDescriptors) {
  const int leaked = ::open("/dev/null", O_RDONLY);  // deliberately not close-on-exec
  ASSERT_GE(leaked, 3);
  const auto r = run_processes({sh("fds", "ls /proc/$$/fd")});
  ::close(leaked);
  ASSERT_TRUE(r[0].ok());
  EXPECT_EQ(r[0].stdout_text, "0\n1\n2\n");
}

TEST(ProcessGroup, LargeOutputOfManyChildrenIsComplete) {
  LaunchOptions lo;
  lo.timeout_s = 20.0;
  std::vector<ChildSpec> specs;
  // 200 000 bytes each: far more than a pipe buffer, so the parent must read while they write.
  for (int i = 0; i < 12; ++i)
    specs.push_back(sh("big" + std::to_string(i), "head -c 200000 /dev/zero | tr '\\0' 'x'"));
  const auto r = run_processes(specs, lo);
  for (const auto& c : r) {
    EXPECT_TRUE(c.ok()) << c.name;
    EXPECT_EQ(c.stdout_text.size(), 200000u) << c.name;
  }
}

TEST(ProcessGroup, OutputIsCappedAndFlagged) {
  LaunchOptions lo;
  lo.max_output_bytes = 1000;
  const auto r = run_processes({sh("big", "head -c 5000 /dev/zero")}, lo);
  EXPECT_TRUE(r[0].ok());
  EXPECT_EQ(r[0].stdout_text.size(), 1000u);
  EXPECT_TRUE(r[0].output_truncated);
}

TEST(ProcessGroup, DeadlineStopsHungChildren) {
  LaunchOptions lo;
  lo.timeout_s = 0.5;
  lo.term_grace_s = 0.2;
  const auto t0 = std::chrono::steady_clock::now();
  const auto r = run_processes({sh("hang", "sleep 30"), sh("fast", "true")}, lo);
  const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_LT(took, 5.0);  // a generous bound: the point is that it does not wait 30 s
  EXPECT_EQ(r[0].status, ChildStatus::kTimedOut);
  EXPECT_TRUE(r[1].ok());
}

TEST(ProcessGroup, IgnoredTermIsFollowedByKill) {
  LaunchOptions lo;
  lo.timeout_s = 0.5;
  lo.term_grace_s = 0.1;
  const auto r = run_processes({sh("stubborn", "trap '' TERM; sleep 30")}, lo);
  EXPECT_EQ(r[0].status, ChildStatus::kTimedOut);
  EXPECT_EQ(r[0].signal, SIGKILL);
}

TEST(ProcessGroup, KillOnRequest) {
  ProcessGroup g(LaunchOptions{});
  const auto victim = g.start(sh("victim", "sleep 30"));
  const auto other = g.start(sh("other", "sleep 0.2; echo done"));
  EXPECT_TRUE(g.running(victim));
  bool killed = false;
  const auto r = g.wait_all([&](ProcessGroup& pg) {
    if (!killed) {
      pg.kill(victim);
      killed = true;
    }
  });
  EXPECT_EQ(r[victim].status, ChildStatus::kKilled);
  EXPECT_EQ(r[victim].signal, SIGKILL);
  EXPECT_TRUE(r[other].ok());
  EXPECT_EQ(r[other].stdout_text, "done\n");
  EXPECT_THROW(g.kill(7), Error);
}

TEST(ProcessGroup, KillOnOutputAndAfterTime) {
  auto a = sh("marker", "echo starting; echo 'round 1 sent' >&2; sleep 30");
  a.kill_on_output = "round 1 sent";
  auto b = sh("timed", "sleep 30");
  b.kill_after_s = 0.2;
  LaunchOptions lo;
  lo.timeout_s = 10.0;
  const auto t0 = std::chrono::steady_clock::now();
  const auto r = run_processes({a, b}, lo);
  const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_LT(took, 5.0);
  EXPECT_EQ(r[0].status, ChildStatus::kKilled);
  EXPECT_EQ(r[0].stdout_text, "starting\n");
  EXPECT_EQ(r[1].status, ChildStatus::kKilled);
}

TEST(ProcessGroup, SignalFromElsewhereIsReported) {
  const auto r = run_processes({sh("suicide", "kill -9 $$")});
  EXPECT_EQ(r[0].status, ChildStatus::kSignaled);
  EXPECT_EQ(r[0].signal, SIGKILL);
}

TEST(ProcessGroup, MissingExecutableFailsToStart) {
  ChildSpec s;
  s.name = "missing";
  s.argv = {"/nonexistent/voronav-nothing"};
  const auto r = run_processes({s});
  EXPECT_EQ(r[0].status, ChildStatus::kFailedToStart);
  EXPECT_NE(r[0].stderr_text.find("No such file"), std::string::npos);
  ProcessGroup g;
  EXPECT_THROW(g.start(ChildSpec{}), Error);
  EXPECT_THROW(ProcessGroup(LaunchOptions{0.0, 0.5, 1000}), Error);
}

TEST(EchoArgs, RoundTripAndErrors) {
  EchoOptions o;
  o.id = 3;
  o.peers = 7;
  o.rounds = 9;
  o.interval_s = 0.125;
  o.range_m = std::numeric_limits<double>::infinity();
  o.loss = 0.25;
  o.partition = "p-1";
  const EchoOptions back = parse_echo_args(echo_args(o));
  EXPECT_EQ(back.id, 3u);
  EXPECT_EQ(back.peers, 7u);
  EXPECT_EQ(back.rounds, 9);
  EXPECT_EQ(back.interval_s, 0.125);
  EXPECT_TRUE(std::isinf(back.range_m));
  EXPECT_EQ(back.loss, 0.25);
  EXPECT_EQ(back.partition, "p-1");
  EXPECT_THROW((void)parse_echo_args({"--id"}), Error);
  EXPECT_THROW((void)parse_echo_args({"--id", "-1"}), Error);
  EXPECT_THROW((void)parse_echo_args({"--loss", "abc"}), Error);
  EXPECT_THROW((void)parse_echo_args({"--bogus", "1"}), Error);
  EchoOptions bad;
  bad.id = 5;
  bad.peers = 3;
  EXPECT_THROW((void)run_echo(bad), Error);
}

SelftestOptions selftest_options(std::uint32_t n) {
  SelftestOptions o;
  o.processes = n;
  o.echo_command = {self_executable(), "dds-echo"};
  o.timeout_s = 30.0;
  o.quiet_s = 1.0;
  return o;
}

nlohmann::json parse(const SelftestReport& r) {
  return nlohmann::json::parse(r.json);
}

TEST(Selftest, SixProcessesEveryInRangeMessageExactlyOnce) {
  const auto r = run_selftest(selftest_options(6));
  for (const auto& v : r.violations)
    ADD_FAILURE() << v;
  EXPECT_TRUE(r.passed);
  // Line of 6 robots 10 m apart, range 25 m: each hears its neighbours up to 2 away:
  // ordered in-range pairs = 2 * (5 + 4) = 18, 5 broadcasts each; directed i -> i+1 mod 6 is in
  // range except 5 -> 0 (50 m), so 5 x 5 directed.
  EXPECT_EQ(r.expected, 18u * 5u + 5u * 5u);
  EXPECT_EQ(r.delivered, r.expected);
  EXPECT_EQ(r.out_of_range_delivered, 0u);
  EXPECT_EQ(r.duplicates, 0u);
  const auto j = parse(r);
  EXPECT_EQ(j["children"].size(), 6u);
  EXPECT_TRUE(j["passed"].get<bool>());
}

TEST(Selftest, KilledProcessDoesNotHangTheOthers) {
  auto o = selftest_options(6);
  o.kill_id = 2;
  o.rounds = 10;
  o.quiet_s = 0.5;
  const auto t0 = std::chrono::steady_clock::now();
  const auto r = run_selftest(o);
  const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for (const auto& v : r.violations)
    ADD_FAILURE() << v;
  EXPECT_TRUE(r.passed);
  EXPECT_LT(took, 25.0);
  EXPECT_EQ(r.children[2].status, ChildStatus::kKilled);
  for (std::uint32_t i = 0; i < 6; ++i)
    if (i != 2) {
      EXPECT_TRUE(r.children[i].ok()) << i;
    }
  EXPECT_EQ(r.delivered, r.expected);  // from the survivors, all arrived
}

TEST(Selftest, LossIsHonoured) {
  auto o = selftest_options(4);
  o.range_m = std::numeric_limits<double>::infinity();
  o.rounds = 50;
  o.interval_s = 0.002;
  o.loss = 0.3;
  const auto r = run_selftest(o);
  for (const auto& v : r.violations)
    ADD_FAILURE() << v;
  EXPECT_TRUE(r.passed);
  // 4 robots, everyone in range: 12 pairs x 50 broadcasts + 4 x 50 directed = 800 expected.
  ASSERT_EQ(r.expected, 800u);
  const double ratio = static_cast<double>(r.delivered) / static_cast<double>(r.expected);
  // Binomial(800, 0.7): sd 1.6 %; +-8 % is 5 sd.
  EXPECT_NEAR(ratio, 0.7, 0.08);
  EXPECT_EQ(r.duplicates, 0u);
}

TEST(Selftest, BadOptionsThrow) {
  auto o = selftest_options(1);
  EXPECT_THROW((void)run_selftest(o), Error);
  o = selftest_options(3);
  o.kill_id = 3;
  EXPECT_THROW((void)run_selftest(o), Error);
  o = selftest_options(3);
  o.loss = -0.1;
  EXPECT_THROW((void)run_selftest(o), Error);
}

TEST(Selftest, BrokenEchoCommandIsReportedNotHung) {
  auto o = selftest_options(3);
  o.echo_command = {"/bin/sh", "-c", "exit 4", "sh"};
  const auto r = run_selftest(o);
  EXPECT_FALSE(r.passed);
  EXPECT_EQ(r.violations.size(), 3u);
  EXPECT_EQ(r.children[0].exit_code, 4);
}

}  // namespace
}  // namespace voronav::dds
