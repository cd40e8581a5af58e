// Glue between run results and the replay page (report::Recording): map layers from a
// topological map, robot tracks from a coordinated schedule. Lives in the app because it joins
// modules that do not depend on each other (report knows only core).
#pragma once

#include <vector>

#include "voronav/coordination/coordinator.hpp"
#include "voronav/exploration/explorer.hpp"
#include "voronav/report/recording.hpp"
#include "voronav/sim/netsim.hpp"
#include "voronav/topology/topological_map.hpp"

namespace voronav::cli {

/// Adds the Voronoi diagram, the regions and the topological graph as toggleable layers.
void add_topology_layers(report::Recording& rec, const topology::TopologicalMap& topo,
                         bool visible = true);

/// Robot tracks (sampled every `dt` [s]) of a coordinated schedule: each robot waits at its start
/// for its delay, drives its timed path, then stays at its goal.
void add_schedule_tracks(report::Recording& rec, const std::vector<coordination::Agent>& agents,
                         const coordination::CoordinationResult& result, double dt = 0.2);

/// A recording of a coordination run on `map`, ready for write_replay_html.
[[nodiscard]] report::Recording coordination_recording(
    const OccupancyGrid& map, const std::vector<coordination::Agent>& agents,
    const coordination::CoordinationResult& result);

/// A recording of one networked-robots run (needs NetSimOptions::record): robot tracks, unicast
/// messages as lines between robots (broadcasts to every robot in `radio_range_m`), the source's
/// route and the obstacle changes at the time they happened.
[[nodiscard]] report::Recording netsim_recording(const sim::NetSimScenario& scenario,
                                                 const sim::NetSimResult& result,
                                                 double radio_range_m);

/// A recording of a swarm exploration run: the team's final map, robot tracks (ground truth),
/// the Voronoi tree and its feature points as layers, each robot's tree route, and coverage
/// over time.
[[nodiscard]] report::Recording exploration_recording(const exploration::ExplorationResult& result);

}  // namespace voronav::cli
