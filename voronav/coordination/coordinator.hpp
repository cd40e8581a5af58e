// coordinate(): the whole method of seed 002 for robots on fixed paths, plus the continuous-time
// correctness net: build the (M,D) network from the collision boxes, search a priority order
// (none | exhaustive | edf | ga), resolve the start delays, then verify the schedule in continuous
// time. If the verifier finds an overlap the boxes missed (possible only with a coarse
// node_spacing or foreign input), the lower-priority robot of that pair gets a larger minimum
// delay and the order is resolved again; every such repair is reported.
#pragma once

#include <string>
#include <vector>

#include "voronav/coordination/md_network.hpp"
#include "voronav/coordination/priority_search.hpp"
#include "voronav/coordination/verify.hpp"

namespace voronav::coordination {

struct CoordinateOptions {
  CollisionMapOptions map;  ///< node spacing, at-start / at-goal behaviour
  SearchOptions search;
  double tolerance = 1e-6;  ///< verifier tolerance [m]
  int max_repairs = 200;    ///< verifier-driven repairs before giving up
  bool verify = true;       ///< run the continuous-time check
};

struct CoordinationResult {
  ResolveStatus status = ResolveStatus::kOk;
  std::vector<int> order;           ///< robot indices, highest priority first
  std::vector<double> delays;       ///< start delay per robot [s]
  std::vector<double> arrivals;     ///< T^completed per robot [s]
  double makespan = 0.0;            ///< max arrival [s]
  double sum_of_arrivals = 0.0;     ///< [s]
  bool valid = false;               ///< the continuous-time check passed
  bool verified = false;            ///< the check was run
  int repairs = 0;                  ///< conflicts the boxes missed and that were repaired
  std::vector<Conflict> missed;     ///< those conflicts
  std::vector<Conflict> remaining;  ///< conflicts still present when valid == false
  std::size_t boxes = 0;            ///< collision boxes in the network
  SearchResult search;
  EdfResult edf;
  double time_ms = 0.0;  ///< wall time of network + search + resolution + verification
  std::string message;   ///< human-readable status
};

[[nodiscard]] CoordinationResult coordinate(const std::vector<Agent>& agents,
                                            const CoordinateOptions& options = {});

}  // namespace voronav::coordination
