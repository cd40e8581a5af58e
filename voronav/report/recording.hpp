// report::Recording: everything a replay page shows about one run, as a plain value type that the
// simulator, the networked robots, exploration and coordination fill in (issue 9). It holds the map
// (occupancy grid) with optional raster layers (Voronoi, labels, regions) and graph layers (nodes,
// edges), timed robot tracks, planned paths, messages between robots, obstacle changes and metric
// plots. It is saved as JSON (schema in docs/replay.md) and turned into a self-contained HTML page
// by write_replay_html(). Units: metres, seconds, radians; world frame as core::GridGeometry.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "voronav/core/grid_map.hpp"
#include "voronav/core/occupancy.hpp"
#include "voronav/core/pose2.hpp"
#include "voronav/core/vec2.hpp"

namespace voronav::report {

/// How a raster layer is coloured: kMask paints every non-zero cell in the layer colour; kLabels
/// gives each distinct non-zero value its own colour (regions, obstacle labels).
enum class RasterStyle { kMask, kLabels };

/// A raster drawn over the map; same geometry as the recording's map. 0 = nothing drawn.
struct RasterLayer {
  std::string name;  ///< shown on the toggle, e.g. "Voronoi"
  RasterStyle style = RasterStyle::kMask;
  std::string color = "#d62728";  ///< CSS colour for kMask (#rrggbb)
  bool visible = true;            ///< initial state of the toggle
  GridMap<std::int32_t> cells;
  friend bool operator==(const RasterLayer&, const RasterLayer&) = default;
};

struct GraphNode {
  int id = 0;
  Vec2 position;      ///< world [m]
  std::string label;  ///< optional text drawn beside the node
  friend bool operator==(const GraphNode&, const GraphNode&) = default;
};
struct GraphEdge {
  int from = 0;  ///< node id
  int to = 0;    ///< node id
  friend bool operator==(const GraphEdge&, const GraphEdge&) = default;
};
/// A graph drawn over the map (topological graph, Voronoi tree, (M,D) network...).
struct GraphLayer {
  std::string name;
  std::string color = "#1f77b4";
  bool visible = true;
  std::vector<GraphNode> nodes;
  std::vector<GraphEdge> edges;
  friend bool operator==(const GraphLayer&, const GraphLayer&) = default;
};

/// One sample of a robot's pose.
struct TimedPose {
  double t = 0.0;  ///< [s]
  Pose2 pose;      ///< world [m, rad]
  friend bool operator==(const TimedPose&, const TimedPose&) = default;
};
/// A robot and its recorded motion; poses between samples are interpolated linearly.
struct RobotTrack {
  int id = 0;                    ///< robot id used by paths and messages; unique
  std::string name;              ///< legend text; "robot <id>" when empty
  double radius = 0.3;           ///< [m], > 0
  std::string color;             ///< CSS #rrggbb; empty = automatic palette
  std::vector<TimedPose> poses;  ///< non-decreasing t
  friend bool operator==(const RobotTrack&, const RobotTrack&) = default;
};

/// A planned path of a robot, shown from time t_start on (re-plans add a new path).
struct PathRecord {
  int robot = 0;             ///< robot id
  double t_start = 0.0;      ///< [s] when the path was planned
  std::string label;         ///< e.g. "A*", "RAS", "repair"
  std::vector<Vec2> points;  ///< world [m]
  friend bool operator==(const PathRecord&, const PathRecord&) = default;
};

/// A message sent between two robots; drawn as a line between them for a moment at time t.
struct MessageRecord {
  double t = 0.0;          ///< [s]
  int from = 0;            ///< robot id
  int to = 0;              ///< robot id
  std::string type;        ///< e.g. "Search", "Path", "Repair"
  std::int64_t bytes = 0;  ///< payload size [bytes], >= 0
  friend bool operator==(const MessageRecord&, const MessageRecord&) = default;
};

/// Cells of the map that change occupancy at time t (a door closes, an obstacle appears).
struct ObstacleChange {
  double t = 0.0;  ///< [s]
  std::vector<Cell> cells;
  std::int8_t value = kOccupied;  ///< new occupancy value (0 free, 100 occupied, -1 unknown)
  friend bool operator==(const ObstacleChange&, const ObstacleChange&) = default;
};

/// A place marked on the map: a robot's goal, the destination of a route search, a start.
struct MarkerRecord {
  std::string kind = "goal";  ///< "goal", "start" or "destination" (drawn differently)
  Vec2 position;              ///< world [m]
  int robot = -1;             ///< robot id it belongs to (drawn in its colour); -1 = none
  std::string label;          ///< shown on hover and in the legend, e.g. "goal of robot 3"
  friend bool operator==(const MarkerRecord&, const MarkerRecord&) = default;
};

/// Something that happened at time t ("route found", "obstacle change", "repair", "robot killed"):
/// the page lists events on a track under the time slider; a click jumps to the event.
struct EventRecord {
  double t = 0.0;    ///< [s]
  std::string kind;  ///< short category, e.g. "route", "change", "repair", "kill", "arrival"
  std::string text;  ///< one sentence, shown as tooltip and in the event list
  int robot = -1;    ///< robot id concerned; -1 = none
  friend bool operator==(const EventRecord&, const EventRecord&) = default;
};

enum class PlotKind { kLine, kBar };

/// One series of a plot. Line plots: x and y of equal length. Bar plots: y holds one value per
/// category of the plot and x is empty.
struct Series {
  std::string name;
  std::string color;  ///< CSS #rrggbb; empty = automatic palette
  std::vector<double> x;
  std::vector<double> y;
  friend bool operator==(const Series&, const Series&) = default;
};
/// A chart drawn under the map. When time_axis is true the x axis is the replay time [s] and the
/// page draws a cursor at the current time.
struct Plot {
  std::string title;
  std::string x_label;  ///< including the unit, e.g. "time [s]"
  std::string y_label;  ///< including the unit, e.g. "coverage [%]"
  PlotKind kind = PlotKind::kLine;
  bool time_axis = false;
  std::vector<std::string> categories;  ///< bar plots: one label per bar group
  std::vector<Series> series;
  friend bool operator==(const Plot&, const Plot&) = default;
};

struct Recording {
  std::string title;
  std::string description;  ///< one paragraph shown under the title
  OccupancyGrid map;        ///< the static map at t = start_time
  std::vector<RasterLayer> rasters;
  std::vector<GraphLayer> graphs;
  std::vector<RobotTrack> robots;
  std::vector<PathRecord> paths;
  std::vector<MessageRecord> messages;
  std::vector<ObstacleChange> obstacle_changes;
  std::vector<MarkerRecord> markers;
  std::vector<EventRecord> events;
  std::vector<Plot> plots;
  double message_display_s = 0.5;  ///< [s] how long a message line stays visible, > 0
  /// Exploration: when each cell of `map` becomes known. Empty (the default): the whole map is
  /// shown from the start. Otherwise of the map's size; k >= 0: the cell shows its map value from
  /// t = k * reveal_period_s on (unknown grey before); -1: never known.
  GridMap<std::int32_t> reveal;
  double reveal_period_s = 0.1;  ///< [s], > 0
  /// Graph layers that appear during the run (a tree built at time t): graphs[graph] is drawn
  /// from t on; graphs not named here are drawn all the time. In JSON: graphs[i].shown_from.
  struct GraphAppearance {
    std::size_t graph = 0;
    double t = 0.0;  ///< [s]
    friend bool operator==(const GraphAppearance&, const GraphAppearance&) = default;
  };
  std::vector<GraphAppearance> graph_appearances;

  /// [first, last] time over tracks, messages, changes and events; {0, 0} when nothing is timed.
  [[nodiscard]] double start_time() const;
  [[nodiscard]] double end_time() const;

  friend bool operator==(const Recording&, const Recording&) = default;
};

/// The JSON format identifier and version written into every recording.
inline constexpr std::string_view kRecordingFormat = "voronav-recording";
inline constexpr int kRecordingVersion = 1;

/// Checks a recording for values the page cannot show: NaN/inf, empty map, rasters whose size
/// differs from the map, unknown robot or node ids, duplicate robot ids, decreasing track times,
/// cells outside the map, bad colours, non-positive radius, series of mismatched length.
/// Throws voronav::Error naming `source` and the offending field, e.g. "robots[1].poses[3].t".
void validate(const Recording& recording, const std::string& source = "recording");

/// Robot pose at time t (linear interpolation of position, shortest-arc yaw; clamped at the ends).
/// Precondition: !track.poses.empty().
[[nodiscard]] Pose2 pose_at(const RobotTrack& track, double t);

/// Serialises to the JSON of docs/replay.md (compact; maps run-length encoded).
[[nodiscard]] std::string to_json(const Recording& recording);
/// Parses and validates a recording; malformed input throws voronav::Error(source, line, reason).
[[nodiscard]] Recording from_json(std::string_view text, const std::string& source = "recording");

/// File versions of to_json / from_json.
void save_recording(const Recording& recording, const std::string& path);
[[nodiscard]] Recording load_recording(const std::string& path);

}  // namespace voronav::report
