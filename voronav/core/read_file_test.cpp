// read_file_bounded: a file over the limit (by size, or a device read without end) is refused
// with an error naming it; a file within the limit reads back exactly.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "voronav/core/error.hpp"
#include "voronav/core/read_file.hpp"

namespace voronav {
namespace {

std::filesystem::path temp_file(const std::string& name, const std::string& content) {
  const auto p = std::filesystem::temp_directory_path() / name;
  std::ofstream(p, std::ios::binary) << content;
  return p;
}

std::string error_of(const std::filesystem::path& p, std::size_t limit) {
  try {
    (void)read_file_bounded(p, limit, "schedule file");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(ReadFileBounded, ReadsAFileWithinTheLimitExactly) {
  const std::string content("a\0b\nc", 5);
  const auto p = temp_file("voronav_read_file_ok.bin", content);
  EXPECT_EQ(read_file_bounded(p, 5), content);
  std::filesystem::remove(p);
}

TEST(ReadFileBounded, RefusesARegularFileOverTheLimitByItsSize) {
  const auto p = temp_file("voronav_read_file_big.bin", std::string(2048, 'x'));
  const std::string e = error_of(p, 1024);
  EXPECT_NE(e.find(p.string() + ": the schedule file is 2048 bytes, over the limit of 0 MiB"),
            std::string::npos)
      << e;
  std::filesystem::remove(p);
}

TEST(ReadFileBounded, StopsReadingADeviceWithoutEnd) {
  const std::string e = error_of("/dev/zero", std::size_t{1} << 20);
  EXPECT_NE(e.find("/dev/zero: the schedule file is over the limit of 1 MiB"), std::string::npos)
      << e;
}

TEST(ReadFileBounded, NamesAMissingFileAndAFolder) {
  EXPECT_NE(error_of("/nonexistent/x.yaml", 10).find("/nonexistent/x.yaml: cannot open"),
            std::string::npos);
  EXPECT_NE(error_of(std::filesystem::temp_directory_path(), 10).find("it is a directory"),
            std::string::npos);
}

}  // namespace
}  // namespace voronav
