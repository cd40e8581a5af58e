// In-process baseline for the DDS measurements (bench/run_dds_bench.sh): two DdsTransport
// participants in one process on the loopback config; a ping-pong round trip (A sends, B answers,
// A receives) per iteration, for several payload sizes. The multi-process numbers of
// bench/results/dds.md are reported as ratios against this, measured in the same run.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <string>

#include "voronav/dds/cyclone_config.hpp"
#include "voronav/dds/dds_transport.hpp"

namespace {

using voronav::dds::DdsTransport;
using voronav::dds::DdsTransportOptions;
using voronav::network::RobotId;

DdsTransportOptions options(std::uint32_t id) {
  DdsTransportOptions o;
  o.self = RobotId{id};
  o.domain_id = static_cast<std::uint32_t>(1 + ::getpid() % 200);
  o.config_xml = voronav::dds::loopback_config_xml();
  o.partition = "bench-" + std::to_string(::getpid());
  o.close_timeout_s = 0.2;
  return o;
}

// Blocks until `t` delivers one packet (or 1 s passes; then the iteration is counted as lost).
bool receive_one(DdsTransport& t) {
  for (int i = 0; i < 100; ++i) {
    auto got = t.receive(t.self());
    if (!got.empty()) return true;
    t.wait_for_data(0.01);
  }
  return false;
}

void BM_InProcessRoundTrip(benchmark::State& state) {
  DdsTransport a(options(1)), b(options(2));
  a.update_position(RobotId{1}, {0, 0});
  b.update_position(RobotId{2}, {1, 0});
  if (!a.wait_for_peers(1, 10.0) || !b.wait_for_peers(1, 10.0)) {
    state.SkipWithError("discovery timed out");
    return;
  }
  const std::vector<std::uint8_t> payload(static_cast<std::size_t>(state.range(0)), 0x5a);
  std::int64_t lost = 0;
  for (auto _ : state) {
    a.send(RobotId{1}, RobotId{2}, payload);
    if (!receive_one(b)) ++lost;
    b.send(RobotId{2}, RobotId{1}, payload);
    if (!receive_one(a)) ++lost;
  }
  state.counters["lost"] = static_cast<double>(lost);
  state.SetBytesProcessed(state.iterations() * 2 * state.range(0));
}
BENCHMARK(BM_InProcessRoundTrip)->Arg(64)->Arg(1024)->Arg(16384)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
