#include "voronav/network/messages.hpp"

#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <string>
#include <type_traits>

#include "voronav/core/error.hpp"

namespace voronav::network {

std::string_view to_string(MessageType t) {
  switch (t) {
    case MessageType::kSearch:
      return "search";
    case MessageType::kPath:
      return "path";
    case MessageType::kRepair:
      return "repair";
    case MessageType::kRequest:
      return "request";
    case MessageType::kAck:
      return "ack";
    case MessageType::kNotify:
      return "notify";
    case MessageType::kLinkAck:
      return "link_ack";
  }
  return "unknown";
}

namespace {

constexpr std::size_t kMaxCount = 1u << 24;  // sanity bound on any element count

class Writer {
 public:
  void u8(std::uint8_t v) { out_.push_back(v); }
  void u16(std::uint16_t v) {
    for (int i = 0; i < 2; ++i)
      out_.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
  }
  void u32(std::uint32_t v) {
    for (int i = 0; i < 4; ++i)
      out_.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
  }
  void u64(std::uint64_t v) {
    for (int i = 0; i < 8; ++i)
      out_.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
  }
  void f32(float v) {
    if (!std::isfinite(v)) throw Error("message", 0, "cannot encode a non-finite number");
    u32(std::bit_cast<std::uint32_t>(v));
  }
  void f64(double v) {
    if (!std::isfinite(v)) throw Error("message", 0, "cannot encode a non-finite number");
    u64(std::bit_cast<std::uint64_t>(v));
  }
  void vec(Vec2 v) {
    f32(static_cast<float>(v.x));
    f32(static_cast<float>(v.y));
  }
  void id(RobotId r) { u32(r.value); }
  void count(std::size_t n) {
    if (n > kMaxCount)
      throw Error("message", 0, "too many elements to encode: " + std::to_string(n));
    u32(static_cast<std::uint32_t>(n));
  }
  void ids(const std::vector<RobotId>& v) {
    count(v.size());
    for (RobotId r : v)
      id(r);
  }
  void points(const std::vector<VoronoiPoint>& v) {
    count(v.size());
    for (const auto& p : v) {
      vec(p.position);
      f32(p.clearance);
      f32(p.cost);
    }
  }
  std::vector<std::uint8_t>& bytes() { return out_; }

 private:
  std::vector<std::uint8_t> out_;
};

class Reader {
 public:
  Reader(std::span<const std::uint8_t> b, std::size_t begin, std::size_t end)
      : b_(b), pos_(begin), end_(end) {}
  [[noreturn]] void fail(const std::string& what) const {
    throw Error("message", 0, "byte " + std::to_string(pos_) + ": " + what);
  }
  void need(std::size_t n, const char* what) const {
    if (end_ - pos_ < n) fail(std::string("truncated ") + what);
  }
  std::uint8_t u8(const char* what) {
    need(1, what);
    return b_[pos_++];
  }
  std::uint32_t u32(const char* what) {
    need(4, what);
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i)
      v |= static_cast<std::uint32_t>(b_[pos_++]) << (8 * i);
    return v;
  }
  std::uint64_t u64(const char* what) {
    need(8, what);
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i)
      v |= static_cast<std::uint64_t>(b_[pos_++]) << (8 * i);
    return v;
  }
  float f32(const char* what) {
    const float v = std::bit_cast<float>(u32(what));
    if (!std::isfinite(v)) fail(std::string("non-finite ") + what);
    return v;
  }
  double f64(const char* what) {
    const double v = std::bit_cast<double>(u64(what));
    if (!std::isfinite(v)) fail(std::string("non-finite ") + what);
    return v;
  }
  Vec2 vec(const char* what) {
    const double x = f32(what);
    const double y = f32(what);
    return {x, y};
  }
  RobotId id(const char* what) { return RobotId{u32(what)}; }
  std::size_t count(std::size_t element_bytes, const char* what) {
    const std::uint32_t n = u32(what);
    if (n > kMaxCount || static_cast<std::uint64_t>(n) * element_bytes > end_ - pos_)
      fail(std::string("count ") + std::to_string(n) + " of " + what + " exceeds the message");
    return n;
  }
  std::vector<RobotId> ids(const char* what) {
    std::vector<RobotId> v(count(4, what));
    for (auto& r : v)
      r = id(what);
    return v;
  }
  std::vector<VoronoiPoint> points(const char* what) {
    std::vector<VoronoiPoint> v(count(16, what));
    for (auto& p : v) {
      p.position = vec(what);
      p.clearance = f32(what);
      p.cost = f32(what);
      if (p.clearance < 0.0f) fail(std::string("negative clearance in ") + what);
    }
    return v;
  }
  [[nodiscard]] std::size_t pos() const { return pos_; }
  [[nodiscard]] bool done() const { return pos_ == end_; }

 private:
  std::span<const std::uint8_t> b_;
  std::size_t pos_;
  std::size_t end_;
};

std::uint8_t cell_code(std::int8_t v) {
  if (v < 0) return 2;  // unknown
  return v >= 50 ? 1 : 0;
}
std::int8_t code_value(std::uint8_t c) {
  return c == 0 ? kFree : c == 1 ? kOccupied : kUnknown;
}

void encode_payload(Writer& w, const SearchMessage& m) {
  w.id(m.source);
  w.u32(m.num);
  w.vec(m.destination);
  w.ids(m.relays);
  w.points(m.open_points);
  w.count(m.close_points.size());
  for (Vec2 p : m.close_points)
    w.vec(p);
}
void encode_payload(Writer& w, const PathMessage& m) {
  w.id(m.source);
  w.u32(m.num);
  w.ids(m.relays);
  w.points(m.whole_path);
  w.u32(m.exit_index);
  w.ids(m.owners);
  w.ids(m.carriers);
  w.vec(m.toward);
}
void encode_payload(Writer& w, const RepairMessage& m) {
  w.id(m.source);
  w.u32(m.num);
  w.ids(m.relays);
  w.points(m.whole_path);
  w.u32(m.broken_from);
  w.u32(m.broken_to);
  w.count(m.blocked.size());
  for (Vec2 p : m.blocked)
    w.vec(p);
  if (m.hop_limit != 0) w.u8(m.hop_limit);  // optional last byte (0 = not sent)
}
void encode_payload(Writer& w, const RequestMessage& m) {
  w.id(m.source);
  w.u32(m.num);
}
void encode_payload(Writer& w, const AckMessage& m) {
  w.id(m.source);
  w.u32(m.num);
  w.id(m.responder);
  const auto& g = m.local_map.geometry();
  w.u32(static_cast<std::uint32_t>(g.width));
  w.u32(static_cast<std::uint32_t>(g.height));
  w.f64(g.resolution);
  w.f64(g.origin.position.x);
  w.f64(g.origin.position.y);
  w.f64(g.origin.yaw);
  std::uint8_t acc = 0;
  int k = 0;
  for (std::int8_t v : m.local_map.values()) {
    acc = static_cast<std::uint8_t>(acc | (cell_code(v) << (2 * k)));
    if (++k == 4) {
      w.u8(acc);
      acc = 0;
      k = 0;
    }
  }
  if (k != 0) w.u8(acc);
}
void encode_payload(Writer& w, const NotifyMessage& m) {
  w.id(m.source);
  w.id(m.reporter);
  w.vec(m.where);
}
void encode_payload(Writer& w, const LinkAckMessage& m) {
  w.id(m.acked_origin);
  w.u32(m.acked_id);
}

Payload decode_payload(MessageType t, Reader& r) {
  switch (t) {
    case MessageType::kSearch: {
      SearchMessage m;
      m.source = r.id("source");
      m.num = r.u32("num");
      m.destination = r.vec("destination");
      m.relays = r.ids("relays");
      m.open_points = r.points("open points");
      m.close_points.resize(r.count(8, "close points"));
      for (auto& p : m.close_points)
        p = r.vec("close point");
      return m;
    }
    case MessageType::kPath: {
      PathMessage m;
      m.source = r.id("source");
      m.num = r.u32("num");
      m.relays = r.ids("relays");
      m.whole_path = r.points("whole path");
      m.exit_index = r.u32("exit index");
      m.owners = r.ids("owners");
      if (!m.owners.empty() && m.owners.size() != m.whole_path.size())
        r.fail("owners must be empty or one per whole path point");
      m.carriers = r.ids("carriers");
      m.toward = r.vec("toward");
      return m;
    }
    case MessageType::kRepair: {
      RepairMessage m;
      m.source = r.id("source");
      m.num = r.u32("num");
      m.relays = r.ids("relays");
      m.whole_path = r.points("whole path");
      m.broken_from = r.u32("broken_from");
      m.broken_to = r.u32("broken_to");
      if (m.broken_from > m.broken_to ||
          m.broken_to >= std::max<std::size_t>(m.whole_path.size(), 1))
        r.fail("broken range outside the whole path");
      m.blocked.resize(r.count(8, "blocked cells"));
      for (auto& p : m.blocked)
        p = r.vec("blocked cell");
      if (!r.done()) {
        m.hop_limit = r.u8("hop limit");
        if (m.hop_limit == 0) r.fail("a sent hop limit must be > 0");
      }
      return m;
    }
    case MessageType::kRequest: {
      RequestMessage m;
      m.source = r.id("source");
      m.num = r.u32("num");
      return m;
    }
    case MessageType::kAck: {
      AckMessage m;
      m.source = r.id("source");
      m.num = r.u32("num");
      m.responder = r.id("responder");
      GridGeometry g;
      const std::uint32_t w = r.u32("width"), h = r.u32("height");
      if (w > 65536 || h > 65536) r.fail("map size too large");
      g.width = static_cast<int>(w);
      g.height = static_cast<int>(h);
      g.resolution = r.f64("resolution");
      if (!(g.resolution > 0.0)) r.fail("resolution must be positive");
      g.origin.position.x = r.f64("origin");
      g.origin.position.y = r.f64("origin");
      g.origin.yaw = r.f64("origin");
      const std::size_t cells = g.size();
      const std::size_t packed = (cells + 3) / 4;
      r.need(packed, "map cells");
      m.local_map = OccupancyGrid(g, kUnknown);
      auto data = m.local_map.data();
      std::size_t i = 0;
      for (std::size_t b = 0; b < packed; ++b) {
        const std::uint8_t byte = r.u8("map cells");
        for (int k = 0; k < 4 && i < cells; ++k, ++i) {
          const auto c = static_cast<std::uint8_t>((byte >> (2 * k)) & 3u);
          if (c == 3) r.fail("invalid cell code 3");
          data[i] = code_value(c);
        }
      }
      return m;
    }
    case MessageType::kNotify: {
      NotifyMessage m;
      m.source = r.id("source");
      m.reporter = r.id("reporter");
      m.where = r.vec("where");
      return m;
    }
    case MessageType::kLinkAck: {
      LinkAckMessage m;
      m.acked_origin = r.id("acked origin");
      m.acked_id = r.u32("acked id");
      return m;
    }
  }
  r.fail("unknown message type");
}

}  // namespace

MessageType Envelope::type() const {
  return static_cast<MessageType>(payload.index() + 1);
}

std::uint32_t crc32(std::span<const std::uint8_t> bytes) {
  static const auto table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t i = 0; i < 256; ++i) {
      std::uint32_t c = i;
      for (int k = 0; k < 8; ++k)
        c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[i] = c;
    }
    return t;
  }();
  std::uint32_t c = 0xFFFFFFFFu;
  for (std::uint8_t b : bytes)
    c = table[(c ^ b) & 0xFFu] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

std::vector<std::uint8_t> encode(const Envelope& message) {
  Writer w;
  w.u8('V');
  w.u8('N');
  w.u8(kWireVersion);
  w.u8(static_cast<std::uint8_t>(message.type()));
  w.id(message.header.sender);
  w.id(message.header.receiver);
  w.id(message.header.origin);
  w.u32(message.header.msg_id);
  w.u8(message.header.hops);
  const std::size_t len_pos = w.bytes().size();
  w.u32(0);
  std::visit([&](const auto& m) { encode_payload(w, m); }, message.payload);
  auto& out = w.bytes();
  const auto len = static_cast<std::uint32_t>(out.size() - len_pos - 4);
  for (int i = 0; i < 4; ++i)
    out[len_pos + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(len >> (8 * i));
  const std::uint32_t crc = crc32(out);
  w.u32(crc);
  return std::move(out);
}

std::uint8_t peek_type(std::span<const std::uint8_t> bytes) {
  if (bytes.size() < kEnvelopeOverhead || bytes[0] != 'V' || bytes[1] != 'N') return 0;
  return bytes[3] < kMessageTypeCount ? bytes[3] : 0;
}

Envelope decode(std::span<const std::uint8_t> bytes) {
  Reader r(bytes, 0, bytes.size());
  if (bytes.size() < kEnvelopeOverhead)
    r.fail("truncated: " + std::to_string(bytes.size()) + " bytes, a message has at least " +
           std::to_string(kEnvelopeOverhead));
  if (r.u8("magic") != 'V' || r.u8("magic") != 'N') r.fail("bad magic (expected 'VN')");
  const std::uint8_t version = r.u8("version");
  if (version != kWireVersion)
    r.fail("unsupported version " + std::to_string(version) + " (expected " +
           std::to_string(kWireVersion) + ")");
  const std::uint8_t type = r.u8("type");
  if (type == 0 || type >= kMessageTypeCount)
    r.fail("unknown message type " + std::to_string(type));
  Envelope e;
  e.header.sender = r.id("sender");
  e.header.receiver = r.id("receiver");
  e.header.origin = r.id("origin");
  e.header.msg_id = r.u32("msg id");
  e.header.hops = r.u8("hops");
  const std::uint32_t len = r.u32("payload length");
  const std::size_t payload_begin = r.pos();
  if (static_cast<std::uint64_t>(payload_begin) + len + 4 != bytes.size())
    r.fail("payload length " + std::to_string(len) + " does not match the " +
           std::to_string(bytes.size()) + " bytes received (truncated or trailing bytes)");
  const std::uint32_t want = crc32(bytes.first(bytes.size() - 4));
  Reader tail(bytes, bytes.size() - 4, bytes.size());
  if (tail.u32("crc") != want) r.fail("CRC mismatch (garbled message)");
  Reader body(bytes, payload_begin, payload_begin + len);
  e.payload = decode_payload(static_cast<MessageType>(type), body);
  if (!body.done()) body.fail("trailing bytes in payload");
  return e;
}

std::size_t grid_payload_bytes(const OccupancyGrid& map) {
  return 8 + 32 + (map.size() + 3) / 4;
}

std::size_t points_payload_bytes(std::size_t open, std::size_t close) {
  return 8 + open * 16 + 4 + close * 8;
}

}  // namespace voronav::network
