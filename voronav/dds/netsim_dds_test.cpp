// Tests of the pieces of the multi-process netsim run that need no child process: the metrics JSON
// the world process prints and the launcher reads back, and a robot agent behind a real
// DdsTransport that is sent garbage and a real Search by a raw participant (it counts the garbage,
// never crashes, and continues the Search). The multi-process runs themselves are checked end to
// end in tests/cli_netsim_dds.py.
#include "voronav/dds/netsim_dds.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>

#include "voronav/core/error.hpp"
#include "voronav/dds/cyclone_config.hpp"
#include "voronav/dds/dds_transport.hpp"
#include "voronav/network/messages.hpp"
#include "voronav/sim/robot_agent.hpp"
#include "voronav/sim/scenario_file.hpp"

namespace voronav::dds {
namespace {

TEST(NetsimDds, MetricsJsonRoundTrips) {
  sim::NetSimMetrics m;
  m.success = true;
  m.route_time_s = 12.4;
  m.arrival_time_s = 51.2;
  m.travel_m = 123.25;
  m.source_travel_m = 40.5;
  m.route_length_m = 38.75;
  m.traffic_bytes = 123456789012ull;
  m.messages = 42;
  m.computation = 987654321;
  m.max_robot_computation = 12345;
  m.cpu_s = 0.125;
  m.max_robot_cpu_s = 0.0625;
  m.by_type["search"] = {7, 2100};
  m.by_type["path"] = {3, 600};
  m.alpha_bytes = 300.0;
  m.gamma_bytes = 200.0;
  m.search_attempts = 2;
  m.repairs = 1;
  m.replans = 0;
  m.corrupt_packets = 5;
  m.repairs_executed = 2;
  m.repair_requests = 7;
  m.source_repair_requests = 3;
  m.repair_answers = 4;
  m.repair_answers_received = 5;
  m.repair_answers_refused = 1;
  m.repair_rings_expanded = 3;
  m.simulated_s = 51.2;
  m.wall_s = 3.5;
  sim::RobotMetrics r;
  r.work = 99;
  r.travel_m = 1.5;
  r.sent_bytes = 700;
  r.sent_messages = 3;
  r.sent_by_type[static_cast<std::size_t>(network::MessageType::kSearch)] = {2, 600};
  m.robots = {r, {}};
  const auto back = metrics_from_json(metrics_to_json(m));
  EXPECT_EQ(back.success, m.success);
  EXPECT_EQ(back.route_time_s, m.route_time_s);
  EXPECT_EQ(back.arrival_time_s, m.arrival_time_s);
  EXPECT_EQ(back.travel_m, m.travel_m);
  EXPECT_EQ(back.route_length_m, m.route_length_m);
  EXPECT_EQ(back.traffic_bytes, m.traffic_bytes);
  EXPECT_EQ(back.messages, m.messages);
  EXPECT_EQ(back.computation, m.computation);
  EXPECT_EQ(back.max_robot_computation, m.max_robot_computation);
  EXPECT_EQ(back.by_type.at("search").bytes, 2100u);
  EXPECT_EQ(back.by_type.at("path").messages, 3u);
  EXPECT_EQ(back.search_attempts, 2);
  EXPECT_EQ(back.corrupt_packets, 5u);
  EXPECT_EQ(back.repairs_executed, 2);
  EXPECT_EQ(back.repair_requests, 7);
  EXPECT_EQ(back.source_repair_requests, 3);
  EXPECT_EQ(back.repair_answers, 4);
  EXPECT_EQ(back.repair_answers_received, 5);
  EXPECT_EQ(back.repair_answers_refused, 1);
  EXPECT_EQ(back.repair_rings_expanded, 3);
  ASSERT_EQ(back.robots.size(), 2u);
  EXPECT_EQ(back.robots[0].work, 99u);
  EXPECT_EQ(back.robots[0].sent_by_type[1].bytes, 600u);
  EXPECT_EQ(back.robots[1].sent_messages, 0u);
  EXPECT_THROW((void)metrics_from_json("{\"success\": true}"), Error);
  EXPECT_THROW((void)metrics_from_json("not json"), Error);
}

TEST(NetsimDds, LockstepOptionsAreValidated) {
  LockstepLink l;
  EXPECT_NO_THROW(l.validate());
  l.step_timeout_s = std::nan("");
  EXPECT_THROW(l.validate(), Error);
  l = {};
  l.domain_id = 231;
  EXPECT_THROW(l.validate(), Error);
  l = {};
  l.partition.clear();
  EXPECT_THROW(l.validate(), Error);
  RobotProcessOptions r;
  r.scenario_path = std::string(VORONAV_SOURCE_DIR) + "/data/netsim/corridor.yaml";
  r.id = 10;  // the corridor has robots 0..9
  try {
    (void)run_robot_process(r);
    ADD_FAILURE() << "robot 10 of 10 accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("10 robots"), std::string::npos) << e.what();
  }
}

TEST(NetsimDds, AgentBehindDdsCountsGarbageAndContinuesARealSearch) {
  const auto file =
      sim::load_netsim_scenario(std::string(VORONAV_SOURCE_DIR) + "/data/netsim/corridor.yaml");
  const auto& sc = file.scenario;
  DdsTransportOptions o;
  o.self = network::RobotId{1};
  o.domain_id = static_cast<std::uint32_t>(1 + (::getpid() + 7) % 200);
  o.config_xml = loopback_config_xml();
  o.partition = "agent-test-" + std::to_string(::getpid());
  o.radio_range_m = file.options.radio.range_m;
  o.close_timeout_s = 0.2;
  DdsTransport dds(o);
  RawDdsWriter raw(o);   // speaks for robot 0, the source
  RawDdsWriter raw2(o);  // robot 2, closer to the destination (so robot 1 relays, not walks)
  BinaryGrid truth = binarize(sc.world);
  sim::AgentContext ctx{&sc, &file.options, &truth, nullptr};
  sim::RobotAgent agent(ctx, network::RobotId{1}, sc.robots[1], dds);
  agent.begin();
  ASSERT_TRUE(raw.wait_for_readers(1, 10.0));
  ASSERT_TRUE(raw2.wait_for_readers(1, 10.0));
  raw.write(RawPose{1, 0, sc.robots[0].x, sc.robots[0].y, 0.0});
  raw2.write(RawPose{1, 2, sc.robots[2].x, sc.robots[2].y, 0.0});
  ASSERT_TRUE(dds.wait_for_poses({network::RobotId{0}, network::RobotId{2}}, 0.0, 10.0));
  auto sample = [](std::uint64_t seq, std::vector<std::uint8_t> bytes) {
    RawPayloadSample s;
    s.sender = 0;
    s.seq = seq;
    s.bytes = std::move(bytes);
    s.length = static_cast<std::uint32_t>(s.bytes.size());
    return s;
  };
  // Well-formed for DDS, garbage for the protocol (no magic, no CRC).
  raw.write(sample(1, {'n', 'o', 't', ' ', 'a', ' ', 'm', 's', 'g'}));
  // A real Search from the source: one open point 2 m ahead of it (inside its 3 m sensing), with
  // the cost of getting there.
  network::SearchMessage m;
  m.source = network::RobotId{0};
  m.num = 1;
  m.destination = sc.destination;
  m.relays = {network::RobotId{0}};
  m.open_points = {network::VoronoiPoint{sc.robots[0] + Vec2{2.0, 0.0}, 1.1f, 2.0f}};
  const auto bytes = network::encode(network::Envelope{
      network::Header{network::RobotId{0}, network::kBroadcast, network::RobotId{0}, 1, 0}, m});
  raw.write(sample(2, bytes));
  const auto search = static_cast<std::size_t>(network::MessageType::kSearch);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  double t = 0.0;
  while (std::chrono::steady_clock::now() < deadline &&
         (agent.report().corrupt_packets < 1 ||
          agent.report().metrics.sent_by_type[search].messages < 1)) {
    dds.wait_for_data(0.05);
    t += file.options.dt_s;
    agent.communicate(t);
  }
  EXPECT_EQ(agent.report().corrupt_packets, 1u) << "the garbage is counted, not fatal";
  EXPECT_EQ(agent.report().metrics.sent_by_type[search].messages, 1u)
      << "robot 1's area continues the source's: it forwards the Search";
  EXPECT_EQ(dds.stats().rejected, 0u) << "both samples were well-formed DDS samples";
}

}  // namespace
}  // namespace voronav::dds
