#include "voronav/network/messages.hpp"

#include <gtest/gtest.h>

#include <random>

#include "voronav/core/error.hpp"

namespace voronav::network {
namespace {

Envelope search_envelope() {
  SearchMessage s;
  s.source = RobotId{3};
  s.num = 7;
  s.destination = {12.5, -4.25};
  s.relays = {RobotId{3}, RobotId{9}};
  s.open_points = {{{1.5, 2.0}, 0.75f, 3.5f}, {{-2.0, 8.25}, 1.25f, 0.0f}};
  s.close_points = {{0.5, 0.5}};
  return Envelope{Header{RobotId{9}, kBroadcast, RobotId{3}, 42, 2}, s};
}

std::vector<Envelope> all_kinds() {
  std::vector<Envelope> v{search_envelope()};
  PathMessage p{RobotId{1},
                2,
                {RobotId{1}, RobotId{4}},
                {{{1, 1}, 1.0f, 0.0f}, {{2, 2}, 0.5f, 1.5f}},
                1,
                {RobotId{4}, RobotId{7}},
                {RobotId{8}},
                {3.5, -1.0}};
  v.push_back({Header{RobotId{4}, RobotId{1}, RobotId{6}, 5, 1}, p});
  RepairMessage r{RobotId{1},
                  3,
                  {RobotId{2}},
                  {{{0, 0}, 1, 0}, {{1, 0}, 1, 1}, {{2, 0}, 1, 2}},
                  0,
                  2,
                  {{0.5, 0.25}, {0.75, 0.25}}};
  v.push_back({Header{RobotId{2}, kBroadcast, RobotId{2}, 9, 0}, r});
  r.hop_limit = 4;  // repair_expand_hops: the optional last byte
  v.push_back({Header{RobotId{2}, kBroadcast, RobotId{2}, 10, 1}, r});
  v.push_back({Header{RobotId{0}, kBroadcast, RobotId{0}, 1, 0}, RequestMessage{RobotId{0}, 1}});
  OccupancyGrid g(GridGeometry{5, 3, 0.2, {{1.0, 2.0}, 0.0}}, kUnknown);
  g[Cell{0, 0}] = kFree;
  g[Cell{4, 2}] = kOccupied;
  g[Cell{2, 1}] = kFree;
  v.push_back({Header{RobotId{5}, RobotId{0}, RobotId{5}, 77, 3},
               AckMessage{RobotId{0}, 1, RobotId{5}, g}});
  v.push_back({Header{RobotId{5}, RobotId{0}, RobotId{5}, 78, 0},
               NotifyMessage{RobotId{0}, RobotId{5}, {3, 4}}});
  v.push_back({Header{RobotId{0}, RobotId{5}, RobotId{0}, 79, 0}, LinkAckMessage{RobotId{5}, 77}});
  return v;
}

TEST(Messages, EveryKindRoundTrips) {
  for (const auto& e : all_kinds()) {
    const auto bytes = encode(e);
    EXPECT_EQ(peek_type(bytes), static_cast<std::uint8_t>(e.type()));
    const Envelope back = decode(bytes);
    EXPECT_EQ(back, e) << to_string(e.type());
    EXPECT_EQ(encode(back), bytes);
  }
}

TEST(Messages, SizesFollowTheContent) {
  const auto e = search_envelope();
  const auto bytes = encode(e);
  // header + CRC + source/num + destination + relays + open points + close points.
  EXPECT_EQ(bytes.size(), kEnvelopeOverhead + 8 + 8 + (4 + 2 * 4) + (4 + 2 * 16) + (4 + 8));
  OccupancyGrid g(GridGeometry{10, 10, 0.1, {}}, kFree);
  const auto ack = encode({Header{}, AckMessage{RobotId{0}, 0, RobotId{1}, g}});
  EXPECT_EQ(ack.size(), kEnvelopeOverhead + 12 + 4 + 4 + 32 + 25);  // 100 cells at 2 bits
  EXPECT_EQ(grid_payload_bytes(g), 8 + 32 + 25u);
}

TEST(Messages, EveryTruncationIsRejected) {
  for (const auto& e : all_kinds()) {
    const auto bytes = encode(e);
    for (std::size_t n = 0; n < bytes.size(); ++n) {
      EXPECT_THROW((void)decode(std::span(bytes).first(n)), Error) << n;
    }
  }
}

TEST(Messages, ARepairCarriesItsHopLimitOnlyWhenSet) {
  RepairMessage r{RobotId{1}, 3, {RobotId{1}}, {{{0, 0}, 1, 0}, {{1, 0}, 1, 1}}, 0, 1, {}};
  const auto plain = encode({Header{}, r});
  r.hop_limit = 8;
  const auto ringed = encode({Header{}, r});
  EXPECT_EQ(ringed.size(), plain.size() + 1);  // a Repair without it keeps the bytes of Table 5
  EXPECT_EQ(std::get<RepairMessage>(decode(plain).payload).hop_limit, 0);
  EXPECT_EQ(std::get<RepairMessage>(decode(ringed).payload).hop_limit, 8);
}

TEST(Messages, TrailingBytesAreRejected) {
  auto bytes = encode(search_envelope());
  bytes.push_back(0);
  EXPECT_THROW((void)decode(bytes), Error);
}

TEST(Messages, EverySingleBitFlipIsRejected) {
  const auto bytes = encode(all_kinds()[1]);
  for (std::size_t i = 0; i < bytes.size(); ++i)
    for (int b = 0; b < 8; ++b) {
      auto bad = bytes;
      bad[i] = static_cast<std::uint8_t>(bad[i] ^ (1u << b));
      EXPECT_THROW((void)decode(bad), Error) << "byte " << i << " bit " << b;
    }
}

TEST(Messages, RandomGarbageNeverCrashesAndIsRejected) {
  std::mt19937 rng(11);
  for (int t = 0; t < 2000; ++t) {
    std::vector<std::uint8_t> junk(rng() % 200);
    for (auto& b : junk)
      b = static_cast<std::uint8_t>(rng());
    if (t % 2 == 0 && junk.size() > 4) {
      junk[0] = 'V';
      junk[1] = 'N';
      junk[2] = kWireVersion;
      junk[3] = static_cast<std::uint8_t>(1 + rng() % 7);
    }
    EXPECT_THROW((void)decode(junk), Error);
  }
}

TEST(Messages, ErrorsNameTheProblem) {
  auto bytes = encode(search_envelope());
  bytes[2] = 9;
  try {
    (void)decode(bytes);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("version 9"), std::string::npos) << e.what();
  }
  bytes = encode(search_envelope());
  bytes[bytes.size() - 6] ^= 0x10;
  try {
    (void)decode(bytes);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("CRC"), std::string::npos) << e.what();
  }
}

TEST(Messages, LyingCountWithValidCrcIsRejected) {
  // A well-formed envelope whose relay count claims more elements than the payload holds.
  auto bytes = encode(search_envelope());
  const std::size_t relay_count_at = 2 + 1 + 1 + 4 * 4 + 1 + 4 + 8 + 8;
  bytes[relay_count_at] = 200;
  const auto crc = crc32(std::span(bytes).first(bytes.size() - 4));
  for (int i = 0; i < 4; ++i)
    bytes[bytes.size() - 4 + static_cast<std::size_t>(i)] =
        static_cast<std::uint8_t>(crc >> (8 * i));
  EXPECT_THROW((void)decode(bytes), Error);
}

TEST(Messages, NonFiniteValuesAreNotEncoded) {
  auto e = search_envelope();
  std::get<SearchMessage>(e.payload).destination.x = std::nan("");
  EXPECT_THROW((void)encode(e), Error);
}

TEST(Messages, Crc32MatchesTheStandardCheckValue) {
  const std::string s = "123456789";
  EXPECT_EQ(crc32(std::span(reinterpret_cast<const std::uint8_t*>(s.data()), s.size())),
            0xCBF43926u);
}

}  // namespace
}  // namespace voronav::network
