// Helpers shared by the CLI subcommands: parsing "X,Y" points, loading a map and converting
// between the user's coordinates (Moving AI file cells for .map, metres for ROS/image maps) and
// grid cells, and writing JSON.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "voronav/core/pose2.hpp"
#include "voronav/core/vec2.hpp"
#include "voronav/io/map_loader.hpp"

namespace voronav::cli {

/// Number validators for CLI11 options. Unlike CLI::NonNegativeNumber / PositiveNumber they
/// refuse nan and inf and state the range readably (no 309-digit largest double), e.g.
/// "--radius: expected a finite number >= 0, got '-1'".
[[nodiscard]] CLI::Validator non_negative();
[[nodiscard]] CLI::Validator positive();
/// A finite number in [lo, hi].
[[nodiscard]] CLI::Validator finite_range(double lo, double hi);

/// Output validators, checked when the options are parsed (before anything is computed or
/// written). output_dir(): a folder that is not the filesystem root, not an existing file, and
/// whose nearest existing ancestor is a writable folder. output_file(): a file path that is not an
/// existing folder, and whose folder is not the filesystem root and exists or can be created.
[[nodiscard]] CLI::Validator output_dir();
[[nodiscard]] CLI::Validator output_file();

/// Long runs: Ctrl-C (SIGINT) ends the process at once with "voronav <command>: interrupted"
/// and exit code 130. When stderr is a terminal, a progress line on stderr, rewritten every second
/// from 2 s on: "voronav <command>: 43 % of 600 s simulated, 5 s elapsed (Ctrl-C stops)" (what the
/// command last gave set_progress(); "still running after N s" when it gives nothing); with
/// VORONAV_PROGRESS=1 and
/// stderr not a terminal, the same as a line every 10 s from 5 s on. Never on stdout; off with
/// `--quiet` (found in argv, also before the options are parsed).
void watch_long_run(const std::string& command, int argc, char** argv);
/// The fraction of the work done (NaN: unknown) and what it is, e.g. (0.43, "of 600 s simulated").
void set_progress(double fraction, const std::string& what = {});
/// --quiet: no progress lines.
void set_quiet(bool quiet);
/// Adds the --quiet flag to a command.
void add_quiet_flag(CLI::App* command);
/// Clears the progress line before a message on stderr (the next tick writes it again).
void clear_progress_line();
/// Clears the progress line (the command is done); called before the process exits.
void finish_progress();

/// Parses "X,Y" (finite numbers); throws voronav::Error naming `option` otherwise.
[[nodiscard]] Vec2 parse_point(const std::string& text, const std::string& option);

/// A loaded map plus the coordinate convention its users speak.
struct MapContext {
  io::LoadedMap map;
  /// true: points are cells ((x, y) as in Moving AI files, y down, for .map; grid cells with row 0
  /// at the bottom otherwise); false: world metres.
  bool cell_coordinates = false;

  [[nodiscard]] Cell to_cell(Vec2 p, const std::string& option) const;
  /// The user-facing cell coordinates of a grid cell (flipped back for .map files).
  [[nodiscard]] nlohmann::json cell_json(Cell c) const;
  [[nodiscard]] std::string frame_name() const;
  /// The convention of cell coordinates in JSON: "movingai_y_down" for .map files (x right,
  /// y down, as in .scen), "grid_y_up" otherwise (row 0 at the bottom, as nav_msgs/OccupancyGrid).
  [[nodiscard]] const char* cell_frame() const;
};

/// A pose as JSON: {"x", "y" [m], "yaw" [rad], "frame_id": "map"} (REP-103).
[[nodiscard]] nlohmann::json pose_json(const Pose2& p, bool with_frame = true);

/// Loads any supported map; `force_cells` makes ROS/image maps take cell coordinates too.
[[nodiscard]] MapContext load_map_context(const std::filesystem::path& path, bool force_cells);

/// Prints JSON (pretty, 2 spaces) to stdout.
void print_json(const nlohmann::json& j);

/// Creates the output folder `dir` (and its parents) given by `option`; a folder that cannot be
/// created is a voronav::Error naming the option, the folder and the system's reason.
void make_output_dir(const std::filesystem::path& dir, const std::string& option);

/// The folder of bundled data (data/ in the source tree), or empty when not found.
[[nodiscard]] std::filesystem::path bundled_data_dir();

}  // namespace voronav::cli
