#include "voronav/bag/mcap_writer.hpp"

#include <lz4frame.h>
#include <zstd.h>

#include <algorithm>
#include <limits>

#include "voronav/bag/crc32.hpp"
#include "voronav/core/error.hpp"

namespace voronav::bag {
namespace {

constexpr std::uint8_t kMagic[8] = {0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'};

/// Little-endian record builder.
struct Buf {
  std::vector<std::uint8_t> b;
  void u8(std::uint8_t v) { b.push_back(v); }
  void u16(std::uint16_t v) { le(v, 2); }
  void u32(std::uint32_t v) { le(v, 4); }
  void u64(std::uint64_t v) { le(v, 8); }
  void le(std::uint64_t v, int n) {
    for (int i = 0; i < n; ++i)
      b.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
  }
  void bytes(std::span<const std::uint8_t> s) { b.insert(b.end(), s.begin(), s.end()); }
  void str(const std::string& s) {
    u32(static_cast<std::uint32_t>(s.size()));
    b.insert(b.end(), s.begin(), s.end());
  }
  void str_map(const std::map<std::string, std::string>& m) {
    Buf inner;
    for (const auto& [k, v] : m) {
      inner.str(k);
      inner.str(v);
    }
    u32(static_cast<std::uint32_t>(inner.b.size()));
    bytes(inner.b);
  }
};

/// opcode + uint64 length + content.
std::vector<std::uint8_t> record(Op op, const std::vector<std::uint8_t>& content) {
  Buf r;
  r.u8(static_cast<std::uint8_t>(op));
  r.u64(content.size());
  r.bytes(content);
  return std::move(r.b);
}

std::vector<std::uint8_t> compress(Compression c, const std::vector<std::uint8_t>& in) {
  std::vector<std::uint8_t> out;
  if (c == Compression::kZstd) {
    out.resize(ZSTD_compressBound(in.size()));
    const std::size_t n = ZSTD_compress(out.data(), out.size(), in.data(), in.size(), 3);
    if (ZSTD_isError(n) != 0) throw Error(std::string("MCAP: zstd: ") + ZSTD_getErrorName(n));
    out.resize(n);
  } else if (c == Compression::kLz4) {
    out.resize(LZ4F_compressFrameBound(in.size(), nullptr));
    const std::size_t n = LZ4F_compressFrame(out.data(), out.size(), in.data(), in.size(), nullptr);
    if (LZ4F_isError(n) != 0) throw Error(std::string("MCAP: lz4: ") + LZ4F_getErrorName(n));
    out.resize(n);
  } else {
    out = in;
  }
  return out;
}

}  // namespace

Compression parse_compression(const std::string& name) {
  if (name == "none") return Compression::kNone;
  if (name == "zstd") return Compression::kZstd;
  if (name == "lz4") return Compression::kLz4;
  throw Error("compression", 0, "expected none, zstd or lz4, got '" + name + "'");
}

const char* mcap_compression_name(Compression c) {
  return c == Compression::kZstd ? "zstd" : c == Compression::kLz4 ? "lz4" : "";
}

McapWriter::McapWriter(const std::filesystem::path& file, McapOptions options)
    : path_(file), out_(file, std::ios::binary | std::ios::trunc), opt_(std::move(options)) {
  if (!out_) throw Error(file.string(), 0, "cannot open for writing");
  put(kMagic);
  Buf h;
  h.str(opt_.profile);
  h.str("voronav");
  put(record(Op::kHeader, h.b));
}

McapWriter::~McapWriter() {
  try {
    close();
  } catch (...) {  // NOLINT(bugprone-empty-catch): destructors must not throw
  }
}

void McapWriter::put(std::span<const std::uint8_t> bytes) {
  out_.write(reinterpret_cast<const char*>(bytes.data()),
             static_cast<std::streamsize>(bytes.size()));
  if (!out_) throw Error(path_.string(), 0, "write failed");
  offset_ += bytes.size();
  data_crc_ = crc32(bytes, data_crc_);
}

std::uint16_t McapWriter::add_schema(const std::string& name, const std::string& encoding,
                                     const std::string& data) {
  if (schemas_.size() >= std::numeric_limits<std::uint16_t>::max() - 1)
    throw Error("MCAP: too many schemas");
  const auto id = static_cast<std::uint16_t>(schemas_.size() + 1);
  schemas_.push_back({id, name, encoding, data});
  Buf s;
  s.u16(id);
  s.str(name);
  s.str(encoding);
  s.str(data);  // uint32 length + bytes, the same layout as a string
  const auto rec = record(Op::kSchema, s.b);
  chunk_.insert(chunk_.end(), rec.begin(), rec.end());
  return id;
}

std::uint16_t McapWriter::add_channel(std::uint16_t schema_id, const std::string& topic,
                                      const std::string& message_encoding,
                                      const std::map<std::string, std::string>& metadata) {
  if (schema_id == 0 || schema_id > schemas_.size())
    throw Error("MCAP: channel '" + topic + "' names unknown schema " + std::to_string(schema_id));
  if (channels_.size() >= std::numeric_limits<std::uint16_t>::max())
    throw Error("MCAP: too many channels");
  const auto id = static_cast<std::uint16_t>(channels_.size());
  channels_.push_back({id, schema_id, topic, message_encoding, metadata});
  Buf c;
  c.u16(id);
  c.u16(schema_id);
  c.str(topic);
  c.str(message_encoding);
  c.str_map(metadata);
  const auto rec = record(Op::kChannel, c.b);
  chunk_.insert(chunk_.end(), rec.begin(), rec.end());
  channel_counts_[id];
  return id;
}

void McapWriter::write(std::uint16_t channel_id, std::uint64_t log_time, std::uint64_t publish_time,
                       std::span<const std::uint8_t> data) {
  if (closed_) throw Error(path_.string(), 0, "MCAP: write after close");
  if (channel_id >= channels_.size())
    throw Error("MCAP: message on unknown channel " + std::to_string(channel_id));
  Buf m;
  m.u16(channel_id);
  m.u32(sequence_[channel_id]++);
  m.u64(log_time);
  m.u64(publish_time);
  m.bytes(data);
  chunk_index_[channel_id].emplace_back(log_time, chunk_.size());
  const auto rec = record(Op::kMessage, m.b);
  chunk_.insert(chunk_.end(), rec.begin(), rec.end());
  chunk_start_ = chunk_has_messages_ ? std::min(chunk_start_, log_time) : log_time;
  chunk_end_ = chunk_has_messages_ ? std::max(chunk_end_, log_time) : log_time;
  chunk_has_messages_ = true;
  start_ = message_count_ == 0 ? log_time : std::min(start_, log_time);
  end_ = message_count_ == 0 ? log_time : std::max(end_, log_time);
  ++message_count_;
  ++channel_counts_[channel_id];
  if (chunk_.size() >= opt_.chunk_size) flush_chunk();
}

void McapWriter::flush_chunk() {
  if (chunk_.empty()) return;
  const std::uint64_t chunk_offset = offset_;
  const std::vector<std::uint8_t> packed = compress(opt_.compression, chunk_);
  Buf c;
  c.u64(chunk_start_);
  c.u64(chunk_end_);
  c.u64(chunk_.size());
  c.u32(crc32(chunk_));
  c.str(mcap_compression_name(opt_.compression));
  c.u64(packed.size());
  c.bytes(packed);
  const auto chunk_rec = record(Op::kChunk, c.b);
  put(chunk_rec);
  const std::uint64_t index_start = offset_;
  std::map<std::uint16_t, std::uint64_t> index_offsets;
  for (auto& [channel, entries] : chunk_index_) {
    std::stable_sort(entries.begin(), entries.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    Buf mi;
    mi.u16(channel);
    mi.u32(static_cast<std::uint32_t>(entries.size() * 16));
    for (const auto& [t, off] : entries) {
      mi.u64(t);
      mi.u64(off);
    }
    index_offsets[channel] = offset_;
    put(record(Op::kMessageIndex, mi.b));
  }
  Buf ci;
  ci.u64(chunk_start_);
  ci.u64(chunk_end_);
  ci.u64(chunk_offset);
  ci.u64(chunk_rec.size());
  Buf offsets;
  for (const auto& [channel, off] : index_offsets) {
    offsets.u16(channel);
    offsets.u64(off);
  }
  ci.u32(static_cast<std::uint32_t>(offsets.b.size()));
  ci.bytes(offsets.b);
  ci.u64(offset_ - index_start);
  ci.str(mcap_compression_name(opt_.compression));
  ci.u64(packed.size());
  ci.u64(chunk_.size());
  chunk_indexes_.push_back(record(Op::kChunkIndex, ci.b));
  chunk_.clear();
  chunk_index_.clear();
  chunk_has_messages_ = false;
  chunk_start_ = chunk_end_ = 0;
}

void McapWriter::close() {
  if (closed_) return;
  closed_ = true;
  flush_chunk();
  Buf de;
  de.u32(data_crc_);
  put(record(Op::kDataEnd, de.b));

  // Summary section: one group per record kind, each noted in a Summary Offset record.
  const std::uint64_t summary_start = offset_;
  data_crc_ = 0;  // from here on: the summary CRC
  std::vector<std::uint8_t> offsets;
  auto group = [&](Op op, const std::vector<std::vector<std::uint8_t>>& records) {
    if (records.empty()) return;
    const std::uint64_t start = offset_;
    for (const auto& r : records)
      put(r);
    Buf so;
    so.u8(static_cast<std::uint8_t>(op));
    so.u64(start);
    so.u64(offset_ - start);
    const auto rec = record(Op::kSummaryOffset, so.b);
    offsets.insert(offsets.end(), rec.begin(), rec.end());
  };
  std::vector<std::vector<std::uint8_t>> recs;
  for (const auto& s : schemas_) {
    Buf b;
    b.u16(s.id);
    b.str(s.name);
    b.str(s.encoding);
    b.str(s.data);
    recs.push_back(record(Op::kSchema, b.b));
  }
  group(Op::kSchema, recs);
  recs.clear();
  for (const auto& c : channels_) {
    Buf b;
    b.u16(c.id);
    b.u16(c.schema_id);
    b.str(c.topic);
    b.str(c.encoding);
    b.str_map(c.metadata);
    recs.push_back(record(Op::kChannel, b.b));
  }
  group(Op::kChannel, recs);
  Buf st;
  st.u64(message_count_);
  st.u16(static_cast<std::uint16_t>(schemas_.size()));
  st.u32(static_cast<std::uint32_t>(channels_.size()));
  st.u32(0);  // attachments
  st.u32(0);  // metadata
  st.u32(static_cast<std::uint32_t>(chunk_indexes_.size()));
  st.u64(start_);
  st.u64(end_);
  Buf counts;
  for (const auto& [channel, n] : channel_counts_) {
    counts.u16(channel);
    counts.u64(n);
  }
  st.u32(static_cast<std::uint32_t>(counts.b.size()));
  st.bytes(counts.b);
  group(Op::kStatistics, {record(Op::kStatistics, st.b)});
  group(Op::kChunkIndex, chunk_indexes_);
  const std::uint64_t summary_offset_start = offset_;
  put(offsets);
  Buf f;
  f.u8(static_cast<std::uint8_t>(Op::kFooter));
  f.u64(8 + 8 + 4);
  f.u64(summary_start);
  f.u64(summary_offset_start);
  put(f.b);  // the summary CRC covers the footer up to and including summary_offset_start
  Buf crc;
  crc.u32(data_crc_);
  put(crc.b);
  put(kMagic);
  out_.close();
  if (!out_) throw Error(path_.string(), 0, "MCAP: closing the file failed");
}

}  // namespace voronav::bag
