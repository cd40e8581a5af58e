// Repair (seed 000, Tables 4–5; decentralized_repair.cpp): who answers a Repair and how the
// source takes the answers. A hand-made hall where a block closes the route ahead of the source
// and several robots know a way around it.
#include <gtest/gtest.h>

#include <map>

#include "voronav/sim/netsim.hpp"
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

}  // namespace
}  // namespace voronav::sim
