// A synthetic but realistic recording for trying the replay page before the simulator feeds it
// (issue 9, `voronav replay --example`): a 32 m x 20 m office (corridor and five rooms) at
// 0.1 m/cell, three robots driving planned routes, a box that appears in the corridor at t = 6 s
// so that robot 1 re-plans around it, messages between robots, the region labels, the medial axis
// (Voronoi) of every room and a topological graph as layers, and the explored-area coverage
// computed from the tracks by ray casting. Deterministic: no randomness.
#pragma once

#include "voronav/report/recording.hpp"

namespace voronav::report {

struct ExampleOptions {
  double sample_period_s = 0.2;    ///< [s] spacing of track samples, > 0
  double sensor_range_m = 3.0;     ///< [m] range of the simulated range sensor for coverage, > 0
  double coverage_period_s = 0.5;  ///< [s] spacing of coverage samples, > 0
  double radio_range_m = 15.0;     ///< [m] robots further apart do not exchange messages
};

[[nodiscard]] Recording make_example_recording(const ExampleOptions& options = {});

}  // namespace voronav::report
