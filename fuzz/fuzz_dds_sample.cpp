// libFuzzer target: DDS sample decoding as a receiving voronav process does it. The first byte
// picks the wire type (Payload, Pose, Tick, Report from voronav/dds/idl, bits 0-1) and the byte
// order (bit 3) of the XCDR1 encoding; the rest is the serialized sample. Cyclone's normalizer
// checks it (as on receipt), the sample is read into the generated C struct and freed, and a
// Payload's bytes go through network::decode as DdsTransport hands them on.
#include <dds/dds.h>
#include <dds/ddsi/ddsi_cdrstream.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <span>
#include <vector>

#include "fuzz_util.hpp"
#include "seed_messages.hpp"
#include "voronav/network/messages.hpp"
#include "voronav_dds.h"

namespace {

/// A sample serialized as Cyclone sends it (XCDR1, little endian), with the selector byte first.
std::vector<std::uint8_t> serialized(std::uint8_t selector, const void* sample,
                                     const dds_topic_descriptor_t& desc) {
  dds_ostream_t os;
  dds_ostream_init(&os, 0, 1);
  (void)dds_stream_write(&os, static_cast<const char*>(sample), desc.m_ops);
  std::vector<std::uint8_t> out{selector};
  out.insert(out.end(), os.m_buffer, os.m_buffer + os.m_index);
  dds_ostream_fini(&os);
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  std::vector<std::vector<std::uint8_t>> seeds;
  for (auto& m : voronav::fuzz::sample_messages()) {
    voronav_dds_Payload p{};
    p.version = voronav_dds_kWireVersion;
    p.sender = 1;
    p.receiver = voronav_dds_kBroadcastId;
    p.seq = 3;
    p.sent_at = 1.25;
    p.length = static_cast<std::uint32_t>(m.size());
    p.bytes._length = p.bytes._maximum = p.length;
    p.bytes._buffer = m.data();
    seeds.push_back(serialized(0, &p, voronav_dds_Payload_desc));
  }
  voronav_dds_Pose pose{voronav_dds_kWireVersion, 2, 1.5, -2.0, 3.0};
  seeds.push_back(serialized(1, &pose, voronav_dds_Pose_desc));
  std::uint8_t alive[3] = {1, 1, 0};
  std::uint64_t seq[3] = {4, 5, 6};
  voronav_dds_Tick tick{};
  tick.version = voronav_dds_kWireVersion;
  tick.step = 9;
  tick.alive._length = tick.alive._maximum = 3;
  tick.alive._buffer = alive;
  tick.seq._length = tick.seq._maximum = 3;
  tick.seq._buffer = seq;
  seeds.push_back(serialized(2, &tick, voronav_dds_Tick_desc));
  voronav_dds_Report report{};
  char detail[] = "x";
  report.version = voronav_dds_kWireVersion;
  report.detail = detail;
  seeds.push_back(serialized(3, &report, voronav_dds_Report_desc));
  voronav::fuzz::write_seeds(seeds);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace voronav;
  if (size < 1 || size > (1u << 20)) return 0;
  const dds_topic_descriptor_t* descs[] = {&voronav_dds_Payload_desc, &voronav_dds_Pose_desc,
                                           &voronav_dds_Tick_desc, &voronav_dds_Report_desc};
  const dds_topic_descriptor_t* desc = descs[data[0] & 3];
  // XCDR1 only: voronav's readers accept nothing else (internal/wire_qos.hpp). Debian's Cyclone
  // 0.10.2 XCDR2 normalizer reads and byte-swaps past the end of a sample that ends inside an
  // 8-byte member, by an amount set by whatever lies behind it (fixed upstream in 2023, cyclonedds
  // pull request #1559; docs/dds.md, "Data representation"), so XCDR2 input is not ours to fuzz.
  const std::uint32_t xcdr = 1;
  const bool bswap = (data[0] & 8) != 0;
  // The normalizer works in place on an aligned copy, as Cyclone does with a received buffer.
  // Behind the sample lies a guard of kGuard bytes with a known pattern: a write past the end,
  // or into the input, is a finding that names the stage.
  constexpr std::size_t kGuard = 64;
  const std::size_t n = size - 1;
  std::vector<std::uint64_t> buf((n + kGuard + 7) / 8);
  auto* bytes = reinterpret_cast<unsigned char*>(buf.data());
  std::memset(bytes, 0xA5, buf.size() * 8);
  std::memcpy(bytes, data + 1, n);
  const std::vector<std::uint8_t> input(data, data + size);
  auto check = [&](const char* stage) {
    if (std::memcmp(input.data(), data, size) != 0) {
      std::fprintf(stderr, "fuzz_dds_sample: the input changed during %s\n", stage);
      std::abort();
    }
    for (std::size_t i = n; i < buf.size() * 8; ++i)
      if (bytes[i] != 0xA5) {
        std::fprintf(stderr,
                     "fuzz_dds_sample: %s wrote byte %zu past the end of a %zu-byte sample "
                     "(selector %d)\n",
                     stage, i - n + 1, n, data[0]);
        std::abort();
      }
  };
  std::uint32_t off = 0;
  const void* ok =
      dds_stream_normalize_data(reinterpret_cast<char*>(bytes), &off, static_cast<std::uint32_t>(n),
                                bswap, xcdr, desc->m_ops);
  check("normalize");
  if (ok == nullptr) return 0;  // rejected, as Cyclone rejects it on receipt
  std::vector<std::uint64_t> sample(desc->m_size / 8 + 1, 0);
  dds_istream_t is;
  dds_istream_init(&is, off, reinterpret_cast<char*>(bytes), xcdr);
  (void)dds_stream_read(&is, reinterpret_cast<char*>(sample.data()), desc->m_ops);
  dds_istream_fini(&is);
  check("read");
  if (desc == &voronav_dds_Payload_desc) {
    const auto* p = reinterpret_cast<const voronav_dds_Payload*>(sample.data());
    if (p->bytes._length > 0 && p->length == p->bytes._length)
      fuzz::expect_clean("message", [&] {
        (void)network::decode(std::span<const std::uint8_t>(p->bytes._buffer, p->bytes._length));
      });
  }
  check("decode");
  dds_stream_free_sample(sample.data(), desc->m_ops);
  check("free");
  return 0;
}
