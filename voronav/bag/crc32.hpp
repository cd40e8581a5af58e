// CRC-32 (IEEE 802.3, reflected polynomial 0xEDB88320) as the MCAP specification uses it for the
// data section, chunks and summary. Incremental: pass the previous value to continue.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

namespace voronav::bag {

/// CRC-32 of `bytes`, continuing from `crc` (0 for a fresh checksum).
[[nodiscard]] std::uint32_t crc32(std::span<const std::uint8_t> bytes, std::uint32_t crc = 0);

}  // namespace voronav::bag
