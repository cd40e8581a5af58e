// Transport: how robots exchange messages, whatever carries them. The simulated radio (range,
// latency, loss, byte accounting) and the Cyclone DDS transport (robots as separate processes)
// both implement it, so the navigation protocols of seed 000 run unchanged over either.
// Payloads are the compact binary form of the messages (the bytes a real network carries).
#pragma once

#include <compare>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "voronav/core/vec2.hpp"

namespace voronav::network {

/// A robot's identity on the network (distinct type: cannot be mixed up with counts or indices).
struct RobotId {
  std::uint32_t value = 0;
  friend constexpr auto operator<=>(RobotId, RobotId) = default;
};

/// Destination of a broadcast: every robot within radio range of the sender.
inline constexpr RobotId kBroadcast{std::numeric_limits<std::uint32_t>::max()};

/// One delivered message.
struct Packet {
  RobotId from;
  RobotId to;  ///< the receiver, or kBroadcast when it was broadcast
  std::vector<std::uint8_t> bytes;
  double sent_at_s = 0.0;  ///< sender's clock when sent [s]
};

/// A robot within radio range and where it is.
struct Neighbour {
  RobotId id;
  Vec2 position;
  friend bool operator==(const Neighbour&, const Neighbour&) = default;
};

class Transport {
 public:
  virtual ~Transport() = default;
  /// Sends `bytes` from `from` to the single robot `to`; dropped when `to` is out of radio range.
  virtual void send(RobotId from, RobotId to, std::span<const std::uint8_t> bytes) = 0;
  /// Sends `bytes` to every robot within radio range of `from` (not to `from` itself).
  virtual void broadcast(RobotId from, std::span<const std::uint8_t> bytes) = 0;
  /// Takes every packet delivered to `self` since the last call, in delivery order.
  [[nodiscard]] virtual std::vector<Packet> receive(RobotId self) = 0;
  /// Where robot `id` is now [m, world frame]; radio range is checked against these positions.
  virtual void update_position(RobotId id, Vec2 position) = 0;
  /// The robots within radio range of `self` now and their positions (ascending ids): what a
  /// robot knows of its radio neighbours (seed 000 uses it to decide who is closest to the goal).
  [[nodiscard]] virtual std::vector<Neighbour> nearby(RobotId self) = 0;
};

}  // namespace voronav::network
