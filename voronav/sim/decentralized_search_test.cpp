// Table 2 of seed 000 (decentralized_search.cpp): a relay handles a Search it has not handled
// yet, and a copy of a Search it already forwarded only when the copy is new to it, i.e. lowers
// one of its costs. One relay in a hall, the other robots played by hand over the simulated radio.
#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "voronav/network/messages.hpp"
#include "voronav/network/sim_radio.hpp"
#include "voronav/sim/robot_agent.hpp"
#include "voronav/sim/scenario_file.hpp"

namespace voronav::sim {
namespace {

using network::RobotId;

// A free hall 20 x 6 m (0.2 m cells, walls around). Robot 0 is the source (never stepped
// here), robot 1 the relay at (8, 3) (it senses x 5..11 m), robot 2 a listener at (14, 3), closer
// to the destination (18.5, 3): the relay hands the Search on to it, so it forwards rather than
// walks. Robots 3 and 4 are senders near the relay.
struct Hall {
  NetSimScenario sc;
  NetSimOptions opt;
  BinaryGrid truth;
  network::SimRadio radio;
  std::optional<RobotAgent> relay;
  double t = 0.0;
  std::uint32_t msg = 1;

  Hall() {
    sc.world = OccupancyGrid(GridGeometry{100, 30, 0.2, {}}, kOccupied);
    for (int y = 2; y < 28; ++y)
      for (int x = 2; x < 98; ++x)
        sc.world[Cell{x, y}] = kFree;
    sc.robots = {{1.5, 3.0}, {8.0, 3.0}, {14.0, 3.0}, {5.0, 3.0}, {5.0, 4.0}};
    sc.destination = {18.5, 3.0};
    opt.method = Method::kDecentralized;
    truth = BinaryGrid(sc.world.geometry(), 0);
    for (std::size_t i = 0; i < truth.size(); ++i)
      truth[i] = sc.world[i] == kFree ? 0 : 1;
    for (std::uint32_t i = 0; i < sc.robots.size(); ++i)
      radio.update_position(RobotId{i}, sc.robots[i]);
    relay.emplace(AgentContext{&sc, &opt, &truth, nullptr, nullptr}, RobotId{1}, sc.robots[1],
                  radio);
    relay->begin();
  }

  // `from` broadcasts Search Num 1 of the source with one open point at (6, 3) (clearance
  // 1 m, cost `cost` from the source); the relay handles what it hears.
  void search_from(std::uint32_t from, float cost) {
    network::SearchMessage m;
    m.source = RobotId{0};
    m.num = 1;
    m.destination = sc.destination;
    m.relays = {RobotId{0}, RobotId{from}};
    m.open_points = {{{6.0, 3.0}, 1.0f, cost}};
    const network::Envelope e{{RobotId{from}, network::kBroadcast, RobotId{from}, msg++, 1}, m};
    radio.broadcast(RobotId{from}, network::encode(e));
    t += 0.2;
    radio.set_time(t);
    relay->communicate(t);
  }

  // The Searches the listener heard from the relay since the last call.
  std::vector<network::SearchMessage> forwarded() {
    std::vector<network::SearchMessage> out;
    radio.set_time(t + 0.1);  // (delivered after the radio latency)
    for (const auto& p : radio.receive(RobotId{2})) {
      const auto e = network::decode(p.bytes);
      if (p.from == RobotId{1} && e.type() == network::MessageType::kSearch)
        out.push_back(std::get<network::SearchMessage>(e.payload));
    }
    return out;
  }
};

float cheapest(const network::SearchMessage& m) {
  float c = 1e30f;
  for (const auto& p : m.open_points)
    c = std::min(c, p.cost);
  return c;
}

TEST(DecentralizedSearch, ACopyThatLowersNoCostIsIgnoredAndOneThatDoesIsHandled) {
  Hall h;
  // Table 2: a new Search is searched and forwarded.
  h.search_from(3, 10.0f);
  auto fw = h.forwarded();
  ASSERT_EQ(fw.size(), 1u) << "the relay continues the Search and forwards it";
  const float first = cheapest(fw[0]);
  EXPECT_GT(first, 10.0f);
  EXPECT_EQ(h.relay->report().point_searches, 1);
  // The same point at the same cost from another robot (a re-forward) and at a higher cost:
  // neither lowers a cost of the relay, so neither is new: no search, no forward.
  h.search_from(4, 10.0f);
  h.search_from(4, 12.5f);
  EXPECT_TRUE(h.forwarded().empty());
  EXPECT_EQ(h.relay->report().point_searches, 1) << "no search for a copy that is not new";
  EXPECT_EQ(h.relay->report().search_copies_ignored, 2);
  // A copy that reaches the point 6 m cheaper is new: searched again and forwarded with costs
  // 6 m lower.
  h.search_from(4, 4.0f);
  fw = h.forwarded();
  ASSERT_EQ(fw.size(), 1u);
  EXPECT_NEAR(cheapest(fw[0]), first - 6.0f, 1e-3);
  EXPECT_EQ(h.relay->report().point_searches, 2);
  EXPECT_EQ(h.relay->report().search_copies_ignored, 2);
  // The first copy is now dearer than what the relay holds: ignored.
  h.search_from(3, 10.0f);
  EXPECT_TRUE(h.forwarded().empty());
  EXPECT_EQ(h.relay->report().point_searches, 2);
  EXPECT_EQ(h.relay->report().search_copies_ignored, 3);
}

}  // namespace
}  // namespace voronav::sim

namespace voronav::sim {
namespace {

// Figure 18 for a boxed-in source (sense_when_boxed_in): scenario 2 run 10 of Table 7, as
// `voronav netsim --scenario 2 --run 10 --write-scenario` writes it (data/netsim). After the
// second change the source stands in a room whose two known exits are closed; the relays in
// range stand at the destination with maps that still hold the doors open, so every answer is
// blocked at once. Without the sensing walk it never leaves the room; with it, it senses the
// gaps of its known space, searches again from there and arrives.
TEST(DecentralizedSearch, ABoxedInSourceSensesTheGapsOfItsKnownSpaceAndArrives) {
  const auto f =
      load_netsim_scenario(std::string(VORONAV_SOURCE_DIR) + "/data/netsim/s2_run10_boxed_in.yaml");
  const NetSimScenario& sc = f.scenario;
  NetSimOptions o = f.options;
  o.repair_sense_walk = false;  // as saved (before stop 28): the Search mechanism alone
  o.method = Method::kDecentralized;
  o.sense_when_boxed_in = false;
  const auto off = run_netsim(sc, o).metrics;
  EXPECT_FALSE(off.success) << "the s2r10 trace: boxed in, no arrival without the rule";
  EXPECT_EQ(off.sensing_walks, 0);
  o.sense_when_boxed_in = true;
  const auto on = run_netsim(sc, o).metrics;
  EXPECT_TRUE(on.success);
  EXPECT_GE(on.sensing_walks, 1);
  EXPECT_GT(on.sensing_walk_m, 0.0);
  EXPECT_LE(on.sensing_walk_m, on.source_travel_m);
}

// Scenario 4, run 15 (data/netsim/s4_run15_window.yaml; issue #13, stop 26). The source has
// spent its last Search (max_search_attempts) and walks to the destination on its own map. The
// third change (429.8 s) closes the door ahead; it replans round it and, at 484 s at
// (39.7, 24.5), the walk can no longer be planned in the window around its two ends: the only
// way its map holds runs 0.4 m west of the window. It stopped there and stood still to the 900 s
// limit. Now the source's own destination walk plans once more on its whole local map before it
// stops (walk_replan_whole_map stays off for every other walk) and arrives.
TEST(DecentralizedSearch, ASourceWalkBlockedInItsWindowPlansOnItsWholeMap) {
  const auto f =
      load_netsim_scenario(std::string(VORONAV_SOURCE_DIR) + "/data/netsim/s4_run15_window.yaml");
  NetSimOptions o = f.options;
  o.repair_sense_walk = false;  // as saved (before stop 28): the Search mechanism alone
  o.method = Method::kDecentralized;
  ASSERT_FALSE(o.walk_replan_whole_map);
  const auto m = run_netsim(f.scenario, o).metrics;
  EXPECT_EQ(m.search_attempts, o.max_search_attempts) << "no Search left: only its walk";
  EXPECT_EQ(m.changes_on_route, 3);
  EXPECT_TRUE(m.success) << "stopped at (39.7, 24.5) at 484 s before the fix";
  EXPECT_LT(m.simulated_s, o.time_limit_s);
}

}  // namespace
}  // namespace voronav::sim
