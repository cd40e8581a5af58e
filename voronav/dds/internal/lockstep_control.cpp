#include "voronav/dds/internal/lockstep_control.hpp"

#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>

#include "voronav/core/error.hpp"
#include "voronav/dds/internal/wire_qos.hpp"
#include "voronav_dds.h"

namespace voronav::dds::internal {

namespace {

constexpr std::uint16_t kVersion = voronav_dds_kWireVersion;

std::shared_ptr<spdlog::logger> log() {
  static std::shared_ptr<spdlog::logger> l = [] {
    if (auto existing = spdlog::get("voronav_netsim_dds")) return existing;
    return spdlog::stderr_color_mt("voronav_netsim_dds");
  }();
  return l;
}

dds_qos_t* control_qos() {
  dds_qos_t* q = dds_create_qos();
  dds_qset_reliability(q, DDS_RELIABILITY_RELIABLE, to_duration(1.0));
  dds_qset_history(q, DDS_HISTORY_KEEP_LAST, 1);
  dds_qset_durability(q, DDS_DURABILITY_TRANSIENT_LOCAL);
  dds_qset_ignorelocal(q, DDS_IGNORELOCAL_PARTICIPANT);
  allow_xcdr1_only(q);
  return q;
}

}  // namespace

dds_entity_t must(dds_entity_t e, const char* what) {
  if (e < 0)
    throw Error(
        "cyclonedds", 0,
        std::string(what) + " failed: " + dds_strretcode(e) + " (" + std::to_string(e) + ")");
  return e;
}

double steady_s() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

void die_now() {
  std::fflush(nullptr);
  std::raise(SIGKILL);
  std::abort();
}

dds_duration_t to_duration(double seconds) {
  return static_cast<dds_duration_t>(std::llround(std::max(0.0, seconds) * 1e9));
}

ControlLink::ControlLink(dds_entity_t participant, const std::string& partition, bool world) {
  const dds_entity_t tick_topic =
      must(dds_create_topic(participant, &voronav_dds_Tick_desc, "voronav_tick", nullptr, nullptr),
           "dds_create_topic(tick)");
  const dds_entity_t report_topic = must(
      dds_create_topic(participant, &voronav_dds_Report_desc, "voronav_report", nullptr, nullptr),
      "dds_create_topic(report)");
  dds_qos_t* pq = dds_create_qos();
  dds_qset_partition1(pq, partition.c_str());
  const dds_entity_t pub =
      must(dds_create_publisher(participant, pq, nullptr), "dds_create_publisher");
  const dds_entity_t sub =
      must(dds_create_subscriber(participant, pq, nullptr), "dds_create_subscriber");
  dds_delete_qos(pq);
  dds_qos_t* q = control_qos();
  writer_ = must(dds_create_writer(pub, world ? tick_topic : report_topic, q, nullptr),
                 "dds_create_writer(control)");
  reader_ = must(dds_create_reader(sub, world ? report_topic : tick_topic, q, nullptr),
                 "dds_create_reader(control)");
  dds_delete_qos(q);
  waitset_ = must(dds_create_waitset(participant), "dds_create_waitset");
  const dds_entity_t rc =
      must(dds_create_readcondition(reader_, DDS_ANY_STATE), "dds_create_readcondition");
  must(dds_waitset_attach(waitset_, rc, reader_), "dds_waitset_attach");
}

void ControlLink::write(const TickMsg& t) {
  voronav_dds_Tick s{};
  s.version = kVersion;
  s.step = t.step;
  s.stop = t.stop;
  s.first_route_s = t.first_route_s;
  auto alive = t.alive;
  auto seq = t.seq;
  auto changes = t.changes;
  s.alive._buffer = alive.data();
  s.alive._length = s.alive._maximum = static_cast<std::uint32_t>(alive.size());
  s.seq._buffer = seq.data();
  s.seq._length = s.seq._maximum = static_cast<std::uint32_t>(seq.size());
  s.changes._buffer = changes.data();
  s.changes._length = s.changes._maximum = static_cast<std::uint32_t>(changes.size());
  const dds_return_t rc = dds_write(writer_, &s);
  if (rc != DDS_RETCODE_OK) must(rc, "dds_write(tick)");
}

void ControlLink::write(const ReportMsg& r) {
  voronav_dds_Report s{};
  s.version = kVersion;
  s.id = r.id;
  s.step = r.step;
  s.kind = r.kind;
  s.seq = r.seq;
  s.prev_seq = r.prev_seq;
  s.changes_applied = r.changes_applied;
  s.route_time_s = r.route_time_s;
  s.arrived = r.arrived;
  std::string detail = r.detail;
  s.detail = detail.data();
  const dds_return_t rc = dds_write(writer_, &s);
  if (rc != DDS_RETCODE_OK) must(rc, "dds_write(report)");
}

template <typename Sample, typename F>
void ControlLink::take_all(F&& on_sample) {
  constexpr int kBatch = 32;
  for (;;) {
    void* buf[kBatch] = {};
    dds_sample_info_t si[kBatch];
    const dds_return_t n = dds_take(reader_, buf, si, kBatch, kBatch);
    if (n <= 0) return;
    for (dds_return_t i = 0; i < n; ++i)
      if (si[i].valid_data) on_sample(*static_cast<const Sample*>(buf[i]));
    dds_return_loan(reader_, buf, n);
  }
}

std::optional<TickMsg> ControlLink::take_tick() {
  std::optional<TickMsg> out;
  take_all<voronav_dds_Tick>([&](const voronav_dds_Tick& s) {
    if (s.version != kVersion || s.alive._length != s.seq._length) {
      log()->error("rejected a malformed tick (version {}, {} alive flags, {} seqs)", s.version,
                   s.alive._length, s.seq._length);
      return;
    }
    TickMsg t;
    t.step = s.step;
    t.stop = s.stop;
    t.first_route_s = s.first_route_s;
    t.alive.assign(s.alive._buffer, s.alive._buffer + s.alive._length);
    t.seq.assign(s.seq._buffer, s.seq._buffer + s.seq._length);
    t.changes.assign(s.changes._buffer, s.changes._buffer + s.changes._length);
    if (!out || t.step >= out->step) out = std::move(t);
  });
  return out;
}

std::vector<ReportMsg> ControlLink::take_reports() {
  std::vector<ReportMsg> out;
  take_all<voronav_dds_Report>([&](const voronav_dds_Report& s) {
    if (s.version != kVersion || s.kind < kReady || s.kind > kFailedReport) {
      log()->error("rejected a malformed report (version {}, kind {})", s.version, s.kind);
      return;
    }
    ReportMsg r;
    r.id = s.id;
    r.step = s.step;
    r.kind = s.kind;
    r.seq = s.seq;
    r.prev_seq = s.prev_seq;
    r.changes_applied = s.changes_applied;
    r.route_time_s = s.route_time_s;
    r.arrived = s.arrived;
    r.detail = s.detail ? s.detail : "";
    out.push_back(std::move(r));
  });
  return out;
}

void ControlLink::wait(double timeout_s) {
  dds_waitset_wait(waitset_, nullptr, 0, to_duration(timeout_s));
}

std::size_t ControlLink::matched_readers() const {
  dds_publication_matched_status_t st{};
  if (dds_get_publication_matched_status(writer_, &st) < 0) return 0;
  return st.current_count;
}

void ControlLink::flush(double timeout_s) {
  dds_wait_for_acks(writer_, to_duration(timeout_s));
}

}  // namespace voronav::dds::internal
