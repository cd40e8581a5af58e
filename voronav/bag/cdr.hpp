// CdrWriter: serializes ROS 2 messages as XCDR1 (plain CDR), little endian, the way rmw
// implementations put them on the wire and rosbag2 stores them: a 4-byte encapsulation header
// (0x00 0x01 = CDR_LE, two option bytes 0), then each primitive aligned to its own size relative
// to the end of that header; strings as uint32 length (with the terminating NUL) + bytes + NUL;
// sequences as uint32 count + elements.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

namespace voronav::bag {

class CdrWriter {
 public:
  CdrWriter();

  void u8(std::uint8_t v) { raw(&v, 1, 1); }
  void i8(std::int8_t v) { raw(&v, 1, 1); }
  void boolean(bool v) { u8(v ? 1 : 0); }
  void i32(std::int32_t v) { raw(&v, 4, 4); }
  void u32(std::uint32_t v) { raw(&v, 4, 4); }
  void f32(float v) { raw(&v, 4, 4); }
  void f64(double v) { raw(&v, 8, 8); }
  void string(std::string_view s);
  /// A sequence length (uint32).
  void count(std::size_t n);
  /// int8[] / uint8[] body in one go (after count()).
  void bytes(const void* data, std::size_t n) { raw(data, n, 1); }

  [[nodiscard]] const std::vector<std::uint8_t>& data() const { return buf_; }
  [[nodiscard]] std::vector<std::uint8_t> take() { return std::move(buf_); }

 private:
  void align(std::size_t n);
  void raw(const void* p, std::size_t n, std::size_t alignment);
  std::vector<std::uint8_t> buf_;
};

}  // namespace voronav::bag
