// Scenario files of `voronav netsim` (YAML, docs/formats.md): the world map (any format
// io::load_map reads, e.g. the real ROS maps), the robots (explicit or placed "half on the Voronoi
// diagram, half at random"), source, destination, obstacle changes and every NetSimOptions field,
// so that a run can be described outside the code, repeated, and handed to robot processes.
// Errors name the file, the line and what was expected; save + load is the identity.
#pragma once

#include <string>

#include "voronav/sim/netsim.hpp"

namespace voronav::sim {

struct NetSimScenarioFile {
  NetSimScenario scenario;
  NetSimOptions options;   ///< defaults overridden by what the file gives
  std::string world_path;  ///< resolved path of the world map
  /// Whether the file gives options.method (otherwise options.method is the default and a caller
  /// may run both methods).
  bool has_method = false;
};

/// Throws voronav::Error naming the file, the line and what was expected.
[[nodiscard]] NetSimScenarioFile load_netsim_scenario(const std::string& path);

/// Writes `path` (YAML) and the world map beside it as a ROS map (<stem>_world.yaml + .pgm), so
/// that load_netsim_scenario(path) gives back the same scenario and options (every field except
/// options.record). The world must hold only kFree / kOccupied cells and every change value must
/// be kFree or kOccupied; throws voronav::Error otherwise or when a file cannot be written.
void save_netsim_scenario(const std::string& path, const NetSimScenario& scenario,
                          const NetSimOptions& options);

}  // namespace voronav::sim
