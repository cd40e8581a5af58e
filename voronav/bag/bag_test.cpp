// Tests of the MCAP writer and the ROS 2 CDR encoders: hand-computed CDR bytes, CRC-32 check
// value, and full round trips through a small test-only MCAP reader written from the
// specification (records, chunk CRCs, message indexes, chunk indexes, summary offsets, footer).
#include <gtest/gtest.h>
#include <lz4frame.h>
#include <zstd.h>

#include <unistd.h>
#include <cstring>
#include <fstream>
#include <map>
#include <numbers>
#include <set>

#include "voronav/bag/cdr.hpp"
#include "voronav/bag/crc32.hpp"
#include "voronav/bag/mcap_writer.hpp"
#include "voronav/bag/ros_bag.hpp"
#include "voronav/bag/ros_msgs.hpp"
#include "voronav/bag/run_bag.hpp"
#include "voronav/core/error.hpp"

namespace voronav::bag {
namespace {

using Bytes = std::vector<std::uint8_t>;

// ---- a minimal MCAP reader (test only) -------------------------------------------------------

struct Cursor {
  const Bytes& b;
  std::size_t pos = 0;
  std::size_t end = 0;
  std::uint64_t le(int n) {
    if (pos + static_cast<std::size_t>(n) > end) throw std::runtime_error("read past end");
    std::uint64_t v = 0;
    for (int i = 0; i < n; ++i)
      v |= static_cast<std::uint64_t>(b[pos + static_cast<std::size_t>(i)]) << (8 * i);
    pos += static_cast<std::size_t>(n);
    return v;
  }
  std::uint8_t u8() { return static_cast<std::uint8_t>(le(1)); }
  std::uint16_t u16() { return static_cast<std::uint16_t>(le(2)); }
  std::uint32_t u32() { return static_cast<std::uint32_t>(le(4)); }
  std::uint64_t u64() { return le(8); }
  std::string str() {
    const std::uint32_t n = u32();
    if (pos + n > end) throw std::runtime_error("string past end");
    std::string s(b.begin() + static_cast<std::ptrdiff_t>(pos),
                  b.begin() + static_cast<std::ptrdiff_t>(pos + n));
    pos += n;
    return s;
  }
};

struct Message {
  std::uint16_t channel;
  std::uint32_t sequence;
  std::uint64_t log_time, publish_time;
  Bytes data;
};
struct Read {
  std::string profile;
  std::map<std::uint16_t, std::pair<std::string, std::string>> schemas;  // id -> name, data
  std::map<std::uint16_t, std::string> channels;                         // id -> topic
  std::map<std::uint16_t, std::string> channel_encoding;
  std::vector<Message> messages;  // in file order
  std::uint64_t stat_messages = 0;
  std::uint32_t stat_chunks = 0;
  std::size_t chunk_indexes = 0;
  std::map<std::uint16_t, std::uint64_t> stat_counts;
  std::set<std::string> compressions;
};

Bytes decompress(const std::string& how, const Bytes& in, std::size_t size) {
  Bytes out(size);
  if (how.empty()) return in;
  if (how == "zstd") {
    const std::size_t n = ZSTD_decompress(out.data(), out.size(), in.data(), in.size());
    if (ZSTD_isError(n) != 0 || n != size) throw std::runtime_error("zstd");
    return out;
  }
  if (how == "lz4") {
    LZ4F_dctx* ctx = nullptr;
    LZ4F_createDecompressionContext(&ctx, LZ4F_VERSION);
    std::size_t dst = out.size(), src = in.size();
    const std::size_t r = LZ4F_decompress(ctx, out.data(), &dst, in.data(), &src, nullptr);
    LZ4F_freeDecompressionContext(ctx);
    if (LZ4F_isError(r) != 0 || dst != size) throw std::runtime_error("lz4");
    return out;
  }
  throw std::runtime_error("unknown compression " + how);
}

Bytes slurp(const std::filesystem::path& p) {
  std::ifstream f(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(f), {}};
}

// Parses and checks everything the specification lets a reader check; EXPECTs on the way.
Read read_mcap(const Bytes& b) {
  static const Bytes magic{0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'};
  Read out;
  EXPECT_GE(b.size(), 8U + 8U + 29U);
  EXPECT_TRUE(std::equal(magic.begin(), magic.end(), b.begin()));
  EXPECT_TRUE(std::equal(magic.begin(), magic.end(), b.end() - 8));
  // Footer: the last record before the closing magic (opcode + length 20 + 20 bytes).
  Cursor f{b, b.size() - 8 - 29, b.size() - 8};
  EXPECT_EQ(f.u8(), 0x02);
  EXPECT_EQ(f.u64(), 20U);
  const std::uint64_t summary_start = f.u64(), summary_offset_start = f.u64();
  const std::uint32_t summary_crc = f.u32();
  EXPECT_EQ(crc32(std::span(b.data() + summary_start, b.size() - 8 - 4 - summary_start)),
            summary_crc);

  // Data section.
  Cursor c{b, 8, static_cast<std::size_t>(summary_start)};
  std::map<std::uint64_t, std::pair<std::uint64_t, std::string>> chunks;  // offset -> len, comp
  std::map<std::uint64_t, std::uint16_t> message_indexes;                 // offset -> channel
  bool data_end = false;
  std::vector<std::pair<std::uint64_t, Bytes>> chunk_records;  // offset, uncompressed records
  while (c.pos < c.end) {
    const std::size_t start = c.pos;
    const std::uint8_t op = c.u8();
    const std::uint64_t len = c.u64();
    const std::size_t body = c.pos;
    Cursor r{b, body, body + len};
    if (op == 0x01) {
      out.profile = r.str();
      EXPECT_EQ(r.str(), "voronav");
    } else if (op == 0x06) {
      const std::uint64_t t0 = r.u64(), t1 = r.u64(), size = r.u64();
      const std::uint32_t crc = r.u32();
      const std::string comp = r.str();
      out.compressions.insert(comp);
      const std::uint64_t n = r.u64();
      Bytes packed(b.begin() + static_cast<std::ptrdiff_t>(r.pos),
                   b.begin() + static_cast<std::ptrdiff_t>(r.pos + n));
      const Bytes recs = decompress(comp, packed, size);
      EXPECT_EQ(crc32(recs), crc) << "chunk at " << start;
      EXPECT_LE(t0, t1);
      chunks[start] = {9 + len, comp};
      chunk_records.emplace_back(start, recs);
      // Records inside the chunk.
      Cursor in{recs, 0, recs.size()};
      while (in.pos < in.end) {
        const std::uint8_t iop = in.u8();
        const std::uint64_t ilen = in.u64();
        Cursor ir{recs, in.pos, in.pos + ilen};
        if (iop == 0x03) {
          const std::uint16_t id = ir.u16();
          const std::string name = ir.str();
          EXPECT_EQ(ir.str(), "ros2msg");
          out.schemas[id] = {name, ir.str()};
        } else if (iop == 0x04) {
          const std::uint16_t id = ir.u16();
          EXPECT_TRUE(out.schemas.count(ir.u16()));
          out.channels[id] = ir.str();
          out.channel_encoding[id] = ir.str();
        } else if (iop == 0x05) {
          Message m;
          m.channel = ir.u16();
          EXPECT_TRUE(out.channels.count(m.channel)) << "message before its channel";
          m.sequence = ir.u32();
          m.log_time = ir.u64();
          m.publish_time = ir.u64();
          EXPECT_GE(m.log_time, t0);
          EXPECT_LE(m.log_time, t1);
          m.data.assign(recs.begin() + static_cast<std::ptrdiff_t>(ir.pos),
                        recs.begin() + static_cast<std::ptrdiff_t>(ir.end));
          out.messages.push_back(std::move(m));
        } else {
          ADD_FAILURE() << "unexpected record " << int(iop) << " in a chunk";
        }
        in.pos += ilen;
      }
    } else if (op == 0x07) {
      const std::uint16_t channel = r.u16();
      message_indexes[start] = channel;
      const std::uint32_t n = r.u32();
      EXPECT_EQ(n % 16, 0U);
      // Every entry points at a message record of this channel with this log time.
      const Bytes& recs = chunk_records.back().second;
      std::uint64_t prev = 0;
      for (std::uint32_t k = 0; k < n / 16; ++k) {
        const std::uint64_t t = r.u64(), off = r.u64();
        EXPECT_GE(t, prev);
        prev = t;
        Cursor m{recs, static_cast<std::size_t>(off), recs.size()};
        EXPECT_EQ(m.u8(), 0x05);
        m.u64();
        EXPECT_EQ(m.u16(), channel);
        m.u32();
        EXPECT_EQ(m.u64(), t);
      }
    } else if (op == 0x0F) {
      EXPECT_EQ(r.u32(), crc32(std::span(b.data(), start))) << "data section CRC";
      data_end = true;
    } else {
      ADD_FAILURE() << "unexpected record " << int(op) << " in the data section";
    }
    c.pos = body + len;
  }
  EXPECT_TRUE(data_end);

  // Summary section.
  Cursor s{b, static_cast<std::size_t>(summary_start),
           static_cast<std::size_t>(summary_offset_start)};
  std::map<std::uint8_t, std::pair<std::uint64_t, std::uint64_t>> groups;
  while (s.pos < s.end) {
    const std::size_t start = s.pos;
    const std::uint8_t op = s.u8();
    const std::uint64_t len = s.u64();
    Cursor r{b, s.pos, s.pos + len};
    if (groups.empty() || groups.rbegin()->first != op) {
      if (groups.count(op) == 0) groups[op] = {start, 0};
    }
    groups[op].second = s.pos + len - groups[op].first;
    if (op == 0x03) {
      const std::uint16_t id = r.u16();
      EXPECT_EQ(out.schemas.at(id).first, r.str());
      r.str();
      EXPECT_EQ(out.schemas.at(id).second, r.str());
    } else if (op == 0x04) {
      const std::uint16_t id = r.u16();
      r.u16();
      EXPECT_EQ(out.channels.at(id), r.str());
    } else if (op == 0x0B) {
      out.stat_messages = r.u64();
      EXPECT_EQ(r.u16(), out.schemas.size());
      EXPECT_EQ(r.u32(), out.channels.size());
      r.u32();
      r.u32();
      out.stat_chunks = r.u32();
      r.u64();
      r.u64();
      const std::uint32_t n = r.u32();
      for (std::uint32_t k = 0; k < n / 10; ++k) {
        const std::uint16_t ch = r.u16();
        out.stat_counts[ch] = r.u64();
      }
    } else if (op == 0x08) {
      ++out.chunk_indexes;
      r.u64();
      r.u64();
      const std::uint64_t off = r.u64(), len2 = r.u64();
      EXPECT_EQ(chunks.at(off).first, len2);
      const std::uint32_t n = r.u32();
      for (std::uint32_t k = 0; k < n / 10; ++k) {
        const std::uint16_t ch = r.u16();
        EXPECT_EQ(message_indexes.at(r.u64()), ch);
      }
      r.u64();
      EXPECT_EQ(r.str(), chunks.at(off).second);
    } else {
      ADD_FAILURE() << "unexpected record " << int(op) << " in the summary";
    }
    s.pos += len;
  }
  // Summary offsets point at the groups.
  Cursor so{b, static_cast<std::size_t>(summary_offset_start), b.size() - 8 - 29};
  std::size_t offsets = 0;
  while (so.pos < so.end) {
    EXPECT_EQ(so.u8(), 0x0E);
    EXPECT_EQ(so.u64(), 17U);
    const std::uint8_t op = so.u8();
    EXPECT_EQ(so.u64(), groups.at(op).first);
    EXPECT_EQ(so.u64(), groups.at(op).second);
    ++offsets;
  }
  EXPECT_EQ(offsets, groups.size());
  EXPECT_EQ(out.stat_messages, out.messages.size());
  EXPECT_EQ(out.stat_chunks, chunks.size());
  EXPECT_EQ(out.chunk_indexes, chunks.size());
  return out;
}

// ---- a minimal CDR reader (test only) ----------------------------------------------------------

struct CdrIn {
  const Bytes& b;
  std::size_t pos = 4;
  void align(std::size_t n) { pos += (n - (pos - 4) % n) % n; }
  template <typename T>
  T get() {
    align(sizeof(T));
    T v;
    std::memcpy(&v, b.data() + pos, sizeof(T));
    pos += sizeof(T);
    return v;
  }
  std::string str() {
    const auto n = get<std::uint32_t>();
    std::string s(b.begin() + static_cast<std::ptrdiff_t>(pos),
                  b.begin() + static_cast<std::ptrdiff_t>(pos + n - 1));
    EXPECT_EQ(b[pos + n - 1], 0);
    pos += n;
    return s;
  }
};

std::filesystem::path tmp(const std::string& name) {
  return std::filesystem::temp_directory_path() /
         ("voronav_bag_" + std::to_string(::getpid()) + "_" + name);
}

// ---- tests ------------------------------------------------------------------------------------

TEST(Crc32, CheckValue) {
  const std::string s = "123456789";
  EXPECT_EQ(crc32(std::span(reinterpret_cast<const std::uint8_t*>(s.data()), s.size())),
            0xCBF43926U);
  // Incremental equals one-shot.
  const auto* p = reinterpret_cast<const std::uint8_t*>(s.data());
  EXPECT_EQ(crc32(std::span(p + 4, 5), crc32(std::span(p, 4))), 0xCBF43926U);
}

TEST(Cdr, StringHasEncapsulationHeaderLengthWithNulAndNul) {
  const Bytes b = ros::encode(ros::StringMsg{"hi"});
  EXPECT_EQ(b, (Bytes{0x00, 0x01, 0x00, 0x00, 3, 0, 0, 0, 'h', 'i', 0}));
}

TEST(Cdr, AlignmentCountsFromAfterTheHeader) {
  // PoseArray, stamp (8 bytes) + frame "ab" (4 + 3 bytes) ends at 15: the uint32 count pads to
  // 16, the first float64 pads from 20 to 24.
  ros::PoseArrayMsg m;
  m.header = {{1, 2}, "ab"};
  m.poses.push_back(ros::Pose::from({{1.5, -2.0}, 0.0}));
  const Bytes b = ros::encode(m);
  ASSERT_EQ(b.size(), 4U + 24U + 56U);
  EXPECT_EQ(b[4 + 15], 0);  // padding
  EXPECT_EQ(b[4 + 16], 1);  // count = 1
  for (int k = 20; k < 24; ++k)
    EXPECT_EQ(b[static_cast<std::size_t>(4 + k)], 0);
  double x = 0;
  std::memcpy(&x, b.data() + 4 + 24, 8);
  EXPECT_EQ(x, 1.5);
  double w = 0;
  std::memcpy(&w, b.data() + 4 + 24 + 48, 8);
  EXPECT_EQ(w, 1.0);  // identity rotation
}

TEST(Ros2Time, FromSeconds) {
  EXPECT_EQ(ros::Time::from_seconds(1.25).sec, 1);
  EXPECT_EQ(ros::Time::from_seconds(1.25).nanosec, 250000000U);
  EXPECT_EQ(ros::Time::from_seconds(-3.0).sec, 0);  // clamped
  EXPECT_EQ(ros::Time::from_seconds(1e12).sec, 2147483647);
  const auto q = ros::Quaternion::from_yaw(std::numbers::pi / 2);
  EXPECT_NEAR(q.z, std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(q.w, std::sqrt(0.5), 1e-15);
}

TEST(Cdr, OccupancyGridFields) {
  OccupancyGrid g(GridGeometry{3, 2, 0.25, {{-1.0, 2.0}, 0.0}}, kFree);
  g[Cell{2, 1}] = kOccupied;
  g[Cell{0, 0}] = kUnknown;
  const Bytes b = ros::encode(ros::OccupancyGridMsg::from(g, ros::Time::from_seconds(1.5)));
  CdrIn in{b};
  EXPECT_EQ(in.get<std::int32_t>(), 1);
  EXPECT_EQ(in.get<std::uint32_t>(), 500000000U);
  EXPECT_EQ(in.str(), "map");
  in.get<std::int32_t>();
  in.get<std::uint32_t>();
  EXPECT_EQ(in.get<float>(), 0.25F);
  EXPECT_EQ(in.get<std::uint32_t>(), 3U);
  EXPECT_EQ(in.get<std::uint32_t>(), 2U);
  EXPECT_EQ(in.get<double>(), -1.0);
  EXPECT_EQ(in.get<double>(), 2.0);
  for (int k = 0; k < 5; ++k)
    in.get<double>();
  ASSERT_EQ(in.get<std::uint32_t>(), 6U);
  EXPECT_EQ(static_cast<std::int8_t>(b[in.pos]), kUnknown);
  EXPECT_EQ(static_cast<std::int8_t>(b[in.pos + 5]), kOccupied);
  EXPECT_EQ(in.pos + 6, b.size());
}

TEST(Ros2Msg, DefinitionsCarryEveryDependencyOnce) {
  const std::string d = ros::definition("nav_msgs/msg/OccupancyGrid");
  EXPECT_EQ(d.rfind("std_msgs/Header header\n", 0), 0U);
  for (const char* dep :
       {"std_msgs/Header", "builtin_interfaces/Time", "nav_msgs/MapMetaData", "geometry_msgs/Pose",
        "geometry_msgs/Point", "geometry_msgs/Quaternion"}) {
    const std::string line = std::string("\nMSG: ") + dep + "\n";
    const auto at = d.find(line);
    EXPECT_NE(at, std::string::npos) << dep;
    EXPECT_EQ(d.find(line, at + 1), std::string::npos) << dep;
    EXPECT_EQ(d.substr(at - 80, 80), std::string(80, '='));
  }
  EXPECT_NE(ros::definition("visualization_msgs/msg/MarkerArray").find("MSG: std_msgs/ColorRGBA"),
            std::string::npos);
  EXPECT_THROW((void)ros::definition("sensor_msgs/msg/Image"), Error);
}

class McapRoundTrip : public ::testing::TestWithParam<Compression> {};

TEST_P(McapRoundTrip, RecordsCrcsAndIndexes) {
  const auto file = tmp("rt.mcap");
  {
    McapOptions o;
    o.compression = GetParam();
    o.chunk_size = 300;  // several chunks
    McapWriter w(file, o);
    const auto s =
        w.add_schema("std_msgs/msg/String", "ros2msg", ros::definition("std_msgs/String"));
    const auto a = w.add_channel(s, "/a", "cdr");
    const auto b = w.add_channel(s, "/b", "cdr", {{"k", "v"}});
    for (int i = 0; i < 40; ++i) {
      const auto data = ros::encode(ros::StringMsg{"message " + std::to_string(i)});
      // out of order inside a chunk on purpose: the index is sorted, the chunk range covers it
      w.write(i % 3 == 0 ? b : a, static_cast<std::uint64_t>(1000 * (i ^ 1)), 7, data);
    }
    w.close();
  }
  const Read r = read_mcap(slurp(file));
  EXPECT_EQ(r.profile, "ros2");
  ASSERT_EQ(r.messages.size(), 40U);
  EXPECT_EQ(r.stat_counts.at(1), 14U);
  EXPECT_EQ(r.stat_counts.at(0), 26U);
  EXPECT_GT(r.stat_chunks, 2U);
  EXPECT_EQ(r.compressions, std::set<std::string>{mcap_compression_name(GetParam())});
  for (int i = 0; i < 40; ++i) {
    const Message& m = r.messages[static_cast<std::size_t>(i)];
    EXPECT_EQ(m.log_time, static_cast<std::uint64_t>(1000 * (i ^ 1)));
    EXPECT_EQ(m.publish_time, 7U);
    CdrIn in{m.data};
    EXPECT_EQ(in.str(), "message " + std::to_string(i));
  }
  // Sequence numbers count per channel.
  EXPECT_EQ(r.messages[3].sequence, 1U);
  std::filesystem::remove(file);
}

INSTANTIATE_TEST_SUITE_P(Compressions, McapRoundTrip,
                         ::testing::Values(Compression::kNone, Compression::kZstd,
                                           Compression::kLz4));

TEST(McapWriter, EmptyFileIsValid) {
  const auto file = tmp("empty.mcap");
  { McapWriter w(file); }
  const Read r = read_mcap(slurp(file));
  EXPECT_TRUE(r.messages.empty());
  std::filesystem::remove(file);
}

TEST(McapWriter, UnwritableFileNamesIt) {
  try {
    McapWriter w("/nonexistent-dir/x.mcap");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-dir/x.mcap"), std::string::npos);
  }
  EXPECT_THROW(RosBagWriter("/nonexistent-dir/y.mcap"), Error);
  EXPECT_THROW((void)parse_compression("gzip"), Error);
}

TEST(RunBag, TopicsTimesAndValuesOfARecording) {
  report::Recording rec;
  rec.map = OccupancyGrid(GridGeometry{10, 8, 0.5, {{-2.0, -1.0}, 0.0}}, kFree);
  report::RobotTrack r1{1, "", 0.2, "", {{0.0, {{0.0, 0.0}, 0.0}}, {2.0, {{2.0, 0.0}, 0.0}}}};
  report::RobotTrack r2{2, "", 0.2, "", {{1.0, {{0.0, 1.0}, 1.0}}}};
  rec.robots = {r1, r2};
  rec.paths.push_back({1, 0.0, "route", {{0.0, 0.0}, {1.0, 0.0}, {2.0, 0.0}}});
  rec.messages.push_back({0.5, 1, 2, "Search", 20});
  rec.obstacle_changes.push_back({1.5, {Cell{3, 3}}, kOccupied});
  rec.graphs.push_back(
      {"Topological graph", "#1f77b4", true, {{0, {0, 0}, "R0"}, {1, {1, 1}, ""}}, {{0, 1}}});
  BagExtras extras;
  extras.events.push_back({1.0, "kill", "robot 2"});
  const auto file = tmp("run.mcap");
  const auto counts = write_run_bag(rec, file, extras);
  EXPECT_EQ(counts.at("/map"), 2U);
  EXPECT_EQ(counts.at("/tf"), 3U);  // t = 0, 1, 2
  EXPECT_EQ(counts.at("/robots"), 3U);
  EXPECT_EQ(counts.at("/plan"), 1U);
  EXPECT_EQ(counts.at("/robot_1/plan"), 1U);
  EXPECT_EQ(counts.at("/messages"), 1U);
  EXPECT_EQ(counts.at("/topology"), 1U);
  EXPECT_EQ(counts.at("/events"), 3U);  // route, obstacle change, kill
  const Read r = read_mcap(slurp(file));
  std::uint64_t prev = 0;
  std::map<std::string, int> seen;
  for (const auto& m : r.messages) {
    EXPECT_GE(m.log_time, prev);
    prev = m.log_time;
    const std::string& topic = r.channels.at(m.channel);
    EXPECT_EQ(r.channel_encoding.at(m.channel), "cdr");
    ++seen[topic];
    CdrIn in{m.data};
    if (topic == "/tf") {
      ASSERT_EQ(in.get<std::uint32_t>(), 2U);
      in.get<std::int32_t>();
      in.get<std::uint32_t>();
      EXPECT_EQ(in.str(), "map");
      EXPECT_EQ(in.str(), "robot_1/base_link");
      const double x = in.get<double>();
      EXPECT_NEAR(x, static_cast<double>(m.log_time) * 1e-9, 1e-9);  // 1 m/s along x
    }
    if (topic == "/map" && seen[topic] == 2) {
      EXPECT_EQ(m.log_time, 1500000000U);
      EXPECT_EQ(static_cast<std::int8_t>(m.data[m.data.size() - 80 + 3 * 10 + 3]), kOccupied);
    }
  }
  EXPECT_EQ(r.schemas.size(), 6U);  // grid, path, tf, pose array, marker array, string
  for (const auto& [id, s] : r.schemas)
    EXPECT_EQ(s.second, ros::definition(s.first));
  std::filesystem::remove(file);
}

TEST(RunBag, KnownMapSeriesGrowsWithTheRevealTimes) {
  // 2 x 2: cell 0 seen at 0 s, cells 1 and 2 at 1 s, cell 3 never; sampled every 1 s up to 3 s.
  OccupancyGrid final_map(GridGeometry{2, 2, 1.0, {}}, kFree);
  final_map[Cell{1, 0}] = kOccupied;
  const std::vector<float> reveal = {0.0F, 1.0F, 1.0F, -1.0F};
  const auto s = known_map_series(final_map, reveal, 3.0, 1.0);
  ASSERT_EQ(s.size(), 2U);  // t = 0 (1 cell), t = 1 (3 cells); nothing new at 2 and 3
  EXPECT_DOUBLE_EQ(s[0].first, 0.0);
  EXPECT_DOUBLE_EQ(s[1].first, 1.0);
  const auto known = [](const OccupancyGrid& g) {
    int n = 0;
    for (std::size_t i = 0; i < g.size(); ++i)
      n += g[g.cell_at(i)] != kUnknown ? 1 : 0;
    return n;
  };
  EXPECT_EQ(known(s[0].second), 1);
  EXPECT_EQ(known(s[1].second), 3);
  EXPECT_EQ((s[1].second[Cell{1, 0}]), kOccupied);
  EXPECT_EQ((s[1].second[Cell{1, 1}]), kUnknown);
  // A cell seen at 2.5 s: the last sample (at the end, 3 s) shows it.
  const auto late = known_map_series(final_map, {0.0F, 1.0F, 1.0F, 2.5F}, 3.0, 1.0);
  ASSERT_EQ(late.size(), 3U);
  EXPECT_DOUBLE_EQ(late.back().first, 3.0);
  EXPECT_EQ(known(late.back().second), 4);
  // At most max_snapshots: the period widens to (3 - 0) / (2 - 1) = 3 s.
  const auto two = known_map_series(final_map, {0.0F, 1.0F, 1.0F, 2.5F}, 3.0, 0.1, 2);
  ASSERT_EQ(two.size(), 2U);
  EXPECT_DOUBLE_EQ(two[1].first, 3.0);
  EXPECT_THROW((void)known_map_series(final_map, {0.0F}, 3.0, 1.0), Error);
  EXPECT_THROW((void)known_map_series(final_map, reveal, 3.0, 0.0), Error);
  EXPECT_TRUE(known_map_series(final_map, {-1.0F, -1.0F, -1.0F, -1.0F}, 3.0, 1.0).empty());
}

}  // namespace
}  // namespace voronav::bag
