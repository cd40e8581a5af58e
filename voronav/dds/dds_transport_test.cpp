// In-process tests of the DDS transport: several participants in one process on a loopback
// domain (each test on its own domain id and partition, so parallel test processes never mix).
#include "voronav/dds/dds_transport.hpp"

#include <dds/dds.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <thread>

#include "voronav/core/error.hpp"
#include "voronav/dds/cyclone_config.hpp"
#include "voronav_dds.h"

namespace voronav::dds {
namespace {

using network::kBroadcast;
using network::Packet;
using network::RobotId;

constexpr double kTimeout = 5.0;

DdsTransportOptions base_options(std::uint32_t self, double range = 10.0) {
  static int counter = 0;
  static const std::string partition =
      "test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  DdsTransportOptions o;
  o.self = RobotId{self};
  o.domain_id = static_cast<std::uint32_t>(1 + ::getpid() % 200);
  o.config_xml = loopback_config_xml();
  o.partition = partition;
  o.radio_range_m = range;
  o.close_timeout_s = 0.2;
  return o;
}

std::vector<std::uint8_t> bytes_of(const std::string& s) {
  return {s.begin(), s.end()};
}
std::string text_of(const Packet& p) {
  return {p.bytes.begin(), p.bytes.end()};
}

// Receives until `n` packets arrived or the timeout passed.
std::vector<Packet> receive_n(DdsTransport& t, std::size_t n, double timeout_s = kTimeout) {
  std::vector<Packet> got;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (got.size() < n && std::chrono::steady_clock::now() < deadline) {
    t.wait_for_data(0.05);
    for (auto& p : t.receive(t.self()))
      got.push_back(std::move(p));
  }
  return got;
}

// Receives for `seconds` (to check that nothing else arrives).
std::vector<Packet> receive_for(DdsTransport& t, double seconds) {
  return receive_n(t, std::numeric_limits<std::size_t>::max(), seconds);
}

TEST(CycloneConfig, LoopbackXmlHasUnicastPeersAndIndices) {
  const std::string xml = loopback_config_xml();
  EXPECT_NE(xml.find("<NetworkInterface address=\"127.0.0.1\"/>"), std::string::npos);
  EXPECT_NE(xml.find("<AllowMulticast>false</AllowMulticast>"), std::string::npos);
  EXPECT_NE(xml.find("<ParticipantIndex>auto</ParticipantIndex>"), std::string::npos);
  EXPECT_NE(xml.find("<MaxAutoParticipantIndex>119</MaxAutoParticipantIndex>"), std::string::npos);
  EXPECT_NE(xml.find("<Peer address=\"127.0.0.1\"/>"), std::string::npos);
}

TEST(CycloneConfig, InterfaceByNameAndSeveralPeers) {
  CycloneConfigOptions o;
  o.interface = "eth0";
  o.peers = {"10.0.0.1", "robot-b.local"};
  const std::string xml = cyclone_config_xml(o);
  EXPECT_NE(xml.find("<NetworkInterface name=\"eth0\"/>"), std::string::npos);
  EXPECT_NE(xml.find("<Peer address=\"10.0.0.1\"/>"), std::string::npos);
  EXPECT_NE(xml.find("<Peer address=\"robot-b.local\"/>"), std::string::npos);
}

TEST(CycloneConfig, BadOptionsThrow) {
  CycloneConfigOptions o;
  o.interface = "";
  EXPECT_THROW((void)cyclone_config_xml(o), Error);
  o = {};
  o.peers.clear();
  EXPECT_THROW((void)cyclone_config_xml(o), Error);
  o = {};
  o.max_auto_participant_index = 120;
  EXPECT_THROW((void)cyclone_config_xml(o), Error);
  o = {};
  o.lease_duration_s = std::nan("");
  EXPECT_THROW((void)cyclone_config_xml(o), Error);
  EXPECT_THROW(write_cyclone_config("/nonexistent-dir/x.xml", {}), Error);
}

TEST(CycloneConfig, WrittenFileRoundTrips) {
  const std::string path = ::testing::TempDir() + "/voronav_dds_cfg.xml";
  write_cyclone_config(path, {});
  std::FILE* f = std::fopen(path.c_str(), "rb");
  ASSERT_NE(f, nullptr);
  std::string content(8192, '\0');
  content.resize(std::fread(content.data(), 1, content.size(), f));
  std::fclose(f);
  EXPECT_EQ(content, loopback_config_xml());
  EXPECT_EQ(cyclone_uri_for(path).rfind("file:///", 0), 0u);
}

// A writer that offers only XCDR2 never matches a voronav reader (internal/wire_qos.hpp: Debian's
// Cyclone 0.10.2 XCDR2 normalizer overruns a sample that ends inside an 8-byte member), and one
// that offers XCDR1 does, so the check is the data representation and not something else.
TEST(DdsTransport, ReadersMatchOnlyXcdr1Writers) {
  auto o = base_options(1);
  DdsTransport t(o);  // creates the domain with the loopback configuration
  const dds_entity_t participant = dds_create_participant(o.domain_id, nullptr, nullptr);
  ASSERT_GT(participant, 0);
  const dds_entity_t topic =
      dds_create_topic(participant, &voronav_dds_Payload_desc, "voronav_payload", nullptr, nullptr);
  ASSERT_GT(topic, 0);
  auto matched_writers = [&](dds_data_representation_id_t representation) {
    dds_qos_t* q = dds_create_qos();
    dds_qset_partition1(q, o.partition.c_str());
    dds_qset_reliability(q, DDS_RELIABILITY_RELIABLE, DDS_MSECS(100));
    dds_qset_data_representation(q, 1, &representation);
    const dds_entity_t w = dds_create_writer(participant, topic, q, nullptr);
    dds_delete_qos(q);
    EXPECT_GT(w, 0);
    dds_publication_matched_status_t st{};
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(2);
    while (std::chrono::steady_clock::now() < deadline) {
      EXPECT_EQ(dds_get_publication_matched_status(w, &st), DDS_RETCODE_OK);
      if (st.current_count > 0) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    dds_delete(w);
    return st.current_count;
  };
  EXPECT_EQ(matched_writers(DDS_DATA_REPRESENTATION_XCDR2), 0u);
  EXPECT_EQ(matched_writers(DDS_DATA_REPRESENTATION_XCDR1), 1u) << "the transport's payload reader";
  dds_delete(participant);
}

TEST(DdsTransport, BadOptionsThrow) {
  auto o = base_options(1);
  o.radio_range_m = 0.0;
  EXPECT_THROW(DdsTransport{o}, Error);
  o = base_options(1);
  o.radio_range_m = std::nan("");
  EXPECT_THROW(DdsTransport{o}, Error);
  o = base_options(1);
  o.loss_probability = 1.5;
  EXPECT_THROW(DdsTransport{o}, Error);
  o = base_options(1);
  o.history_depth = 0;
  EXPECT_THROW(DdsTransport{o}, Error);
  o = base_options(1);
  o.domain_id = 300;
  EXPECT_THROW(DdsTransport{o}, Error);
  o = base_options(1);
  o.self = kBroadcast;
  EXPECT_THROW(DdsTransport{o}, Error);
  o = base_options(1);
  o.partition.clear();
  EXPECT_THROW(DdsTransport{o}, Error);
}

TEST(DdsTransport, MalformedConfigXmlThrows) {
  auto o = base_options(1);
  o.domain_id = 231 - 1;  // a domain no other test uses
  o.config_xml = "<CycloneDDS><Domain><General><NoSuchElement>1</NoSuchElement>";
  EXPECT_THROW(DdsTransport{o}, Error);
}

TEST(DdsTransport, MisuseThrows) {
  DdsTransport a(base_options(1));
  const auto b = bytes_of("x");
  EXPECT_THROW(a.send(RobotId{2}, RobotId{3}, b), Error);  // not our id
  EXPECT_THROW(a.broadcast(RobotId{2}, b), Error);
  EXPECT_THROW(a.send(RobotId{1}, RobotId{1}, b), Error);  // to itself
  EXPECT_THROW(a.broadcast(RobotId{1}, std::span<const std::uint8_t>{}), Error);
  std::vector<std::uint8_t> big(a.options().max_payload_bytes + 1, 7);
  EXPECT_THROW(a.broadcast(RobotId{1}, big), Error);
  EXPECT_THROW((void)a.receive(RobotId{2}), Error);
  EXPECT_THROW(a.update_position(RobotId{2}, {0, 0}), Error);
  EXPECT_THROW(a.update_position(RobotId{1}, {std::nan(""), 0}), Error);
  EXPECT_EQ(a.stats().sent_broadcast, 0u);
}

TEST(DdsTransport, TwoParticipantsExchangePayloads) {
  DdsTransport a(base_options(1));
  DdsTransport b(base_options(2));
  a.update_position(RobotId{1}, {0.0, 0.0});
  b.update_position(RobotId{2}, {3.0, 4.0});
  ASSERT_TRUE(a.wait_for_peers(1, kTimeout));
  ASSERT_TRUE(b.wait_for_peers(1, kTimeout));
  EXPECT_EQ(a.known_position(RobotId{2}), (Vec2{3.0, 4.0}));
  EXPECT_EQ(a.known_robots(), (std::vector<RobotId>{RobotId{2}}));

  a.broadcast(RobotId{1}, bytes_of("hello"));
  a.send(RobotId{1}, RobotId{2}, bytes_of("direct"));
  b.send(RobotId{2}, RobotId{1}, bytes_of("reply"));
  const auto at_b = receive_n(b, 2);
  ASSERT_EQ(at_b.size(), 2u);
  EXPECT_EQ(text_of(at_b[0]), "hello");
  EXPECT_EQ(at_b[0].from, RobotId{1});
  EXPECT_EQ(at_b[0].to, kBroadcast);
  EXPECT_EQ(text_of(at_b[1]), "direct");
  EXPECT_EQ(at_b[1].to, RobotId{2});
  EXPECT_LE(at_b[0].sent_at_s, at_b[1].sent_at_s);
  const auto at_a = receive_n(a, 1);
  ASSERT_EQ(at_a.size(), 1u);
  EXPECT_EQ(text_of(at_a[0]), "reply");
  EXPECT_TRUE(receive_for(a, 0.1).empty());  // nothing of its own comes back
  EXPECT_TRUE(a.flush(kTimeout));
  EXPECT_EQ(a.stats().sent_broadcast, 1u);
  EXPECT_EQ(a.stats().sent_unicast, 1u);
  EXPECT_EQ(b.stats().delivered, 2u);
  EXPECT_EQ(b.stats().rejected, 0u);
  EXPECT_EQ(b.stats().duplicates, 0u);
}

TEST(DdsTransport, DirectedMessageReachesOnlyItsReceiver) {
  DdsTransport a(base_options(1)), b(base_options(2)), c(base_options(3));
  a.update_position(RobotId{1}, {0, 0});
  b.update_position(RobotId{2}, {1, 0});
  c.update_position(RobotId{3}, {0, 1});
  for (auto* t : {&a, &b, &c})
    ASSERT_TRUE(t->wait_for_peers(2, kTimeout));
  a.send(RobotId{1}, RobotId{3}, bytes_of("for c"));
  const auto at_c = receive_n(c, 1);
  ASSERT_EQ(at_c.size(), 1u);
  EXPECT_EQ(text_of(at_c[0]), "for c");
  EXPECT_TRUE(receive_for(b, 0.2).empty());
  EXPECT_EQ(b.stats().not_for_me, 1u);
}

TEST(DdsTransport, RangeFilterUsesLatestPose) {
  DdsTransport a(base_options(1, 10.0)), near(base_options(2, 10.0)), far(base_options(3, 10.0));
  a.update_position(RobotId{1}, {0, 0});
  near.update_position(RobotId{2}, {10.0, 0});  // exactly at range: in
  far.update_position(RobotId{3}, {10.5, 0});   // just beyond
  for (auto* t : {&a, &near, &far})
    ASSERT_TRUE(t->wait_for_peers(2, kTimeout));
  a.broadcast(RobotId{1}, bytes_of("one"));
  EXPECT_EQ(receive_n(near, 1).size(), 1u);
  EXPECT_TRUE(receive_for(far, 0.3).empty());
  EXPECT_EQ(far.stats().dropped_range, 1u);

  // far moves into range; once a has the new pose, a hears far too.
  far.update_position(RobotId{3}, {5.0, 5.0});
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (a.known_position(RobotId{3}) != Vec2{5.0, 5.0} &&
         std::chrono::steady_clock::now() < deadline) {
    a.wait_for_data(0.05);
    (void)a.receive(RobotId{1});
  }
  ASSERT_EQ(a.known_position(RobotId{3}), (Vec2{5.0, 5.0}));
  far.broadcast(RobotId{3}, bytes_of("now near"));
  const auto got = receive_n(a, 1);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(text_of(got[0]), "now near");
}

TEST(DdsTransport, UnknownPoseMeansDrop) {
  DdsTransport a(base_options(1)), silent(base_options(2));
  a.update_position(RobotId{1}, {0, 0});
  // `silent` never publishes its position: it cannot hear a, and a cannot hear it.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while ((a.matched_receivers() < 1 || silent.matched_receivers() < 1 ||
          !silent.known_position(RobotId{1})) &&
         std::chrono::steady_clock::now() < deadline) {
    silent.wait_for_data(0.02);
    (void)silent.receive(RobotId{2});
  }
  ASSERT_TRUE(silent.known_position(RobotId{1}).has_value());
  ASSERT_TRUE(a.wait_for_peers(0, 0.0));
  a.broadcast(RobotId{1}, bytes_of("x"));
  silent.broadcast(RobotId{2}, bytes_of("y"));
  EXPECT_TRUE(receive_for(silent, 0.3).empty());
  EXPECT_TRUE(receive_for(a, 0.1).empty());
  EXPECT_EQ(silent.stats().dropped_unknown_pose, 1u);
  EXPECT_EQ(a.stats().dropped_unknown_pose, 1u);
}

TEST(DdsTransport, InfiniteRangeNeedsNoPose) {
  const double inf = std::numeric_limits<double>::infinity();
  DdsTransport a(base_options(1, inf)), b(base_options(2, inf));
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (a.matched_receivers() < 1 && std::chrono::steady_clock::now() < deadline)
    a.wait_for_data(0.02);
  ASSERT_EQ(a.matched_receivers(), 1u);
  a.broadcast(RobotId{1}, bytes_of("anywhere"));
  EXPECT_EQ(receive_n(b, 1).size(), 1u);
}

class Malformed : public ::testing::Test {
 protected:
  void SetUp() override {
    auto o = base_options(2);
    o.max_payload_bytes = 100;
    b_ = std::make_unique<DdsTransport>(o);
    a_ = std::make_unique<DdsTransport>(base_options(1));
    raw_ = std::make_unique<RawDdsWriter>(base_options(99));
    a_->update_position(RobotId{1}, {0, 0});
    b_->update_position(RobotId{2}, {1, 0});
    ASSERT_TRUE(b_->wait_for_peers(1, kTimeout));
    ASSERT_TRUE(raw_->wait_for_readers(2, kTimeout));
    raw_->write(RawPose{1, 7, 2.0, 0.0, 0.0});  // the raw participant is robot 7
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (!b_->known_position(RobotId{7}) && std::chrono::steady_clock::now() < deadline) {
      b_->wait_for_data(0.02);
      (void)b_->receive(RobotId{2});
    }
    ASSERT_TRUE(b_->known_position(RobotId{7}).has_value());
  }
  RawPayloadSample valid(std::uint64_t seq, const std::string& text) {
    RawPayloadSample s;
    s.sender = 7;
    s.seq = seq;
    s.bytes = bytes_of(text);
    s.length = static_cast<std::uint32_t>(s.bytes.size());
    return s;
  }
  std::uint64_t rejected(RejectReason r) const {
    return b_->stats().rejected_by_reason[static_cast<std::size_t>(r)];
  }
  std::unique_ptr<DdsTransport> a_, b_;
  std::unique_ptr<RawDdsWriter> raw_;
};

TEST_F(Malformed, BadSamplesAreRejectedAndCounted) {
  auto s = valid(1, "v9");
  s.version = 9;
  raw_->write(s);
  s = valid(2, "");
  raw_->write(s);  // empty payload
  s = valid(3, "abc");
  s.length = 4;
  raw_->write(s);  // length field lies
  s = valid(4, std::string(101, 'x'));
  raw_->write(s);  // too large for b (max 100)
  s = valid(5, "i am robot 1");
  s.sender = 1;
  raw_->write(s);  // claims robot 1's id, which belongs to another participant
  s = valid(6, "i am robot 2");
  s.sender = 2;
  raw_->write(s);                                      // claims the receiver's own id
  raw_->write(RawPose{1, 7, std::nan(""), 0.0, 0.0});  // non-finite pose
  raw_->write(RawPose{3, 9, 1.0, 0.0, 0.0});           // pose with unknown version
  raw_->write(RawPose{1, 8, 1.0, 0.0, 0.0});           // the participant claims a second id
  raw_->write(valid(7, "fine"));                       // and a good one still gets through
  const auto got = receive_n(*b_, 1);
  (void)receive_for(*b_, 0.2);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(text_of(got[0]), "fine");
  EXPECT_EQ(got[0].from, RobotId{7});
  EXPECT_EQ(rejected(RejectReason::kUnknownVersion), 2u);
  EXPECT_EQ(rejected(RejectReason::kEmptyPayload), 1u);
  EXPECT_EQ(rejected(RejectReason::kLengthMismatch), 1u);
  EXPECT_EQ(rejected(RejectReason::kTooLarge), 1u);
  EXPECT_EQ(rejected(RejectReason::kSpoofedSender), 3u);
  EXPECT_EQ(rejected(RejectReason::kInvalidPose), 1u);
  EXPECT_EQ(b_->stats().rejected, 9u);
  EXPECT_EQ(b_->known_position(RobotId{7}), (Vec2{2.0, 0.0}));  // bad poses did not move it
  EXPECT_FALSE(b_->known_position(RobotId{8}).has_value());
}

TEST_F(Malformed, DuplicatesDroppedAndGapsCounted) {
  raw_->write(valid(1, "first"));
  raw_->write(valid(1, "again"));  // same sequence number
  raw_->write(valid(5, "fifth"));  // 2, 3, 4 never sent
  raw_->write(valid(3, "late"));   // older than the last one
  const auto got = receive_n(*b_, 2);
  (void)receive_for(*b_, 0.2);
  ASSERT_EQ(got.size(), 2u);
  EXPECT_EQ(text_of(got[0]), "first");
  EXPECT_EQ(text_of(got[1]), "fifth");
  EXPECT_EQ(b_->stats().duplicates, 2u);
  EXPECT_EQ(b_->stats().gaps, 3u);
}

// Delivered sequence numbers (first byte .. as index) under seeded loss.
std::vector<int> lossy_run(double p, std::uint64_t seed, int n) {
  auto ob = base_options(2);
  ob.loss_probability = p;
  ob.loss_seed = seed;
  DdsTransport a(base_options(1)), b(ob);
  a.update_position(RobotId{1}, {0, 0});
  b.update_position(RobotId{2}, {1, 0});
  EXPECT_TRUE(a.wait_for_peers(1, kTimeout));
  EXPECT_TRUE(b.wait_for_peers(1, kTimeout));
  for (int i = 0; i < n; ++i) {
    std::vector<std::uint8_t> msg{static_cast<std::uint8_t>(i & 0xff),
                                  static_cast<std::uint8_t>(i >> 8)};
    a.broadcast(RobotId{1}, msg);
  }
  EXPECT_TRUE(a.flush(kTimeout));
  std::vector<int> got;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (std::chrono::steady_clock::now() < deadline) {
    b.wait_for_data(0.05);
    for (const auto& pk : b.receive(RobotId{2}))
      got.push_back(pk.bytes[0] | (pk.bytes[1] << 8));
    const auto st = b.stats();
    if (st.delivered + st.dropped_loss >= static_cast<std::uint64_t>(n)) break;
  }
  const auto st = b.stats();
  EXPECT_EQ(st.delivered + st.dropped_loss, static_cast<std::uint64_t>(n));
  EXPECT_EQ(st.gaps, 0u);
  return got;
}

TEST(DdsTransport, LossIsHonouredAndSeeded) {
  const int n = 200;  // below the history depth (256): nothing is lost to history overflow
  const auto first = lossy_run(0.5, 42, n);
  // Binomial(200, 0.5): mean 100, sd 7; +-35 is 5 sd.
  EXPECT_GT(first.size(), 65u);
  EXPECT_LT(first.size(), 135u);
  for (std::size_t i = 1; i < first.size(); ++i)
    EXPECT_LT(first[i - 1], first[i]);
  const auto second = lossy_run(0.5, 42, n);
  EXPECT_EQ(first, second);  // same seed, same arrivals: the same packets are lost
  EXPECT_TRUE(lossy_run(1.0, 1, 50).empty());
  EXPECT_EQ(lossy_run(0.0, 1, 50).size(), 50u);
}

TEST(DdsTransport, BoundedHistoryLosesOldestAndCountsGaps) {
  auto ob = base_options(2);
  ob.history_depth = 16;
  DdsTransport a(base_options(1)), b(ob);
  a.update_position(RobotId{1}, {0, 0});
  b.update_position(RobotId{2}, {1, 0});
  ASSERT_TRUE(a.wait_for_peers(1, kTimeout));
  ASSERT_TRUE(b.wait_for_peers(1, kTimeout));
  const int n = 100;
  for (int i = 0; i < n; ++i)
    a.broadcast(RobotId{1}, std::vector<std::uint8_t>{std::uint8_t(i)});
  ASSERT_TRUE(a.flush(kTimeout));
  // b did not take anything meanwhile: its keep-last history of 16 kept only the newest.
  const auto got = receive_for(b, 0.3);
  ASSERT_FALSE(got.empty());
  EXPECT_LE(got.size(), 16u);
  EXPECT_EQ(got.back().bytes[0], n - 1);
  EXPECT_EQ(b.stats().delivered + b.stats().gaps, static_cast<std::uint64_t>(n));
}

}  // namespace
}  // namespace voronav::dds
