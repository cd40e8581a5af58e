// voronav replay: turns a recording JSON (docs/replay.md) into a self-contained replay page
// DIR/index.html, writes a synthetic example recording and its page, or shows a map file alone
// (issue 9).
#include <filesystem>
#include <iostream>

#include "cli_common.hpp"
#include "command.hpp"
#include "voronav/core/error.hpp"
#include "voronav/io/map_loader.hpp"
#include "voronav/report/example_recording.hpp"
#include "voronav/report/replay_html.hpp"

namespace voronav::cli {
namespace {

namespace fs = std::filesystem;

struct ReplayArgs {
  fs::path recording;
  bool example = false;
  fs::path map;
  fs::path out;
  bool json = false;
};

void run(const ReplayArgs& a) {
  const int sources = (a.recording.empty() ? 0 : 1) + (a.example ? 1 : 0) + (a.map.empty() ? 0 : 1);
  if (sources != 1)
    throw Error("voronav replay", 0,
                "give exactly one of --recording FILE, --example or --map FILE");
  if (a.out.empty()) throw Error("--out", 0, "an output directory is required");
  std::error_code ec;
  if (fs::exists(a.out, ec) && !fs::is_directory(a.out, ec))
    throw Error(a.out.string(), 0, "--out must be a directory, and this is a file");
  // The inputs are read before the output folder is made: a refused input leaves nothing behind.
  report::Recording rec;
  fs::path recording_file = a.recording;
  if (!a.recording.empty()) rec = report::load_recording(a.recording.string());
  if (!a.map.empty()) rec.map = io::load_map(a.map).grid;
  fs::create_directories(a.out, ec);
  if (ec) throw Error(a.out.string(), 0, "cannot create the directory: " + ec.message());

  if (a.example) {
    rec = report::make_example_recording();
    recording_file = a.out / "recording.json";
    report::save_recording(rec, recording_file.string());
  } else if (!a.map.empty()) {
    rec.title = "Map " + a.map.filename().string();
    rec.description = "The occupancy grid of " + a.map.string() + " (no recorded run).";
    recording_file = a.out / "recording.json";
    report::save_recording(rec, recording_file.string());
  }
  const std::string page = report::write_replay_html(rec, (a.out / "index.html").string());
  std::error_code size_error;
  const auto bytes = fs::file_size(page, size_error);
  if (size_error)
    throw Error(page, 0,
                "the replay page was written but cannot be read back: " + size_error.message());
  if (a.json) {
    print_json({{"index_html", fs::absolute(page).string()},
                {"recording", fs::absolute(recording_file).string()},
                {"bytes", bytes},
                {"robots", rec.robots.size()},
                {"messages", rec.messages.size()},
                {"layers", rec.rasters.size() + rec.graphs.size()},
                {"plots", rec.plots.size()},
                {"start_s", rec.start_time()},
                {"end_s", rec.end_time()}});
  } else {
    std::cout << "replay page: " << fs::absolute(page).string() << " (" << bytes / 1024 << " KiB)\n"
              << "recording:   " << fs::absolute(recording_file).string() << "\n"
              << "shows:       " << rec.robots.size() << " robots, " << rec.messages.size()
              << " messages, " << rec.rasters.size() + rec.graphs.size() << " map layers, "
              << rec.plots.size() << " plots over " << rec.end_time() - rec.start_time() << " s\n"
              << "open it in a browser (no network needed).\n";
  }
}

void setup(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "replay", "Write a self-contained replay page (index.html) for a recorded run");
  auto args = std::make_shared<ReplayArgs>();
  auto* rec =
      cmd->add_option("--recording", args->recording, "Recording JSON (format: docs/replay.md)");
  auto* ex = cmd->add_flag("--example", args->example,
                           "Use a synthetic example recording (3 robots in an office); also "
                           "writes it to DIR/recording.json");
  auto* map = cmd->add_option("--map", args->map,
                              "Show a map file alone (ROS .yaml, Moving AI .map, floor plan "
                              ".png/.pgm); also writes DIR/recording.json");
  rec->excludes(ex);
  rec->excludes(map);
  ex->excludes(map);
  cmd->add_option("--out", args->out, "Output directory; the page is DIR/index.html")
      ->required()
      ->check(output_dir());
  cmd->add_flag("--json", args->json,
                "JSON output: index_html, recording, bytes, robots, messages, layers, plots, "
                "start_s, end_s");
  cmd->callback([args] { run(*args); });
}

const Command reg{{"replay", setup, 60}};

}  // namespace
}  // namespace voronav::cli
