// DdsTransport: network::Transport over Eclipse Cyclone DDS 0.10, so that each robot can be its own
// process (or computer) and the decentralized protocol of seed 000 runs over the middleware robots
// actually use (the DDS of ROS 2), with the same binary payloads as the simulated radio.
//
// One DdsTransport is one robot (`DdsTransportOptions::self`) and one DDS participant. Two topics
// (types in voronav/dds/idl/voronav_dds.idl, compiled by idlc):
//  - "voronav_payload": sender, receiver (or broadcast), per-sender sequence number, send time and
//    the message bytes; reliable, keep-last history bounded per sender, volatile;
//  - "voronav_pose": id, x, y, time; reliable, keep-last 1 per robot, transient-local (a robot that
//    joins late still learns where the others are).
// Radio range (seed 000: robots talk only within range) is honoured by the receiver: a packet is
// dropped when the sender's latest pose from the pose topic is farther than `radio_range_m` from
// this robot's own position. An unknown pose (sender's or our own) means the packet is dropped,
// because delivering it could let a robot hear someone the simulated radio would not.
// Every incoming sample is checked (wire version, empty payload, length field vs. bytes, size
// limit, non-finite pose, a participant claiming an id that another participant already uses or a
// second id): a bad sample is rejected with a logged error (spdlog) and counted, never a crash.
// Loss injection: each packet that passes the range check is dropped with `loss_probability`
// (seeded), like the simulated radio's loss. Every wait takes a timeout.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "voronav/core/vec2.hpp"
#include "voronav/network/transport.hpp"

namespace voronav::dds {

struct DdsTransportOptions {
  /// The robot this transport speaks for; send()/broadcast()/receive() accept only this id.
  network::RobotId self{0};
  /// DDS domain id (0..230; the default port mapping puts domain d on UDP ports 7400 + 250 d ...).
  std::uint32_t domain_id = 0;
  /// Cyclone configuration XML for the domain (e.g. loopback_config_xml()); empty = Cyclone's
  /// defaults or the file named by the CYCLONEDDS_URI environment variable.
  std::string config_xml;
  /// DDS partition: runs on the same domain with different partitions never see each other.
  std::string partition = "voronav";
  /// Radio range [m] (> 0). Infinity = no range filtering (and then no pose is needed).
  double radio_range_m = std::numeric_limits<double>::infinity();
  /// Probability in [0, 1] that a packet passing the range check is dropped (seeded).
  double loss_probability = 0.0;
  std::uint64_t loss_seed = 1;
  /// Keep-last depth of the payload history, per sender, in the writer and the reader (>= 1).
  int history_depth = 256;
  /// Largest accepted payload [bytes]; larger outgoing payloads throw, larger incoming are
  /// rejected.
  std::size_t max_payload_bytes = 64 * 1024;
  /// Longest time a reliable write may block when the receivers are slow [s].
  double max_blocking_s = 1.0;
  /// On destruction, wait at most this long for receivers to acknowledge what was sent [s].
  double close_timeout_s = 1.0;
  /// Check the radio range with the positions the sender and this robot had when the packet was
  /// sent (the poses stamped at or before Packet::sent_at_s, from a short history) instead of the
  /// latest ones. With a lockstep clock (robot processes of `voronav netsim --transport dds`,
  /// netsim_dds.hpp) this gives exactly the receptions of the simulated radio.
  bool range_at_send_time = false;
  /// Poses kept per robot for range_at_send_time and nearby() (>= 1).
  int pose_history = 16;
  /// nearby() ignores robots whose pose is older than this [s] (a robot that stopped publishing,
  /// e.g. a dead process, is no neighbour). Infinity = any pose counts.
  double pose_max_age_s = std::numeric_limits<double>::infinity();
  /// Clock for Packet::sent_at_s and the pose stamps [s]; default: steady clock (CLOCK_MONOTONIC,
  /// shared by every process of one machine, so latencies between local processes are meaningful).
  std::function<double()> clock{};
};

/// Why an incoming sample was rejected.
enum class RejectReason : std::uint8_t {
  kUnknownVersion,  ///< wire version is not kWireVersion
  kEmptyPayload,    ///< zero bytes
  kLengthMismatch,  ///< the length field differs from the number of bytes
  kTooLarge,        ///< more than max_payload_bytes
  kSpoofedSender,   ///< id already bound to another participant, or participant bound to another
                    ///< id, or a sample claiming our own id
  kInvalidPose,     ///< non-finite coordinates
  kUnknownWriter,   ///< the writer's participant could not be identified
};
inline constexpr std::size_t kRejectReasonCount = 7;
[[nodiscard]] std::string_view to_string(RejectReason r);

struct DdsTransportStats {
  std::uint64_t sent_unicast = 0;
  std::uint64_t sent_broadcast = 0;
  std::uint64_t poses_sent = 0;
  std::uint64_t poses_received = 0;
  std::uint64_t delivered = 0;             ///< packets returned by receive()
  std::uint64_t not_for_me = 0;            ///< directed to another robot (normal, not an error)
  std::uint64_t dropped_range = 0;         ///< sender beyond radio range
  std::uint64_t dropped_unknown_pose = 0;  ///< sender's or own position unknown (range is finite)
  std::uint64_t dropped_loss = 0;          ///< injected loss
  std::uint64_t duplicates = 0;            ///< sequence number already seen from that sender
  std::uint64_t gaps = 0;                  ///< sequence numbers skipped (lost to history overflow)
  std::uint64_t rejected = 0;              ///< malformed samples, all reasons
  std::array<std::uint64_t, kRejectReasonCount> rejected_by_reason{};
};

class DdsTransport final : public network::Transport {
 public:
  /// Creates the participant, topics, readers and writers. Throws voronav::Error on bad options
  /// or when Cyclone refuses (e.g. malformed config XML), naming the Cyclone return code.
  explicit DdsTransport(DdsTransportOptions options);
  ~DdsTransport() override;
  DdsTransport(const DdsTransport&) = delete;
  DdsTransport& operator=(const DdsTransport&) = delete;

  void send(network::RobotId from, network::RobotId to,
            std::span<const std::uint8_t> bytes) override;
  void broadcast(network::RobotId from, std::span<const std::uint8_t> bytes) override;
  [[nodiscard]] std::vector<network::Packet> receive(network::RobotId self) override;
  /// Publishes this robot's position on the pose topic (only `self`; other ids throw, since a
  /// process must not speak for another robot).
  void update_position(network::RobotId id, Vec2 position) override;
  /// Robots whose latest pose stamped at or before clock() lies within radio_range_m of our own.
  [[nodiscard]] std::vector<network::Neighbour> nearby(network::RobotId self) override;

  /// Waits until at least `count` other robots are known (pose received and payload writer and
  /// reader matched both ways). Returns false on timeout [s].
  bool wait_for_peers(std::size_t count, double timeout_s);
  /// Waits until a payload or pose sample is available or timeout [s]; true when data is there.
  bool wait_for_data(double timeout_s);
  /// Waits until a pose stamped at or after `min_stamp_s` has arrived from every robot in `ids`
  /// (only poses are taken; payloads stay queued). False on timeout [s].
  bool wait_for_poses(const std::vector<network::RobotId>& ids, double min_stamp_s,
                      double timeout_s);
  /// Highest payload sequence number seen from `id` (also of packets not delivered: for another
  /// robot, out of range, lost); 0 when none. Sequence numbers start at 1 per sender.
  [[nodiscard]] std::uint64_t last_seq_from(network::RobotId id) const;
  /// Sequence number of the last payload this transport sent (0 when none).
  [[nodiscard]] std::uint64_t last_seq_sent() const;
  /// Waits until every matched receiver acknowledged every payload sent; false on timeout [s].
  bool flush(double timeout_s);

  /// The latest position of robot `id` received on the pose topic (own: the last published).
  [[nodiscard]] std::optional<Vec2> known_position(network::RobotId id) const;
  /// Other robots whose pose has been received, ascending.
  [[nodiscard]] std::vector<network::RobotId> known_robots() const;
  /// Number of remote payload readers currently matched by our payload writer.
  [[nodiscard]] std::size_t matched_receivers() const;
  [[nodiscard]] DdsTransportStats stats() const;
  [[nodiscard]] network::RobotId self() const;
  /// The Cyclone participant (dds_entity_t), for more topics on the same participant (the
  /// lockstep control of netsim_dds.hpp): one participant per process keeps discovery cheap.
  [[nodiscard]] std::int32_t participant_handle() const;
  [[nodiscard]] const DdsTransportOptions& options() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Test hook: writes a raw payload sample on the payload topic from a separate participant, with
/// every field under the caller's control (to check that malformed samples are rejected). The
/// participant first publishes a pose as `pose_id` at `pose_position` unless pose_id is nullopt.
struct RawPayloadSample {
  std::uint16_t version = 1;
  std::uint32_t sender = 0;
  std::uint32_t receiver = network::kBroadcast.value;
  std::uint64_t seq = 1;
  double sent_at = 0.0;
  std::uint32_t length = 0;
  std::vector<std::uint8_t> bytes;
};
struct RawPose {
  std::uint16_t version = 1;
  std::uint32_t id = 0;
  double x = 0.0;
  double y = 0.0;
  double t = 0.0;
};

/// A bare participant that writes arbitrary samples (tests of the receiver's validation).
class RawDdsWriter {
 public:
  /// Same domain/config/partition fields as DdsTransportOptions (other fields ignored).
  explicit RawDdsWriter(const DdsTransportOptions& options);
  ~RawDdsWriter();
  RawDdsWriter(const RawDdsWriter&) = delete;
  RawDdsWriter& operator=(const RawDdsWriter&) = delete;
  void write(const RawPayloadSample& sample);
  void write(const RawPose& pose);
  /// Waits until `count` payload readers and pose readers are matched; false on timeout [s].
  bool wait_for_readers(std::size_t count, double timeout_s);
  bool flush(double timeout_s);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace voronav::dds
