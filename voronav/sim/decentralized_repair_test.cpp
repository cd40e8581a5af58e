// Repair (seed 000, Tables 4–5; decentralized_repair.cpp): who answers a Repair and how the
// source takes the answers. A hand-made hall where a block closes the route ahead of the source
// and several robots know a way around it.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <utility>
#include <variant>

#include "voronav/network/sim_radio.hpp"
#include "voronav/sim/netsim.hpp"
#include "voronav/sim/robot_agent.hpp"
#include "voronav/sim/scenario_file.hpp"
#include "voronav/sim/test_halls.hpp"

namespace voronav::sim {
namespace {

// A hall 30 x 8 m with robots in two rows every 3.5 m (y 2.5 and 5.5); the source is robot 0 at
// (1.5, 2.5), the destination (28.5, 2.5). `at_s` after the first route a block closes the lower
// half of the hall at x 20..20.8 m (y 0.4..4 m): the upper half (y 4..7.6 m) stays open, and
// the robots of the upper row near the block know that way around it.
NetSimScenario hall(double after_route_s) {
  return testing::two_row_hall(40, after_route_s);
}

struct Counted {
  NetSimResult res;
  int repairs_sent = 0;     // Repair transmissions (the source's and relayed ones)
  int answers_sent = 0;     // Path transmissions after the change (answers, relayed answers)
  int executed_events = 0;  // detours taken into the route (recording)
  int asked_events = 0;     // breaks that needed help (recording)
  double change_s = 0.0;
};

Counted run(const NetSimOptions& base, double after_route_s) {
  NetSimOptions o = base;
  o.method = Method::kDecentralized;
  o.record = true;
  Counted c;
  c.res = run_netsim(hall(after_route_s), o);
  c.change_s = c.res.metrics.route_time_s + after_route_s;
  for (const auto& m : c.res.recording.messages) {
    if (m.type == network::MessageType::kRepair) ++c.repairs_sent;
    if (m.type == network::MessageType::kPath && m.t_s >= c.change_s - 1e-9) ++c.answers_sent;
  }
  for (const auto& r : c.res.recording.repairs)
    (r.executed ? c.executed_events : c.asked_events) += 1;
  return c;
}

TEST(DecentralizedRepair, SeveralRobotsKnowADetourAndTheSourceTakesOneAnswer) {
  const auto c = run(NetSimOptions{}, 12.0);
  const auto& m = c.res.metrics;
  ASSERT_TRUE(m.success);
  EXPECT_EQ(m.changes_on_route, 1) << "the block is on the route ahead of the source";
  EXPECT_EQ(m.search_attempts, 1) << "repaired without a new Search";
  EXPECT_GE(m.repairs_executed, 1);
  EXPECT_EQ(c.executed_events, m.repairs_executed);
  // The relay next to the block asks (Repair); several robots know a way around it and answer
  // or carry answers (Path messages from at least two robots after the change) ...
  std::map<std::uint32_t, int> path_senders;
  for (const auto& msg : c.res.recording.messages)
    if (msg.type == network::MessageType::kPath && msg.t_s >= c.change_s - 1e-9)
      ++path_senders[msg.from];
  EXPECT_GE(path_senders.size(), 2u);
  EXPECT_GE(c.asked_events, 1);
  // ... but the source does not take every answer. Since the relays' own detours reach the
  // source (ARelaysOwnDetourReachesTheSource), it takes two repaired routes for this one break
  // (20.0 s: a relay's own detour; 20.6 s: the answer to robot 12's Repair, which replaces it):
  // the source takes the first answer to *its own* Repair only, and relay-side repairs of one
  // break carry different Nums (docs/reproductions/networked.md, fourth pass, left open).
  int taken = 0;
  for (const auto& r : c.res.recording.repairs)
    if (r.robot == 0 && r.what.find("takes robot") != std::string::npos) ++taken;
  EXPECT_GE(taken, 1);
  EXPECT_LE(taken, 2);
  // The Repair counters of the run (issue #13: asked vs answered vs taken, reported per run):
  // every break that needed help started one Repair, answers were sent, and the source received
  // at least the answers it took.
  EXPECT_EQ(m.repair_requests, c.asked_events);
  EXPECT_GE(m.repair_answers, 1);
  EXPECT_GE(m.repair_answers_received, taken);
  EXPECT_LE(m.repair_answers_refused, m.repair_answers_received);
  // Every answer the source received was taken, refused or dropped (counted once), and the
  // recorded "takes robot N's detour" events are the answers taken from other robots.
  EXPECT_EQ(m.repair_answers_received,
            m.repair_answers_taken + m.repair_answers_refused + m.repair_answers_dropped);
  EXPECT_EQ(m.repair_answers_taken, taken);
  EXPECT_LE(m.source_repair_requests, m.repair_requests);
  // Every robot handles a Repair once (Table 4 line 1, "New Repair Message"): no robot sends
  // the same Repair twice, so there are at most as many Repair transmissions as robots.
  EXPECT_LE(c.repairs_sent, static_cast<int>(c.res.recording.steps.front().positions.size()));
}

// A relay that finds its saved path broken and knows a detour itself sends the repaired path to
// the source (Table 4). Its saved Path named the robot that sensed each point of the first route
// (`owners`); the repaired path has other points, and before the fourth pass of issue #13 the
// list was sent unchanged: the message did not decode at the source (a corrupt packet), the
// relay's link retries ran out and the Path was counted lost (s3r12).
TEST(DecentralizedRepair, ARelaysOwnDetourReachesTheSource) {
  const auto c = run(NetSimOptions{}, 12.0);
  const auto& m = c.res.metrics;
  ASSERT_TRUE(m.success);
  EXPECT_EQ(m.corrupt_packets, 0u);
  EXPECT_EQ(m.paths_lost, 0);
}

// repair_share_blocks (issue #13, fifth pass): a Repair carries the cells its sender saw blocking
// the route, and a robot that has not seen the change marks them before it answers. In s2 runs 9
// and 13 the only answer came from a robot whose map was older than the change: its detour went
// through the closed door and the source refused it. Here robot 1 stands above a block that
// appeared after it sensed (it has not seen it); a phantom robot asks it to repair a route along
// the corridor's lower half. Without the cells, robot 1's detour runs through the block; with
// them, it goes round it through the upper half.
TEST(DecentralizedRepair, ARepairTellsItsAnswerersWhereTheRouteIsBlocked) {
  using network::RobotId;
  NetSimScenario sc;  // a corridor 20 x 4 m with walls along both long sides
  sc.world = OccupancyGrid(GridGeometry{100, 20, 0.2, {}}, kFree);
  for (int x = 0; x < 100; ++x)
    sc.world[Cell{x, 0}] = sc.world[Cell{x, 19}] = kOccupied;
  sc.robots = {{1.0, 2.0}, {10.0, 3.2}};
  sc.destination = {19.0, 2.0};
  std::vector<Cell> block;  // x 10.0-10.4 m, y 0.2-2.6 m: the lower part of the corridor
  for (int y = 1; y < 13; ++y)
    for (int x = 50; x < 52; ++x)
      block.push_back({x, y});
  const auto& g = sc.world.geometry();
  auto answer = [&](bool share) {
    NetSimOptions o;
    o.method = Method::kDecentralized;
    o.repair_share_blocks = share;
    BinaryGrid truth = binarize(sc.world);
    AgentContext ctx{&sc, &o, &truth, nullptr};
    network::SimRadio radio(o.radio);
    RobotAgent b(ctx, RobotId{1}, sc.robots[1], radio);
    b.begin();  // senses the corridor before the change
    for (Cell c : block)
      truth[c] = 1;  // the change, which robot 1 does not see
    const RobotId phantom{7};
    radio.update_position(phantom, {8.0, 1.4});
    network::RepairMessage m;
    m.source = RobotId{0};
    m.num = 77;
    m.relays = {RobotId{0}, phantom};
    m.whole_path = {{{8.0, 1.4}, 0.25f, 0.0f}, {{12.0, 1.4}, 0.25f, 0.0f}};
    m.broken_from = 0;
    m.broken_to = 1;
    for (Cell c : block)
      if (c.x == 50) m.blocked.push_back(g.cell_center(c));  // the front the phantom saw
    radio.send(phantom, RobotId{1},
               network::encode({network::Header{phantom, RobotId{1}, phantom, 1, 0}, m}));
    std::vector<network::VoronoiPoint> got;
    for (int k = 1; k <= 5 && got.empty(); ++k) {
      radio.set_time(0.2 * k);
      b.flush();
      b.communicate(0.2 * k);
      for (const auto& p : radio.receive(phantom)) {
        const auto e = network::decode(p.bytes);
        if (e.type() == network::MessageType::kPath)
          got = std::get<network::PathMessage>(e.payload).whole_path;
      }
    }
    return got;
  };
  // Whether a move passes over one of the cells the Repair names (x 10.0-10.2 m, y < 2.6 m).
  auto crosses_block = [&](const std::vector<network::VoronoiPoint>& w) {
    for (std::size_t i = 1; i < w.size(); ++i)
      for (int k = 0; k <= 100; ++k) {
        const Vec2 q = w[i - 1].position + (w[i].position - w[i - 1].position) * (k / 100.0);
        if (q.x >= 10.0 && q.x < 10.2 && q.y < 2.6) return true;  // over a cell the Repair names
      }
    return false;
  };
  const auto stale = answer(false), told = answer(true);
  ASSERT_FALSE(stale.empty()) << "robot 1 knows a way on its old map";
  EXPECT_TRUE(crosses_block(stale)) << "its old map has no block: the way runs through it";
  ASSERT_FALSE(told.empty()) << "robot 1 knows a way round the block";
  std::string way;
  for (const auto& p : told)
    way += " (" + std::to_string(p.position.x) + ", " + std::to_string(p.position.y) + ")";
  EXPECT_FALSE(crosses_block(told)) << way;
}

// repair_share_changed (issue #13, stop 18): a Repair carries every cell its sender knows
// occupied inside the free discs of the route's points (the part of the change the route's
// makers saw free), not only the cells beside the broken move; an answerer then offers no detour
// a little to the side through the same block (s2r9, s2r13, s4r6: every answer refused). The
// runs are the same up to the first Repair: with the rule it is larger by the extra cells.
TEST(DecentralizedRepair, ARepairCarriesTheWholeSeenChangeOnTheRoute) {
  auto first_repair_bytes = [](bool changed) {
    NetSimOptions o;
    o.repair_share_changed = changed;
    const auto c = run(o, 12.0);
    EXPECT_TRUE(c.res.metrics.success);
    EXPECT_EQ(c.res.metrics.search_attempts, 1) << "repaired without a new Search";
    for (const auto& m : c.res.recording.messages)
      if (m.type == network::MessageType::kRepair) return m.bytes;
    return std::size_t{0};
  };
  const std::size_t beside = first_repair_bytes(false), whole = first_repair_bytes(true);
  ASSERT_GT(beside, 0u) << "a Repair is sent";
  // 8 bytes a cell: at least 4 more cells of the 0.8 x 3.6 m block than beside the broken move.
  EXPECT_GE(whole, beside + 4 * 8) << beside << " B without the rule";
}

// repair_resend_new_only (issue #13, stop 18): when nobody can answer (here a wall closes the
// whole hall ahead of the source, and no robot moves), the source's Repair is not re-sent to the
// same neighbours, who ignore a Repair they have had (Table 4 line 1). Without the rule it goes
// out again after 1, 2 and 4 s (s4r6: 36 of 43 Repairs were such re-sends).
TEST(DecentralizedRepair, AnUnansweredRepairIsNotResentToTheSameNeighbours) {
  auto sc = hall(12.0);
  sc.changes.front().cells.clear();
  for (int y = 2; y < 38; ++y)  // x 20..20.8 m across the whole hall
    for (int x = 100; x < 104; ++x)
      sc.changes.front().cells.push_back({x, y});
  auto source_repairs = [&](bool new_only) {
    NetSimOptions o;
    o.method = Method::kDecentralized;
    o.record = true;
    o.repair_resend_new_only = new_only;
    // Each of the two rules alone: with repair_share_met_blocks the source also asks once more
    // with the cells it learned (a new Repair, not a re-send of the same one): 2 and 5.
    o.repair_share_met_blocks = false;
    // and repair_fix_answer (stop 21) repairs a refused answer by A*, which ends the wait.
    o.repair_fix_answer = false;
    o.time_limit_s = 90.0;
    const auto res = run_netsim(sc, o);
    EXPECT_FALSE(res.metrics.success) << "no way round the wall";
    double asked = -1.0;  // the source's first own Repair (it relays others' Repairs too)
    for (const auto& r : res.recording.repairs)
      if (r.robot == 0 && !r.executed && asked < 0.0) asked = r.t_s;
    EXPECT_GE(asked, 0.0) << "the source is blocked and asks";
    int n = 0;
    for (const auto& m : res.recording.messages)
      n += m.type == network::MessageType::kRepair && m.from == 0 && m.t_s >= asked - 1e-9 &&
                   m.t_s < asked + o.repair_timeout_s - 0.1
               ? 1
               : 0;
    return n;
  };
  EXPECT_EQ(source_repairs(true), 1);
  EXPECT_EQ(source_repairs(false), 4) << "sent, then re-sent after 1, 2 and 4 s";
}

// A saved run of a paper scenario (data/netsim/NAME), with the decentralized method.
NetSimScenarioFile saved_decentralized_run(const std::string& name) {
  auto f = load_netsim_scenario(std::string(VORONAV_SOURCE_DIR) + "/data/netsim/" + name);
  f.options.method = Method::kDecentralized;
  // The saved runs test the Repair mechanisms of stops 19-27; repair_sense_walk (on by default
  // since stop 28) is set by the tests that measure it.
  f.options.repair_sense_walk = false;
  return f;
}

// repair_share_met_blocks (issue #13, stop 19): scenario 2, run 9. The only answer to the
// source's Repair crosses cells of the change that the source knows blocked and the answerer
// does not: the source refuses it, waits, and goes on by a new Search without a Repair. With the
// rule, the refusal teaches the source which of its cells to tell; it asks again (a new Repair
// carrying them), the answerers plan round them and the source executes a Repair.
// Scenario 2, run 9 (data/netsim/s2_run9_refused.yaml), decentralized, with neither
// repair_share_met_blocks nor repair_fix_answer: the source refuses the only answer (it crosses
// the change the source saw and its answerer did not) and executes no Repair. Returns the
// scenario file and the run's metrics after checking exactly that.
std::pair<NetSimScenarioFile, NetSimMetrics> refused_run9_without_either_rule() {
  auto f = saved_decentralized_run("s2_run9_refused.yaml");
  f.options.repair_share_met_blocks = false;
  f.options.repair_fix_answer = false;
  const auto off = run_netsim(f.scenario, f.options).metrics;
  EXPECT_TRUE(off.success);
  EXPECT_GE(off.repair_answers_refused, 1) << "the answer crosses the change the source saw";
  EXPECT_EQ(off.repairs_executed, 0);
  EXPECT_EQ(off.repair_reasks, 0);
  EXPECT_EQ(off.repair_answers_fixed + off.repair_answers_fixed_walk, 0);
  return {f, off};
}

TEST(DecentralizedRepair, ARefusedAnswerTeachesTheSourceWhatToTellItsAnswerers) {
  const auto [f, off] = refused_run9_without_either_rule();
  ASSERT_TRUE(off.success);
  NetSimOptions o = f.options;
  o.repair_share_met_blocks = true;
  const auto on = run_netsim(f.scenario, o).metrics;
  ASSERT_TRUE(on.success);
  EXPECT_GE(on.repair_reasks, 1) << "a refusal with cells its Repair did not carry: asks again";
  EXPECT_GT(on.repair_cells_max, 0);
  EXPECT_GE(on.repairs_executed, 1);
  EXPECT_LT(on.repair_answers_refused, on.repair_answers_received);
}

// repair_fix_answer (issue #13, stop 21): scenario 2, run 9 again. The only answer crosses the
// change the source saw and its answerer did not, so without the rule the source refuses it and
// executes no Repair. With it, the source keeps the answer and replans only its blocked part on
// its own map (here by A*: its own points hold no detour), and drives the repaired answer.
TEST(DecentralizedRepair, TheSourceRepairsARefusedAnswerOnItsOwnMap) {
  const auto [f, off] = refused_run9_without_either_rule();
  ASSERT_TRUE(off.success);
  NetSimOptions o = f.options;
  o.repair_fix_answer = true;
  const auto on = run_netsim(f.scenario, o).metrics;
  ASSERT_TRUE(on.success);
  EXPECT_GE(on.repair_answers_refused, 1) << "the answer is still blocked in the source's map";
  EXPECT_GE(on.repair_answers_fixed_walk, 1) << "the source replans the blocked part by A*";
  EXPECT_GE(on.repairs_executed,
            on.repairs_own + on.repair_answers_fixed + on.repair_answers_fixed_walk);
}

// Every Repair answer the source receives is taken, refused or dropped (issue #13, stop 27:
// repair_answers_taken, repair_answers_dropped). turtlebot3_world.yaml has the one answer that was
// neither taken nor refused before the counters: robot 1's detour to robot 2's own Repair reaches
// the source after it has passed the detour's first point (route point 2), so splice_route drops
// it. s2_run10_boxed_in.yaml has answers taken and refused, depot.yaml all three kinds.
TEST(DecentralizedRepair, EveryAnswerTheSourceReceivesIsTakenRefusedOrDropped) {
  const auto tb3 = [] {
    const auto f = saved_decentralized_run("turtlebot3_world.yaml");
    return run_netsim(f.scenario, f.options).metrics;
  }();
  ASSERT_TRUE(tb3.success);
  EXPECT_EQ(tb3.repair_answers_received, 1);
  EXPECT_EQ(tb3.repair_answers_dropped, 1) << "its splice point is behind the source";
  EXPECT_EQ(tb3.repair_answers_taken, 0);
  EXPECT_EQ(tb3.repair_answers_refused, 0);
  for (const char* name : {"s2_run10_boxed_in.yaml", "depot.yaml"}) {
    const auto f = saved_decentralized_run(name);
    const auto m = run_netsim(f.scenario, f.options).metrics;
    EXPECT_GE(m.repair_answers_taken, 1) << name;
    EXPECT_GE(m.repair_answers_refused, 1) << name;
    EXPECT_EQ(m.repair_answers_received,
              m.repair_answers_taken + m.repair_answers_refused + m.repair_answers_dropped)
        << name;
    // An answer taken is a Repair executed; the source's own detours and fixed answers are too.
    EXPECT_GE(m.repairs_executed, m.repair_answers_taken) << name;
  }
  // The same accounting with the defaults (repair_sense_walk on: sensed answers come too).
  for (const char* name : {"turtlebot3_world.yaml", "s2_run10_boxed_in.yaml", "depot.yaml"}) {
    auto f = load_netsim_scenario(std::string(VORONAV_SOURCE_DIR) + "/data/netsim/" + name);
    f.options.method = Method::kDecentralized;
    f.options.repair_sense_walk = NetSimOptions{}.repair_sense_walk;
    const auto m = run_netsim(f.scenario, f.options).metrics;
    EXPECT_GE(m.repair_answers_received, 1) << name;
    EXPECT_EQ(m.repair_answers_received,
              m.repair_answers_taken + m.repair_answers_refused + m.repair_answers_dropped)
        << name << " (defaults)";
    EXPECT_LE(m.repair_answers_sensed_taken, m.repair_answers_taken) << name;
  }
}

// repair_expand_hops (issue #13, stop 22): scenario 3, run 7 (data/netsim/s3_run7_unanswered.yaml).
// No robot within repair_hops (2) of the blocked source knows a way round the change: no answer
// comes, no Repair executes and the source replans on its own map. With the expanding ring, the
// source asks again up to 4 hops after repair_timeout_s, and an answer comes back hop by hop from
// beyond two hops. That answerer had not seen the change either, so the source refuses it as
// blocked in its own map; with repair_fix_answer too it repairs that answer and executes a Repair.
TEST(DecentralizedRepair, AnUnansweredRepairIsSentAgainFarther) {
  auto f = saved_decentralized_run("s3_run7_unanswered.yaml");
  f.options.repair_expand_hops = 0;
  f.options.repair_fix_answer = false;
  const auto off = run_netsim(f.scenario, f.options).metrics;
  ASSERT_TRUE(off.success);
  EXPECT_GE(off.source_repair_requests, 1);
  EXPECT_EQ(off.repair_answers_received, 0) << "nobody within two hops answers";
  EXPECT_EQ(off.repairs_executed, 0);
  EXPECT_EQ(off.repair_rings_expanded, 0);

  NetSimOptions o = f.options;
  o.repair_expand_hops = 32;
  const auto ring = run_netsim(f.scenario, o).metrics;
  ASSERT_TRUE(ring.success);
  EXPECT_EQ(ring.repair_rings_expanded, 1) << "one larger ring (4 hops) brought an answer";
  EXPECT_GE(ring.repair_answers_received, 1) << "the answer came back from beyond two hops";
  EXPECT_EQ(ring.repair_answers_refused, ring.repair_answers_received)
      << "its answerer had not seen the change";

  o.repair_fix_answer = true;
  const auto both = run_netsim(f.scenario, o).metrics;
  ASSERT_TRUE(both.success);
  EXPECT_EQ(both.repair_rings_expanded, 1);
  EXPECT_GE(both.repairs_executed, 1) << "the source repairs the far answer and drives it";
  EXPECT_GE(both.repair_answers_fixed + both.repair_answers_fixed_walk, 1);
  EXPECT_LT(both.source_travel_m, ring.source_travel_m);
}

// repair_sense_walk (issue #13, stop 28): scenario 3, run 7 (data/netsim/s3_run7_unanswered.yaml),
// class (a): no robot within repair_hops knows a way round the change, so off no answer comes and
// no Repair executes (the source replans on its own map). On, the source's nearest neighbour
// (robot 1, 2 m away) walks to the break, still knows no detour there, walks on round it to the
// route point past it and answers with the way it drove; the source takes that answer.
TEST(DecentralizedRepair, ARelaySensesTheBreakAndAnswersWhenNoRobotKnowsAWayRound) {
  auto f = saved_decentralized_run("s3_run7_unanswered.yaml");
  f.options.repair_sense_walk = false;
  const auto off = run_netsim(f.scenario, f.options).metrics;
  ASSERT_TRUE(off.success);
  EXPECT_EQ(off.repair_answers_received, 0) << "nobody within two hops answers";
  EXPECT_EQ(off.repairs_executed, 0);
  EXPECT_EQ(off.repair_sense_walks, 0);
  EXPECT_EQ(off.repair_answers_sensed, 0);

  NetSimOptions o = f.options;
  o.repair_sense_walk = true;
  const auto on = run_netsim(f.scenario, o).metrics;
  ASSERT_TRUE(on.success);
  EXPECT_EQ(on.repair_sense_walks, 1) << "one robot walks: the hand-off rule names one";
  EXPECT_GT(on.repair_sense_walk_m, 0.0);
  EXPECT_EQ(on.repair_sense_answers, 1);
  EXPECT_EQ(on.repair_answers_sensed, 1);
  EXPECT_EQ(on.repair_answers_sensed_taken, 1) << "the sensed answer is free in the source's map";
  EXPECT_GE(on.repairs_executed, 1);
  EXPECT_EQ(on.repair_answers_refused, 0);
  EXPECT_LT(on.replans, off.replans) << "the source drives the answer, not its own A* walk";
}

// repair_sense_walk (issue #13, stop 28): scenario 2, run 9 (data/netsim/s2_run9_refused.yaml),
// class (b): the one answer comes from robot 1, which had not seen the closed door; its detour
// crosses the door strip beside the cell the Repair carried and the source refuses it. On, robot
// 3 (the source's only neighbour, still on a bridge walk of the Search) walks to the break and
// says so (the source waits for it), finds no detour there once it has seen the door, walks round
// it and answers with the way it drove: the source takes that answer instead of its own A* walk.
TEST(DecentralizedRepair, ARelaySensesTheBreakWhenTheAnswerersMapsAreStale) {
  auto f = saved_decentralized_run("s2_run9_refused.yaml");
  f.options.repair_sense_walk = false;
  const auto off = run_netsim(f.scenario, f.options).metrics;
  ASSERT_TRUE(off.success);
  EXPECT_GE(off.repair_answers_refused, 1);
  EXPECT_EQ(off.repair_answers_refused, off.repair_answers_received) << "every answer stale";
  EXPECT_EQ(off.repairs_executed, 0);

  NetSimOptions o = f.options;
  o.repair_sense_walk = true;
  const auto on = run_netsim(f.scenario, o).metrics;
  ASSERT_TRUE(on.success);
  EXPECT_EQ(on.repair_answers_refused, off.repair_answers_refused) << "the stale answer still goes";
  EXPECT_EQ(on.repair_sense_walks, 1);
  EXPECT_EQ(on.repair_answers_sensed_taken, 1);
  EXPECT_GE(on.repairs_executed, 1);
  EXPECT_LT(on.source_travel_m, off.source_travel_m);
}

// repair_fix_seen_only (issue #13, stop 22): scenario 2, run 7 (data/netsim/s2_run7_fix_seen.yaml).
// With repair_fix_answer the source repairs a refused answer by A* on its own map; with
// repair_fix_seen_only that A* first keeps to cells the source knows free and the answer's free
// discs, and here it finds such a walk (without the option the walk may cross unknown cells).
TEST(DecentralizedRepair, ARepairedAnswerKeepsToSpaceSeenFree) {
  auto f = saved_decentralized_run("s2_run7_fix_seen.yaml");
  f.options.repair_fix_answer = true;
  f.options.repair_fix_seen_only = false;
  const auto any = run_netsim(f.scenario, f.options).metrics;
  ASSERT_TRUE(any.success);
  EXPECT_GE(any.repair_answers_fixed_walk, 1) << "a refused answer repaired by A*";
  EXPECT_EQ(any.repair_answers_fixed_seen, 0);

  NetSimOptions o = f.options;
  o.repair_fix_seen_only = true;
  const auto seen = run_netsim(f.scenario, o).metrics;
  ASSERT_TRUE(seen.success);
  EXPECT_GE(seen.repair_answers_fixed_seen, 1) << "the walk kept to space seen free";
  EXPECT_LE(seen.repair_answers_fixed_seen, seen.repair_answers_fixed_walk);
  EXPECT_GE(seen.repairs_executed, 1);
}

// repair_walk_keep_ratio (issue #13, stop 24): scenario 4, run 11 (data/netsim/s4_run11_walk.yaml)
// with repair_fix_answer. The source repairs a refused answer by A* on its own map (unknown cells
// count free) and drives the walk onto it. Each time walls it has just seen block that walk, it
// planned again to the next route point and dropped the walk's own: within 9 s the repaired
// answer's points were gone and it walked through unknown space toward the destination 35 m
// away; it made 127 replans and did not arrive. With the rule (K = 1000) it plans again
// to the same point of the answer (a kept target) and arrives.
TEST(DecentralizedRepair, ABlockedWalkKeepsItsRoutePoint) {
  auto f = saved_decentralized_run("s4_run11_walk.yaml");
  f.options.repair_fix_answer = true;
  f.options.repair_walk_keep_ratio = 0.0;
  const auto drop = run_netsim(f.scenario, f.options).metrics;
  EXPECT_GE(drop.repair_answers_fixed_walk, 1) << "a refused answer repaired by A*";
  EXPECT_FALSE(drop.success) << "the walk dropped the answer's points and the source got lost";
  EXPECT_EQ(drop.repair_walk_targets_kept, 0);

  NetSimOptions o = f.options;
  o.repair_walk_keep_ratio = 1000.0;
  const auto keep = run_netsim(f.scenario, o).metrics;
  ASSERT_TRUE(keep.success);
  EXPECT_GE(keep.repair_answers_fixed_walk, 1);
  EXPECT_GE(keep.repair_walk_targets_kept, 1) << "blocked walks planned again to their point";
  EXPECT_LT(keep.source_travel_m, drop.source_travel_m);
}

}  // namespace
}  // namespace voronav::sim
