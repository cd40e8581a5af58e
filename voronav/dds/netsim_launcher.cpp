// The launcher of the multi-process netsim run (netsim_dds.hpp): one process per robot plus the
// world process, a world restart when it was injected, and the result.
#include "voronav/dds/netsim_dds.hpp"

#include <dds/dds.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <functional>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <thread>

#include "voronav/core/error.hpp"
#include "voronav/dds/cyclone_config.hpp"
#include "voronav/dds/dds_transport.hpp"
#include "voronav/dds/internal/lockstep_control.hpp"
#include "voronav/dds/internal/netsim_json.hpp"
#include "voronav/dds/internal/netsim_trace.hpp"
#include "voronav/sim/robot_agent.hpp"
#include "voronav/sim/scenario_file.hpp"

namespace voronav::dds {

using nlohmann::json;
namespace fs = std::filesystem;
using namespace internal;

// ---- the launcher -----------------------------------------------------------------------------
DdsRunResult run_netsim_dds(const DdsRunOptions& o) {
  if (o.scenario_path.empty()) throw Error("scenario", 0, "a scenario file is required");
  o.link.validate();
  if (!(o.timeout_s > 0.0) || !std::isfinite(o.timeout_s))
    throw Error("--dds-timeout", 0, "expected a positive finite number of seconds");
  if (!(o.loss >= 0.0 && o.loss <= 1.0))
    throw Error("--loss", 0, "expected a probability in [0, 1]");
  const auto file = sim::load_netsim_scenario(o.scenario_path);  // errors before any process
  const auto n = static_cast<std::uint32_t>(file.scenario.robots.size());
  if (n + 1 > 110)
    throw Error("scenario", 0,
                std::to_string(n) +
                    " robots: at most 109 robot processes per machine (the "
                    "loopback config has 120 participant slots)");
  if (o.kill_robot && *o.kill_robot >= n) throw Error("--kill-robot", 0, "no such robot");
  const double t0 = steady_s();
  const fs::path dir = o.work_dir.empty() ? fs::temp_directory_path() : fs::path(o.work_dir);
  fs::create_directories(dir);
  static int counter = 0;
  const std::string tag = std::to_string(::getpid()) + "-" + std::to_string(++counter);
  const fs::path config = dir / ("voronav-netsim-" + tag + ".xml");
  write_cyclone_config(config, CycloneConfigOptions{});
  struct Remove {
    fs::path p;
    ~Remove() {
      std::error_code ec;
      fs::remove(p, ec);
    }
  } remove{config};
  // Trace files (DdsRunOptions::record), removed after they are read.
  const std::string world_trace =
      o.record ? (dir / ("voronav-trace-" + tag + "-world.jsonl")).string() : "";
  std::vector<std::string> robot_traces;
  if (o.record)
    for (std::uint32_t i = 0; i < n; ++i)
      robot_traces.push_back(
          (dir / ("voronav-trace-" + tag + "-robot" + std::to_string(i) + ".jsonl")).string());
  struct RemoveAll {
    std::vector<std::string> files;
    ~RemoveAll() {
      std::error_code ec;
      for (const auto& f : files)
        fs::remove(f, ec);
    }
  } remove_traces{robot_traces};
  if (o.record) remove_traces.files.push_back(world_trace);
  for (const auto& f : remove_traces.files) {
    std::error_code ec;
    fs::remove(f, ec);  // appended to: start empty
  }
  const std::uint32_t domain =
      o.domain_id.value_or(1 + static_cast<std::uint32_t>(::getpid()) % 200);
  const std::string partition = "netsim-" + tag;
  std::vector<std::string> cmd = o.command;
  if (cmd.empty()) cmd = {self_executable()};
  auto common = [&](std::vector<std::string> a) {
    for (auto s : {std::string("--scenario"), o.scenario_path, std::string("--domain"),
                   std::to_string(domain), std::string("--partition"), partition,
                   std::string("--startup-timeout"), std::to_string(o.link.startup_timeout_s),
                   std::string("--step-timeout"), std::to_string(o.link.step_timeout_s)})
      a.push_back(s);
    return a;
  };
  auto spec = [&](const std::string& name, std::vector<std::string> args) {
    ChildSpec s;
    s.name = name;
    s.argv = cmd;
    s.argv.insert(s.argv.end(), args.begin(), args.end());
    s.env["CYCLONEDDS_URI"] = cyclone_uri_for(config);
    return s;
  };
  LaunchOptions lo;
  lo.timeout_s = o.timeout_s;
  ProcessGroup group(lo);
  auto world_args = [&](bool resume) {
    auto a = common({"netsim-world"});
    if (resume) a.push_back("--resume");
    if (o.record) {
      a.push_back("--trace");
      a.push_back(world_trace);
    }
    if (!resume && o.world_restart_at_step) {
      a.push_back("--die-at-step");
      a.push_back(std::to_string(*o.world_restart_at_step));
    }
    return a;
  };
  std::size_t world = group.start(spec("world", world_args(false)));
  for (std::uint32_t i = 0; i < n; ++i) {
    auto a = common({"robot", "--id", std::to_string(i), "--transport", "dds"});
    if (o.loss > 0.0) {
      a.push_back("--loss");
      a.push_back(std::to_string(o.loss));
    }
    if (o.record) {
      a.push_back("--trace");
      a.push_back(robot_traces[i]);
    }
    if (o.kill_robot && *o.kill_robot == i) {
      a.push_back("--die-at-step");
      a.push_back(std::to_string(o.kill_at_step));
    }
    group.start(spec("robot " + std::to_string(i), a));
  }
  DdsRunResult res;
  const double deadline = t0 + o.timeout_s;
  for (;;) {
    const bool none = group.poll(0.05);
    if (!group.running(world)) {
      const auto& err = group.stderr_so_far(world);
      const bool injected = err.find("(fault injection)") != std::string::npos;
      if (injected && res.world_restarts == 0 && group.stdout_so_far(world).empty()) {
        ++res.world_restarts;
        world = group.start(spec("world (resumed)", world_args(true)));
        continue;
      }
    }
    if (none || steady_s() >= deadline) break;
  }
  res.children = group.wait_all();
  res.wall_s = steady_s() - t0;
  const auto& w = res.children[world];
  if (!w.ok()) {
    res.error = "world process: " + std::string(to_string(w.status)) + " (exit " +
                std::to_string(w.exit_code) + "): " + w.stderr_text.substr(0, 2000);
    return res;
  }
  try {
    const json j = json::parse(w.stdout_text);
    res.metrics = metrics_from_json(j.at("metrics").dump());
    res.dead = j.at("dead").get<std::vector<std::uint32_t>>();
    res.steps = j.at("steps").get<std::uint32_t>();
  } catch (const std::exception& e) {
    res.error = std::string("world process output: ") + e.what();
    return res;
  }
  res.ok = true;
  const auto& scenario = file.scenario;
  if (o.record) read_netsim_traces(robot_traces, world_trace, scenario, res.recording, res.events);
  if (o.kill_robot)
    for (const auto& c : res.children)
      if (c.name == "robot " + std::to_string(*o.kill_robot) &&
          c.status == ChildStatus::kSignaled && c.signal == SIGKILL)
        res.events.push_back({o.kill_at_step * file.options.dt_s, o.kill_at_step, "killed",
                              static_cast<std::int64_t>(*o.kill_robot),
                              "robot " + std::to_string(*o.kill_robot) + " killed at step " +
                                  std::to_string(o.kill_at_step) + " (fault injection)"});
  std::stable_sort(res.events.begin(), res.events.end(), [](const DdsEvent& a, const DdsEvent& b) {
    // a kill before the world notices it
    return a.step != b.step ? a.step < b.step : (a.kind == "killed") > (b.kind == "killed");
  });
  for (std::size_t i = 0; i < res.children.size(); ++i) {
    if (i == world) continue;
    const auto& c = res.children[i];
    const bool injected_kill = c.status == ChildStatus::kSignaled && c.signal == SIGKILL;
    if (!c.ok() && !injected_kill && c.name.rfind("world", 0) != 0) {
      res.ok = false;
      res.error += c.name + ": " + std::string(to_string(c.status)) + " (exit " +
                   std::to_string(c.exit_code) + ") " + c.stderr_text.substr(0, 500) + "\n";
    }
  }
  return res;
}

}  // namespace voronav::dds
