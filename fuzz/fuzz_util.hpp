// Helpers for the libFuzzer targets in fuzz/: the loaders read files, so each input is written to
// a per-process scratch folder first; the only exception a loader may throw is voronav::Error, and
// its message must name the input file (anything else aborts, which libFuzzer reports).
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "voronav/core/error.hpp"

namespace voronav::fuzz {

/// The scratch folder of this process (created once, removed at exit).
inline const std::filesystem::path& scratch() {
  static const std::filesystem::path dir = [] {
    auto d =
        std::filesystem::temp_directory_path() / ("voronav_fuzz_" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    std::atexit([] {
      std::error_code ec;
      std::filesystem::remove_all(scratch(), ec);
    });
    return d;
  }();
  return dir;
}

/// Writes `bytes` to scratch()/name and returns the path.
inline std::filesystem::path put(const std::string& name, std::string_view bytes) {
  const auto p = scratch() / name;
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return p;
}

[[noreturn]] inline void finding(const std::string& what) {
  std::fprintf(stderr, "voronav fuzz finding: %s\n", what.c_str());
  std::abort();
}

/// Runs `load`; voronav::Error is the expected outcome of bad input, but its message must name
/// `source` (empty: any source will do). Any other exception is a finding.
template <typename F>
void expect_clean(const std::string& source, F&& load) {
  try {
    load();
  } catch (const voronav::Error& e) {
    if (!source.empty() && std::string_view(e.what()).find(source) == std::string_view::npos)
      finding("error does not name '" + source + "': " + e.what());
  } catch (const std::exception& e) {
    finding(std::string("unexpected exception: ") + e.what());
  }
}

/// Seeds that only the library can make (a CRC, a CDR stream, a generated recording): when the
/// environment names VORONAV_FUZZ_SEEDS_OUT, they are written there as seed_0, seed_1, ... (the
/// fuzz script points it at the working corpus before libFuzzer reads it).
template <typename Bytes>
void write_seeds(const std::vector<Bytes>& seeds) {
  const char* dir = std::getenv("VORONAV_FUZZ_SEEDS_OUT");
  if (dir == nullptr || *dir == 0) return;
  std::filesystem::create_directories(dir);
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    std::ofstream out(std::filesystem::path(dir) / ("seed_" + std::to_string(i)), std::ios::binary);
    out.write(reinterpret_cast<const char*>(seeds[i].data()),
              static_cast<std::streamsize>(seeds[i].size()));
  }
}

inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

}  // namespace voronav::fuzz
