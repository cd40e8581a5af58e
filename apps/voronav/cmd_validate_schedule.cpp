// voronav validate-schedule FILE: checks any schedule (JSON or YAML, see
// voronav/coordination/schedule_io.hpp) in continuous time: no two robot discs overlap at any
// time. Exit code 0 when valid, 1 when not, 2 for a malformed file.
#include <filesystem>
#include <iostream>

#include "cli_common.hpp"
#include "command.hpp"
#include "voronav/coordination/schedule_io.hpp"
#include "voronav/coordination/verify.hpp"
#include "voronav/io/map_loader.hpp"

namespace voronav::cli {
namespace {

namespace co = coordination;

struct ValidateArgs {
  std::filesystem::path file;
  double tolerance = 1e-6;
  bool json = false;
};

void run(const ValidateArgs& a) {
  const co::Schedule s = co::read_schedule(a.file);
  co::VerifyOptions vo;
  vo.at_start = s.at_start;
  vo.at_goal = s.at_goal;
  vo.tolerance = a.tolerance;
  const std::vector<co::Trajectory> tr = co::trajectories(s);
  std::vector<double> radii;
  for (const auto& ag : s.agents)
    radii.push_back(ag.radius);
  co::Verification v = co::verify_trajectories(tr, radii, vo.tolerance);
  std::string map_checked;
  if (!s.map.empty()) {
    // The map named by the schedule, relative to the schedule file.
    std::filesystem::path mp = s.map;
    if (mp.is_relative()) mp = a.file.parent_path() / mp;
    const auto loaded = io::load_map(mp);
    co::check_map(v, tr, radii, binarize(loaded.grid), vo.tolerance);
    map_checked = mp.string();
  }
  // At most kShown conflicts (the earliest) are printed; conflict_count has them all, so a
  // thousand identical robots do not print half a million lines.
  constexpr std::size_t kShown = 100;
  double makespan = 0.0;
  for (const auto& t : tr)
    makespan = std::max(makespan, t.end_time());
  nlohmann::json conflicts = nlohmann::json::array();
  for (const auto& c : v.conflicts) {
    if (conflicts.size() == kShown) break;
    conflicts.push_back({{"a", s.agents[static_cast<std::size_t>(c.a)].id},
                         {"b", s.agents[static_cast<std::size_t>(c.b)].id},
                         {"time", c.time},
                         {"distance", c.distance},
                         {"radii", s.agents[static_cast<std::size_t>(c.a)].radius +
                                       s.agents[static_cast<std::size_t>(c.b)].radius}});
  }
  nlohmann::json walls = nlohmann::json::array();
  for (const auto& h : v.wall_hits) {
    walls.push_back({{"robot", s.agents[static_cast<std::size_t>(h.robot)].id},
                     {"time", h.time},
                     {"cell", {h.cell.x, h.cell.y}},
                     {"distance", h.distance}});
  }
  if (a.json) {
    print_json(
        {{"valid", v.valid},
         {"map", map_checked.empty() ? nlohmann::json(nullptr) : nlohmann::json(map_checked)},
         {"wall_hits", walls},
         {"agents", s.agents.size()},
         {"makespan", makespan},
         {"conflicts", conflicts},
         {"conflict_count", v.conflicts.size()},
         {"undecided_pairs", v.undecided_pairs},
         {"min_clearance", std::isfinite(v.min_clearance) ? nlohmann::json(v.min_clearance)
                                                          : nlohmann::json(nullptr)}});
  } else {
    std::cout << a.file.string() << ": " << s.agents.size() << " robots, makespan " << makespan
              << " s: " << (v.valid ? "valid" : "INVALID") << "\n";
    for (const auto& c : conflicts)
      std::cout << "  overlap " << c.dump() << "\n";
    if (v.conflicts.size() > conflicts.size())
      std::cout << "  ... and " << v.conflicts.size() - conflicts.size()
                << " more overlapping pairs\n";
    for (const auto& w : walls)
      std::cout << "  wall " << w.dump() << "\n";
  }
  if (!v.valid) exit_code() = 1;
}

void setup(CLI::App& app) {
  auto* cmd = app.add_subcommand("validate-schedule",
                                 "Check a schedule in continuous time: no two robots ever overlap");
  auto a = std::make_shared<ValidateArgs>();
  cmd->add_option("file", a->file, "schedule .json or .yaml")->required()->check(CLI::ExistingFile);
  cmd->add_option("--tolerance", a->tolerance, "accepted overlap depth [m]")
      ->check(non_negative())
      ->capture_default_str();
  cmd->add_flag("--json", a->json, "JSON output");
  cmd->callback([a] { run(*a); });
}

const Command reg{{"validate-schedule", setup, 41}};

}  // namespace
}  // namespace voronav::cli
