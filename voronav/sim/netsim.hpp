// The networked-robot simulation of seed 000: robots with 3 m exact sensing and a 25 m simulated
// radio find a route for the source robot to a destination, by
//  - the decentralized method (Tables 1–5): Search messages carry the sender's open Voronoi
//    points and are forwarded only by robots whose open points continue them (relays that cannot
//    continue but are closer to the destination walk over and sense the gap, figure 18); the robot
//    whose area holds the destination answers with a Path message that travels back through the
//    relays, each waiting a little, selecting the shortest, saving it and prepending its own
//    piece (Table 3); a relay that senses a break sends Repair to its neighbours, any of which
//    that knows a detour answers (Tables 4–5). Added for a real network: hop-by-hop LinkAck
//    retries, a source retry that re-sends the same Search (same Num: nothing is cancelled),
//    a multi-hop fallback for Paths whose next relay is out of range, duplicate suppression, a
//    hop bound.
//  - the centralized baseline: the source floods a Request, every robot answers with an Ack
//    holding its whole local map (routed back hop by hop), the source plans A* over the merged
//    map with unknown = free, walks and senses by itself, replans on what it sees; a robot that
//    sees its map change tells the source (Notify), which requests all maps again and replans.
// Metrics follow eq. 1–9: traffic (bytes, messages; α, β, γ measured as mean sizes), computation
// (work units = cells + point pairs processed, and CPU time; total and max per robot), time until
// the source has a route, travel distance of all robots, success.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "voronav/core/occupancy.hpp"
#include "voronav/network/messages.hpp"
#include "voronav/network/sim_radio.hpp"
#include "voronav/network/voronoi_points.hpp"
#include "voronav/sim/source_repair_trace.hpp"

namespace voronav::sim {

enum class Method { kCentralized, kDecentralized };
/// Who produced the route the source drives (issue #13): `kRelays` when it holds open points
/// sensed by other robots and the source had not itself sensed a way to the destination when it
/// arrived; `kSourceAlone` otherwise; `kNone` when the source never had a route.
enum class RouteFoundBy : std::uint8_t { kNone, kRelays, kSourceAlone };
[[nodiscard]] std::string_view to_string(RouteFoundBy b);
/// Inverse of to_string; throws voronav::Error.
[[nodiscard]] RouteFoundBy parse_route_found_by(std::string_view s);
[[nodiscard]] std::string_view to_string(Method m);
/// "centralized" / "decentralized"; throws voronav::Error otherwise.
[[nodiscard]] Method parse_method(std::string_view s);

/// An obstacle change (Table 7): `cells` become `value` at the simulated time `at_s` when it is
/// >= 0, else `after_route_s` seconds after the source first has a route. With
/// `centralized_at_s` >= 0 the centralized method gets the change at that time instead of at_s
/// (the paper runs: the same door closes when each method's source is the same distance before
/// it on its route in use, scenarios.hpp time_changes_on_routes).
struct ObstacleChange {
  double after_route_s = 0.0;
  double at_s = -1.0;
  double centralized_at_s = -1.0;
  std::vector<Cell> cells;
  std::int8_t value = kOccupied;
};

struct NetSimScenario {
  OccupancyGrid world;       ///< ground truth (kFree / kOccupied)
  std::vector<Vec2> robots;  ///< initial positions [m]; robots[source] is the source
  std::size_t source = 0;
  Vec2 destination;  ///< [m]
  std::vector<ObstacleChange> changes;
  /// Throws voronav::Error when robots/destination are off the map or in obstacles, etc.
  void validate() const;
};

struct NetSimOptions {
  Method method = Method::kDecentralized;
  double sensing_range_m = 3.0;  ///< seed 000: ultrasonic range
  double speed_mps = 1.0;        ///< seed 000: 1 m/s
  double robot_radius_m = 0.2;
  double dt_s = 0.2;            ///< simulation step [s]
  double time_limit_s = 900.0;  ///< a run fails when the source has not arrived by then
  network::RadioOptions radio{};
  network::VoronoiPointsOptions points{};
  double path_wait_s = 0.5;  ///< Table 3 "wait for a little while" [s]
  /// A robot that cannot continue a Search waits this long for one it can continue before it
  /// walks over to sense the gap itself [s].
  double bridge_wait_s = 2.0;
  double search_timeout_s = 60.0;  ///< source re-sends the same Search (same Num) after this [s]
  /// From its second attempt on the source also walks toward the destination itself (as the
  /// centralized source does) while it waits; off by default: the source waits for the relays.
  bool source_walks_on_retry = false;
  // Scale options (docs/reproductions/networked.md, "Scale"). Off by default: the Table 6/7
  // results are those of the protocol without them (with them, scenarios 1 and 3 lose runs);
  // scale_options() turns on the set the scale runs use.
  /// Adaptive retry: the source waits at least this many seconds per metre of straight-line
  /// distance from where it starts the Search to the destination (a Search that must bridge
  /// gaps needs ~2 s/m: every hop costs bridge_wait_s plus a walk). 0 = the fixed timeout only.
  double search_timeout_per_m = 0.0;
  /// The source pushes its retry back to at least now + this whenever it overhears a Search of
  /// its current Num from a neighbour (the Search is still spreading near it) [s]; 0 = off.
  double search_activity_s = 0.0;
  /// A robot that is bridging a gap (figure 18) when a Search with a new Num arrives keeps
  /// walking and tries the new Search's points as it senses, instead of starting over.
  bool keep_bridge_on_new_search = false;
  /// The source's start point (its own position, a pseudo open point) may join the source's own
  /// open points by a straight move its map knows is free, as own points join each other.
  bool source_straight_start = true;
  /// Ignored (kept so older scenario files load): the hand-off rule is now always the one rule
  /// of decentralized_search.cpp (a neighbour > 1 m closer than the sender's nearest sent point
  /// takes the Search on), which cannot deadlock (issue #13).
  bool frontier_by_points = false;
  /// When a robot's walk (bridge, destination) cannot be planned in the window around its two
  /// ends (known walls close it), plan again on a window holding the robot's whole local map.
  bool walk_replan_whole_map = false;
  /// Figure 18 for a boxed-in source (issue #13): when the source's route is blocked and neither
  /// a Repair answer it can take nor a replan on its own map gets it on, it goes and senses the
  /// gap of its own known space that its way to the destination crosses (the first move of its
  /// optimistic way that is not known free), then sends a new Search from there
  /// (docs/reproductions/networked.md, "Sensing walk"). false = a new Search at once, as before.
  bool sense_when_boxed_in = true;
  int max_search_attempts = 8;
  double link_timeout_s = 0.3;  ///< hop-by-hop retry after no LinkAck [s]
  int link_retries = 6;
  int hop_limit = 32;   ///< flood bound (hops) for Search, Request and Repair
  int repair_hops = 2;  ///< Repair reaches neighbours up to this many hops
  /// Decentralized, not in the paper (issue #13, stop 22): an expanding-ring Repair. When no
  /// answer at all reached the source within repair_timeout_s of its Repair, it sends a new
  /// Repair (new Num) with twice the hop limit (carried in the message, RepairMessage::hop_limit),
  /// up to this many hops, and waits repair_timeout_s again, before it replans on its own map;
  /// robots that relay it add themselves to its relays so the answer comes back hop by hop.
  /// Counted in repair_rings_expanded. 0 = off (the fixed neighbourhood of repair_hops). Off by
  /// default (32 measured, docs/reproductions/networked.md, stop 22): s4 arrives in 14 runs
  /// instead of 12 and executes Repair in 10 of 12 change runs instead of 6, but s2r12 and s2r16
  /// get no answer even at 32 hops, s3r7's far answer is refused (its answerer had not seen the
  /// change) and s2's and s3's sources drive farther (143.8 / 56.8 m instead of 137.7 / 52.4).
  int repair_expand_hops = 0;
  double collect_s = 1.5;         ///< centralized: wait this long without new Ack before planning
  double repair_timeout_s = 8.0;  ///< decentralized: source re-searches when blocked this long
  /// Decentralized, not in the paper (Tables 4–5 say nothing of lost or unanswered Repairs): the
  /// source re-sends its Repair (the same Num, so robots that already had it stay silent, Table 4
  /// line 1 "New Repair Message") when no answer came within this long, doubling the wait after
  /// every re-send (exponential back-off) until repair_timeout_s [s]; 0 = never re-send.
  double repair_resend_s = 1.0;
  /// Decentralized, not in the paper: the source takes a Repair answer only when the repaired
  /// route ahead is free in its own map (it has seen the change; the answerer's map may be older);
  /// the first answer that passes wins, later ones are ignored (docs/reproductions/networked.md).
  bool repair_check_answer = true;
  /// Decentralized, not in the paper: a robot that finds its route broken moves the end of the
  /// break past every route point closer than this to a cell that blocks the broken moves, so no
  /// detour re-joins the route inside or beside the new obstacle, of which it sees only the front
  /// (docs/reproductions/networked.md, fourth pass) [m]; 0 = the first point after the block.
  double repair_rejoin_m = 1.0;
  /// Decentralized, not in the paper (issue #13, fifth pass): a Repair carries the cells its
  /// sender saw blocking the broken moves, and every robot that receives it marks them occupied
  /// in its own map before it looks for a detour, so a robot that has not seen the change answers
  /// no detour through it (s2 runs 9, 13: the only answer went through the closed door).
  bool repair_share_blocks = true;
  /// Decentralized, not in the paper (issue #13, stop 18): with repair_share_blocks, a Repair
  /// also carries every cell its sender knows occupied inside the free disc of a point of the
  /// route ahead: the part of the change the route's makers saw free. The cells beside the broken
  /// move alone let an answerer offer a detour a little to the side, through the same closed
  /// door, which the source then refused (s2r9, s2r13). Off by default: with it the source takes
  /// those answers in s2r9 and s2r13 but meets the change again at once, s2r13 no longer arrives
  /// and s4r10 sends 128.9 kB instead of 56.5 kB (docs/reproductions/networked.md, stop 18).
  bool repair_share_changed = false;
  /// Decentralized, not in the paper (issue #13, stop 19): the source's Repair carries the cells
  /// it knows blocked at every change it has met, not only at the break it asks about: the cells
  /// beside each break it handled, and the cells of its map that block the moves of an answer it
  /// refused. After a refusal that taught it cells its Repair did not carry, it asks again (a new
  /// Repair, new Num) with them, so the answerers (who mark them, repair_share_blocks) plan round
  /// them. The answerers had not seen an earlier change and offered the old way through it
  /// (s4r6: every answer refused). Off by default: it makes Repair execute in more change runs
  /// (s2 10 of 12 instead of 8), but on the same change placements the source no longer arrives
  /// in s2r13, s4r7, s4r10 and s4r14 (docs/reproductions/networked.md, stop 19).
  bool repair_share_met_blocks = false;
  /// Decentralized, not in the paper (issue #13, stop 21): when the source refuses a Repair
  /// answer because it crosses cells its own map knows blocked (repair_check_answer; the
  /// answerer had not seen the change), it repairs the answer itself instead of waiting on: it
  /// keeps the answer's route and replaces only its blocked part, first by a detour through its
  /// own Voronoi points (as its own Repair, Table 5), else by A* on its own map to the first
  /// point of the answer past the block (as the repair timeout's replan, but onto the answer's
  /// way). Counted as a Repair executed and apart in repair_answers_fixed /
  /// repair_answers_fixed_walk. Off by default: on the change placements of the default
  /// (off) it executes Repair in 45 of 48 change runs instead of 37 with 60 arrivals instead of
  /// 59, but on the placements that make_paper_run chose with it on (until stop 25; they no
  /// longer depend on it), s4 arrives in 12 runs instead of 13 and s2's source drives 153.4 m
  /// instead of 137.3 m (docs/reproductions/networked.md, stop 21).
  bool repair_fix_answer = false;
  /// Decentralized, not in the paper (issue #13, stop 22): with repair_fix_answer, the A* that
  /// repairs a refused answer first keeps to space someone sensed free (cells the source knows
  /// free, the free discs of the answer's points); only when that finds no walk it counts unknown
  /// cells free as before. Counted in repair_answers_fixed_seen. Off by default: on the 64 runs
  /// of s1-s4 with repair_fix_answer it found a walk in 3 (s2r7, r11, r15), and every run gave
  /// the same figures as without it; s4r11 still makes 127 replans (reproductions/networked.md,
  /// stop 22).
  bool repair_fix_seen_only = false;
  /// Decentralized, not in the paper (issue #13, stop 24): with repair_fix_answer, when the walk
  /// onto a refused answer the source repaired by A* (unknown cells count free) is blocked by
  /// walls it has just seen, the source plans again to the same point of the answer, as long as
  /// the new walk is at most this many times the larger of the first walk to it and the answer's
  /// piece it replaced; beyond that, and with 0, it drops the point and plans to the next route
  /// point, as every other replan does. Dropping one point per blocked step lost the whole
  /// repaired answer in s4r11 (17 points in 9 s, then a walk through unknown space toward the
  /// destination 35 m away; 127 replans, no arrival). Counted in repair_walk_targets_kept.
  /// Off by default: with repair_fix_answer and 1000 (in effect no bound), Repair executes in 45
  /// of 48 change runs of s1-s4 (37 with the defaults), with 62 arrivals instead of 59 and less
  /// source travel in s1, s2 and s4, on the default's change placements and on its own; but s3's
  /// source drives 0.01 / 0.04 m more (docs/reproductions/networked.md, stop 24). And with both
  /// on, the source often arrives before Table 7's later changes happen: in s1 it meets 14 of
  /// the 22 change entries (6 runs of 9-16 meet only their first change), so the change runs no
  /// longer test what Table 7 asks (stop 25). make_paper_run places the changes with both off
  /// whatever their defaults (scenarios.cpp probe_options).
  double repair_walk_keep_ratio = 0.0;
  /// Decentralized, beyond the paper (issue #13, stop 28): a relay goes and senses the break of
  /// a Repair on the source's behalf, as figure 18's relays do for the Search. The robot that
  /// heard the Repair from the source itself and is nearest the source of the robots it sees
  /// there walks to the source's side of the break when it knows no detour (class (a), stop 22),
  /// or when the Repair told it blocked cells its map did not know (its map is stale there: its
  /// detour would cross the change, class (b), stop 25), if its way there is at most half of what
  /// it drives in repair_sense_wait_s. It tells the source (a short notice), which then waits up
  /// to repair_sense_wait_s for it. Once it has sensed the break it answers from its own map; if
  /// it still knows no detour it walks on, on its own (optimistic) map, to the route point past
  /// the break and answers with the way it drove (or tells the source it gave up). Its answer
  /// goes to the source directly (marked in PathMessage::exit_index; counted in
  /// repair_answers_sensed / repair_answers_sensed_taken, repair_sense_walks, _walk_m, _answers).
  /// On by default since stop 28 (docs/reproductions/networked.md, stop 28): with it, Repair
  /// executes in every change run of s1-s4 and every decentralized run arrives.
  bool repair_sense_walk = true;
  /// With repair_sense_walk: how long the source waits for a relay that said it walks to sense
  /// the break, and how long that relay keeps at it [s].
  double repair_sense_wait_s = 60.0;
  /// Decentralized, not in the paper: the source re-sends its Repair (repair_resend_s) only when
  /// a robot is in radio range that was not at any earlier send: a robot that had it ignores it
  /// (Table 4 line 1), so a re-send to the same neighbours only adds traffic (s4r6: 36 of 43
  /// Repairs were re-sends, none answered).
  bool repair_resend_new_only = true;
  /// Decentralized, not in the paper: the source takes a repaired route only when no cell within
  /// the robot radius of its moves is unknown to the source and next to a cell it saw blocking
  /// its route: there the obstacle may continue unseen (s1r7, s4r6). Off by default: it changed
  /// nothing in s1r7 and s4r6, and in s2r6 it refused the answers and the source never arrived.
  bool repair_check_seen = false;
  /// Decentralized, not in the paper: a Path whose link retries ran out (the next robot left
  /// radio range) is carried on by the multi-hop fallback of Table 3 instead of being lost.
  bool path_fallback_after_retries = true;
  /// These options with the scale options the scale runs use (bench/netsim_bench.cpp):
  /// search_timeout_per_m 2.5, search_activity_s 30, keep_bridge_on_new_search,
  /// source_straight_start (already on by default) and walk_replan_whole_map
  /// (frontier_by_points stays as it is).
  [[nodiscard]] NetSimOptions scale_options() const;
  bool record = false;  ///< keep a Recording of every step
  std::uint64_t seed = 1;
  void validate() const;
};

/// One recorded step (for the replay viewer and pictures).
struct RecordedMessage {
  double t_s = 0.0;
  std::uint32_t from = 0;
  std::uint32_t to = 0;  ///< network::kBroadcast.value for broadcasts
  network::MessageType type{};
  std::size_t bytes = 0;
};
/// One handled route break (for the replay's event track): who, when, and whether a detour was
/// found there (a Repair executed, Tables 4–5) or help was asked for (Repair broadcast, or the
/// centralized source's re-request).
struct RecordedRepair {
  double t_s = 0.0;
  std::uint32_t robot = 0;
  bool executed = false;  ///< a detour was found (counts in NetSimMetrics::repairs_executed)
  std::string what;       ///< plain words, e.g. "repairs the route with its own detour"
};
struct RecordedStep {
  double t_s = 0.0;
  std::vector<Vec2> positions;
};
struct Recording {
  GridGeometry world;
  std::vector<RecordedStep> steps;
  std::vector<RecordedMessage> messages;
  std::vector<RecordedRepair> repairs;          ///< every route break handled, in time order
  std::vector<OccupancyGrid> final_local_maps;  ///< each robot's map at the end (window)
  std::vector<Vec2> route;                      ///< the source's final route [m]
  std::vector<std::vector<network::VoronoiPoint>> open_points;  ///< per robot, at the end
  /// Each robot's map and open points when the source first had a route (decentralized).
  std::vector<OccupancyGrid> maps_at_route;
  std::vector<std::vector<network::VoronoiPoint>> open_points_at_route;
};

struct RobotMetrics {
  std::uint64_t work = 0;  ///< cells + point pairs processed
  double cpu_s = 0.0;
  double travel_m = 0.0;
  std::uint64_t sent_bytes = 0;
  std::uint64_t sent_messages = 0;
  /// Transmissions by message type (index = network::MessageType value).
  std::array<network::TrafficCounter, network::kMessageTypeCount> sent_by_type{};
};

/// The source's Repair counters (SourceRepairTrace) are those of its AgentReport.
struct NetSimMetrics : SourceRepairTrace {
  bool success = false;
  double route_time_s = -1.0;    ///< first time the source has a route (-1 never)
  double arrival_time_s = -1.0;  ///< when the source reached the destination (-1 never)
  double travel_m = 0.0;         ///< eq. 3: sum over robots
  double source_travel_m = 0.0;
  double route_length_m = 0.0;  ///< eq. 2: the first route the source drives, from where it was
  double relay_travel_m = 0.0;  ///< travel of every robot but the source
  std::uint64_t traffic_bytes = 0;
  std::uint64_t messages = 0;
  std::uint64_t computation = 0;  ///< eq. 8/9: total work units
  std::uint64_t max_robot_computation = 0;
  double cpu_s = 0.0;
  double max_robot_cpu_s = 0.0;
  std::map<std::string, network::TrafficCounter> by_type;  ///< per message type
  double alpha_bytes = 0.0;  ///< mean Request (centralized) / Search (decentralized) size
  double beta_bytes = 0.0;   ///< mean centralized Ack size
  double gamma_bytes = 0.0;  ///< mean decentralized answer (Path) size
  int search_attempts = 0;
  int repairs = 0;  ///< breaks handled (decentralized Repair / centralized re-request)
  int replans = 0;  ///< centralized A* plans
  std::uint64_t corrupt_packets = 0;
  /// Who produced the route (robot_agent.hpp, RouteFoundBy; the centralized source always
  /// plans alone, so its runs say source_alone).
  RouteFoundBy route_found_by = RouteFoundBy::kNone;
  int route_robots = 0;          ///< robots whose open points are on the first route
  int paths_lost = 0;            ///< Path messages that could not be delivered
  int paths_unacknowledged = 0;  ///< Paths without LinkAck after the retries (received or not)
  int paths_late = 0;  ///< Paths of an earlier Search the source received (delivered, not lost)
  int repairs_executed = 0;  ///< local Repairs (Tables 4–5) that produced a detour
  /// Repair traffic (robot_agent.hpp AgentReport): Repair messages started by all robots and by
  /// the source, and detours sent back. The source's executed Repairs that are not counted in
  /// repairs_own / repair_answers_fixed* are answers or relay detours it took as they were.
  int repair_requests = 0, source_repair_requests = 0, repair_answers = 0;
  int changes_on_route = 0;  ///< obstacle changes that touched the source's route ahead
  int changes_applied = 0;   ///< obstacle changes that happened during the run
  /// Decentralized: point searches run by all robots, and copies of an already forwarded Search
  /// ignored as not new (Table 2 line 4; docs/reproductions/networked.md).
  std::uint64_t point_searches = 0;
  std::uint64_t search_copies_ignored = 0;
  /// Sensing walks of the boxed-in source (sense_when_boxed_in): how many, the metres it drove
  /// on them, and whether the route it arrived on went through the space one of them sensed.
  int sensing_walks = 0;
  double sensing_walk_m = 0.0;
  bool route_used_sensing = false;
  /// repair_sense_walk: walks relays started to sense a Repair's break, the metres they drove on
  /// them, and the answers they sent from what they sensed (all robots).
  int repair_sense_walks = 0;
  double repair_sense_walk_m = 0.0;
  int repair_sense_answers = 0;
  double simulated_s = 0.0;
  double wall_s = 0.0;
  std::vector<RobotMetrics> robots;
};

struct NetSimResult {
  NetSimMetrics metrics;
  Recording recording;  ///< filled when options.record
};

/// Runs one scenario with one method, every robot a RobotAgent (robot_agent.hpp) over the
/// simulated radio, in one process. Deterministic for given scenario and options.
[[nodiscard]] NetSimResult run_netsim(const NetSimScenario& scenario, const NetSimOptions& options);

/// Where an obstacle change happened (cell centres, world frame [m]).
struct ChangeBox {
  Vec2 lo, hi;
};
/// Applies `change` to the ground truth (1 = blocked) and returns the box it touched.
ChangeBox apply_change(BinaryGrid& truth, const ObstacleChange& change);
/// Indices of the changes from `applied` on that are due at now_s for `method`, given when the
/// source first had a route (-1: not yet, nothing is due). Changes are taken in file order.
[[nodiscard]] std::vector<std::size_t> changes_due(const NetSimScenario& scenario,
                                                   double first_route_s, double now_s,
                                                   std::size_t applied,
                                                   Method method = Method::kDecentralized);

}  // namespace voronav::sim
