// voronav map: builds an occupancy grid (seed 003, eq. 1-3) from a simulated sonar or laser sweep
// over a ground-truth map and reports how many cells agree with the truth.
#include <filesystem>
#include <iostream>

#include "cli_common.hpp"
#include "command.hpp"
#include "voronav/core/error.hpp"
#include "voronav/mapping/occupancy_map.hpp"
#include "voronav/mapping/sweep.hpp"
#include "voronav/render/figure.hpp"

namespace voronav::cli {
namespace {

struct MapArgs {
  std::filesystem::path map, png;
  std::string sensor = "laser";
  int poses = 100;
  double range = 0.0;  // 0 = sensor default
  double clearance = 0.3;
  double noise = 0.0;
  std::uint64_t seed = 1;
  bool json = false;
};

void run(const MapArgs& a) {
  if (a.sensor != "laser" && a.sensor != "sonar")
    throw Error("--sensor", 0, "expected laser or sonar, got '" + a.sensor + "'");
  const MapContext ctx = load_map_context(a.map, false);
  const BinaryGrid truth = binarize(ctx.map.grid);
  const GridGeometry& geo = truth.geometry();
  mapping::SweepOptions opt;
  opt.sensor = a.sensor == "laser" ? mapping::SweepSensor::kLaser : mapping::SweepSensor::kSonar;
  opt.poses = a.poses;
  opt.range = a.range;
  opt.clearance = a.clearance;
  opt.noise_stddev = a.noise;
  opt.seed = a.seed;
  const mapping::SweepResult sweep = mapping::simulate_sweep(truth, opt);
  const mapping::OccupancyMap& m = sweep.map;
  const mapping::CellAgreement& ag = sweep.agreement;
  if (!a.png.empty()) {
    render::Figure fig(geo, {.title = a.sensor + " map, " + std::to_string(a.poses) + " poses"});
    fig.occupancy(m.to_occupancy_grid());
    fig.save(a.png);
  }
  if (a.json) {
    print_json({{"map", a.map.string()},
                {"sensor", a.sensor},
                {"poses", a.poses},
                {"agreement", ag.agreement},
                {"observed", ag.observed},
                {"compared_cells", ag.compared}});
    return;
  }
  std::cout << "sensor:    " << a.sensor << ", " << a.poses << " poses\n"
            << "observed:  " << 100.0 * ag.observed << " % of the cells\n"
            << "agreement: " << 100.0 * ag.agreement << " % of the observed cells\n";
}

void setup(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "map", "Build an occupancy grid from a simulated sonar/laser sweep over a ground-truth map");
  auto args = std::make_shared<MapArgs>();
  cmd->add_option("--map", args->map, "Ground-truth map file (ROS .yaml, .map, .png/.pgm)")
      ->required();
  cmd->add_option("--sensor", args->sensor, "laser | sonar (a ring of 16)")->capture_default_str();
  cmd->add_option("--poses", args->poses, "Number of random sensor poses")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  cmd->add_option("--range", args->range, "Maximum range [m] (0 = 10 m laser, 5 m sonar)")
      ->check(non_negative());
  cmd->add_option("--clearance", args->clearance, "Poses keep at least this from obstacles [m]")
      ->check(non_negative())
      ->capture_default_str();
  cmd->add_option("--noise", args->noise, "Laser range noise sigma [m]")->check(non_negative());
  cmd->add_option("--seed", args->seed, "Random seed (poses, noise)")
      ->check(non_negative())
      ->capture_default_str();
  cmd->add_option("--png", args->png, "Picture of the built map");
  cmd->add_flag("--json", args->json, "JSON output: agreement, observed (fractions 0..1)");
  add_quiet_flag(cmd);
  cmd->callback([args] { run(*args); });
}

const Command reg{{"map", setup, 35}};

}  // namespace
}  // namespace voronav::cli
