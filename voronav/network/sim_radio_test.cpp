#include "voronav/network/sim_radio.hpp"

#include <gtest/gtest.h>

#include "voronav/core/error.hpp"

namespace voronav::network {
namespace {

std::vector<std::uint8_t> request_bytes(std::uint32_t id) {
  return encode(
      {Header{RobotId{0}, kBroadcast, RobotId{0}, id, 0}, RequestMessage{RobotId{0}, id}});
}

TEST(SimRadio, BroadcastReachesOnlyRobotsInRange) {
  SimRadio radio(RadioOptions{.range_m = 25.0, .latency_s = 0.01});
  radio.update_position(RobotId{0}, {0, 0});
  radio.update_position(RobotId{1}, {24.9, 0});
  radio.update_position(RobotId{2}, {25.1, 0});
  radio.update_position(RobotId{3}, {0, -10});
  const auto b = request_bytes(1);
  radio.broadcast(RobotId{0}, b);
  EXPECT_TRUE(radio.receive(RobotId{1}).empty()) << "latency not elapsed";
  radio.set_time(0.01);
  const auto got1 = radio.receive(RobotId{1});
  ASSERT_EQ(got1.size(), 1u);
  EXPECT_EQ(got1[0].from, RobotId{0});
  EXPECT_EQ(got1[0].to, kBroadcast);
  EXPECT_EQ(got1[0].bytes, b);
  EXPECT_TRUE(radio.receive(RobotId{2}).empty());
  EXPECT_EQ(radio.receive(RobotId{3}).size(), 1u);
  EXPECT_TRUE(radio.receive(RobotId{0}).empty());
  // One transmission on the air, bytes = the serialized size, counted under its type.
  EXPECT_EQ(radio.stats().total.messages, 1u);
  EXPECT_EQ(radio.stats().total.bytes, b.size());
  EXPECT_EQ(radio.stats().by_type[static_cast<int>(MessageType::kRequest)].bytes, b.size());
  EXPECT_EQ(radio.stats().sent_by_robot[0].bytes, b.size());
  EXPECT_EQ(radio.stats().received_by_robot[3].messages, 1u);
}

TEST(SimRadio, UnicastOutOfRangeIsDroppedButStillOnTheAir) {
  SimRadio radio;
  radio.update_position(RobotId{0}, {0, 0});
  radio.update_position(RobotId{1}, {30, 0});
  radio.send(RobotId{0}, RobotId{1}, request_bytes(1));
  radio.set_time(1.0);
  EXPECT_TRUE(radio.receive(RobotId{1}).empty());
  EXPECT_EQ(radio.stats().out_of_range, 1u);
  EXPECT_EQ(radio.stats().total.messages, 1u);
  radio.update_position(RobotId{1}, {20, 0});
  radio.send(RobotId{0}, RobotId{1}, request_bytes(2));
  radio.set_time(2.0);
  EXPECT_EQ(radio.receive(RobotId{1}).size(), 1u);
}

TEST(SimRadio, LossRateIsHonoured) {
  SimRadio radio(RadioOptions{.loss = 0.2, .seed = 5});
  radio.update_position(RobotId{0}, {0, 0});
  radio.update_position(RobotId{1}, {1, 0});
  const int n = 20000;
  for (int i = 0; i < n; ++i)
    radio.send(RobotId{0}, RobotId{1}, request_bytes(static_cast<std::uint32_t>(i)));
  radio.set_time(1.0);
  const double got = static_cast<double>(radio.receive(RobotId{1}).size()) / n;
  EXPECT_NEAR(got, 0.8, 0.015);
  EXPECT_EQ(radio.stats().lost + radio.stats().receptions, static_cast<std::uint64_t>(n));
}

TEST(SimRadio, DuplicationAndReorderingHappenDeterministically) {
  auto run = [] {
    SimRadio radio(RadioOptions{.duplicate = 0.3, .reorder = 0.3, .seed = 9});
    radio.update_position(RobotId{0}, {0, 0});
    radio.update_position(RobotId{1}, {1, 0});
    for (std::uint32_t i = 0; i < 200; ++i)
      radio.send(RobotId{0}, RobotId{1}, request_bytes(i));
    radio.set_time(10.0);
    std::vector<std::uint32_t> ids;
    for (const auto& p : radio.receive(RobotId{1}))
      ids.push_back(decode(p.bytes).header.msg_id);
    return ids;
  };
  const auto a = run();
  EXPECT_EQ(a, run());
  EXPECT_GT(a.size(), 230u);
  EXPECT_FALSE(std::is_sorted(a.begin(), a.end()));
}

TEST(SimRadio, InvalidOptionsAreRejected) {
  EXPECT_THROW(SimRadio(RadioOptions{.loss = 1.5}), Error);
  EXPECT_THROW(SimRadio(RadioOptions{.range_m = -1}), Error);
  EXPECT_THROW(SimRadio(RadioOptions{.latency_s = std::nan("")}), Error);
  SimRadio radio;
  EXPECT_THROW(radio.update_position(RobotId{0}, {std::nan(""), 0}), Error);
  EXPECT_THROW(radio.update_position(kBroadcast, {0, 0}), Error);
}

TEST(SimRadio, NeighboursListsRobotsInRange) {
  SimRadio radio(RadioOptions{.range_m = 5});
  radio.update_position(RobotId{0}, {0, 0});
  radio.update_position(RobotId{1}, {3, 4});
  radio.update_position(RobotId{2}, {3, 4.1});
  const auto n = radio.neighbours(RobotId{0});
  ASSERT_EQ(n.size(), 1u);
  EXPECT_EQ(n[0], RobotId{1});
}

}  // namespace
}  // namespace voronav::network
