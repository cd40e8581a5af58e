// voronav map: builds an occupancy grid (seed 003, eq. 1-3) from a simulated sonar or laser sweep
// over a ground-truth map and reports how many cells agree with the truth.
#include <filesystem>
#include <iostream>
#include <random>

#include "cli_common.hpp"
#include "command.hpp"
#include "voronav/core/error.hpp"
#include "voronav/field/distance_transform.hpp"
#include "voronav/mapping/occupancy_map.hpp"
#include "voronav/mapping/range_simulation.hpp"
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
  // Sensor poses: random free cells at least `clearance` from obstacles (fixed seed).
  const field::DistanceField df = field::distance_transform(truth, {.border_is_blocked = true});
  std::vector<Cell> candidates;
  const double min_d = a.clearance / geo.resolution;
  for (std::size_t i = 0; i < truth.size(); ++i)
    if (!truth[i] && std::sqrt(static_cast<double>(df.squared_distance[i])) >= min_d)
      candidates.push_back(geo.cell_at(i));
  if (candidates.empty())
    throw Error(a.map.string(), 0, "no free cell with the requested --clearance");
  std::mt19937_64 rng(a.seed);
  std::uniform_int_distribution<std::size_t> pick(0, candidates.size() - 1);
  std::uniform_real_distribution<double> yaw(-std::numbers::pi, std::numbers::pi);
  mapping::OccupancyMap m(geo);
  mapping::LaserSimulationOptions laser;
  laser.noise_stddev = a.noise;
  mapping::SonarRingOptions sonar;
  if (a.range > 0) laser.max_range = sonar.max_range = a.range;
  mapping::SonarModelOptions sonar_model;
  sonar_model.max_range = sonar.max_range;
  mapping::LaserModelOptions laser_model;
  laser_model.max_range = laser.max_range;
  for (int k = 0; k < a.poses; ++k) {
    const Pose2 pose{geo.cell_center(candidates[pick(rng)]), yaw(rng)};
    laser.seed = a.seed + static_cast<std::uint64_t>(k);
    if (a.sensor == "laser")
      m.insert_scan(mapping::simulate_laser_scan(truth, pose, laser), laser_model);
    else
      m.insert_scan(mapping::simulate_sonar_ring(truth, pose, sonar), sonar_model);
  }
  const OccupancyGrid built = m.threshold();
  const mapping::CellAgreement ag = mapping::cell_agreement(built, truth);
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
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--clearance", args->clearance, "Poses keep at least this from obstacles [m]")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--noise", args->noise, "Laser range noise sigma [m]")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--seed", args->seed, "Random seed (poses, noise)")->capture_default_str();
  cmd->add_option("--png", args->png, "Picture of the built map");
  cmd->add_flag("--json", args->json, "JSON output: agreement, observed (fractions 0..1)");
  cmd->callback([args] { run(*args); });
}

const Command reg{{"map", setup, 35}};

}  // namespace
}  // namespace voronav::cli
