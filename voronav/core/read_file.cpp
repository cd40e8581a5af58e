#include "voronav/core/read_file.hpp"

#include <fstream>
#include <system_error>

#include "voronav/core/error.hpp"

namespace voronav {
namespace {

std::string mib(std::size_t bytes) {
  return std::to_string(bytes >> 20) + " MiB";
}

}  // namespace

std::string read_file_bounded(const std::filesystem::path& path, std::size_t limit,
                              const std::string& what) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (!ec && fs::is_directory(st))
    throw Error(path.string(), 0, "cannot read the " + what + ": it is a directory");
  if (!ec && fs::is_regular_file(st)) {
    const auto size = fs::file_size(path, ec);
    if (!ec && size > limit)
      throw Error(path.string(), 0,
                  "the " + what + " is " + std::to_string(size) + " bytes, over the limit of " +
                      mib(limit));
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path.string(), 0, "cannot open the " + what);
  std::string data;
  char buf[1 << 16];
  while (in) {
    in.read(buf, sizeof buf);
    const auto got = static_cast<std::size_t>(in.gcount());
    if (got == 0) break;
    if (data.size() + got > limit)
      throw Error(
          path.string(), 0,
          "the " + what + " is over the limit of " + mib(limit) + " (stopped reading there)");
    data.append(buf, got);
  }
  if (in.bad()) throw Error(path.string(), 0, "read error in the " + what);
  return data;
}

}  // namespace voronav
