#include "cli_common.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <thread>

#include <cmath>
#include <iostream>
#include <sstream>
#include <system_error>

#include "voronav/core/error.hpp"
#include "voronav/io/movingai.hpp"

namespace voronav::cli {

namespace {

/// Shortest form that reads back, e.g. 1e+18 rather than 1000000000000000000.000000.
std::string short_number(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

CLI::Validator number_validator(const std::string& desc, std::function<bool(double)> ok) {
  return CLI::Validator(
      [desc, ok](std::string& text) -> std::string {
        double v = 0.0;
        std::size_t used = 0;
        try {
          v = std::stod(text, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        if (used == 0 || used != text.size() || !std::isfinite(v) || !ok(v))
          return "expected " + desc + ", got '" + text + "'";
        return {};
      },
      desc, "");
}

/// The nearest existing ancestor of `p` (p itself when it exists).
std::filesystem::path existing_ancestor(std::filesystem::path p) {
  std::error_code ec;
  p = std::filesystem::absolute(p, ec);
  while (!p.empty() && !std::filesystem::exists(p, ec) && p.has_relative_path())
    p = p.parent_path();
  return p;
}

std::string check_folder(const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path abs = fs::weakly_canonical(fs::absolute(dir, ec), ec);
  if (!abs.empty() && abs == abs.root_path())
    return "refusing to write into the filesystem root '" + abs.string() + "'; give a folder";
  const fs::path anc = existing_ancestor(dir);
  if (anc.empty() || !fs::is_directory(anc, ec))
    return "'" + anc.string() + "' is not a folder, so '" + dir.string() + "' cannot be created";
  if (::access(anc.c_str(), W_OK | X_OK) != 0)
    return "folder '" + anc.string() + "' is not writable";
  return {};
}

}  // namespace

CLI::Validator non_negative() {
  return number_validator("a finite number >= 0", [](double v) { return v >= 0.0; });
}

CLI::Validator positive() {
  return number_validator("a finite number > 0", [](double v) { return v > 0.0; });
}

CLI::Validator finite_range(double lo, double hi) {
  return number_validator("a number in " + short_number(lo) + ".." + short_number(hi),
                          [lo, hi](double v) { return v >= lo && v <= hi; });
}

CLI::Validator output_dir() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        namespace fs = std::filesystem;
        if (text.empty()) return "expected a folder name";
        std::error_code ec;
        if (fs::exists(text, ec) && !fs::is_directory(text, ec))
          return "'" + text + "' is a file, expected a directory";
        return check_folder(text);
      },
      "FOLDER", "");
}

CLI::Validator output_file() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        namespace fs = std::filesystem;
        if (text.empty()) return "expected a file name";
        std::error_code ec;
        if (fs::is_directory(text, ec))
          return "'" + text + "' is a folder, expected a file name (e.g. " +
                 (fs::path(text) / "scenario.yaml").string() + ")";
        fs::path parent = fs::path(text).parent_path();
        if (parent.empty()) parent = ".";
        return check_folder(parent);
      },
      "FILE", "");
}

namespace {
std::string g_interrupt_line;  // written once before the handler is installed

extern "C" void on_interrupt(int) {
  const ssize_t n = ::write(STDERR_FILENO, g_interrupt_line.data(), g_interrupt_line.size());
  (void)n;
  std::_Exit(130);
}
}  // namespace

namespace {
// Progress of the running command (set_progress), read by the watcher thread.
std::mutex g_progress_mutex;
std::string g_progress_text;           // e.g. "43 % of 600 s simulated"
std::atomic<bool> g_quiet{false};      // --quiet
std::atomic<bool> g_line_open{false};  // a "\r" line is on the terminal
std::atomic<bool> g_finished{false};
}  // namespace

void set_progress(double fraction, const std::string& what) {
  std::ostringstream os;
  if (std::isfinite(fraction))
    os << static_cast<int>(std::floor(std::clamp(fraction, 0.0, 1.0) * 100.0)) << " %";
  if (!what.empty()) os << (os.tellp() > 0 ? " " : "") << what;
  const std::lock_guard lock(g_progress_mutex);
  g_progress_text = os.str();
}

void set_quiet(bool quiet) {
  g_quiet = quiet;
}

void clear_progress_line() {
  const std::lock_guard lock(g_progress_mutex);
  if (g_line_open.exchange(false)) {
    const char clear[] = "\r\033[K";
    const ssize_t n = ::write(STDERR_FILENO, clear, sizeof clear - 1);
    (void)n;
  }
}

void finish_progress() {
  g_finished = true;
  const std::lock_guard lock(g_progress_mutex);
  if (g_line_open.exchange(false)) {
    const char clear[] = "\r\033[K";
    const ssize_t n = ::write(STDERR_FILENO, clear, sizeof clear - 1);
    (void)n;
  }
}

void add_quiet_flag(CLI::App* command) {
  command->add_flag_callback(
      "--quiet", [] { set_quiet(true); },
      "no progress lines on stderr (progress is shown only when stderr is a terminal, never on "
      "stdout)");
}

void watch_long_run(const std::string& command, int argc, char** argv) {
  g_interrupt_line = "\nvoronav " + command + ": interrupted\n";
  std::signal(SIGINT, on_interrupt);
  // --quiet is looked for here too: the watcher starts before the options are parsed.
  for (int i = 2; i < argc; ++i)
    if (std::strcmp(argv[i], "--quiet") == 0 && command.rfind("dds-", 0) != 0) g_quiet = true;
  const char* env = std::getenv("VORONAV_PROGRESS");
  const bool forced = env != nullptr && std::strcmp(env, "1") == 0;
  const bool tty = ::isatty(STDERR_FILENO) != 0;
  if (!forced && !tty) return;
  std::thread([command, tty] {
    // On a terminal: one line, rewritten every second from 2 s on. Otherwise (VORONAV_PROGRESS=1,
    // e.g. a log file): a line every 10 s from 5 s on.
    const auto t0 = std::chrono::steady_clock::now();
    for (int k = 0;; ++k) {
      const int s = tty ? 2 + k : 5 + 10 * k;
      std::this_thread::sleep_until(t0 + std::chrono::seconds(s));
      if (g_quiet || g_finished) continue;
      const std::lock_guard lock(g_progress_mutex);
      if (g_finished) continue;
      std::string line = "voronav " + command + ": ";
      line += g_progress_text.empty()
                  ? "still running after " + std::to_string(s) + " s (Ctrl-C stops)"
                  : g_progress_text + ", " + std::to_string(s) + " s elapsed (Ctrl-C stops)";
      line = tty ? "\r\033[K" + line : line + "\n";
      const ssize_t n = ::write(STDERR_FILENO, line.data(), line.size());
      (void)n;
      if (tty) g_line_open = true;
    }
  }).detach();
}

Vec2 parse_point(const std::string& text, const std::string& option) {
  const auto comma = text.find(',');
  auto fail = [&]() -> Vec2 {
    throw Error(option, 0, "expected two finite numbers 'X,Y', got '" + text + "'");
  };
  if (comma == std::string::npos) return fail();
  try {
    std::size_t used_x = 0, used_y = 0;
    const std::string xs = text.substr(0, comma), ys = text.substr(comma + 1);
    const double x = std::stod(xs, &used_x), y = std::stod(ys, &used_y);
    if (used_x != xs.size() || used_y != ys.size() || !std::isfinite(x) || !std::isfinite(y))
      return fail();
    return {x, y};
  } catch (const std::logic_error&) {
    return fail();
  }
}

Cell MapContext::to_cell(Vec2 p, const std::string& option) const {
  const auto& g = map.grid.geometry();
  std::optional<Cell> c;
  if (cell_coordinates) {
    if (p.x != std::floor(p.x) || p.y != std::floor(p.y) || std::abs(p.x) > 1e9 ||
        std::abs(p.y) > 1e9)
      throw Error(option, 0, "expected integer cell coordinates for this map");
    const int x = static_cast<int>(p.x), y = static_cast<int>(p.y);
    c = map.format == io::MapFormat::kMovingAi ? io::movingai_to_cell(x, y, g.height) : Cell{x, y};
  } else {
    c = g.world_to_cell(p);
  }
  if (!c || !g.contains(*c)) {
    std::ostringstream os;
    os << "point (" << p.x << ", " << p.y << ") " << frame_name() << " is outside the ";
    if (cell_coordinates) {
      os << g.width << "x" << g.height << " cell map";
    } else {  // in the unit the user gave: the map's extent in metres
      double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
      for (const Vec2 corner :
           {Vec2{0, 0}, Vec2{static_cast<double>(g.width), 0},
            Vec2{0, static_cast<double>(g.height)},
            Vec2{static_cast<double>(g.width), static_cast<double>(g.height)}}) {
        const Vec2 w = g.grid_to_world(corner);
        x0 = std::min(x0, w.x), x1 = std::max(x1, w.x), y0 = std::min(y0, w.y),
        y1 = std::max(y1, w.y);
      }
      os << "map, which spans x " << x0 << " .. " << x1 << " m, y " << y0 << " .. " << y1 << " m ("
         << g.width << "x" << g.height << " cells of " << g.resolution << " m)";
    }
    throw Error(option, 0, os.str());
  }
  return *c;
}

nlohmann::json MapContext::cell_json(Cell c) const {
  if (map.format == io::MapFormat::kMovingAi) {
    const auto [x, y] = io::cell_to_movingai(c, map.grid.height());
    return {x, y};
  }
  return {c.x, c.y};
}

const char* MapContext::cell_frame() const {
  return map.format == io::MapFormat::kMovingAi ? "movingai_y_down" : "grid_y_up";
}

nlohmann::json pose_json(const Pose2& p, bool with_frame) {
  nlohmann::json j{{"x", p.position.x}, {"y", p.position.y}, {"yaw", p.yaw}};
  if (with_frame) j["frame_id"] = "map";
  return j;
}

std::string MapContext::frame_name() const {
  if (!cell_coordinates) return "[m, world frame]";
  return map.format == io::MapFormat::kMovingAi ? "[cells, Moving AI x right / y down]"
                                                : "[cells, row 0 at the bottom]";
}

MapContext load_map_context(const std::filesystem::path& path, bool force_cells) {
  MapContext ctx{io::load_map(path), false};
  ctx.cell_coordinates = force_cells || ctx.map.format == io::MapFormat::kMovingAi;
  return ctx;
}

void print_json(const nlohmann::json& j) {
  std::cout << j.dump(2) << "\n";
}

void make_output_dir(const std::filesystem::path& dir, const std::string& option) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec)
    throw Error(option, 0,
                "cannot create the output folder '" + dir.string() + "': " + ec.message());
}

std::filesystem::path bundled_data_dir() {
  namespace fs = std::filesystem;
  for (const fs::path& p : {fs::path(VORONAV_SOURCE_DIR) / "data", fs::path("data")})
    if (fs::exists(p / "README.md")) return p;
  return {};
}

}  // namespace voronav::cli
