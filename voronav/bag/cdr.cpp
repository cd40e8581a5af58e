#include "voronav/bag/cdr.hpp"

#include <bit>
#include <cstring>
#include <limits>

#include "voronav/core/error.hpp"

namespace voronav::bag {

static_assert(std::endian::native == std::endian::little,
              "CdrWriter writes the host's bytes as CDR_LE; a big-endian host needs swapping");

namespace {
constexpr std::size_t kHeader = 4;  // encapsulation header; alignment counts from its end
}

CdrWriter::CdrWriter() : buf_{0x00, 0x01, 0x00, 0x00} {}

void CdrWriter::align(std::size_t n) {
  const std::size_t pos = buf_.size() - kHeader;
  const std::size_t pad = (n - pos % n) % n;
  buf_.insert(buf_.end(), pad, 0);
}

void CdrWriter::raw(const void* p, std::size_t n, std::size_t alignment) {
  align(alignment);
  const auto* b = static_cast<const std::uint8_t*>(p);
  buf_.insert(buf_.end(), b, b + n);
}

void CdrWriter::count(std::size_t n) {
  if (n > std::numeric_limits<std::uint32_t>::max())
    throw Error("CDR: sequence of " + std::to_string(n) + " elements exceeds uint32");
  u32(static_cast<std::uint32_t>(n));
}

void CdrWriter::string(std::string_view s) {
  count(s.size() + 1);
  raw(s.data(), s.size(), 1);
  buf_.push_back(0);
}

}  // namespace voronav::bag
