// RobotAgent: one robot of the networked-robot experiments of seed 000, on its own: its pose, its
// local map (exact 3 m sensing), its Voronoi points and its whole share of the protocol, both the
// decentralized one (Search / Path / Repair, Tables 1–5) and the centralized baseline (Request /
// Ack / Notify), talking to the other robots only through a network::Transport. The step and
// the shared machinery are in robot_agent.cpp; each protocol has its own units:
// decentralized_search.cpp (Tables 1–2), decentralized_path.cpp (Table 3),
// decentralized_repair.cpp (Tables 4–5), centralized_protocol.cpp (the baseline). The in-process
// simulator (run_netsim) steps many agents over the simulated radio; a robot process
// (voronav robot, voronav/dds) steps one agent over Cyclone DDS. Both follow the same step, so the
// same scenario gives the same route and the same messages:
//   move(t_k)        drive along the waypoints, sense; sends and the new position are held back
//   flush()          publish the position, then send what move() held back (sent at t_k)
//   communicate(t_k) take the packets sent up to t_{k-1}, handle them, run the timers (retries,
//                    Path selection, bridging, search timeout)
//   world_changed()  the ground truth changed (an obstacle change of Table 7): sense it if near
// Positions the protocol reads (who is a neighbour, and where) are those after every robot's
// move of the step; during move() they are those of the step before.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>
#include <unordered_set>
#include <vector>

#include "voronav/network/messages.hpp"
#include "voronav/network/sim_radio.hpp"
#include "voronav/network/transport.hpp"
#include "voronav/network/voronoi_points.hpp"
#include "voronav/sim/disc_sweep.hpp"
#include "voronav/sim/netsim.hpp"
#include "voronav/sim/segment_cache.hpp"
#include "voronav/sim/source_repair_trace.hpp"
#include "voronav/sim/world.hpp"

namespace voronav::sim {

/// What every agent shares: the scenario (source, destination, world geometry), the options and
/// the ground truth it senses (1 = blocked; whoever owns it applies the obstacle changes).
struct AgentContext {
  const NetSimScenario* scenario = nullptr;
  const NetSimOptions* options = nullptr;
  const BinaryGrid* truth = nullptr;
  /// When set, every transmission is appended here (recordings).
  std::vector<RecordedMessage>* message_log = nullptr;
  /// When set, every route break handled (and every Repair executed) is appended here.
  std::vector<RecordedRepair>* repair_log = nullptr;
};

/// One robot's share of the run metrics (NetSimMetrics is the sum over robots, see
/// aggregate_metrics()).
struct AgentReport : SourceRepairTrace {
  RobotMetrics metrics;  ///< work, CPU, travel, bytes and messages sent (also by type)
  int search_attempts = 0;
  int repairs = 0;
  int replans = 0;
  std::uint64_t corrupt_packets = 0;
  // Only the source fills these.
  bool arrived = false;
  double route_time_s = -1.0;
  double arrival_time_s = -1.0;
  double route_length_m = 0.0;  ///< eq. 2: open-point path the source drives (first route)
  RouteFoundBy found_by = RouteFoundBy::kNone;
  int route_robots = 0;  ///< robots whose open points are on the first route
  // Every robot.
  int paths_lost = 0;  ///< Path messages that could not be delivered (counted, not dropped)
  /// Paths whose link retries ran out without a LinkAck (issue #13): a Path sent while its
  /// addressee was in radio range (lossless radio) was received, and only the ack failed; it
  /// counts here and not in paths_lost.
  int paths_unacknowledged = 0;
  /// (source) Paths of an earlier Search received after it started a new one: not lost.
  int paths_late = 0;
  int repairs_executed = 0;  ///< local Repairs (Tables 4–5) that produced a detour
  /// Repair traffic, traced (issue #13): Repair messages this robot started (Tables 4–5 line 1,
  /// not the re-sends) and detours it sent back (an answer, or a relay's own detour); the
  /// source's own Repair counters are those of SourceRepairTrace.
  int repair_requests = 0, repair_answers = 0;
  int changes_on_route = 0;  ///< (source) obstacle changes that touched its route ahead
  int point_searches = 0;    ///< decentralized point searches run (try_continue)
  /// Copies of an already forwarded Search ignored as not new (Table 2 line 4).
  int search_copies_ignored = 0;
  /// (source) Sensing walks of a boxed-in source (NetSimMetrics::sensing_walks).
  int sensing_walks = 0;
  double sensing_walk_m = 0.0;
  bool route_used_sensing = false;
  /// repair_sense_walk (relays): NetSimMetrics::repair_sense_walks, _walk_m, _answers.
  int repair_sense_walks = 0;
  double repair_sense_walk_m = 0.0;
  int repair_sense_answers = 0;
};

/// Sums the robots' reports (eq. 3–9) into the metrics of a run; `source` is the source's index.
[[nodiscard]] NetSimMetrics aggregate_metrics(const std::vector<AgentReport>& robots,
                                              std::size_t source, Method method);

class RobotAgent {
 public:
  /// `context` and `transport` must outlive the agent.
  RobotAgent(const AgentContext& context, network::RobotId id, Vec2 position,
             network::Transport& transport);
  RobotAgent(const RobotAgent&) = delete;
  RobotAgent& operator=(const RobotAgent&) = delete;

  /// t = 0, first part: publish the position and sense.
  void begin();
  /// t = 0, second part (every robot's position known): the source starts its method.
  void start();
  void move(double now_s);
  void flush();
  void communicate(double now_s);
  /// The ground truth changed inside [lo, hi] (world frame [m]) at now_s.
  void world_changed(double now_s, Vec2 lo, Vec2 hi);

  [[nodiscard]] network::RobotId id() const { return r_.id; }
  [[nodiscard]] Vec2 position() const { return r_.pos; }
  [[nodiscard]] bool is_source() const;
  [[nodiscard]] bool arrived() const { return report_.arrived; }
  /// When the source first had a route (-1 before; only meaningful for the source).
  [[nodiscard]] double first_route_s() const { return report_.route_time_s; }
  [[nodiscard]] AgentReport report() const;
  [[nodiscard]] const LocalMap& local_map() const { return r_.map; }
  /// The robot's open points now (for observers: adds nothing to its work).
  [[nodiscard]] std::vector<network::VoronoiPoint> open_points() const;
  /// The source's current route [m] (decentralized: route points; centralized: waypoints).
  [[nodiscard]] std::vector<Vec2> route() const;

 private:
  struct SenderInfo {
    network::RobotId id;
    Vec2 pos;  // where the sender was when its Search arrived (a Path goes back toward it)
    std::vector<network::RobotId> relays;
    std::size_t offset = 0;  // first of its points in s_in.open_points
    std::size_t count = 0;
  };
  enum class Walk { kIdle, kBridge, kDestination, kBack, kSense, kRepair };
  struct State {
    network::RobotId id;
    Vec2 pos;
    LocalMap map;
    std::vector<Vec2> waypoints;
    std::size_t wp = 0;
    bool points_dirty = true;
    network::VoronoiPoints pts;
    std::unordered_set<std::uint64_t> seen;
    std::uint32_t next_msg = 1;
    // Decentralized search state (one search at a time: the latest Num).
    std::uint32_t s_num = 0xFFFFFFFFu;
    bool s_done = false;
    network::SearchMessage s_in;  // what the senders told us: all their points, concatenated
    std::vector<SenderInfo> s_senders;
    std::uint8_t s_hops = 0;
    int reforwards = 0;
    std::vector<network::VoronoiPoint> s_comb;  // sender points + own points (+ destination)
    network::PointSearch s_search;
    std::size_t s_na = 0;             // number of sender points in s_comb
    std::vector<std::size_t> s_sent;  // sent point index -> s_comb index
    SegmentCache own_moves;           // try_continue's own-edge checks, until the map changes
    std::uint64_t s_map_version = ~std::uint64_t{0};  // map version of the last point search
    std::size_t s_trail_size = 0;                     // walk_trail size at the last point search
    std::optional<network::CopyCheck> s_check;  // the last search's points, indexed for copies
    Walk walk = Walk::kIdle;
    double walk_since_check = 0.0;
    double bridge_at = -1.0;  // when to start bridging if no continuable Search came
    std::vector<network::PathMessage> got_paths;
    double path_deadline = -1.0;
    bool path_forwarded = false;
    std::optional<network::PathMessage> saved;
    double saved_cost = 0.0;  // length of the saved Path from the source
    // A Path this robot must deliver whose next relay is out of range and no neighbour is closer
    // to it: the robot walks back toward where that relay was (multi-hop fallback, last resort).
    std::optional<network::PathMessage> pending;
    double pending_since = -1.0;
    bool walk_map_changed = false;  // the map changed since the last walk check
    // Where a relay walked for the current search (every metre): driven, so known free; its
    // points join the robot's open points (a walk senses a strip whose Voronoi points alone
    // need not connect).
    std::vector<Vec2> walk_trail;
    std::unordered_set<std::uint32_t> repairs_seen;
    std::uint32_t repair_counter = 0;
    // Centralized.
    network::RobotId parent = network::kBroadcast;
    std::uint32_t req_num = 0xFFFFFFFFu;
  };
  struct Outgoing {
    network::RobotId to;
    std::vector<std::uint8_t> bytes;
    std::uint64_t key;
    int tries;
    double next_at;
    bool reached = false;  // (Path) the addressee was in radio range at one of its transmissions
  };
  struct Held {
    network::RobotId to;  // kBroadcast for a broadcast
    std::vector<std::uint8_t> bytes;
  };

  template <typename F>
  auto timed(F&& f);
  void do_sense();
  const network::VoronoiPoints& points();
  [[nodiscard]] network::VoronoiPointsOptions points_opts() const;
  [[nodiscard]] const NetSimOptions& opt() const { return *ctx_.options; }
  [[nodiscard]] const NetSimScenario& scen() const { return *ctx_.scenario; }
  [[nodiscard]] network::RobotId source_id() const;

  // messaging
  void transmit(network::RobotId to, std::vector<std::uint8_t> bytes);
  void broadcast(network::Payload p, std::uint8_t hops);
  void send_reliable(network::RobotId to, network::Payload p);
  void link_ack(const network::Header& h);
  void handle_packet(const network::Packet& p);
  void timers();
  /// Appends to ctx_.repair_log (when recording) a route break handled now by this robot.
  void log_repair(bool executed, std::string what);

  void on_map_changed();
  // motion
  bool segment_blocked(Vec2 a, Vec2 b) const;
  bool segment_known_free(Vec2 a, Vec2 b) const;
  bool plan_walk(Vec2 target, const std::vector<network::VoronoiPoint>* seen = nullptr,
                 bool whole_map = false);
  bool walk_blocked() const;
  bool source_walk_on_whole_map();
  void walk_progress(bool arrived);
  // decentralized: Search (Tables 1-2)
  void start_search();
  bool try_continue();
  [[nodiscard]] bool dest_reached() const;
  void on(const network::Header& h, const network::SearchMessage& m);
  void process_search(network::RobotId sender, const network::SearchMessage& m, std::uint8_t hops);
  [[nodiscard]] bool copy_is_new(const network::SearchMessage& m);
  void start_bridge();
  void after_continue(std::uint8_t hops);
  void forward_search(std::uint8_t hops);
  [[nodiscard]] std::size_t sender_of(std::size_t i) const;
  struct Piece {
    std::size_t sender = 0;  // index into s_senders
    std::uint32_t exit = 0;  // index into that sender's points
    std::vector<network::VoronoiPoint> points;
  };
  [[nodiscard]] Piece own_piece(std::size_t last) const;
  void answer_path();
  [[nodiscard]] double reference_distance() const;
  [[nodiscard]] bool hands_off_to(Vec2 robot, double sender_reference, double slack) const;
  void consider_bridge(const network::SearchMessage& m);
  bool source_walk_check();
  void retry_search();
  [[nodiscard]] bool source_sees_way();
  [[nodiscard]] std::size_t own_index_at(Vec2 p) const;
  bool start_sensing_walk();
  void sensing_walk_progress(bool arrived);
  std::size_t end_sensing_walk();
  void note_route_used_sensing();
  // decentralized: Path (Table 3)
  void deliver_path(network::PathMessage p, network::RobotId to, Vec2 toward, bool carrier);
  void pending_step();
  bool path_after_retries(const std::vector<std::uint8_t>& bytes);
  [[nodiscard]] std::optional<Vec2> neighbour_position(network::RobotId id);
  void on(const network::Header& h, const network::PathMessage& m);
  void select_path();
  void finish_route(const network::PathMessage& p, bool own_answer);
  void count_change_on_route(Vec2 lo, Vec2 hi);
  [[nodiscard]] std::size_t next_route_index() const;
  void set_source_waypoints(std::size_t from);
  // decentralized: Repair (Tables 4-5)
  std::optional<std::pair<std::uint32_t, std::uint32_t>> find_break(
      const std::vector<network::VoronoiPoint>& path, std::size_t from);
  [[nodiscard]] std::uint32_t rejoin_past_block(const std::vector<network::VoronoiPoint>& path,
                                                std::pair<std::uint32_t, std::uint32_t> br);
  [[nodiscard]] std::vector<Vec2> blocking_cells(const std::vector<network::VoronoiPoint>& path,
                                                 std::pair<std::uint32_t, std::uint32_t> br);
  [[nodiscard]] std::vector<Vec2> changed_cells(const std::vector<network::VoronoiPoint>& path,
                                                std::vector<Vec2> cells);
  [[nodiscard]] std::vector<Vec2> occupied_in_discs(const std::vector<network::VoronoiPoint>& path,
                                                    std::vector<Vec2> cells);
  void learn_blocks(const std::vector<Vec2>& blocked);
  std::size_t add_met_blocks(const std::vector<Vec2>& cells);
  [[nodiscard]] std::vector<Vec2> with_met_blocks(std::vector<Vec2> cells) const;
  void learn_from_refusal(const std::vector<network::VoronoiPoint>& rest);
  bool fix_refused_answer(std::vector<network::VoronoiPoint> rest, network::RobotId from);
  [[nodiscard]] bool tells_more(const network::RepairMessage& m,
                                const std::vector<Vec2>& cells) const;
  [[nodiscard]] bool seen_near_block(const std::vector<network::VoronoiPoint>& ahead) const;
  void shrink_to_map(std::vector<network::VoronoiPoint>& path);
  std::vector<network::VoronoiPoint> detour(std::vector<network::VoronoiPoint> path,
                                            std::uint32_t from, std::uint32_t to);
  void check_relay_route();
  void on(const network::Header& h, const network::RepairMessage& m);
  void on_repair_path(network::PathMessage m, network::RobotId from);
  bool splice_route(const std::vector<network::VoronoiPoint>& whole, network::RobotId from,
                    bool sensed = false);
  void repair_timers();
  void repair_done();
  bool expand_repair_ring();
  void send_repair(const network::RepairMessage& m);
  void drive_walk_then_route();
  [[nodiscard]] double walk_length() const;
  void check_source_route();
  bool replan_to_route();
  [[nodiscard]] std::uint32_t next_repair_num();
  // repair_sense_walk (decentralized_repair_walk.cpp)
  [[nodiscard]] bool walks_for_repair(const network::Header& h);
  bool start_repair_walk(const network::RepairMessage& m);
  void repair_walk_progress(bool arrived);
  void answer_sensed(const std::vector<network::VoronoiPoint>& fixed);
  void end_repair_walk();
  void send_sense_notice(std::uint32_t what);
  // centralized baseline
  void start_request();
  void on(const network::Header& h, const network::RequestMessage& m);
  void on(const network::Header& h, const network::AckMessage& m);
  void on(const network::Header& h, const network::NotifyMessage& m);
  void on(const network::Header& h, const network::LinkAckMessage& m);
  void plan_central();
  void check_central_path();

  AgentContext ctx_;
  network::Transport& transport_;
  DiscSweep sweep_{-1.0};  // the robot's disc (radius r, less 0.01 cell) along a straight move
  State r_;
  AgentReport report_;
  std::vector<Outgoing> outbox_;
  bool holding_ = false;  // inside move(): sends and the position wait for flush()
  std::vector<Held> held_;
  double now_ = 0.0;
  bool last_sense_changed_ = false;
  // Source only.
  std::uint32_t search_num_ = 0;
  double search_deadline_ = 0.0;  // retry the Search (Num + 1) when no route by then
  std::vector<network::VoronoiPoint> route_;
  std::vector<network::RobotId> route_owners_;  // who sensed each route_ point (first route)
  std::size_t route_base_ = 0;
  std::vector<Vec2> trail_;     // source positions since its latest Search
  std::size_t back_steps_ = 0;  // waypoints of the way back along the trail
  // repair_walk_keep_ratio: the point of a repaired answer the source's walk goes to
  // (fix_refused_answer), the larger of the first walk to it and the answer's piece it replaced
  // [m], and the longest walk to it that is kept (-1: no such walk under way).
  Vec2 fix_walk_target_{};
  double fix_walk_first_m_ = -1.0;
  double fix_walk_bound_m_ = -1.0;
  double blocked_since_ = -1.0;
  Vec2 walk_prev;  // position before this step's move
  // Source walking toward the destination because no radio neighbour could take its Search on:
  // metres since it last looked for one, and the robots it already handed the Search to.
  double source_walk_since_ = 0.0;
  std::vector<network::RobotId> handed_to_;
  // Source, sensing walks (figure 18, boxed in): its map when the walk started, and the world
  // cells the walks made known (1); the route it arrives on used them when one of its points
  // past its start lies on such a cell.
  std::optional<LocalMap> map_before_walk_;
  bool boxed_in_ = false;
  // Where it last searched anew after a block it could not repair (a second block within the
  // sensing range of it means the answers lead nowhere: it is boxed in).
  std::optional<Vec2>
      searched_after_block_;  // since its last sensing walk, until it has a route again
  BinaryGrid sensed_by_walks_;
  std::uint32_t repair_seq_ = 0;
  // Source: the Repair it waits an answer for, re-sent (same Num) with back-off (repair_resend_s).
  std::optional<network::RepairMessage> repair_out_;
  // Source: robots in radio range at the sends of repair_out_ (repair_resend_new_only).
  std::vector<network::RobotId> repair_heard_;
  double repair_resend_at_ = -1.0;
  double repair_resend_gap_ = 0.0;
  // Source (repair_expand_hops): repair_answers_received when it sent repair_out_.
  int answers_at_repair_ = 0;
  // Relay (repair_sense_walk): the Repair whose break it walks to sense, the walk's phase (0: to
  // the source's side of the break, 1: on round it to the route point past it) and when it
  // gives up (the source no longer waits then).
  std::optional<network::RepairMessage> repair_walk_;
  int repair_walk_phase_ = 0;
  double repair_walk_until_ = -1.0;
  // Source (repair_sense_walk): until when it waits for a relay that said it walks to sense the
  // break of its Repair (-1: no such relay).
  double sense_wait_until_ = -1.0;
  // Relay: the ends of the break of its saved path it already asked about (asked once).
  std::optional<std::pair<Vec2, Vec2>> relay_break_;
  // Source: the cells that blocked its route at its latest break (repair_check_seen).
  std::vector<Vec2> block_seen_;
  // Source (repair_share_met_blocks): the cells it knows blocked at every change it has met
  // (beside its breaks, on the moves of answers it refused), sorted (y, x), each once.
  std::vector<Cell> met_blocks_;
  bool collecting_ = false;
  double last_ack_ = 0.0;
};

}  // namespace voronav::sim
