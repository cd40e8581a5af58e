// voronav dds-echo / dds-selftest / dds-config: robots as separate processes over Cyclone DDS
// (issue #8). dds-echo is one participant (used by dds-selftest, one process per robot);
// dds-selftest launches K of them and checks exactly-once in-range delivery, range, a killed
// process and injected loss; dds-config prints or writes the Cyclone config (loopback by default).
#include <algorithm>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>

#include "cli_common.hpp"
#include "command.hpp"
#include "voronav/core/error.hpp"
#include "voronav/dds/cyclone_config.hpp"
#include "voronav/dds/selftest.hpp"
#include "voronav/render/plot.hpp"

namespace voronav::cli {
namespace {

struct EchoArgs {
  dds::EchoOptions o;
  std::string config_file;
};

void run_echo(const EchoArgs& a) {
  dds::EchoOptions o = a.o;
  if (!a.config_file.empty()) {
    std::ifstream f(a.config_file, std::ios::binary);
    if (!f) throw Error(a.config_file, 0, "cannot read the Cyclone config file");
    std::ostringstream ss;
    ss << f.rdbuf();
    o.config_xml = ss.str();
  }
  std::cout << dds::run_echo(o) << std::endl;
}

void setup_echo(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "dds-echo",
      "One DDS participant (robot --id of --peers on a line): publishes its pose, sends test "
      "payloads, prints what it received as JSON");
  auto a = std::make_shared<EchoArgs>();
  auto& o = a->o;
  cmd->add_option("--id", o.id, "This robot's id (0..peers-1)")->required();
  cmd->add_option("--peers", o.peers, "Number of robots taking part (ids 0..peers-1)")->required();
  cmd->add_option("--rounds", o.rounds, "Broadcasts (and directed messages) to send")
      ->check(positive())
      ->capture_default_str();
  cmd->add_option("--interval", o.interval_s, "Pause between rounds [s]")->capture_default_str();
  cmd->add_option("--payload-bytes", o.payload_bytes, "Size of each payload [bytes] (>= 16)")
      ->capture_default_str();
  cmd->add_option("--spacing", o.spacing_m, "Robot i stands at (i * spacing, 0) [m]")
      ->capture_default_str();
  cmd->add_option("--range", o.range_m, "Radio range [m] ('inf' = unlimited)")
      ->capture_default_str();
  cmd->add_option("--loss", o.loss, "Injected loss probability at the receiver")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--seed", o.seed, "Seed of the loss injection")->capture_default_str();
  cmd->add_option("--domain", o.domain_id, "DDS domain id (0..230)")
      ->check(CLI::Range(0, 230))
      ->capture_default_str();
  cmd->add_option("--partition", o.partition, "DDS partition")->capture_default_str();
  cmd->add_option("--history-depth", o.history_depth, "Keep-last depth per sender")
      ->check(positive())
      ->capture_default_str();
  cmd->add_option("--startup-timeout", o.startup_timeout_s, "Wait for the peers at most [s]")
      ->capture_default_str();
  cmd->add_option("--quiet", o.quiet_s, "Stop after this long without traffic [s]")
      ->capture_default_str();
  cmd->add_option("--timeout", o.timeout_s, "Hard limit for the run [s]")->capture_default_str();
  cmd->add_option("--config", a->config_file,
                  "Cyclone config XML file (default: $CYCLONEDDS_URI or Cyclone's defaults)");
  cmd->callback([a] { run_echo(*a); });
}

struct SelftestArgs {
  dds::SelftestOptions o;
  int kill = -1;
  int domain = -1;
  bool json = false;
};

void run_selftest(const SelftestArgs& a) {
  dds::SelftestOptions o = a.o;
  if (a.kill >= 0) o.kill_id = static_cast<std::uint32_t>(a.kill);
  if (a.domain >= 0) o.domain_id = static_cast<std::uint32_t>(a.domain);
  const dds::SelftestReport r = dds::run_selftest(o);
  if (a.json) {
    print_json(nlohmann::json::parse(r.json));
  } else {
    std::cout << "dds selftest: " << (r.passed ? "PASSED" : "FAILED") << "\n"
              << "processes:   " << r.processes << (o.kill_id ? " (one killed)" : "") << "\n"
              << "delivered:   " << r.delivered << " of " << r.expected << " in-range messages\n"
              << "out of range delivered: " << r.out_of_range_delivered
              << ", duplicates: " << r.duplicates << "\n"
              << "latency:     p50 " << r.latency_p50_ms << " ms, p99 " << r.latency_p99_ms
              << " ms\n"
              << "wall time:   " << r.wall_s << " s\n";
    for (const auto& v : r.violations)
      std::cout << "  violation: " << v << "\n";
  }
  if (!r.passed) exit_code() = 1;
}

void setup_selftest(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "dds-selftest",
      "Launch K dds-echo processes on loopback and check that every in-range message arrived "
      "exactly once and out-of-range ones did not");
  auto a = std::make_shared<SelftestArgs>();
  auto& o = a->o;
  cmd->add_option("--processes", o.processes, "Number of robot processes (2..110)")
      ->check(CLI::Range(2, 110))
      ->capture_default_str();
  cmd->add_option("--kill", a->kill, "Kill robot ID's process after its first round");
  cmd->add_option("--loss", o.loss, "Injected loss probability at each receiver")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--seed", o.seed, "Seed of the loss injection")->capture_default_str();
  cmd->add_option("--rounds", o.rounds, "Broadcasts (and directed messages) per robot")
      ->check(positive())
      ->capture_default_str();
  cmd->add_option("--interval", o.interval_s, "Pause between rounds [s]")->capture_default_str();
  cmd->add_option("--payload-bytes", o.payload_bytes, "Payload size [bytes] (>= 16)")
      ->capture_default_str();
  cmd->add_option("--spacing", o.spacing_m, "Robots stand on a line this far apart [m]")
      ->capture_default_str();
  cmd->add_option("--range", o.range_m, "Radio range [m] ('inf' = unlimited)")
      ->capture_default_str();
  cmd->add_option("--domain", a->domain, "DDS domain id (default: derived from the process id)")
      ->check(CLI::Range(0, 230));
  cmd->add_option("--timeout", o.timeout_s, "Limit for the whole run [s]")->capture_default_str();
  cmd->add_option("--startup-timeout", o.startup_timeout_s, "Discovery limit per process [s]")
      ->capture_default_str();
  cmd->add_option("--quiet", o.quiet_s, "A process stops after this long without traffic [s]")
      ->capture_default_str();
  cmd->add_flag("--json", a->json,
                "JSON output: passed, wall_s, expected, delivered, delivery_ratio, "
                "out_of_range_delivered, duplicates, latency, violations, children");
  cmd->callback([a] { run_selftest(*a); });
}

struct ConfigArgs {
  dds::CycloneConfigOptions o;
  std::vector<std::string> peers;
  std::string out;
};

void setup_config(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "dds-config",
      "Print (or write with --out) a Cyclone DDS config: unicast discovery, multicast off; "
      "loopback by default. Use it with CYCLONEDDS_URI=file://FILE");
  auto a = std::make_shared<ConfigArgs>();
  cmd->add_option("--interface", a->o.interface, "Interface address or name")
      ->capture_default_str();
  cmd->add_option("--peer", a->peers, "Discovery peer address (repeat; default 127.0.0.1)");
  cmd->add_flag("--multicast", a->o.allow_multicast, "Allow multicast");
  cmd->add_option("--max-index", a->o.max_auto_participant_index,
                  "Highest participant index = processes per machine - 1 (0..119)")
      ->capture_default_str();
  cmd->add_option("--lease", a->o.lease_duration_s, "Participant lease duration [s]")
      ->capture_default_str();
  cmd->add_option("--out", a->out, "Write to this file instead of stdout")->check(output_file());
  cmd->callback([a] {
    dds::CycloneConfigOptions o = a->o;
    if (!a->peers.empty()) o.peers = a->peers;
    if (a->out.empty())
      std::cout << dds::cyclone_config_xml(o);
    else
      dds::write_cyclone_config(a->out, o);
  });
}

struct ScalingArgs {
  std::vector<std::uint32_t> processes{2, 6, 12, 20};
  double startup_timeout = 60.0;
  double quiet = 3.0;
  std::string png;
  bool json = false;
};

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

void run_scaling(const ScalingArgs& a) {
  nlohmann::json runs = nlohmann::json::array();
  std::vector<double> n, wall, disc_med, disc_max;
  for (std::uint32_t k : a.processes) {
    dds::SelftestOptions o;
    o.processes = k;
    o.startup_timeout_s = a.startup_timeout;
    o.quiet_s = a.quiet;
    o.timeout_s = a.startup_timeout + a.quiet + 60.0;
    const dds::SelftestReport r = dds::run_selftest(o);
    const auto j = nlohmann::json::parse(r.json);
    std::vector<double> starts;
    for (const auto& c : j["children"])
      if (c.contains("startup_s")) starts.push_back(c["startup_s"].get<double>());
    const double smax = starts.empty() ? 0.0 : *std::max_element(starts.begin(), starts.end());
    runs.push_back({{"processes", k},
                    {"passed", r.passed},
                    {"wall_s", r.wall_s},
                    {"discovery_median_s", median(starts)},
                    {"discovery_max_s", smax},
                    {"delivered", r.delivered},
                    {"expected", r.expected},
                    {"violations", r.violations.size()}});
    n.push_back(k);
    wall.push_back(r.wall_s);
    disc_med.push_back(median(starts));
    disc_max.push_back(smax);
    if (!a.json)
      std::cout << k << " processes: " << (r.passed ? "passed" : "FAILED") << ", wall " << r.wall_s
                << " s, discovery median " << median(starts) << " s, max " << smax << " s\n";
    if (!r.passed) exit_code() = 1;
  }
  if (!a.png.empty()) {
    render::PlotOptions po;
    po.title = "dds-selftest on loopback: time vs. number of robot processes";
    po.x_label = "processes";
    po.y_label = "seconds";
    render::Plot plot(po);
    plot.line("selftest wall time", n, wall, render::Color::hex(0x1f77b4), true);
    plot.line("discovery, slowest process", n, disc_max, render::Color::hex(0xd62728), true);
    plot.line("discovery, median process", n, disc_med, render::Color::hex(0x2ca02c), true);
    plot.save(a.png);
  }
  if (a.json) print_json({{"runs", runs}});
}

void setup_scaling(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "dds-scaling",
      "Run dds-selftest for several process counts; report (and plot) wall and discovery time");
  auto a = std::make_shared<ScalingArgs>();
  cmd->add_option("--processes", a->processes, "Process counts, e.g. 2,6,12,20")
      ->delimiter(',')
      ->check(CLI::Range(2, 110))
      ->capture_default_str();
  cmd->add_option("--startup-timeout", a->startup_timeout, "Discovery limit per process [s]")
      ->capture_default_str();
  cmd->add_option("--quiet", a->quiet, "A process stops after this long without traffic [s]")
      ->capture_default_str();
  cmd->add_option("--png", a->png, "Write a plot (PNG or SVG by extension)");
  cmd->add_flag("--json", a->json, "JSON output: one entry per process count");
  cmd->callback([a] { run_scaling(*a); });
}

const Command reg_echo{{"dds-echo", setup_echo, 80}};
const Command reg_scaling{{"dds-scaling", setup_scaling, 83}};
const Command reg_selftest{{"dds-selftest", setup_selftest, 81}};
const Command reg_config{{"dds-config", setup_config, 82}};

}  // namespace
}  // namespace voronav::cli
