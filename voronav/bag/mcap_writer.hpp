// McapWriter: writes an MCAP file (https://mcap.dev/spec, version 0) from the specification:
// magic, Header, Schema/Channel/Message records grouped into Chunks (zstd, lz4 frame or no
// compression) each followed by its Message Index records, Data End with the data-section CRC,
// then the summary section (Schemas, Channels, Statistics, Chunk Indexes), Summary Offsets and
// the Footer with the summary CRC, and the closing magic. Messages may come in any order; each
// chunk records its own time range. Times are uint64 nanoseconds (voronav: simulated time).
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <span>
#include <string>
#include <vector>

namespace voronav::bag {

enum class Compression { kNone, kZstd, kLz4 };

/// "none", "zstd" or "lz4"; throws voronav::Error for anything else.
[[nodiscard]] Compression parse_compression(const std::string& name);
/// The MCAP compression string: "", "zstd" or "lz4".
[[nodiscard]] const char* mcap_compression_name(Compression c);

struct McapOptions {
  std::string profile = "ros2";
  Compression compression = Compression::kZstd;
  std::size_t chunk_size = 1U << 20;  ///< uncompressed bytes per chunk before it is closed
};

/// MCAP record opcodes (specification, "Records").
enum class Op : std::uint8_t {
  kHeader = 0x01,
  kFooter = 0x02,
  kSchema = 0x03,
  kChannel = 0x04,
  kMessage = 0x05,
  kChunk = 0x06,
  kMessageIndex = 0x07,
  kChunkIndex = 0x08,
  kStatistics = 0x0B,
  kSummaryOffset = 0x0E,
  kDataEnd = 0x0F
};

class McapWriter {
 public:
  /// Opens `file` for writing (throws voronav::Error naming it when that fails) and writes the
  /// magic and the Header record.
  McapWriter(const std::filesystem::path& file, McapOptions options = {});
  McapWriter(const McapWriter&) = delete;
  McapWriter& operator=(const McapWriter&) = delete;
  /// Closes the file if close() was not called (errors are swallowed there; call close()).
  ~McapWriter();

  /// Registers a schema (e.g. "nav_msgs/msg/Path", "ros2msg", definition); returns its id (>= 1).
  std::uint16_t add_schema(const std::string& name, const std::string& encoding,
                           const std::string& data);
  /// Registers a channel on `topic` with `schema_id`; returns its id.
  std::uint16_t add_channel(std::uint16_t schema_id, const std::string& topic,
                            const std::string& message_encoding,
                            const std::map<std::string, std::string>& metadata = {});
  /// Writes one message; log and publish time in nanoseconds.
  void write(std::uint16_t channel_id, std::uint64_t log_time, std::uint64_t publish_time,
             std::span<const std::uint8_t> data);
  /// Flushes the open chunk and writes the summary and footer. Idempotent.
  void close();

 private:
  struct Schema {
    std::uint16_t id;
    std::string name, encoding, data;
  };
  struct Channel {
    std::uint16_t id, schema_id;
    std::string topic, encoding;
    std::map<std::string, std::string> metadata;
  };
  void put(std::span<const std::uint8_t> bytes);
  void flush_chunk();

  std::filesystem::path path_;
  std::ofstream out_;
  McapOptions opt_;
  bool closed_ = false;
  std::uint64_t offset_ = 0;    // bytes written so far
  std::uint32_t data_crc_ = 0;  // CRC of everything written so far
  std::vector<Schema> schemas_;
  std::vector<Channel> channels_;
  std::map<std::uint16_t, std::uint32_t> sequence_;
  std::map<std::uint16_t, std::uint64_t> channel_counts_;
  std::uint64_t message_count_ = 0, start_ = 0, end_ = 0;
  // the open chunk
  std::vector<std::uint8_t> chunk_;
  std::map<std::uint16_t, std::vector<std::pair<std::uint64_t, std::uint64_t>>> chunk_index_;
  std::uint64_t chunk_start_ = 0, chunk_end_ = 0;
  bool chunk_has_messages_ = false;
  std::vector<std::vector<std::uint8_t>> chunk_indexes_;  // encoded Chunk Index records
};

}  // namespace voronav::bag
