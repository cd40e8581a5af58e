#include "voronav/dds/dds_transport.hpp"

#include <dds/dds.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <deque>
#include <limits>
#include <map>
#include <mutex>
#include <random>
#include <thread>

#include "voronav/core/error.hpp"
#include "voronav/dds/internal/wire_qos.hpp"
#include "voronav_dds.h"

namespace voronav::dds {

std::string_view to_string(RejectReason r) {
  switch (r) {
    case RejectReason::kUnknownVersion:
      return "unknown_version";
    case RejectReason::kEmptyPayload:
      return "empty_payload";
    case RejectReason::kLengthMismatch:
      return "length_mismatch";
    case RejectReason::kTooLarge:
      return "too_large";
    case RejectReason::kSpoofedSender:
      return "spoofed_sender";
    case RejectReason::kInvalidPose:
      return "invalid_pose";
    case RejectReason::kUnknownWriter:
      return "unknown_writer";
  }
  return "unknown";
}

namespace {

constexpr const char* kPayloadTopic = "voronav_payload";
constexpr const char* kPoseTopic = "voronav_pose";
constexpr std::uint16_t kWireVersion = voronav_dds_kWireVersion;
constexpr std::uint32_t kBroadcastId = network::kBroadcast.value;
static_assert(voronav_dds_kBroadcastId == network::kBroadcast.value);

using Guid = std::array<std::uint8_t, 16>;

// The transport logs to stderr (stdout of a robot process carries its JSON report).
std::shared_ptr<spdlog::logger> logger() {
  static std::shared_ptr<spdlog::logger> l = [] {
    if (auto existing = spdlog::get("voronav_dds")) return existing;
    return spdlog::stderr_color_mt("voronav_dds");
  }();
  return l;
}

dds_duration_t to_ns(double seconds) {
  if (!(seconds > 0.0)) return 0;
  if (seconds > 1e9) return DDS_INFINITY;
  return static_cast<dds_duration_t>(std::llround(seconds * 1e9));
}

double steady_seconds() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

[[noreturn]] void fail(const char* what, dds_return_t rc) {
  throw Error(
      "cyclonedds", 0,
      std::string(what) + " failed: " + dds_strretcode(rc) + " (" + std::to_string(rc) + ")");
}

dds_entity_t check(dds_entity_t e, const char* what) {
  if (e < 0) fail(what, e);
  return e;
}

// Explicitly created domains (with a config XML) are shared by every transport of the process
// on that domain id; the last one to close deletes the domain.
struct DomainRegistry {
  struct Entry {
    dds_entity_t handle = 0;
    int refs = 0;
    std::string xml;
  };
  std::mutex mutex;
  std::map<std::uint32_t, Entry> domains;

  static DomainRegistry& instance() {
    static DomainRegistry r;
    return r;
  }
  void acquire(std::uint32_t id, const std::string& xml) {
    std::lock_guard lock(mutex);
    auto it = domains.find(id);
    if (it != domains.end()) {
      if (it->second.xml != xml)
        throw Error("config_xml", 0,
                    "domain " + std::to_string(id) +
                        " already exists in this process with a different configuration");
      ++it->second.refs;
      return;
    }
    const dds_entity_t d = dds_create_domain(id, xml.c_str());
    if (d < 0) fail("dds_create_domain (check the config XML)", d);
    domains[id] = Entry{d, 1, xml};
  }
  void release(std::uint32_t id) {
    std::lock_guard lock(mutex);
    auto it = domains.find(id);
    if (it == domains.end()) return;
    if (--it->second.refs == 0) {
      dds_delete(it->second.handle);
      domains.erase(it);
    }
  }
};

void validate(const DdsTransportOptions& o) {
  if (o.self == network::kBroadcast) throw Error("self", 0, "the broadcast id is not a robot id");
  if (o.domain_id > 230)
    throw Error("domain_id", 0, "expected 0..230, got " + std::to_string(o.domain_id));
  if (o.partition.empty()) throw Error("partition", 0, "expected a non-empty partition name");
  if (!(o.radio_range_m > 0.0))
    throw Error("radio_range_m", 0, "expected a positive range [m] (or infinity)");
  if (!(o.loss_probability >= 0.0 && o.loss_probability <= 1.0))
    throw Error("loss_probability", 0, "expected a probability in [0, 1]");
  if (o.history_depth < 1) throw Error("history_depth", 0, "expected >= 1");
  if (o.pose_history < 1) throw Error("pose_history", 0, "expected >= 1");
  if (!(o.pose_max_age_s >= 0.0)) throw Error("pose_max_age_s", 0, "expected >= 0 (or infinity)");
  if (o.max_payload_bytes == 0) throw Error("max_payload_bytes", 0, "expected >= 1");
  if (!(o.max_blocking_s >= 0.0) || !std::isfinite(o.max_blocking_s))
    throw Error("max_blocking_s", 0, "expected a finite number of seconds >= 0");
  if (!(o.close_timeout_s >= 0.0) || !std::isfinite(o.close_timeout_s))
    throw Error("close_timeout_s", 0, "expected a finite number of seconds >= 0");
}

// The participant, topics, publisher and subscriber shared by DdsTransport and RawDdsWriter.
struct Endpoints {
  std::uint32_t domain_id = 0;
  bool explicit_domain = false;
  dds_entity_t participant = 0;
  dds_entity_t payload_topic = 0;
  dds_entity_t pose_topic = 0;
  dds_entity_t publisher = 0;
  dds_entity_t subscriber = 0;

  explicit Endpoints(const DdsTransportOptions& o) : domain_id(o.domain_id) {
    if (!o.config_xml.empty()) {
      DomainRegistry::instance().acquire(o.domain_id, o.config_xml);
      explicit_domain = true;
    }
    try {
      participant =
          check(dds_create_participant(o.domain_id, nullptr, nullptr), "dds_create_participant");
      payload_topic = check(
          dds_create_topic(participant, &voronav_dds_Payload_desc, kPayloadTopic, nullptr, nullptr),
          "dds_create_topic(payload)");
      pose_topic =
          check(dds_create_topic(participant, &voronav_dds_Pose_desc, kPoseTopic, nullptr, nullptr),
                "dds_create_topic(pose)");
      dds_qos_t* q = dds_create_qos();
      dds_qset_partition1(q, o.partition.c_str());
      publisher = dds_create_publisher(participant, q, nullptr);
      subscriber = dds_create_subscriber(participant, q, nullptr);
      dds_delete_qos(q);
      check(publisher, "dds_create_publisher");
      check(subscriber, "dds_create_subscriber");
    } catch (...) {
      close();
      throw;
    }
  }
  ~Endpoints() { close(); }
  Endpoints(const Endpoints&) = delete;
  Endpoints& operator=(const Endpoints&) = delete;

  void close() {
    if (participant > 0) dds_delete(participant);
    participant = 0;
    if (explicit_domain) DomainRegistry::instance().release(domain_id);
    explicit_domain = false;
  }

  static dds_qos_t* payload_qos(const DdsTransportOptions& o) {
    dds_qos_t* q = dds_create_qos();
    dds_qset_reliability(q, DDS_RELIABILITY_RELIABLE, to_ns(o.max_blocking_s));
    dds_qset_history(q, DDS_HISTORY_KEEP_LAST, o.history_depth);
    dds_qset_durability(q, DDS_DURABILITY_VOLATILE);
    dds_qset_ignorelocal(q, DDS_IGNORELOCAL_PARTICIPANT);
    internal::allow_xcdr1_only(q);
    return q;
  }
  static dds_qos_t* pose_qos() {
    dds_qos_t* q = dds_create_qos();
    dds_qset_reliability(q, DDS_RELIABILITY_RELIABLE, to_ns(0.1));
    dds_qset_history(q, DDS_HISTORY_KEEP_LAST, 1);
    dds_qset_durability(q, DDS_DURABILITY_TRANSIENT_LOCAL);
    dds_qset_ignorelocal(q, DDS_IGNORELOCAL_PARTICIPANT);
    internal::allow_xcdr1_only(q);
    return q;
  }
};

std::size_t publication_matched(dds_entity_t writer) {
  dds_publication_matched_status_t st{};
  if (dds_get_publication_matched_status(writer, &st) < 0) return 0;
  return st.current_count;
}
std::size_t subscription_matched(dds_entity_t reader) {
  dds_subscription_matched_status_t st{};
  if (dds_get_subscription_matched_status(reader, &st) < 0) return 0;
  return st.current_count;
}

}  // namespace

struct DdsTransport::Impl {
  DdsTransportOptions options;
  dds_entity_t payload_writer = 0;
  dds_entity_t payload_reader = 0;
  dds_entity_t pose_writer = 0;
  dds_entity_t pose_reader = 0;
  dds_entity_t waitset = 0;

  // Writer (publication handle) -> its participant's GUID, filled by the matched listener so that
  // samples of a writer that left meanwhile can still be attributed.
  mutable std::mutex writers_mutex;
  std::map<dds_instance_handle_t, Guid> writer_participant;

  mutable std::mutex mutex;  // everything below
  std::map<std::uint32_t, Guid> id_owner;
  std::map<Guid, std::uint32_t> owner_id;
  std::map<std::uint32_t, Vec2> positions;
  std::optional<Vec2> own_position;
  // Stamped poses (oldest first), own included, for range_at_send_time and nearby().
  std::map<std::uint32_t, std::deque<std::pair<double, Vec2>>> pose_hist;
  std::map<std::uint32_t, std::uint64_t> last_seq;
  std::uint64_t next_seq = 1;
  DdsTransportStats stats;
  std::mt19937_64 rng;
  // Last member: destroyed first, so no listener callback can run on destroyed members.
  Endpoints ep;

  explicit Impl(DdsTransportOptions o)
      : options(std::move(o)),
        rng(options.loss_seed * 0x9E3779B97F4A7C15ULL ^ options.self.value),
        ep(options) {
    if (!options.clock) options.clock = steady_seconds;
    dds_listener_t* listener = dds_create_listener(this);
    dds_lset_subscription_matched(listener, &Impl::on_matched);
    dds_qos_t* pq = Endpoints::payload_qos(options);
    dds_qos_t* sq = Endpoints::pose_qos();
    dds_qos_t* rq = Endpoints::pose_qos();
    // The reader keeps a few poses per robot, so none is lost between two drains.
    dds_qset_history(rq, DDS_HISTORY_KEEP_LAST, std::max(1, options.pose_history));
    payload_writer = dds_create_writer(ep.publisher, ep.payload_topic, pq, nullptr);
    payload_reader = dds_create_reader(ep.subscriber, ep.payload_topic, pq, listener);
    pose_writer = dds_create_writer(ep.publisher, ep.pose_topic, sq, nullptr);
    pose_reader = dds_create_reader(ep.subscriber, ep.pose_topic, rq, listener);
    dds_delete_qos(pq);
    dds_delete_qos(sq);
    dds_delete_qos(rq);
    dds_delete_listener(listener);
    check(payload_writer, "dds_create_writer(payload)");
    check(payload_reader, "dds_create_reader(payload)");
    check(pose_writer, "dds_create_writer(pose)");
    check(pose_reader, "dds_create_reader(pose)");
    waitset = check(dds_create_waitset(ep.participant), "dds_create_waitset");
    for (dds_entity_t r : {payload_reader, pose_reader}) {
      const dds_entity_t rc = check(dds_create_readcondition(r, DDS_ANY_STATE), "readcondition");
      check(dds_waitset_attach(waitset, rc, r), "dds_waitset_attach");
    }
  }

  static void on_matched(dds_entity_t reader, const dds_subscription_matched_status_t status,
                         void* arg) {
    auto* self = static_cast<Impl*>(arg);
    if (status.current_count_change <= 0 || status.last_publication_handle == 0) return;
    self->remember_writer(reader, status.last_publication_handle);
  }

  std::optional<Guid> remember_writer(dds_entity_t reader, dds_instance_handle_t h) {
    dds_builtintopic_endpoint_t* ep_data = dds_get_matched_publication_data(reader, h);
    if (ep_data == nullptr) return std::nullopt;
    Guid g{};
    std::memcpy(g.data(), ep_data->participant_key.v, g.size());
    dds_builtintopic_free_endpoint(ep_data);
    std::lock_guard lock(writers_mutex);
    writer_participant[h] = g;
    return g;
  }

  std::optional<Guid> participant_of(dds_entity_t reader, dds_instance_handle_t h) {
    {
      std::lock_guard lock(writers_mutex);
      auto it = writer_participant.find(h);
      if (it != writer_participant.end()) return it->second;
    }
    return remember_writer(reader, h);
  }

  void reject(RejectReason r, const std::string& detail) {
    const auto i = static_cast<std::size_t>(r);
    ++stats.rejected;
    const std::uint64_t n = ++stats.rejected_by_reason[i];
    if (n <= 10 || n % 1000 == 0)
      logger()->error("dds robot {}: rejected sample ({}): {} [{} so far]", options.self.value,
                      to_string(r), detail, n);
  }

  // Binds robot id <-> participant on first sight; false when it contradicts an earlier binding.
  bool bind_identity(std::uint32_t id, const Guid& g) {
    if (id == options.self.value || id == kBroadcastId) return false;
    auto a = id_owner.find(id);
    if (a != id_owner.end() && a->second != g) return false;
    auto b = owner_id.find(g);
    if (b != owner_id.end() && b->second != id) return false;
    id_owner[id] = g;
    owner_id[g] = id;
    return true;
  }

  bool check_identity(dds_entity_t reader, const dds_sample_info_t& si, std::uint32_t id) {
    const auto g = participant_of(reader, si.publication_handle);
    if (!g) {
      reject(RejectReason::kUnknownWriter, "sample claiming id " + std::to_string(id));
      return false;
    }
    if (!bind_identity(id, *g)) {
      reject(RejectReason::kSpoofedSender,
             "a participant claims id " + std::to_string(id) + " which is bound elsewhere");
      return false;
    }
    return true;
  }

  void remember_pose(std::uint32_t id, double t, Vec2 p) {
    auto& h = pose_hist[id];
    if (!h.empty() && t < h.back().first) h.clear();  // a restarted clock: start over
    h.emplace_back(t, p);
    while (h.size() > static_cast<std::size_t>(std::max(1, options.pose_history)))
      h.pop_front();
  }

  /// Latest pose of `id` stamped at or before t (own included); nullopt when none.
  std::optional<Vec2> pose_at(std::uint32_t id, double t) const {
    auto it = pose_hist.find(id);
    if (it == pose_hist.end()) return std::nullopt;
    for (auto p = it->second.rbegin(); p != it->second.rend(); ++p)
      if (p->first <= t + 1e-9) return p->second;
    return std::nullopt;
  }

  /// Age at t of the pose pose_at(id, t) returns [s] (infinity when none).
  double pose_age(std::uint32_t id, double t) const {
    auto it = pose_hist.find(id);
    if (it == pose_hist.end()) return std::numeric_limits<double>::infinity();
    for (auto p = it->second.rbegin(); p != it->second.rend(); ++p)
      if (p->first <= t + 1e-9) return t - p->first;
    return std::numeric_limits<double>::infinity();
  }

  void drain_poses() {
    constexpr std::size_t kBatch = 64;
    for (;;) {
      void* buf[kBatch] = {};
      dds_sample_info_t si[kBatch];
      const dds_return_t n = dds_take(pose_reader, buf, si, kBatch, kBatch);
      if (n <= 0) return;
      for (dds_return_t i = 0; i < n; ++i) {
        if (!si[i].valid_data) continue;
        const auto* p = static_cast<const voronav_dds_Pose*>(buf[i]);
        if (p->version != kWireVersion) {
          reject(RejectReason::kUnknownVersion, "pose version " + std::to_string(p->version));
          continue;
        }
        if (!std::isfinite(p->x) || !std::isfinite(p->y)) {
          reject(RejectReason::kInvalidPose, "non-finite pose of id " + std::to_string(p->id));
          continue;
        }
        if (!check_identity(pose_reader, si[i], p->id)) continue;
        positions[p->id] = Vec2{p->x, p->y};
        remember_pose(p->id, p->t, Vec2{p->x, p->y});
        ++stats.poses_received;
      }
      dds_return_loan(pose_reader, buf, n);
      if (static_cast<std::size_t>(n) < kBatch) return;
    }
  }

  void handle_payload(const voronav_dds_Payload& s, const dds_sample_info_t& si,
                      std::vector<std::pair<dds_time_t, network::Packet>>& out) {
    if (s.version != kWireVersion) {
      reject(RejectReason::kUnknownVersion, "payload version " + std::to_string(s.version));
      return;
    }
    if (!check_identity(payload_reader, si, s.sender)) return;
    if (s.bytes._length == 0) {
      reject(RejectReason::kEmptyPayload, "from id " + std::to_string(s.sender));
      return;
    }
    if (s.length != s.bytes._length) {
      reject(RejectReason::kLengthMismatch, "length field " + std::to_string(s.length) + " but " +
                                                std::to_string(s.bytes._length) + " bytes");
      return;
    }
    if (s.bytes._length > options.max_payload_bytes) {
      reject(RejectReason::kTooLarge, std::to_string(s.bytes._length) + " bytes");
      return;
    }
    auto& last = last_seq[s.sender];
    if (s.seq <= last) {
      ++stats.duplicates;
      return;
    }
    stats.gaps += s.seq - last - 1;
    last = s.seq;
    if (s.receiver != kBroadcastId && s.receiver != options.self.value) {
      ++stats.not_for_me;
      return;
    }
    if (std::isfinite(options.radio_range_m)) {
      std::optional<Vec2> own = own_position, theirs;
      if (options.range_at_send_time) {
        own = pose_at(options.self.value, s.sent_at);
        theirs = pose_at(s.sender, s.sent_at);
      } else if (auto it = positions.find(s.sender); it != positions.end()) {
        theirs = it->second;
      }
      if (!own || !theirs) {
        ++stats.dropped_unknown_pose;
        return;
      }
      if (distance(*own, *theirs) > options.radio_range_m) {
        ++stats.dropped_range;
        return;
      }
    }
    if (options.loss_probability > 0.0 &&
        std::uniform_real_distribution<double>(0.0, 1.0)(rng) < options.loss_probability) {
      ++stats.dropped_loss;
      return;
    }
    network::Packet p;
    p.from = network::RobotId{s.sender};
    p.to = s.receiver == kBroadcastId ? network::kBroadcast : options.self;
    p.bytes.assign(s.bytes._buffer, s.bytes._buffer + s.bytes._length);
    p.sent_at_s = s.sent_at;
    ++stats.delivered;
    out.emplace_back(si.source_timestamp, std::move(p));
  }

  void write_payload(std::uint32_t receiver, std::span<const std::uint8_t> bytes) {
    if (bytes.empty()) throw Error("bytes", 0, "cannot send an empty payload");
    if (bytes.size() > options.max_payload_bytes)
      throw Error("bytes", 0,
                  "payload of " + std::to_string(bytes.size()) +
                      " bytes exceeds max_payload_bytes " +
                      std::to_string(options.max_payload_bytes));
    std::lock_guard lock(mutex);
    voronav_dds_Payload s{};
    s.version = kWireVersion;
    s.sender = options.self.value;
    s.receiver = receiver;
    s.seq = next_seq++;
    s.sent_at = options.clock();
    s.length = static_cast<std::uint32_t>(bytes.size());
    s.bytes._maximum = s.length;
    s.bytes._length = s.length;
    s.bytes._buffer = const_cast<std::uint8_t*>(bytes.data());
    s.bytes._release = false;
    const dds_return_t rc = dds_write(payload_writer, &s);
    if (rc != DDS_RETCODE_OK) fail("dds_write(payload)", rc);
    if (receiver == kBroadcastId)
      ++stats.sent_broadcast;
    else
      ++stats.sent_unicast;
  }
};

DdsTransport::DdsTransport(DdsTransportOptions options) {
  validate(options);
  impl_ = std::make_unique<Impl>(std::move(options));
}

DdsTransport::~DdsTransport() {
  if (!impl_) return;
  if (impl_->options.close_timeout_s > 0.0) flush(impl_->options.close_timeout_s);
  // Deleting the participant stops the listener before Impl goes away.
  impl_->ep.close();
}

void DdsTransport::send(network::RobotId from, network::RobotId to,
                        std::span<const std::uint8_t> bytes) {
  if (from != impl_->options.self)
    throw Error("from", 0,
                "this transport is robot " + std::to_string(impl_->options.self.value) +
                    ", cannot send as " + std::to_string(from.value));
  if (to == impl_->options.self) throw Error("to", 0, "a robot cannot send to itself");
  impl_->write_payload(to.value, bytes);
}

void DdsTransport::broadcast(network::RobotId from, std::span<const std::uint8_t> bytes) {
  if (from != impl_->options.self)
    throw Error("from", 0,
                "this transport is robot " + std::to_string(impl_->options.self.value) +
                    ", cannot broadcast as " + std::to_string(from.value));
  impl_->write_payload(kBroadcastId, bytes);
}

std::vector<network::Packet> DdsTransport::receive(network::RobotId self) {
  if (self != impl_->options.self)
    throw Error("self", 0,
                "this transport is robot " + std::to_string(impl_->options.self.value) +
                    ", cannot receive for " + std::to_string(self.value));
  std::lock_guard lock(impl_->mutex);
  impl_->drain_poses();
  std::vector<std::pair<dds_time_t, network::Packet>> got;
  constexpr std::size_t kBatch = 256;
  for (;;) {
    void* buf[kBatch] = {};
    dds_sample_info_t si[kBatch];
    const dds_return_t n = dds_take(impl_->payload_reader, buf, si, kBatch, kBatch);
    if (n <= 0) break;
    for (dds_return_t i = 0; i < n; ++i) {
      if (!si[i].valid_data) continue;
      impl_->handle_payload(*static_cast<const voronav_dds_Payload*>(buf[i]), si[i], got);
    }
    dds_return_loan(impl_->payload_reader, buf, n);
    if (static_cast<std::size_t>(n) < kBatch) break;
  }
  // The reader returns samples grouped by sender; order them by send time (per sender the order
  // is kept, since one writer's timestamps do not decrease).
  std::stable_sort(got.begin(), got.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<network::Packet> out;
  out.reserve(got.size());
  for (auto& g : got)
    out.push_back(std::move(g.second));
  return out;
}

void DdsTransport::update_position(network::RobotId id, Vec2 position) {
  if (id != impl_->options.self)
    throw Error("id", 0,
                "this transport is robot " + std::to_string(impl_->options.self.value) +
                    ", cannot publish the position of " + std::to_string(id.value));
  if (!position.is_finite()) throw Error("position", 0, "expected finite coordinates");
  std::lock_guard lock(impl_->mutex);
  voronav_dds_Pose p{};
  p.version = kWireVersion;
  p.id = id.value;
  p.x = position.x;
  p.y = position.y;
  p.t = impl_->options.clock();
  const dds_return_t rc = dds_write(impl_->pose_writer, &p);
  if (rc != DDS_RETCODE_OK) fail("dds_write(pose)", rc);
  impl_->own_position = position;
  impl_->remember_pose(id.value, p.t, position);
  ++impl_->stats.poses_sent;
}

std::vector<network::Neighbour> DdsTransport::nearby(network::RobotId self) {
  if (self != impl_->options.self)
    throw Error("self", 0, "this transport is robot " + std::to_string(impl_->options.self.value));
  std::lock_guard lock(impl_->mutex);
  impl_->drain_poses();
  const double now = impl_->options.clock();
  std::vector<network::Neighbour> out;
  const auto own = impl_->pose_at(self.value, now);
  if (!own) return out;
  for (const auto& [id, hist] : impl_->pose_hist) {
    if (id == self.value) continue;
    const auto p = impl_->pose_at(id, now);
    if (p && impl_->pose_age(id, now) <= impl_->options.pose_max_age_s &&
        distance(*p, *own) <= impl_->options.radio_range_m)
      out.push_back({network::RobotId{id}, *p});
  }
  return out;
}

bool DdsTransport::wait_for_poses(const std::vector<network::RobotId>& ids, double min_stamp_s,
                                  double timeout_s) {
  const double deadline = steady_seconds() + std::max(0.0, timeout_s);
  for (;;) {
    {
      std::lock_guard lock(impl_->mutex);
      impl_->drain_poses();
      bool all = true;
      for (auto id : ids) {
        if (id == impl_->options.self) continue;
        auto it = impl_->pose_hist.find(id.value);
        if (it == impl_->pose_hist.end() || it->second.empty() ||
            it->second.back().first + 1e-9 < min_stamp_s) {
          all = false;
          break;
        }
      }
      if (all) return true;
    }
    if (steady_seconds() >= deadline) return false;
    // Not the waitset: it fires while payloads wait to be taken, and those stay queued here.
    std::this_thread::sleep_for(std::chrono::microseconds(100));
  }
}

std::uint64_t DdsTransport::last_seq_from(network::RobotId id) const {
  std::lock_guard lock(impl_->mutex);
  auto it = impl_->last_seq.find(id.value);
  return it == impl_->last_seq.end() ? 0 : it->second;
}

std::uint64_t DdsTransport::last_seq_sent() const {
  std::lock_guard lock(impl_->mutex);
  return impl_->next_seq - 1;
}

bool DdsTransport::wait_for_peers(std::size_t count, double timeout_s) {
  const double deadline = steady_seconds() + std::max(0.0, timeout_s);
  for (;;) {
    std::size_t known = 0;
    {
      std::lock_guard lock(impl_->mutex);
      impl_->drain_poses();
      known = impl_->positions.size();
    }
    const std::size_t w = publication_matched(impl_->payload_writer);
    const std::size_t r = subscription_matched(impl_->payload_reader);
    if (known >= count && w >= count && r >= count) return true;
    if (steady_seconds() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

bool DdsTransport::wait_for_data(double timeout_s) {
  const dds_return_t rc = dds_waitset_wait(impl_->waitset, nullptr, 0, to_ns(timeout_s));
  return rc > 0;
}

bool DdsTransport::flush(double timeout_s) {
  const dds_duration_t t = to_ns(timeout_s);
  const bool a = dds_wait_for_acks(impl_->payload_writer, t) == DDS_RETCODE_OK;
  const bool b = dds_wait_for_acks(impl_->pose_writer, t) == DDS_RETCODE_OK;
  return a && b;
}

std::optional<Vec2> DdsTransport::known_position(network::RobotId id) const {
  std::lock_guard lock(impl_->mutex);
  if (id == impl_->options.self) return impl_->own_position;
  auto it = impl_->positions.find(id.value);
  if (it == impl_->positions.end()) return std::nullopt;
  return it->second;
}

std::vector<network::RobotId> DdsTransport::known_robots() const {
  std::lock_guard lock(impl_->mutex);
  std::vector<network::RobotId> out;
  for (const auto& [id, pos] : impl_->positions)
    out.push_back(network::RobotId{id});
  return out;
}

std::size_t DdsTransport::matched_receivers() const {
  return publication_matched(impl_->payload_writer);
}

DdsTransportStats DdsTransport::stats() const {
  std::lock_guard lock(impl_->mutex);
  return impl_->stats;
}

std::int32_t DdsTransport::participant_handle() const {
  return impl_->ep.participant;
}

network::RobotId DdsTransport::self() const {
  return impl_->options.self;
}
const DdsTransportOptions& DdsTransport::options() const {
  return impl_->options;
}

// ---------------------------------------------------------------------------------------------

struct RawDdsWriter::Impl {
  Endpoints ep;
  dds_entity_t payload_writer = 0;
  dds_entity_t pose_writer = 0;

  explicit Impl(const DdsTransportOptions& o) : ep(o) {
    dds_qos_t* pq = Endpoints::payload_qos(o);
    dds_qos_t* sq = Endpoints::pose_qos();
    payload_writer = dds_create_writer(ep.publisher, ep.payload_topic, pq, nullptr);
    pose_writer = dds_create_writer(ep.publisher, ep.pose_topic, sq, nullptr);
    dds_delete_qos(pq);
    dds_delete_qos(sq);
    check(payload_writer, "dds_create_writer(payload)");
    check(pose_writer, "dds_create_writer(pose)");
  }
};

RawDdsWriter::RawDdsWriter(const DdsTransportOptions& options) {
  validate(options);
  impl_ = std::make_unique<Impl>(options);
}

RawDdsWriter::~RawDdsWriter() {
  if (impl_) impl_->ep.close();
}

void RawDdsWriter::write(const RawPayloadSample& sample) {
  voronav_dds_Payload s{};
  s.version = sample.version;
  s.sender = sample.sender;
  s.receiver = sample.receiver;
  s.seq = sample.seq;
  s.sent_at = sample.sent_at;
  s.length = sample.length;
  std::vector<std::uint8_t> copy = sample.bytes;
  s.bytes._maximum = static_cast<std::uint32_t>(copy.size());
  s.bytes._length = static_cast<std::uint32_t>(copy.size());
  s.bytes._buffer = copy.empty() ? nullptr : copy.data();
  s.bytes._release = false;
  const dds_return_t rc = dds_write(impl_->payload_writer, &s);
  if (rc != DDS_RETCODE_OK) fail("dds_write(raw payload)", rc);
}

void RawDdsWriter::write(const RawPose& pose) {
  voronav_dds_Pose p{};
  p.version = pose.version;
  p.id = pose.id;
  p.x = pose.x;
  p.y = pose.y;
  p.t = pose.t;
  const dds_return_t rc = dds_write(impl_->pose_writer, &p);
  if (rc != DDS_RETCODE_OK) fail("dds_write(raw pose)", rc);
}

bool RawDdsWriter::wait_for_readers(std::size_t count, double timeout_s) {
  const double deadline = steady_seconds() + std::max(0.0, timeout_s);
  for (;;) {
    if (publication_matched(impl_->payload_writer) >= count &&
        publication_matched(impl_->pose_writer) >= count)
      return true;
    if (steady_seconds() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

bool RawDdsWriter::flush(double timeout_s) {
  const dds_duration_t t = to_ns(timeout_s);
  const bool a = dds_wait_for_acks(impl_->payload_writer, t) == DDS_RETCODE_OK;
  const bool b = dds_wait_for_acks(impl_->pose_writer, t) == DDS_RETCODE_OK;
  return a && b;
}

}  // namespace voronav::dds
