// Reading a whole input file into memory with a size limit. Every loader goes through this so a
// huge file, or a device without end such as /dev/zero, is refused with an error that names the
// file and the limit, instead of being read until memory runs out.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

namespace voronav {

/// Limit for text inputs (YAML/JSON scenarios, schedules, recordings, .scen files): 64 MiB.
inline constexpr std::size_t kMaxTextFileBytes = std::size_t{64} << 20;
/// Limit for map files (.map, PGM, PNG): 256 MiB (a 16384 x 16384 8-bit raster is 256 MiB).
inline constexpr std::size_t kMaxMapFileBytes = std::size_t{256} << 20;

/// The file's bytes. Throws voronav::Error(path, 0, ...) when it cannot be opened or holds more
/// than `limit` bytes (regular files are checked by size before reading; pipes and devices are
/// read in chunks and refused once past the limit). `what` names the input in the messages.
[[nodiscard]] std::string read_file_bounded(const std::filesystem::path& path, std::size_t limit,
                                            const std::string& what = "file");

}  // namespace voronav
