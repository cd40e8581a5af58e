// The scenarios of seed 000, Table 6 (1: 6 robots 40x40 m, 2: 6 robots 80x80 m, 3: 12 robots
// 40x40 m, 4: 12 robots 80x80 m) and the 16 runs of Table 7 (4 placements x (initial + 1, 2 or 3
// obstacle changes)), built on generated office worlds. Half of the robots stand on the Voronoi
// diagram of the map, half at random free places; robot 0 is the source; the destination is a far
// reachable free place. Obstacle changes close doors (or put down boxes) on the routes in use,
// ahead of the sources, keeping the destination reachable. Also the scale worlds (100 / 1000
// robots).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "voronav/sim/netsim.hpp"
#include "voronav/sim/world.hpp"

namespace voronav::sim {

struct PaperScenario {
  int id = 1;
  int robots = 6;
  double size_m = 40.0;
};

/// Table 6; throws voronav::Error for an id outside 1..4.
[[nodiscard]] PaperScenario paper_scenario(int id);

struct PlacementOptions {
  int robots = 6;
  int changes = 0;              ///< obstacle changes (closed doors), 0..3 in Table 7
  double change_every_s = 4.0;  ///< change k happens k * this after the route is found
  double robot_radius_m = 0.2;
  std::uint64_t seed = 1;
};

/// Places robots, source, destination and changes in an office world.
[[nodiscard]] NetSimScenario place_robots(const OfficeWorld& world,
                                          const PlacementOptions& options);

/// Places robots on any ground-truth grid (kFree / kOccupied; anything else counts as blocked):
/// robot 0 (the source) at a random free place, then alternately one on the Voronoi diagram and
/// one at a random free place; every place keeps robot_radius_m + 0.1 m of clearance. Without
/// `destination`, the destination is the farthest reachable of random free candidates (as for
/// the office worlds); with one, the source is drawn until it can reach it. `options.changes`
/// must be 0 here (obstacle changes need doors: use the OfficeWorld overload). Throws
/// voronav::Error when there is no free space or no source reaches the destination.
[[nodiscard]] NetSimScenario place_robots(const OccupancyGrid& world,
                                          const PlacementOptions& options,
                                          std::optional<Vec2> destination = std::nullopt);

/// Replaces the changes of `sc` by up to `changes` obstacle changes on both methods' routes while
/// they are in use (issue #13): a door both sources drive through closes, or where none can close
/// without cutting off the destination a 0.8 m box is put down where both pass; each when the
/// source of each method is 1.5-3 m before it on its route (at_s for the decentralized method,
/// centralized_at_s for the centralized one: the same place and situation, at each method's own
/// time), keeping the destination reachable; later changes at least every_s after the previous
/// one for both. Where the two routes share no such place, the change is a pair of entries: a
/// door (else a box) on each method's route, each when its source is 1.5-3 m before it, both at
/// the same times (at_s only) and places for both methods, so each method meets one of them on
/// its route. Change k is timed on runs (default options, with the Repair options beyond the
/// paper pinned off whatever their defaults: scenarios.cpp probe_options) with changes 1..k-1
/// and kept only when a run of each method with it applies every change and meets it (one entry
/// of a pair) on the route ahead. Fewer changes when no candidate passes (the run records it).
/// So sc.changes has one entry per change, two per pair.
void time_changes_on_routes(const OfficeWorld& world, NetSimScenario& sc, int changes,
                            double every_s, double robot_radius_m);

/// The runs of Table 7 per paper scenario: 4 placements, each without and with 1, 2, 3 changes.
inline constexpr int kTable7Runs = 16;

/// Run `run` (1..16) of Table 7 for paper scenario `id`; `seed` varies the worlds. Runs 5..16
/// get their changes from time_changes_on_routes.
[[nodiscard]] NetSimScenario make_paper_run(int id, int run, std::uint64_t seed = 1);

/// A square office world of side `size_m` with `robots` robots (the scale runs).
[[nodiscard]] NetSimScenario make_scale_run(int robots, double size_m, std::uint64_t seed = 1);

/// Mean of the metrics of several runs (success_rate = fraction of successes; route_time_s and
/// travel over successful runs).
struct Summary {
  int runs = 0;
  double success_rate = 0.0;
  double traffic_bytes = 0.0;
  double messages = 0.0;
  double computation = 0.0;
  double max_robot_computation = 0.0;
  double cpu_s = 0.0;
  double max_robot_cpu_s = 0.0;
  double route_time_s = 0.0;
  double travel_m = 0.0;
  double alpha_bytes = 0.0, beta_bytes = 0.0, gamma_bytes = 0.0;
};
[[nodiscard]] Summary summarize(const std::vector<NetSimMetrics>& runs);

}  // namespace voronav::sim
