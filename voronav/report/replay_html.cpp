#include "voronav/report/replay_html.hpp"

#include <filesystem>
#include <fstream>

#include "voronav/core/error.hpp"
#include "voronav/report/internal/viewer_html.hpp"

namespace voronav::report {

std::string_view viewer_template() {
  return internal::viewer_html();
}

std::string render_replay_html(const Recording& recording) {
  std::string data = to_json(recording);
  // Inside <script> the only sequence that can end the element early is "</"; JSON allows "\/".
  std::string safe;
  safe.reserve(data.size() + 16);
  for (std::size_t i = 0; i < data.size(); ++i) {
    if (data[i] == '<' && i + 1 < data.size() && data[i + 1] == '/') {
      safe += "<\\/";
      ++i;
    } else if (data[i] == '<' && data.compare(i, 4, "<!--") == 0) {
      safe += "\\u003c";
    } else {
      safe += data[i];
    }
  }
  const std::string_view tpl = viewer_template();
  const auto pos = tpl.find(kRecordingPlaceholder);
  if (pos == std::string_view::npos)
    throw Error("viewer.html", 0, "the page template lacks the recording placeholder");
  std::string page;
  page.reserve(tpl.size() + safe.size());
  page.append(tpl.substr(0, pos));
  page.append(safe);
  page.append(tpl.substr(pos + kRecordingPlaceholder.size()));
  return page;
}

std::string write_replay_html(const Recording& recording, const std::string& path) {
  namespace fs = std::filesystem;
  if (path.empty()) throw Error("--out", 0, "empty output path");
  fs::path out(path);
  std::error_code ec;
  if (path.back() == '/' || fs::is_directory(out, ec)) out /= "index.html";
  if (out.has_parent_path()) {
    fs::create_directories(out.parent_path(), ec);
    if (ec) throw Error(out.parent_path().string(), 0, "cannot create directory: " + ec.message());
  }
  const std::string page = render_replay_html(recording);
  std::ofstream f(out, std::ios::binary);
  if (!f) throw Error(out.string(), 0, "cannot open for writing");
  f << page;
  if (!f) throw Error(out.string(), 0, "write failed");
  return out.string();
}

}  // namespace voronav::report
