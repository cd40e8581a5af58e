// `voronav netsim`: the networked-robot comparison of seed 000 (Tables 6–7): runs the
// decentralized (Voronoi points, Search/Path/Repair) and/or centralized (Request/Ack + A*) method
// on a paper scenario (1..4, 16 runs each) or a scenario file (YAML, one run) and prints the mean
// metrics, as JSON with --json; --write-scenario saves a paper run as a scenario file.
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>

#include "cli_common.hpp"
#include "command.hpp"
#include "recordings.hpp"
#include "voronav/bag/run_bag.hpp"
#include "voronav/core/error.hpp"
#include "voronav/dds/netsim_dds.hpp"
#include "voronav/render/plot.hpp"
#include "voronav/report/replay_html.hpp"
#include "voronav/sim/scenario_file.hpp"
#include "voronav/sim/scenarios.hpp"

namespace voronav::cli {
namespace {

struct NetsimArgs {
  std::string scenario = "1";
  std::string method = "both";
  int runs = sim::kTable7Runs;
  int run = 1;  ///< the paper run --write-scenario writes
  std::uint64_t seed = sim::NetSimOptions{}.seed;
  double loss = sim::NetSimOptions{}.radio.loss;
  std::string out;
  std::string plots;
  std::string write_scenario;
  std::string transport = "sim";
  long kill_robot = -1;
  std::uint32_t kill_at_step = 0;
  long world_restart_at_step = -1;
  double dds_timeout_s = dds::DdsRunOptions{}.timeout_s;
  bool json = false;
  std::string mcap;
  // Whether the option was given on the command line (it then overrides a scenario file).
  bool method_given = false, seed_given = false, loss_given = false, runs_given = false;
  /// --repair-fix-answer true|false (NetSimOptions::repair_fix_answer); unset = the default or
  /// the scenario file's.
  std::optional<bool> repair_fix_answer;
  /// --repair-expand-hops N (NetSimOptions::repair_expand_hops); unset = default or file's.
  std::optional<int> repair_expand_hops;
  /// --repair-fix-seen-only true|false (NetSimOptions::repair_fix_seen_only).
  std::optional<bool> repair_fix_seen_only;
  /// --repair-walk-keep-ratio K (NetSimOptions::repair_walk_keep_ratio).
  std::optional<double> repair_walk_keep_ratio;
  /// --repair-sense-walk true|false (NetSimOptions::repair_sense_walk).
  std::optional<bool> repair_sense_walk;
  /// --repair-sense-wait-s S (NetSimOptions::repair_sense_wait_s).
  std::optional<double> repair_sense_wait_s;
};

/// The --repair-* options that were given, written over `o` (the defaults or a scenario file's);
/// the one place every run plan and --write-scenario takes them from.
void apply_repair_overrides(const NetsimArgs& a, sim::NetSimOptions& o) {
  if (a.repair_fix_answer) o.repair_fix_answer = *a.repair_fix_answer;
  if (a.repair_expand_hops) o.repair_expand_hops = *a.repair_expand_hops;
  if (a.repair_fix_seen_only) o.repair_fix_seen_only = *a.repair_fix_seen_only;
  if (a.repair_walk_keep_ratio) o.repair_walk_keep_ratio = *a.repair_walk_keep_ratio;
  if (a.repair_sense_walk) o.repair_sense_walk = *a.repair_sense_walk;
  if (a.repair_sense_wait_s) o.repair_sense_wait_s = *a.repair_sense_wait_s;
}

/// What to run: `runs` scenarios (paper runs or the one of a file), each with `methods`.
struct Plan {
  std::string label;  ///< "scenario1".."scenario4" or the file's stem (output file names)
  std::string title;  ///< "Scenario 1".."Scenario 4" or the file's stem (plot titles)
  int runs = 1;
  std::function<sim::NetSimScenario(int run)> scenario;
  sim::NetSimOptions options;  ///< for every run; method set per method
  std::vector<sim::Method> methods;
};

/// Figures 22-37 style: one value per run of Table 7, both methods side by side.
void save_plots(const std::string& dir, const std::string& label, const std::string& title,
                const std::map<std::string, std::vector<sim::NetSimMetrics>>& runs) {
  make_output_dir(dir, "--plots");
  struct Fig {
    const char* file;
    const char* title;
    const char* unit;
    double (*get)(const sim::NetSimMetrics&);
  };
  const Fig figs[] = {
      {"traffic", "total traffic", "bytes",
       [](const sim::NetSimMetrics& m) { return static_cast<double>(m.traffic_bytes); }},
      {"computation", "total computation", "work units (cells + point pairs)",
       [](const sim::NetSimMetrics& m) { return static_cast<double>(m.computation); }},
      {"max_robot_cpu", "computation time of the busiest robot", "CPU s",
       [](const sim::NetSimMetrics& m) { return m.max_robot_cpu_s; }},
      {"travel", "travel distance of all robots", "m",
       [](const sim::NetSimMetrics& m) { return m.travel_m; }}};
  for (const auto& f : figs) {
    render::Plot plot({.width_px = 640,
                       .height_px = 360,
                       .title = title + ": " + f.title,
                       .x_label = "run (Table 7)",
                       .y_label = f.unit});
    std::vector<std::string> cats;
    std::size_t n = 0;
    for (const auto& [name, v] : runs)
      n = std::max(n, v.size());
    for (std::size_t i = 1; i <= n; ++i)
      cats.push_back(std::to_string(i));
    plot.categories(cats);
    int c = 0;
    for (const auto& [name, v] : runs) {
      std::vector<double> y;
      for (const auto& m : v)
        y.push_back(f.get(m));
      plot.bars(name, y, c++ == 0 ? render::colors::kBlue : render::colors::kOrange);
    }
    plot.save(std::filesystem::path(dir) / (label + "_" + f.file + ".png"));
  }
}

nlohmann::json summary_json(const sim::Summary& s) {
  return {{"runs", s.runs},
          {"success_rate", s.success_rate},
          {"traffic_bytes", s.traffic_bytes},
          {"messages", s.messages},
          {"computation", s.computation},
          {"max_robot_computation", s.max_robot_computation},
          {"cpu_s", s.cpu_s},
          {"max_robot_cpu_s", s.max_robot_cpu_s},
          {"route_time_s", s.route_time_s},
          {"travel_m", s.travel_m},
          {"alpha_bytes", s.alpha_bytes},
          {"beta_bytes", s.beta_bytes},
          {"gamma_bytes", s.gamma_bytes}};
}

/// Which mechanism produced the results (issue #13): who found the routes, what was lost, which
/// repairs ran, whether the obstacle changes hit the route in use; route and driving lengths.
nlohmann::json mechanism_json(const std::vector<sim::NetSimMetrics>& runs) {
  nlohmann::json by = {{"relays", 0}, {"source_alone", 0}, {"none", 0}};
  int lost = 0, unacked = 0, late = 0, repairs = 0, change_runs = 0, hit = 0, ok = 0;
  int asked = 0, answered = 0, repaired = 0;  // change runs with a Repair asked / answered / taken
  double route = 0.0, source = 0.0, relay = 0.0;
  for (const auto& r : runs) {
    by[std::string(sim::to_string(r.route_found_by))] =
        by[std::string(sim::to_string(r.route_found_by))].get<int>() + 1;
    lost += r.paths_lost;
    unacked += r.paths_unacknowledged;
    late += r.paths_late;
    repairs += r.repairs_executed;
    if (r.changes_applied > 0) {
      ++change_runs;
      hit += r.changes_on_route > 0 ? 1 : 0;
      asked += r.repair_requests > 0 ? 1 : 0;
      answered += r.repair_answers > 0 ? 1 : 0;
      repaired += r.repairs_executed > 0 ? 1 : 0;
    }
    if (r.success) {
      ++ok;
      route += r.route_length_m;
      source += r.source_travel_m;
      relay += r.relay_travel_m;
    }
  }
  const double n = std::max(ok, 1);
  return {{"route_found_by", by},
          {"paths_lost", lost},
          {"paths_unacknowledged", unacked},
          {"paths_late", late},
          {"repairs_executed", repairs},
          {"change_runs", change_runs},
          {"change_runs_on_route", hit},
          {"change_runs_repair_asked", asked},
          {"change_runs_repair_answered", answered},
          {"change_runs_repaired", repaired},
          {"route_length_m", route / n},
          {"source_travel_m", source / n},
          {"relay_travel_m", relay / n}};
}

std::vector<sim::Method> methods_of(const std::string& method) {
  if (method == "both") return {sim::Method::kCentralized, sim::Method::kDecentralized};
  return {sim::parse_method(method)};
}

/// The paper scenario id, or 0 when `--scenario` is not 1..4.
int paper_id(const std::string& s) {
  return s.size() == 1 && s[0] >= '1' && s[0] <= '4' ? s[0] - '0' : 0;
}

Plan make_plan(const NetsimArgs& a) {
  Plan p;
  if (const int id = paper_id(a.scenario)) {
    if (a.runs < 1 || a.runs > sim::kTable7Runs)
      throw Error("--runs", 0, "expected 1.." + std::to_string(sim::kTable7Runs));
    p.label = "scenario" + a.scenario;
    p.title = "Scenario " + a.scenario;
    p.runs = a.runs;
    p.scenario = [id, seed = a.seed](int run) { return sim::make_paper_run(id, run, seed); };
    p.options.seed = a.seed;
    p.options.radio.loss = a.loss;
    apply_repair_overrides(a, p.options);
    p.methods = methods_of(a.method);
    return p;
  }
  std::error_code exists_error;  // a name the file system refuses is "not found", not an exception
  if (!std::filesystem::is_regular_file(a.scenario, exists_error))
    throw Error(a.scenario, 0,
                "scenario file not found (--scenario expects 1, 2, 3, 4 or a scenario YAML file)");
  auto file = std::make_shared<sim::NetSimScenarioFile>(sim::load_netsim_scenario(a.scenario));
  if (a.runs_given) std::cerr << "note: --runs is ignored for a scenario file (one run)\n";
  p.label = p.title = std::filesystem::path(a.scenario).stem().string();
  p.runs = 1;
  p.scenario = [file](int) { return file->scenario; };
  p.options = file->options;
  if (a.seed_given) p.options.seed = a.seed;
  if (a.loss_given) p.options.radio.loss = a.loss;
  apply_repair_overrides(a, p.options);
  // The file's method unless --method is given; a file without one runs both.
  p.methods = a.method_given || !file->has_method ? methods_of(a.method)
                                                  : std::vector<sim::Method>{file->options.method};
  return p;
}

void write_scenario(const NetsimArgs& a) {
  sim::NetSimOptions o;
  sim::NetSimScenario sc;
  if (const int id = paper_id(a.scenario)) {
    if (a.run < 1 || a.run > 16) throw Error("--run", 0, "expected 1..16");
    sc = sim::make_paper_run(id, a.run, a.seed);
    o.seed = a.seed;
    o.radio.loss = a.loss;
    apply_repair_overrides(a, o);
    if (a.method != "both") o.method = sim::parse_method(a.method);
  } else {
    const Plan p = make_plan(a);
    sc = p.scenario(1);
    o = p.options;
    if (p.methods.size() == 1) o.method = p.methods.front();
  }
  sim::save_netsim_scenario(a.write_scenario, sc, o);
  std::cout << "wrote " << a.write_scenario << "\n";
}

/// A run's transmissions by message type (all robots): {type: {messages, bytes}}; the trace
/// that says which messages made the traffic (issue #13).
nlohmann::json by_type_json(const sim::NetSimMetrics& m) {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [name, c] : m.by_type)
    out[name] = {{"messages", c.messages}, {"bytes", c.bytes}};
  return out;
}

/// Per robot: travel, work and what it sent, by message type.
nlohmann::json robots_json(const sim::NetSimMetrics& m) {
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t i = 0; i < m.robots.size(); ++i) {
    const auto& r = m.robots[i];
    nlohmann::json sent = nlohmann::json::object();
    for (int t = 1; t < network::kMessageTypeCount; ++t)
      if (r.sent_by_type[static_cast<std::size_t>(t)].messages > 0)
        sent[std::string(network::to_string(static_cast<network::MessageType>(t)))] =
            r.sent_by_type[static_cast<std::size_t>(t)].messages;
    out.push_back({{"id", i},
                   {"travel_m", r.travel_m},
                   {"work", r.work},
                   {"sent_messages", r.sent_messages},
                   {"sent_bytes", r.sent_bytes},
                   {"sent", sent}});
  }
  return out;
}

/// One run with every robot its own process over Cyclone DDS (voronav/dds/netsim_dds.hpp).
dds::DdsRunResult run_dds(const NetsimArgs& a, const sim::NetSimScenario& sc,
                          const sim::NetSimOptions& o, int run, bool record) {
  namespace fs = std::filesystem;
  const fs::path dir =
      fs::temp_directory_path() / ("voronav-netsim-dds-" + std::to_string(::getpid()));
  make_output_dir(dir, "the DDS run folder");
  struct Cleanup {
    fs::path d;
    ~Cleanup() {
      std::error_code ec;
      fs::remove_all(d, ec);
    }
  } cleanup{dir};
  const auto file = (dir / ("run" + std::to_string(run) + ".yaml")).string();
  sim::save_netsim_scenario(file, sc, o);
  dds::DdsRunOptions d;
  d.scenario_path = file;
  d.loss = o.radio.loss;
  d.work_dir = dir.string();
  d.timeout_s = a.dds_timeout_s;
  d.record = record;
  if (a.kill_robot >= 0) {
    d.kill_robot = static_cast<std::uint32_t>(a.kill_robot);
    d.kill_at_step = a.kill_at_step;
  }
  if (a.world_restart_at_step >= 0)
    d.world_restart_at_step = static_cast<std::uint32_t>(a.world_restart_at_step);
  if (!a.json)
    std::cerr << "netsim: run " << run << " (" << sim::to_string(o.method)
              << "): " << sc.robots.size() << " robot processes + 1 world process over DDS\n";
  auto r = dds::run_netsim_dds(d);
  if (!r.ok) throw Error("--transport dds", 0, "the multi-process run failed: " + r.error);
  return r;
}

std::string seconds_text(double s) {
  std::ostringstream os;
  os << std::fixed << std::setprecision(s < 10 ? 1 : 0) << s << " s";
  return os.str();
}

/// The injected faults of a DDS run and what became of the source's route, in words (issue #20):
/// e.g. "robot 5 killed at step 20 (10.0 s), declared dead at step 21; the source's route was
/// found at 94 s after 2 Searches, 1 repair; the source arrived at 130 s".
std::string fault_report(const NetsimArgs& a, const dds::DdsRunResult& r, double dt_s) {
  std::vector<std::string> parts;
  if (a.kill_robot >= 0) {
    std::string k = "robot " + std::to_string(a.kill_robot) + " killed at step " +
                    std::to_string(a.kill_at_step) + " (" + seconds_text(a.kill_at_step * dt_s) +
                    ")";
    bool declared = false;
    for (const auto& e : r.events)
      if (e.kind == "dead" && e.robot == a.kill_robot) {
        k += ", noticed by the world at step " + std::to_string(e.step);
        declared = true;
        break;
      }
    if (!declared && std::find(r.dead.begin(), r.dead.end(),
                               static_cast<std::uint32_t>(a.kill_robot)) != r.dead.end())
      k += ", declared dead by the world process";
    parts.push_back(k);
  }
  if (a.world_restart_at_step >= 0)
    parts.push_back("the world process killed after step " +
                    std::to_string(a.world_restart_at_step) + " and " +
                    (r.world_restarts > 0 ? "resumed by a new one" : "not resumed"));
  if (parts.empty()) return {};
  std::string out;
  for (const auto& p : parts)
    out += (out.empty() ? "" : "; ") + p;
  const auto& m = r.metrics;
  if (m.route_time_s >= 0) {
    out += "; the source's route was found at " + seconds_text(m.route_time_s) + " after " +
           std::to_string(m.search_attempts) + " Search" + (m.search_attempts == 1 ? "" : "es");
    if (m.repairs > 0)
      out += ", " + std::to_string(m.repairs) + " repair" + (m.repairs == 1 ? "" : "s") + " (" +
             std::to_string(m.repairs_executed) + " local Repair" +
             (m.repairs_executed == 1 ? "" : "s") + " with a detour)";
  } else {
    out += "; the source found no route after " + std::to_string(m.search_attempts) + " Search" +
           (m.search_attempts == 1 ? "" : "es");
  }
  if (m.paths_lost > 0)
    out += " (" + std::to_string(m.paths_lost) + " Path answer" + (m.paths_lost == 1 ? "" : "s") +
           " lost at a dead relay)";
  out += m.arrival_time_s >= 0 ? "; the source arrived at " + seconds_text(m.arrival_time_s)
                               : "; the source did not arrive";
  return out;
}

nlohmann::json dds_events_json(const std::vector<dds::DdsEvent>& events) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& e : events)
    out.push_back({{"t_s", e.t_s},
                   {"step", e.step},
                   {"event", e.kind},
                   {"robot", e.robot},
                   {"detail", e.detail}});
  return out;
}

/// The replay/bag recording of a DDS run: what the processes recorded (trace files), plus the
/// faults as events.
report::Recording dds_recording(const sim::NetSimScenario& sc, const dds::DdsRunResult& r,
                                double range_m) {
  sim::NetSimResult res;
  res.metrics = r.metrics;
  res.recording = r.recording;
  auto rec = netsim_recording(sc, res, range_m);
  rec.title += " (one process per robot, Cyclone DDS)";
  for (const auto& e : r.events) {
    if (e.kind == "change") continue;  // already there from the scenario's changes
    rec.events.push_back(
        {e.t_s, e.kind == "killed" ? "kill" : e.kind, e.detail, static_cast<int>(e.robot)});
  }
  std::stable_sort(rec.events.begin(), rec.events.end(),
                   [](const auto& x, const auto& y) { return x.t < y.t; });
  return rec;
}

void run(const NetsimArgs& a) {
  if (!a.write_scenario.empty()) {
    write_scenario(a);
    return;
  }
  if (a.transport != "sim" && a.transport != "dds")
    throw Error("--transport", 0, "expected 'sim' or 'dds', got '" + a.transport + "'");
  if (a.transport != "dds" && (a.kill_robot >= 0 || a.world_restart_at_step >= 0))
    throw Error("--kill-robot", 0, "fault injection needs --transport dds");
  const Plan plan = make_plan(a);
  const auto& methods = plan.methods;
  std::map<std::string, double> wall;
  nlohmann::json out = nlohmann::json::object();
  nlohmann::json per_run = nlohmann::json::array();
  std::map<std::string, std::vector<sim::NetSimMetrics>> by_method;
  // The runs the replay page (--out) and the bag (--mcap) show, of the last method.
  const int page_run = std::min(plan.runs, 5), bag_run = std::min(plan.runs, 2);
  std::map<int, dds::DdsRunResult> recorded;  // --transport dds: those runs, as recorded
  for (const auto& m : methods) {
    std::vector<sim::NetSimMetrics> all;
    for (int run = 1; run <= plan.runs; ++run) {
      const auto sc = plan.scenario(run);
      sim::NetSimOptions o = plan.options;
      o.method = m;
      nlohmann::json extra = nlohmann::json::object();
      {
        const auto done = static_cast<double>(
            (&m - methods.data()) * static_cast<std::ptrdiff_t>(plan.runs) + (run - 1));
        set_progress(done / static_cast<double>(methods.size() * plan.runs),
                     "of the runs: run " + std::to_string(run) + " of " +
                         std::to_string(plan.runs) + " (" + std::string(sim::to_string(m)) + ")");
      }
      if (a.transport == "dds") {
        const bool record = m == methods.back() && ((!a.out.empty() && run == page_run) ||
                                                    (!a.mcap.empty() && run == bag_run));
        auto r = run_dds(a, sc, o, run, record);
        all.push_back(r.metrics);
        extra = {{"processes", sc.robots.size() + 1},
                 {"wall_s", r.wall_s},
                 {"dead_robots", r.dead},
                 {"world_restarts", r.world_restarts},
                 {"events", dds_events_json(r.events)}};
        if (const auto words = fault_report(a, r, o.dt_s); !words.empty()) {
          extra["faults"] = words;
          clear_progress_line();
          std::cerr << "netsim: run " << run << " (" << sim::to_string(m) << "): " << words << "\n";
        }
        if (record) recorded[run] = std::move(r);
      } else {
        all.push_back(sim::run_netsim(sc, o).metrics);
        extra = {{"wall_s", all.back().wall_s}};
      }
      wall[std::string(sim::to_string(m))] += extra["wall_s"].get<double>();
      const auto& r = all.back();
      per_run.push_back({{"method", std::string(sim::to_string(m))},
                         {"run", run},
                         {"success", r.success},
                         {"traffic_bytes", r.traffic_bytes},
                         {"messages", r.messages},
                         {"computation", r.computation},
                         {"max_robot_computation", r.max_robot_computation},
                         {"cpu_s", r.cpu_s},
                         {"max_robot_cpu_s", r.max_robot_cpu_s},
                         {"route_time_s", r.route_time_s},
                         {"travel_m", r.travel_m},
                         {"route_length_m", r.route_length_m},
                         {"source_travel_m", r.source_travel_m},
                         {"relay_travel_m", r.relay_travel_m},
                         {"route_found_by", std::string(sim::to_string(r.route_found_by))},
                         {"route_robots", r.route_robots},
                         {"paths_lost", r.paths_lost},
                         {"paths_unacknowledged", r.paths_unacknowledged},
                         {"paths_late", r.paths_late},
                         {"repairs_executed", r.repairs_executed},
                         {"repair_requests", r.repair_requests},
                         {"source_repair_requests", r.source_repair_requests},
                         {"repair_answers", r.repair_answers},
                         {"changes", sc.changes.size()},
                         {"changes_applied", r.changes_applied},
                         {"changes_on_route", r.changes_on_route},
                         {"replans", r.replans},
                         {"search_attempts", r.search_attempts},
                         {"point_searches", r.point_searches},
                         {"search_copies_ignored", r.search_copies_ignored},
                         {"sensing_walks", r.sensing_walks},
                         {"sensing_walk_m", r.sensing_walk_m},
                         {"repair_sense_walks", r.repair_sense_walks},
                         {"repair_sense_walk_m", r.repair_sense_walk_m},
                         {"repair_sense_answers", r.repair_sense_answers},
                         {"route_used_sensing", r.route_used_sensing},
                         {"repairs", r.repairs},
                         {"sent_by_type", by_type_json(r)},
                         {"simulated_s", r.simulated_s},
                         {"robot_count", sc.robots.size()},
                         {"source", sc.source},
                         {"source_start", pose_json({sc.robots[sc.source], 0.0})},
                         {"destination", pose_json({sc.destination, 0.0})},
                         {"robots", robots_json(r)}});
      sim::SourceRepairTrace::fields(
          [&](const char* name, auto member) { per_run.back()[name] = r.*member; });
      per_run.back().update(extra);
    }
    out[std::string(sim::to_string(m))] = summary_json(sim::summarize(all));
    out[std::string(sim::to_string(m))].update(mechanism_json(all));
    auto& mine = out[std::string(sim::to_string(m))]["per_run"] = nlohmann::json::array();
    for (const auto& pr : per_run)
      if (pr["method"] == std::string(sim::to_string(m))) {
        auto q = pr;
        q.erase("robots");
        mine.push_back(q);
      }
    out[std::string(sim::to_string(m))]["transport"] = a.transport;
    out[std::string(sim::to_string(m))]["wall_s"] =
        wall[std::string(sim::to_string(m))] / plan.runs;
    by_method[std::string(sim::to_string(m))] = all;
  }
  auto recording_of = [&](int run) {
    const auto sc = plan.scenario(run);
    sim::NetSimOptions o = plan.options;
    o.method = methods.back();
    if (const auto it = recorded.find(run); it != recorded.end())
      return dds_recording(sc, it->second, o.radio.range_m);
    o.record = true;
    return netsim_recording(sc, sim::run_netsim(sc, o), o.radio.range_m);
  };
  if (!a.out.empty()) {
    make_output_dir(a.out, "--out");
    std::ofstream f(std::filesystem::path(a.out) / ("netsim_" + plan.label + ".json"));
    if (!f) throw Error(a.out, 0, "cannot write the results");
    f << nlohmann::json{{"frame_id", "map"}, {"summary", out}, {"runs", per_run}}.dump(2) << "\n";
    // The replay page: run 5 (the first with an obstacle change, Table 7) of the last method,
    // run again with recording on (--transport dds: the recorded multi-process run itself).
    report::write_replay_html(recording_of(page_run),
                              (std::filesystem::path(a.out) / "index.html").string());
  }
  // Run 2 (or 1) of the last method as a ROS 2 bag; with --transport dds what the processes
  // recorded (poses, messages, faults), not an in-process re-run.
  if (!a.mcap.empty()) bag::write_run_bag(recording_of(bag_run), a.mcap);
  if (!a.plots.empty()) save_plots(a.plots, plan.label, plan.title, by_method);
  if (a.json) {
    // Frames and units as the other commands give them (docs/ros.md); the per-method summaries
    // stay at the top level under their method names.
    nlohmann::json j = out;
    j["frame_id"] = "map";
    j["units"] = {{"time", "s"},
                  {"length", "m"},
                  {"traffic", "bytes"},
                  {"computation", "work units (cells + point pairs)"},
                  {"success_rate", "fraction"}};
    j["methods"] = nlohmann::json::array();
    for (auto m : methods)
      j["methods"].push_back(std::string(sim::to_string(m)));
    j["input"] = {{"scenario", a.scenario},
                  {"runs", plan.runs},
                  {"seed", plan.options.seed},
                  {"loss", plan.options.radio.loss},
                  {"transport", a.transport},
                  {"radio_range_m", plan.options.radio.range_m},
                  {"sensing_range_m", plan.options.sensing_range_m},
                  {"speed_mps", plan.options.speed_mps},
                  {"dt_s", plan.options.dt_s}};
    if (a.kill_robot >= 0) {
      j["input"]["kill_robot"] = a.kill_robot;
      j["input"]["kill_at_step"] = a.kill_at_step;
    }
    if (a.world_restart_at_step >= 0) j["input"]["world_restart_at_step"] = a.world_restart_at_step;
    std::cout << j.dump(2) << "\n";
    return;
  }
  for (auto it = out.begin(); it != out.end(); ++it) {
    const auto& v = it.value();
    std::cout << it.key() << ": success " << v["success_rate"].get<double>() * 100 << " %, traffic "
              << v["traffic_bytes"].get<double>() << " B in " << v["messages"].get<double>()
              << " messages, computation " << v["computation"].get<double>() << " (max per robot "
              << v["max_robot_computation"].get<double>() << "), ";
    // route_time_s is the mean over the runs that found a route.
    if (v["success_rate"].get<double>() > 0.0)
      std::cout << "route after " << v["route_time_s"].get<double>() << " s";
    else
      std::cout << "no route found";
    std::cout << ", travel " << v["travel_m"].get<double>() << " m\n";
  }
}

void setup(CLI::App& app) {
  auto args = std::make_shared<NetsimArgs>();
  auto* c =
      app.add_subcommand("netsim",
                         "Networked robots find a route for one of them (the source) to a "
                         "destination, by passing Voronoi points from robot to robot "
                         "(decentralized) or by asking every robot for its map (centralized); "
                         "from Kim, 'Decentralized robot navigation in dynamic environments', "
                         "M.Sc. thesis, 2010");
  c->add_option("--scenario", args->scenario,
                "1, 2, 3 or 4: the thesis's test scenarios (1: 6 robots in 40 m x 40 m, 2: 6 "
                "robots in 80 m x 80 m, 3: 12 robots in 40 m, 4: 12 robots in 80 m, generated "
                "office worlds), or a scenario file (YAML, docs/formats.md; one run)");
  auto* method = c->add_option("--method", args->method,
                               "centralized|decentralized|both (default: both, or the file's)");
  auto* runs = c->add_option("--runs", args->runs,
                             "how many of the thesis's 16 runs per scenario (1..16: 4 robot "
                             "placements, first without then with 1, 2 or 3 obstacle changes)");
  c->add_option("--run", args->run, "the run (1..16) that --write-scenario writes");
  c->add_option("--transport", args->transport,
                "sim (every robot in this process, simulated radio) | dds (one process per "
                "robot plus a world process, Cyclone DDS)")
      ->capture_default_str();
  c->add_option("--kill-robot", args->kill_robot,
                "dds: fault injection, this robot's process (id from 0) dies after "
                "--kill-at-step; what followed is reported on stderr and in the JSON")
      ->check(non_negative());
  c->add_option("--kill-at-step", args->kill_at_step,
                "dds: the simulation step after which it dies [steps of dt_s, 0.2 s by default]");
  c->add_option("--world-restart-at-step", args->world_restart_at_step,
                "dds: the world process dies after this step [steps] and a new one resumes "
                "the run");
  c->add_option("--dds-timeout", args->dds_timeout_s, "dds: limit for one run [s]")
      ->capture_default_str();
  auto* seed = c->add_option("--seed", args->seed,
                             "seed of the generated worlds and robot placements (a scenario "
                             "file: overrides its options.seed)")
                   ->check(non_negative());
  auto* loss =
      c->add_option("--loss", args->loss, "probability that a radio message is lost [0..1]");
  c->add_option("--repair-fix-answer", args->repair_fix_answer,
                "true|false: the decentralized source repairs a Repair answer it refused "
                "(blocked in its map) on its own map instead of waiting (options key "
                "repair_fix_answer; overrides a scenario file's)");
  c->add_option("--repair-expand-hops", args->repair_expand_hops,
                "0..255: an unanswered decentralized Repair is sent again with twice the hop "
                "limit, up to this many hops (0 = off; options key repair_expand_hops; "
                "overrides a scenario file's)")
      ->check(CLI::Range(0, 255));
  c->add_option("--repair-fix-seen-only", args->repair_fix_seen_only,
                "true|false: with --repair-fix-answer, the source's A* repair of a refused answer "
                "first keeps to space seen free (options key repair_fix_seen_only; overrides a "
                "scenario file's)");
  c->add_option("--repair-sense-walk", args->repair_sense_walk,
                "true|false: the relay nearest the blocked decentralized source walks to sense "
                "the break when it knows no way round or had not seen the change, and answers "
                "its Repair from what it sensed (options key repair_sense_walk, default true; "
                "overrides a scenario file's)");
  c->add_option("--repair-sense-wait-s", args->repair_sense_wait_s,
                ">= 0: with --repair-sense-walk, how long the source waits for a relay that "
                "walks to sense the break, and how long that relay keeps at it [s] (options key "
                "repair_sense_wait_s; overrides a scenario file's)")
      ->check(non_negative());
  c->add_option("--repair-walk-keep-ratio", args->repair_walk_keep_ratio,
                ">= 0: with --repair-fix-answer, when the walk onto a refused answer the "
                "source repaired by A* is blocked, it plans again to the same point of the answer "
                "while the walk is at most K times the first walk (or the answer's piece), else "
                "it drops the point (0 = always drop; options key repair_walk_keep_ratio; "
                "overrides a scenario file's)")
      ->check(non_negative());
  c->add_option("--write-scenario", args->write_scenario,
                "write --scenario 1..4 --run K (or the given file) as a scenario file naming "
                "--method (decentralized for both) and exit")
      ->check(output_file());
  c->add_option("--out", args->out,
                "folder for netsim_<scenario>.json (every run) and index.html (the replay page)")
      ->check(output_dir());
  c->add_option(
      "--mcap", args->mcap,
      "Write one run as a ROS 2 bag (MCAP): /map, /plan, /tf, /robots, /messages, /events "
      "(docs/ros.md)");
  c->add_option("--plots", args->plots,
                "folder for bar charts (PNG) of traffic, computation, CPU time and travel per run")
      ->check(output_dir());
  add_quiet_flag(c);
  c->add_flag("--json", args->json,
              "JSON output: a summary per method, every run, frame_id, units, the inputs "
              "(docs/ros.md)");
  c->callback([args, method, runs, seed, loss] {
    args->method_given = method->count() > 0;
    args->runs_given = runs->count() > 0;
    args->seed_given = seed->count() > 0;
    args->loss_given = loss->count() > 0;
    run(*args);
  });
}

const Command reg{{"netsim", setup, 60}};

}  // namespace
}  // namespace voronav::cli
