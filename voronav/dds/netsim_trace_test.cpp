// Trace files of the multi-process netsim run (internal/netsim_trace.hpp): written by TraceFile,
// read back by read_netsim_traces into a sim::Recording and the events.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "voronav/dds/internal/netsim_trace.hpp"

namespace voronav::dds::internal {
namespace {

TEST(NetsimTrace, RobotAndWorldTracesRoundTrip) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("voronav-trace-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string r0 = (dir / "r0.jsonl").string(), r1 = (dir / "r1.jsonl").string(),
                    w = (dir / "w.jsonl").string();
  sim::NetSimScenario sc;
  sc.world = OccupancyGrid(GridGeometry{10, 10, 1.0, {}}, kFree);
  sc.robots = {{1.0, 1.0}, {5.0, 5.0}};
  sc.source = 0;
  {
    TraceFile t0(r0), t1(r1), tw(w);
    ASSERT_TRUE(t0.on() && t1.on() && tw.on());
    t0.robot_step(0, 0.0, {1.0, 1.0}, {});
    t1.robot_step(0, 0.0, {5.0, 5.0}, {{0.0, 1, 0, network::MessageType::kSearch, 40}});
    t0.robot_step(1, 0.2, {1.2, 1.0}, {{0.1, 0, 1, network::MessageType::kSearch, 30}},
                  {{0.2, 0, false, "is blocked and asks its neighbours (Repair message)"}});
    // robot 1 dies after step 0: no line for step 1
    t0.robot_step(2, 0.4, {1.4, 1.0}, {},
                  {{0.4, 0, true, "takes robot 1's detour (Repair executed)"}});
    t0.robot_route({{1.0, 1.0}, {9.0, 1.0}});
    tw.event({0.2, 1, "dead", 1, "declared dead"});
  }
  std::ofstream(r1, std::ios::app) << "{\"k\": 1, \"t\": 0.2, \"p\": [5.";  // cut short by a kill
  sim::Recording rec;
  std::vector<DdsEvent> events;
  read_netsim_traces({r0, r1}, w, sc, rec, events);
  ASSERT_EQ(rec.steps.size(), 3U);
  EXPECT_DOUBLE_EQ(rec.steps[2].t_s, 0.4);
  EXPECT_EQ(rec.steps[2].positions[0], (Vec2{1.4, 1.0}));
  EXPECT_EQ(rec.steps[2].positions[1], (Vec2{5.0, 5.0}));  // the dead robot stays where it was
  ASSERT_EQ(rec.messages.size(), 2U);
  EXPECT_EQ(rec.messages[0].from, 1U);  // sorted by time: robot 1's at 0.0 s first
  EXPECT_EQ(rec.messages[1].to, 1U);
  EXPECT_EQ(rec.messages[1].bytes, 30U);
  EXPECT_EQ(rec.messages[1].type, network::MessageType::kSearch);
  // The route breaks each robot handled (the replay's and the bag's repair/blocked events).
  ASSERT_EQ(rec.repairs.size(), 2U);
  EXPECT_DOUBLE_EQ(rec.repairs[0].t_s, 0.2);
  EXPECT_FALSE(rec.repairs[0].executed);
  EXPECT_EQ(rec.repairs[0].what, "is blocked and asks its neighbours (Repair message)");
  EXPECT_EQ(rec.repairs[1].robot, 0U);
  EXPECT_TRUE(rec.repairs[1].executed);
  EXPECT_EQ(rec.repairs[1].what, "takes robot 1's detour (Repair executed)");
  ASSERT_EQ(rec.route.size(), 2U);
  EXPECT_EQ(rec.route[1], (Vec2{9.0, 1.0}));
  ASSERT_EQ(events.size(), 1U);
  EXPECT_EQ(events[0].kind, "dead");
  EXPECT_EQ(events[0].robot, 1);
  EXPECT_EQ(events[0].step, 1U);
  // No trace path: nothing is written.
  TraceFile off("");
  EXPECT_FALSE(off.on());
  fs::remove_all(dir);
}

}  // namespace
}  // namespace voronav::dds::internal
