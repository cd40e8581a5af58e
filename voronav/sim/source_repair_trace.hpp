// SourceRepairTrace: what happened to the source's Repairs in one run of the networked-robot
// simulator (seed 000, Tables 4-5, and the options beyond the paper in netsim.hpp). The counters
// are kept by the source's agent (AgentReport), copied into the run's metrics (NetSimMetrics)
// and written to every JSON output (`voronav netsim --json`, the DDS robot processes' reports).
// Both structs derive from this one and every output walks fields(), so a new counter is
// declared and named here once instead of in each struct, copy and writer.
//
// Why the run's other counters (paths_lost, repairs_executed, repair_requests, repair_answers,
// point_searches, changes_on_route, sensing_walks, ...) are not fields here: aggregate_metrics()
// copies this whole struct from the source's report (`static_cast<SourceRepairTrace&>(M) = s`),
// while most of those counters are sums over every robot (and repair_requests is reported both
// summed and as the source's own, source_repair_requests). A summed counter placed here would be
// overwritten by the source's value. They stay named in AgentReport / NetSimMetrics and in each
// writer (netsim_json.cpp, cmd_netsim.cpp, bind_sim.cpp).
#pragma once

namespace voronav::sim {

struct SourceRepairTrace {
  /// Repaired routes that reached the source, and those it refused as blocked in its own map.
  int repair_answers_received = 0, repair_answers_refused = 0;
  /// Every received answer is taken, refused or dropped: taken = spliced into the route as it
  /// came; dropped = neither (a later answer to a Repair already answered, or a detour whose
  /// splice point is behind the source or not on its route).
  int repair_answers_taken = 0, repair_answers_dropped = 0;
  /// repair_share_met_blocks: Repairs sent again with cells learned from a refused answer, and
  /// the most cells one of its Repairs carried.
  int repair_reasks = 0, repair_cells_max = 0;
  /// Where executed Repairs came from: the source's own detour (Table 5), and, with
  /// repair_fix_answer, a refused answer it repaired by its own points / by A* on its own map.
  int repairs_own = 0, repair_answers_fixed = 0, repair_answers_fixed_walk = 0;
  /// repair_expand_hops: new Repairs sent with a larger hop limit after none came back.
  int repair_rings_expanded = 0;
  /// repair_fix_seen_only: of repair_answers_fixed_walk, the walks kept to space seen free.
  int repair_answers_fixed_seen = 0;
  /// repair_walk_keep_ratio: replans of a blocked walk that kept the walk's route point.
  int repair_walk_targets_kept = 0;
  /// repair_sense_walk: answers from a relay that sensed the break (received, taken).
  int repair_answers_sensed = 0, repair_answers_sensed_taken = 0;

  /// Calls f(name, member pointer) for every counter, in output order; the name is the JSON key.
  template <class F>
  static void fields(F&& f) {
    using T = SourceRepairTrace;
    f("repair_answers_received", &T::repair_answers_received);
    f("repair_answers_refused", &T::repair_answers_refused);
    f("repair_answers_taken", &T::repair_answers_taken);
    f("repair_answers_dropped", &T::repair_answers_dropped);
    f("repair_reasks", &T::repair_reasks);
    f("repair_cells_max", &T::repair_cells_max);
    f("repairs_own", &T::repairs_own);
    f("repair_answers_fixed", &T::repair_answers_fixed);
    f("repair_answers_fixed_walk", &T::repair_answers_fixed_walk);
    f("repair_rings_expanded", &T::repair_rings_expanded);
    f("repair_answers_fixed_seen", &T::repair_answers_fixed_seen);
    f("repair_walk_targets_kept", &T::repair_walk_targets_kept);
    f("repair_answers_sensed", &T::repair_answers_sensed);
    f("repair_answers_sensed_taken", &T::repair_answers_sensed_taken);
  }
};

}  // namespace voronav::sim
