// The world process of the multi-process netsim run (netsim_dds.hpp): clock, obstacle changes,
// liveness, and the sum of the robots' final reports.
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
#include "voronav/core/stepper.hpp"
#include "voronav/dds/cyclone_config.hpp"
#include "voronav/dds/dds_transport.hpp"
#include "voronav/dds/internal/lockstep_control.hpp"
#include "voronav/dds/internal/netsim_json.hpp"
#include "voronav/dds/internal/netsim_trace.hpp"
#include "voronav/sim/robot_agent.hpp"
#include "voronav/sim/scenario_file.hpp"

namespace voronav::dds {

namespace {

using nlohmann::json;
namespace fs = std::filesystem;
using namespace internal;

dds_entity_t participant_for(const LockstepLink& link, dds_entity_t& domain) {
  domain = 0;
  if (!link.config_xml.empty())
    domain = must(dds_create_domain(link.domain_id, link.config_xml.c_str()), "dds_create_domain");
  return must(dds_create_participant(link.domain_id, nullptr, nullptr), "dds_create_participant");
}

}  // namespace

using nlohmann::json;
namespace fs = std::filesystem;
using namespace internal;

// ---- the world --------------------------------------------------------------------------------
int run_world_process(const WorldProcessOptions& o) {
  o.link.validate();
  const auto file = sim::load_netsim_scenario(o.scenario_path);
  const auto& sc = file.scenario;
  const auto& opts = file.options;
  const auto n = static_cast<std::uint32_t>(sc.robots.size());
  const double wall0 = steady_s();
  dds_entity_t domain = 0;
  const dds_entity_t participant = participant_for(o.link, domain);
  struct Closer {
    dds_entity_t p, d;
    ~Closer() {
      dds_delete(p);
      if (d > 0) dds_delete(d);
    }
  } closer{participant, domain};
  ControlLink link(participant, o.link.partition, true);
  std::map<std::uint32_t, ReportMsg> last;  // newest report per robot
  std::vector<std::uint8_t> alive(n, 1);
  std::vector<std::uint32_t> dead;
  TraceFile trace(o.trace_path);
  std::uint32_t step = 0;     // the last step every live robot completed
  std::uint32_t waiting = 0;  // the step whose reports the world waits for
  auto collect = [&](double timeout_s, const std::function<bool()>& enough) {
    const double deadline = steady_s() + timeout_s;
    for (;;) {
      for (auto& r : link.take_reports()) {
        if (r.id >= n) {
          std::cerr << "voronav-world: report from robot " << r.id << " (the scenario has " << n
                    << ")\n";
          continue;
        }
        auto it = last.find(r.id);
        if (it == last.end() || r.kind == kFinal || r.kind == kFailedReport ||
            r.step >= it->second.step)
          last[r.id] = r;
      }
      if (enough()) return true;
      if (steady_s() >= deadline) return false;
      link.wait(0.02);
    }
  };
  auto has = [&](std::uint32_t j, std::uint8_t kind, std::uint32_t at_step) {
    auto it = last.find(j);
    if (it == last.end()) return false;
    if (it->second.kind == kFinal || it->second.kind == kFailedReport) return kind <= kFinal;
    return it->second.kind >= kind && it->second.step >= at_step;
  };
  auto declare_dead = [&](std::uint32_t j, const std::string& why) {
    if (!alive[j]) return;
    alive[j] = 0;
    dead.push_back(j);
    std::cerr << "voronav-world: robot " << j << " declared dead (" << why << ")\n";
    trace.event({waiting * opts.dt_s, waiting, "dead", j, "declared dead by the world: " + why});
  };
  std::uint32_t resumed_at = 0;
  if (!o.resume) {
    const bool ok = collect(o.link.startup_timeout_s, [&] {
      for (std::uint32_t j = 0; j < n; ++j)
        if (!has(j, kReady, 0)) return false;
      return link.matched_readers() >= n;
    });
    if (!ok) {
      std::size_t ready = 0;
      for (std::uint32_t j = 0; j < n; ++j)
        ready += has(j, kReady, 0) ? 1 : 0;
      std::cerr << "voronav-world: " << ready << " of " << n << " robots ready after "
                << o.link.startup_timeout_s << " s\n";
      TickMsg stop;
      stop.stop = true;
      stop.alive = alive;
      stop.seq.assign(n, 0);
      link.write(stop);
      link.flush(1.0);
      return kExitNoPeers;
    }
    TickMsg t0;
    t0.step = 0;
    t0.alive = alive;
    t0.seq.assign(n, 0);
    link.write(t0);
    collect(o.link.step_timeout_s, [&] {
      for (std::uint32_t j = 0; j < n; ++j)
        if (alive[j] && !has(j, kDone, 0)) return false;
      return true;
    });
    for (std::uint32_t j = 0; j < n; ++j)
      if (!has(j, kDone, 0)) declare_dead(j, "no report of the start");
  } else {
    // Take over: every robot's last report (transient-local), those silent are dead.
    collect(o.link.step_timeout_s, [&] { return last.size() == n && link.matched_readers() >= n; });
    std::uint32_t top = 0;
    for (std::uint32_t j = 0; j < n; ++j) {
      if (!last.count(j) || last[j].kind == kFailedReport || last[j].kind == kFinal)
        declare_dead(j, "no report when the world resumed");
      else
        top = std::max(top, last[j].step);
    }
    // Robots one step behind still need Tick `top`; then everyone is at `top`.
    bool behind = false;
    for (std::uint32_t j = 0; j < n; ++j)
      if (alive[j] && last[j].step + 1 == top) behind = true;
    step = behind ? top - 1 : top;
    resumed_at = step;
    std::cerr << "voronav-world: resuming after step " << step << "\n";
    trace.event({step * opts.dt_s, step, "world_resumed", -1,
                 "a new world process resumed the run after step " + std::to_string(step)});
  }
  // As many steps as run_netsim's loop (core/stepper.hpp).
  const auto steps = static_cast<int>(
      step_count(opts.dt_s, opts.time_limit_s, "netsim.dt_s", "netsim.time_limit_s"));
  const auto source = static_cast<std::uint32_t>(sc.source);
  auto source_arrived = [&] { return last.count(source) && last[source].arrived; };
  while (static_cast<int>(step) < steps && alive[source] && !source_arrived()) {
    const std::uint32_t k = step + 1;
    waiting = k;
    TickMsg t;
    t.step = k;
    t.alive = alive;
    t.seq.assign(n, 0);
    std::uint32_t applied = 0;
    for (std::uint32_t j = 0; j < n; ++j) {
      if (!alive[j]) continue;
      const auto& r = last[j];
      // Its last payload by the end of step k-1.
      t.seq[j] = r.step >= k ? r.prev_seq : r.seq;
      applied = std::max(applied, r.changes_applied);
    }
    t.first_route_s = last[source].route_time_s;
    for (std::size_t c :
         sim::changes_due(sc, t.first_route_s, k * opts.dt_s, applied, opts.method)) {
      t.changes.push_back(static_cast<std::uint32_t>(c));
      trace.event({k * opts.dt_s, k, "change", -1,
                   "obstacle change " + std::to_string(c) + " (" +
                       std::to_string(sc.changes[c].cells.size()) + " cells " +
                       (sc.changes[c].value == kOccupied ? "blocked" : "freed") + ")"});
    }
    link.write(t);
    if (o.die_at_step && *o.die_at_step == k) {
      link.flush(1.0);
      trace.event({k * opts.dt_s, k, "world_killed", -1,
                   "the world process was killed after step " + std::to_string(k)});
      std::cerr << "voronav-world: killing itself after tick " << k << " (fault injection)\n";
      die_now();
    }
    const bool all = collect(o.link.step_timeout_s, [&] {
      for (std::uint32_t j = 0; j < n; ++j)
        if (alive[j] && !has(j, kDone, k)) return false;
      return true;
    });
    if (!all)
      for (std::uint32_t j = 0; j < n; ++j)
        if (alive[j] && !has(j, kDone, k))
          declare_dead(j, "no report of step " + std::to_string(k) + " within " +
                              std::to_string(static_cast<int>(o.link.step_timeout_s)) + " s");
    step = k;
    if (std::count(alive.begin(), alive.end(), 1) == 0) {
      std::cerr << "voronav-world: no robot left\n";
      return kExitRobotsLost;
    }
  }
  TickMsg stop;
  stop.step = step + 1;
  stop.stop = true;
  stop.alive = alive;
  stop.seq.assign(n, 0);
  link.write(stop);
  collect(o.link.step_timeout_s + 5.0, [&] {
    for (std::uint32_t j = 0; j < n; ++j)
      if (alive[j] && !(last.count(j) && last[j].kind == kFinal)) return false;
    return true;
  });
  std::vector<sim::AgentReport> reports(n);
  json per_robot = json::array();
  for (std::uint32_t j = 0; j < n; ++j) {
    if (!(last.count(j) && last[j].kind == kFinal)) {
      if (alive[j]) declare_dead(j, "no final report");
      continue;
    }
    try {
      const json rj = json::parse(last[j].detail);
      reports[j] = agent_report_from(rj);
      per_robot.push_back(rj);
    } catch (const json::exception& e) {
      std::cerr << "voronav-world: malformed final report of robot " << j << ": " << e.what()
                << "\n";
      declare_dead(j, "malformed final report");
    }
  }
  auto m = sim::aggregate_metrics(reports, sc.source, opts.method);
  m.simulated_s = step * opts.dt_s;
  m.changes_applied =
      static_cast<int>(sim::changes_due(sc, last.count(source) ? last[source].route_time_s : -1.0,
                                        step * opts.dt_s, 0, opts.method)
                           .size());
  m.wall_s = steady_s() - wall0;
  std::sort(dead.begin(), dead.end());
  const json out = {{"metrics", json::parse(metrics_to_json(m))},
                    {"dead", dead},
                    {"steps", step},
                    {"resumed_at", resumed_at},
                    {"robots", per_robot}};
  std::cout << out.dump() << "\n";
  return kExitOk;
}

}  // namespace voronav::dds
