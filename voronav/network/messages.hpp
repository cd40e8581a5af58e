// Messages of the networked-robot protocols of seed 000 and their compact binary form: the exact
// bytes the simulated radio accounts for and the DDS transport carries. Search (Table 1–2),
// Path (Table 3), Repair (Tables 4–5) for the decentralized method; Request / Ack (full local
// map) for the centralized baseline; Notify (a robot tells the centralized source its map
// changed) and LinkAck (hop-by-hop acknowledgement used for retries; not in the paper).
//
// Wire format (little-endian), version 1:
//   magic 'V' 'N' | version u8 | type u8 | sender u32 | receiver u32 | origin u32 | msg_id u32 |
//   hops u8 | payload_len u32 | payload | crc32 u32 (IEEE, over everything before it)
// Points are float32 metres; a local map in an Ack is 2 bits per cell (free/occupied/unknown).
// decode() is strict: wrong magic/version/type, truncation, trailing bytes, bad CRC, counts that
// do not fit, non-finite numbers all throw voronav::Error naming the byte offset.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <variant>
#include <vector>

#include "voronav/core/occupancy.hpp"
#include "voronav/core/vec2.hpp"
#include "voronav/network/transport.hpp"

namespace voronav::network {

inline constexpr std::uint8_t kWireVersion = 1;

enum class MessageType : std::uint8_t {
  kSearch = 1,
  kPath = 2,
  kRepair = 3,
  kRequest = 4,
  kAck = 5,
  kNotify = 6,
  kLinkAck = 7,
};
inline constexpr int kMessageTypeCount = 8;  ///< array size for per-type tables (index 0 unused)
[[nodiscard]] std::string_view to_string(MessageType t);

/// A Voronoi point: a position [m, world] and its clearance [m] (radius of the known-free disc
/// around it). Open points are passable for the robot; close points are not. `cost` is the path
/// length [m] from the source to this point along the Search (0 when unused).
struct VoronoiPoint {
  Vec2 position;
  float clearance = 0.0f;
  float cost = 0.0f;
  friend bool operator==(const VoronoiPoint&, const VoronoiPoint&) = default;
};

/// Table 1: Search Message <- Num, Open Point, Destination Address, Relay Robots.
struct SearchMessage {
  RobotId source;
  std::uint32_t num = 0;  ///< Num: the search attempt (a retry increments it)
  Vec2 destination;
  std::vector<RobotId> relays;            ///< Relay Robots, source first
  std::vector<VoronoiPoint> open_points;  ///< the sender's open points (with cost from source)
  std::vector<Vec2> close_points;         ///< the sender's close points
  friend bool operator==(const SearchMessage&, const SearchMessage&) = default;
};

/// Table 3: Path Message <- Relay Robots, a Whole Path. `exit_index` is the index of the
/// receiver's open point (as sent in its Search) where `whole_path` continues. Added for
/// measurement and delivery (not in the paper): `owners` names the robot that sensed each point
/// of `whole_path` (empty, or one per point); `carriers` are the robots that carried the message
/// hop by hop when the next relay was out of range (loop guard of the multi-hop fallback) and
/// `toward` is where that relay was last seen.
struct PathMessage {
  RobotId source;
  std::uint32_t num = 0;
  std::vector<RobotId> relays;  ///< relays still to traverse toward the source
  std::vector<VoronoiPoint> whole_path;
  std::uint32_t exit_index = 0;
  std::vector<RobotId> owners;
  std::vector<RobotId> carriers;
  Vec2 toward;
  friend bool operator==(const PathMessage&, const PathMessage&) = default;
};

/// Table 5: Repair Message <- Source, Relay Robots, a Whole Path. Segments between
/// `broken_from` and `broken_to` (point indices) are broken; answers bridge them.
struct RepairMessage {
  RobotId source;
  std::uint32_t num = 0;
  std::vector<RobotId> relays;
  std::vector<VoronoiPoint> whole_path;
  std::uint32_t broken_from = 0;
  std::uint32_t broken_to = 0;
  /// Not in Table 4 (issue #13, option repair_share_blocks): the centres of the cells its sender
  /// saw blocking the broken moves; receivers mark them occupied before they look for a detour.
  std::vector<Vec2> blocked;
  /// Not in Table 4 (issue #13, option repair_expand_hops): the hop limit of this Repair; 0 =
  /// each receiver's repair_hops (the paper's fixed neighbourhood). The source sends a new Repair
  /// with a larger limit when none came back (an expanding ring); robots that relay such a
  /// Repair add themselves to `relays`, so the answer comes back hop by hop. Sent only when
  /// non-zero (an optional last byte), so a Repair without it is the bytes of Table 5.
  std::uint8_t hop_limit = 0;
  friend bool operator==(const RepairMessage&, const RepairMessage&) = default;
};

/// Centralized baseline: the source asks every robot for its local map.
struct RequestMessage {
  RobotId source;
  std::uint32_t num = 0;
  friend bool operator==(const RequestMessage&, const RequestMessage&) = default;
};

/// Centralized baseline: a robot's whole local map (geometry + occupancy, 2 bits per cell).
struct AckMessage {
  RobotId source;
  std::uint32_t num = 0;
  RobotId responder;
  OccupancyGrid local_map;  ///< values kFree, kOccupied or kUnknown (others are thresholded)
  friend bool operator==(const AckMessage&, const AckMessage&) = default;
};

/// Centralized baseline: "the path is broken": a robot saw its local map change at `where`.
struct NotifyMessage {
  RobotId source;
  RobotId reporter;
  Vec2 where;
  friend bool operator==(const NotifyMessage&, const NotifyMessage&) = default;
};

/// Hop-by-hop acknowledgement of the unicast message (origin, msg_id).
struct LinkAckMessage {
  RobotId acked_origin;
  std::uint32_t acked_id = 0;
  friend bool operator==(const LinkAckMessage&, const LinkAckMessage&) = default;
};

using Payload = std::variant<SearchMessage, PathMessage, RepairMessage, RequestMessage, AckMessage,
                             NotifyMessage, LinkAckMessage>;

/// The routing header every message carries.
struct Header {
  RobotId sender;            ///< this hop's transmitter
  RobotId receiver;          ///< this hop's receiver or kBroadcast
  RobotId origin;            ///< who created the message (end to end)
  std::uint32_t msg_id = 0;  ///< unique per origin: duplicate suppression and LinkAck
  std::uint8_t hops = 0;     ///< hops travelled so far (the flood bound)
  friend bool operator==(const Header&, const Header&) = default;
};

struct Envelope {
  Header header;
  Payload payload;
  [[nodiscard]] MessageType type() const;
  friend bool operator==(const Envelope&, const Envelope&) = default;
};

/// Serializes to the wire format above.
[[nodiscard]] std::vector<std::uint8_t> encode(const Envelope& message);
/// Parses bytes; throws voronav::Error("message", 0, "byte N: ...") on anything malformed.
[[nodiscard]] Envelope decode(std::span<const std::uint8_t> bytes);
/// The type byte of an encoded message without decoding it; nullopt-like 0 when not a message.
[[nodiscard]] std::uint8_t peek_type(std::span<const std::uint8_t> bytes);

/// Bytes of the wire header + CRC (fixed overhead per message).
inline constexpr std::size_t kEnvelopeOverhead = 2 + 1 + 1 + 4 + 4 + 4 + 4 + 1 + 4 + 4;

/// Size [bytes] of a local map sent cell by cell as in an Ack (2 bits per cell + geometry).
[[nodiscard]] std::size_t grid_payload_bytes(const OccupancyGrid& map);
/// Size [bytes] of points as sent in a Search (open with clearance+cost, close as positions).
[[nodiscard]] std::size_t points_payload_bytes(std::size_t open, std::size_t close);

/// IEEE CRC-32 (as zlib); exposed for tests.
[[nodiscard]] std::uint32_t crc32(std::span<const std::uint8_t> bytes);

}  // namespace voronav::network
