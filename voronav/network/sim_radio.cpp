#include "voronav/network/sim_radio.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "voronav/core/error.hpp"
#include "voronav/core/require.hpp"

namespace voronav::network {

void RadioOptions::validate() const {
  auto nonneg = [](double v, const char* name) {
    require_finite_nonneg(std::string("radio.") + name, v);
  };
  auto prob = [](double v, const char* name) {
    if (!(v >= 0.0 && v <= 1.0))
      throw Error(std::string("radio.") + name, 0,
                  "expected a probability in [0, 1], got " + std::to_string(v));
  };
  nonneg(range_m, "range_m");
  nonneg(latency_s, "latency_s");
  nonneg(jitter_s, "jitter_s");
  nonneg(reorder_delay_s, "reorder_delay_s");
  prob(loss, "loss");
  prob(duplicate, "duplicate");
  prob(reorder, "reorder");
}

SimRadio::SimRadio(RadioOptions options) : options_(options), rng_(options.seed) {
  options_.validate();
}

void SimRadio::ensure(RobotId id) {
  if (id == kBroadcast) throw Error("radio", 0, "kBroadcast is not a robot id");
  if (id.value >= 1'000'000)
    throw Error("radio", 0, "robot id too large: " + std::to_string(id.value));
  const std::size_t n = static_cast<std::size_t>(id.value) + 1;
  if (positions_.size() < n) {
    positions_.resize(n);
    known_.resize(n, 0);
    inbox_.resize(n);
    bucket_.resize(n, 0);
    stats_.sent_by_robot.resize(n);
    stats_.received_by_robot.resize(n);
  }
}

void SimRadio::update_position(RobotId id, Vec2 position) {
  if (!position.is_finite()) throw Error("radio", 0, "robot position must be finite");
  ensure(id);
  const std::int64_t b = bucket_of(position);
  if (!known_[id.value] || bucket_[id.value] != b) {
    if (known_[id.value]) std::erase(buckets_[bucket_[id.value]], id.value);
    buckets_[b].push_back(id.value);
    bucket_[id.value] = b;
  }
  positions_[id.value] = position;
  known_[id.value] = 1;
}

namespace {

std::int64_t bucket_index(double v, double side) {
  return static_cast<std::int64_t>(std::clamp(std::floor(v / side), -1e9, 1e9));
}

std::int64_t bucket_key(std::int64_t ix, std::int64_t iy) {
  return static_cast<std::int64_t>((static_cast<std::uint64_t>(ix) << 32) ^
                                   (static_cast<std::uint64_t>(iy) & 0xFFFFFFFFull));
}

}  // namespace

std::int64_t SimRadio::bucket_of(Vec2 p) const {
  const double side = std::max(options_.range_m, 1e-3);
  return bucket_key(bucket_index(p.x, side), bucket_index(p.y, side));
}

void SimRadio::candidates(RobotId id, std::vector<std::uint32_t>& out) const {
  out.clear();
  if (id.value >= known_.size() || !known_[id.value]) return;
  const double side = std::max(options_.range_m, 1e-3);
  const Vec2 p = positions_[id.value];
  const std::int64_t ix = bucket_index(p.x, side), iy = bucket_index(p.y, side);
  for (std::int64_t dy = -1; dy <= 1; ++dy)
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      const auto it = buckets_.find(bucket_key(ix + dx, iy + dy));
      if (it != buckets_.end()) out.insert(out.end(), it->second.begin(), it->second.end());
    }
  std::sort(out.begin(), out.end());
}

void SimRadio::set_time(double now_s) {
  if (!std::isfinite(now_s)) throw Error("radio", 0, "time must be finite");
  now_ = std::max(now_, now_s);
}

bool SimRadio::in_range(RobotId a, RobotId b) const {
  if (a.value >= known_.size() || b.value >= known_.size()) return false;
  if (!known_[a.value] || !known_[b.value]) return false;
  return (positions_[a.value] - positions_[b.value]).squared_norm() <=
         options_.range_m * options_.range_m;
}

std::vector<Neighbour> SimRadio::nearby(RobotId self) {
  std::vector<Neighbour> out;
  for (RobotId n : neighbours(self))
    out.push_back({n, positions_[n.value]});
  return out;
}

std::vector<RobotId> SimRadio::neighbours(RobotId id) const {
  std::vector<RobotId> out;
  candidates(id, scratch_);
  for (std::uint32_t i : scratch_)
    if (i != id.value && in_range(id, RobotId{i})) out.push_back(RobotId{i});
  return out;
}

void SimRadio::account(RobotId from, std::span<const std::uint8_t> bytes) {
  ensure(from);
  stats_.total.messages += 1;
  stats_.total.bytes += bytes.size();
  auto& t = stats_.by_type[peek_type(bytes)];
  t.messages += 1;
  t.bytes += bytes.size();
  stats_.sent_by_robot[from.value].messages += 1;
  stats_.sent_by_robot[from.value].bytes += bytes.size();
}

void SimRadio::deliver(RobotId from, RobotId to, RobotId addressed,
                       std::span<const std::uint8_t> bytes) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  if (options_.loss > 0.0 && u(rng_) < options_.loss) {
    ++stats_.lost;
    return;
  }
  const int copies = (options_.duplicate > 0.0 && u(rng_) < options_.duplicate) ? 2 : 1;
  if (copies == 2) ++stats_.duplicated;
  for (int c = 0; c < copies; ++c) {
    double at = now_ + options_.latency_s;
    if (options_.jitter_s > 0.0) at += u(rng_) * options_.jitter_s;
    if (options_.reorder > 0.0 && u(rng_) < options_.reorder) at += options_.reorder_delay_s;
    Packet p{from, addressed, std::vector<std::uint8_t>(bytes.begin(), bytes.end()), now_};
    inbox_[to.value].push_back(Pending{at, order_++, std::move(p)});
    ++stats_.receptions;
    stats_.received_by_robot[to.value].messages += 1;
    stats_.received_by_robot[to.value].bytes += bytes.size();
  }
}

void SimRadio::send(RobotId from, RobotId to, std::span<const std::uint8_t> bytes) {
  ensure(from);
  if (to == kBroadcast) {
    broadcast(from, bytes);
    return;
  }
  ensure(to);
  account(from, bytes);
  if (from == to || !in_range(from, to)) {
    ++stats_.out_of_range;
    return;
  }
  deliver(from, to, to, bytes);
}

void SimRadio::broadcast(RobotId from, std::span<const std::uint8_t> bytes) {
  ensure(from);
  account(from, bytes);
  // Ascending ids, as a scan of every robot would deliver (the loss draws depend on the order).
  std::vector<std::uint32_t> near;
  candidates(from, near);
  for (std::uint32_t i : near)
    if (i != from.value && in_range(from, RobotId{i})) deliver(from, RobotId{i}, kBroadcast, bytes);
}

std::vector<Packet> SimRadio::receive(RobotId self) {
  std::vector<Packet> out;
  if (self.value >= inbox_.size()) return out;
  auto& box = inbox_[self.value];
  if (box.empty()) return out;
  std::vector<Pending> due, later;
  for (auto& p : box)
    (p.deliver_at <= now_ + 1e-12 ? due : later).push_back(std::move(p));
  box = std::move(later);
  std::sort(due.begin(), due.end(), [](const Pending& a, const Pending& b) {
    if (a.deliver_at != b.deliver_at) return a.deliver_at < b.deliver_at;
    if (a.packet.from != b.packet.from) return a.packet.from < b.packet.from;
    return a.order < b.order;
  });
  out.reserve(due.size());
  for (auto& p : due)
    out.push_back(std::move(p.packet));
  return out;
}

std::size_t SimRadio::in_flight() const {
  std::size_t n = 0;
  for (const auto& b : inbox_)
    n += b.size();
  return n;
}

}  // namespace voronav::network
