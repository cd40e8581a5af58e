// Tests of the replay page: self-contained (no network references), embeds the recording JSON
// that parses back to the same recording, survives hostile strings, and is written where asked.
#include "voronav/report/replay_html.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "voronav/core/error.hpp"
#include "voronav/report/example_recording.hpp"

namespace voronav::report {
namespace {

std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string to_lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::size_t count(const std::string& text, const std::string& needle) {
  std::size_t n = 0;
  for (auto pos = text.find(needle); pos != std::string::npos; pos = text.find(needle, pos + 1))
    ++n;
  return n;
}

// The JSON between <script id="recording" type="application/json"> and </script>.
std::string embedded_json(const std::string& page) {
  const std::string open = R"(<script id="recording" type="application/json">)";
  const auto a = page.find(open);
  EXPECT_NE(a, std::string::npos);
  const auto b = page.find("</script>", a);
  return page.substr(a + open.size(), b - a - open.size());
}

TEST(ReplayHtml, TemplateIsTheFileInTheRepository) {
  const std::string on_disk =
      read_file(std::string(VORONAV_SOURCE_DIR) + "/voronav/report/viewer.html");
  ASSERT_FALSE(on_disk.empty());
  EXPECT_EQ(viewer_template(), on_disk);
  EXPECT_EQ(count(std::string(viewer_template()), std::string(kRecordingPlaceholder)), 1u);
}

TEST(ReplayHtml, PageIsSelfContained) {
  const std::string page = render_replay_html(make_example_recording());
  EXPECT_EQ(page.find("http://"), std::string::npos);
  EXPECT_EQ(page.find("https://"), std::string::npos);
  EXPECT_EQ(page.find("//cdn"), std::string::npos);
  // No element loads anything: no src= attributes, links only to inline data: URLs.
  const std::string lower = to_lower(page);
  EXPECT_EQ(lower.find(" src="), std::string::npos);
  EXPECT_EQ(lower.find(" src ="), std::string::npos);
  std::size_t links = 0;
  for (auto pos = lower.find("href="); pos != std::string::npos;
       pos = lower.find("href=", pos + 1)) {
    EXPECT_EQ(lower.compare(pos, 11, "href=\"data:"), 0) << page.substr(pos, 40);
    ++links;
  }
  EXPECT_EQ(links, 1u);  // the empty favicon
  EXPECT_EQ(page.find("@import"), std::string::npos);
  // The content security policy forbids network access outright.
  EXPECT_NE(page.find("default-src 'none'"), std::string::npos);
  EXPECT_EQ(page.find(kRecordingPlaceholder), std::string::npos);
  // Everything the page needs is inline: one <script> for data, one for code.
  EXPECT_EQ(count(page, "<script"), 2u);
}

TEST(ReplayHtml, EmbeddedJsonParsesBackToTheRecording) {
  const Recording r = make_example_recording();
  const std::string page = render_replay_html(r);
  EXPECT_EQ(from_json(embedded_json(page), "page"), r);
}

TEST(ReplayHtml, HostileStringsCannotCloseTheScriptElement) {
  Recording r = make_example_recording();
  r.title = "</script><script>alert(1)</script><!-- x";
  r.robots[0].name = "</SCRIPT>";
  const std::string page = render_replay_html(r);
  EXPECT_EQ(count(page, "</script>"), count(std::string(viewer_template()), "</script>"));
  EXPECT_EQ(page.find("<!-- x"), std::string::npos);
  EXPECT_EQ(from_json(embedded_json(page), "page"), r);
}

TEST(ReplayHtml, WritesIndexHtmlIntoADirectoryOrToAFile) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "voronav_replay_html_test";
  fs::remove_all(dir);
  const Recording r = make_example_recording();
  const std::string written = write_replay_html(r, (dir / "sub").string() + "/");
  EXPECT_EQ(fs::path(written), dir / "sub" / "index.html");
  EXPECT_TRUE(fs::exists(dir / "sub" / "index.html"));
  EXPECT_EQ(write_replay_html(r, (dir / "sub").string()), (dir / "sub" / "index.html").string());
  EXPECT_EQ(write_replay_html(r, (dir / "page.html").string()), (dir / "page.html").string());
  EXPECT_EQ(read_file(dir / "page.html"), render_replay_html(r));
  // Small enough to open comfortably: the 64 000-cell map is run-length encoded.
  EXPECT_LT(fs::file_size(dir / "page.html"), 400u * 1024u);
  fs::remove_all(dir);
  EXPECT_THROW(write_replay_html(r, ""), Error);
  EXPECT_THROW(write_replay_html(Recording{}, (dir / "x.html").string()), Error);
}

}  // namespace
}  // namespace voronav::report
