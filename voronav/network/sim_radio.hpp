// SimRadio: the simulated radio behind the Transport interface (seed 000: indoor WLAN, 25 m
// range). A transmission reaches the robots within `range_m` of the sender at send time; each
// reception is independently lost with probability `loss`, duplicated with `duplicate`, and
// delayed by `latency_s` (+ uniform jitter; with `reorder` a reception gets an extra delay so
// later messages may overtake it). Receptions due at the same instant are handed over in sender
// order, and in send order per sender (what a receiver of separate processes can reproduce). Bytes
// on the air are the real serialized size, counted once per transmission (a broadcast is one
// transmission), per message type (peeked from the wire header) and per robot. Deterministic for a
// given seed.
#pragma once

#include <array>
#include <cstdint>
#include <random>
#include <unordered_map>
#include <vector>

#include "voronav/network/messages.hpp"
#include "voronav/network/transport.hpp"

namespace voronav::network {

struct RadioOptions {
  double range_m = 25.0;     ///< radio range [m] (seed 000: 25 m indoor WLAN)
  double latency_s = 0.005;  ///< delay from send to delivery [s]
  double jitter_s = 0.0;     ///< extra uniform delay in [0, jitter_s] [s]
  double loss = 0.0;         ///< probability a reception is lost [0, 1]
  double duplicate = 0.0;    ///< probability a reception is delivered twice [0, 1]
  double reorder = 0.0;      ///< probability a reception is held back by reorder_delay_s [0, 1]
  double reorder_delay_s = 0.05;
  std::uint64_t seed = 1;
  /// Throws voronav::Error naming the bad field (NaN, negative, probability outside [0, 1]).
  void validate() const;
};

struct TrafficCounter {
  std::uint64_t messages = 0;
  std::uint64_t bytes = 0;
};

struct RadioStats {
  TrafficCounter total;                                     ///< transmissions on the air
  std::array<TrafficCounter, kMessageTypeCount> by_type{};  ///< index = MessageType value
  std::vector<TrafficCounter> sent_by_robot;                ///< index = RobotId value
  std::vector<TrafficCounter> received_by_robot;
  std::uint64_t receptions = 0;
  std::uint64_t lost = 0;
  std::uint64_t out_of_range = 0;  ///< unicasts whose receiver was out of range
  std::uint64_t duplicated = 0;
};

class SimRadio final : public Transport {
 public:
  explicit SimRadio(RadioOptions options = {});

  void send(RobotId from, RobotId to, std::span<const std::uint8_t> bytes) override;
  void broadcast(RobotId from, std::span<const std::uint8_t> bytes) override;
  [[nodiscard]] std::vector<Packet> receive(RobotId self) override;
  void update_position(RobotId id, Vec2 position) override;
  [[nodiscard]] std::vector<Neighbour> nearby(RobotId self) override;

  /// Advances the radio clock [s]; receive() returns packets whose delivery time has come.
  void set_time(double now_s);
  [[nodiscard]] double time() const { return now_; }
  /// Whether `a` and `b` are within radio range now.
  [[nodiscard]] bool in_range(RobotId a, RobotId b) const;
  /// Robots within range of `id` (not `id` itself), ascending ids.
  [[nodiscard]] std::vector<RobotId> neighbours(RobotId id) const;
  [[nodiscard]] const RadioStats& stats() const { return stats_; }
  [[nodiscard]] const RadioOptions& options() const { return options_; }
  /// Packets still in flight.
  [[nodiscard]] std::size_t in_flight() const;

 private:
  struct Pending {
    double deliver_at;
    std::uint64_t order;
    Packet packet;
  };
  void account(RobotId from, std::span<const std::uint8_t> bytes);
  void deliver(RobotId from, RobotId to, RobotId addressed, std::span<const std::uint8_t> bytes);
  void ensure(RobotId id);
  /// Robots in the grid buckets around `id` (candidates for range checks), ascending ids.
  void candidates(RobotId id, std::vector<std::uint32_t>& out) const;
  [[nodiscard]] std::int64_t bucket_of(Vec2 p) const;

  RadioOptions options_;
  double now_ = 0.0;
  std::uint64_t order_ = 0;
  std::mt19937_64 rng_;
  std::vector<Vec2> positions_;
  std::vector<std::uint8_t> known_;
  std::vector<std::vector<Pending>> inbox_;  ///< per receiver
  // Spatial index: square buckets of side range_m, so the robots within range of a robot are in
  // the 3 x 3 buckets around its own (broadcasts and nearby() need not visit every robot).
  std::vector<std::int64_t> bucket_;  ///< per robot, its bucket key (known robots only)
  std::unordered_map<std::int64_t, std::vector<std::uint32_t>> buckets_;
  mutable std::vector<std::uint32_t> scratch_;
  RadioStats stats_;
};

}  // namespace voronav::network
