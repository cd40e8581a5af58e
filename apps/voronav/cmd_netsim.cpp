// `voronav netsim`: the networked-robot comparison of seed 000 (Tables 6–7): runs the
// decentralized (Voronoi points, Search/Path/Repair) and/or centralized (Request/Ack + A*) method
// on a paper scenario (1..4, 16 runs each) and prints the mean metrics, as JSON with --json.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "command.hpp"
#include "recordings.hpp"
#include "voronav/core/error.hpp"
#include "voronav/render/plot.hpp"
#include "voronav/report/replay_html.hpp"
#include "voronav/sim/scenarios.hpp"

namespace voronav::cli {
namespace {

struct NetsimArgs {
  std::string scenario = "1";
  std::string method = "both";
  int runs = 16;
  std::uint64_t seed = 1;
  double loss = 0.0;
  std::string out;
  std::string plots;
  bool json = false;
};

/// Figures 22-37 style: one value per run of Table 7, both methods side by side.
void save_plots(const std::string& dir, const std::string& scenario,
                const std::map<std::string, std::vector<sim::NetSimMetrics>>& runs) {
  std::filesystem::create_directories(dir);
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
                       .title = "Scenario " + scenario + ": " + f.title,
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
    plot.save(std::filesystem::path(dir) / ("scenario" + scenario + "_" + f.file + ".png"));
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

void run(const NetsimArgs& a) {
  int id = 0;
  try {
    std::size_t used = 0;
    id = std::stoi(a.scenario, &used);
    if (used != a.scenario.size()) id = 0;
  } catch (const std::exception&) {
    id = 0;
  }
  if (id < 1 || id > 4)
    throw Error(
        "--scenario", 0,
        "expected 1, 2, 3 or 4, got '" + a.scenario + "' (scenario files are not supported yet)");
  if (a.runs < 1 || a.runs > 16) throw Error("--runs", 0, "expected 1..16");
  std::vector<sim::Method> methods;
  if (a.method == "both") {
    methods = {sim::Method::kCentralized, sim::Method::kDecentralized};
  } else {
    methods = {sim::parse_method(a.method)};
  }
  nlohmann::json out = nlohmann::json::object();
  nlohmann::json per_run = nlohmann::json::array();
  std::map<std::string, std::vector<sim::NetSimMetrics>> by_method;
  for (auto m : methods) {
    std::vector<sim::NetSimMetrics> all;
    for (int run = 1; run <= a.runs; ++run) {
      const auto sc = sim::make_paper_run(id, run, a.seed);
      sim::NetSimOptions o;
      o.method = m;
      o.seed = a.seed;
      o.radio.loss = a.loss;
      all.push_back(sim::run_netsim(sc, o).metrics);
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
                         {"travel_m", r.travel_m}});
    }
    out[std::string(sim::to_string(m))] = summary_json(sim::summarize(all));
    by_method[std::string(sim::to_string(m))] = all;
  }
  if (!a.out.empty()) {
    std::filesystem::create_directories(a.out);
    std::ofstream f(std::filesystem::path(a.out) / ("netsim_scenario" + a.scenario + ".json"));
    if (!f) throw Error(a.out, 0, "cannot write the results");
    f << nlohmann::json{{"summary", out}, {"runs", per_run}}.dump(2) << "\n";
    // The replay page: run 2 (the first with an obstacle change, Table 7) of the last method,
    // run again with recording on.
    const auto sc = sim::make_paper_run(id, std::min(a.runs, 2), a.seed);
    sim::NetSimOptions o;
    o.method = methods.back();
    o.seed = a.seed;
    o.radio.loss = a.loss;
    o.record = true;
    report::write_replay_html(netsim_recording(sc, sim::run_netsim(sc, o), o.radio.range_m),
                              (std::filesystem::path(a.out) / "index.html").string());
  }
  if (!a.plots.empty()) save_plots(a.plots, a.scenario, by_method);
  if (a.json) {
    std::cout << out.dump(2) << "\n";
    return;
  }
  for (auto it = out.begin(); it != out.end(); ++it) {
    const auto& v = it.value();
    std::cout << it.key() << ": success " << v["success_rate"].get<double>() * 100 << " %, traffic "
              << v["traffic_bytes"].get<double>() << " B in " << v["messages"].get<double>()
              << " messages, computation " << v["computation"].get<double>() << " (max per robot "
              << v["max_robot_computation"].get<double>() << "), route after "
              << v["route_time_s"].get<double>() << " s, travel " << v["travel_m"].get<double>()
              << " m\n";
  }
}

void setup(CLI::App& app) {
  auto args = std::make_shared<NetsimArgs>();
  auto* c =
      app.add_subcommand("netsim", "Networked robots (seed 000): decentralized vs centralized");
  c->add_option("--scenario", args->scenario, "Table 6 scenario 1|2|3|4");
  c->add_option("--method", args->method, "centralized|decentralized|both");
  c->add_option("--runs", args->runs, "runs of Table 7 (1..16)");
  c->add_option("--seed", args->seed, "world/placement seed");
  c->add_option("--loss", args->loss, "radio message loss probability");
  c->add_option("--out", args->out, "directory for per-run JSON");
  c->add_option("--plots", args->plots, "directory for per-run bar charts (PNG)");
  c->add_flag("--json", args->json, "machine-readable output");
  c->callback([args] { run(*args); });
}

const Command reg{{"netsim", setup, 60}};

}  // namespace
}  // namespace voronav::cli
