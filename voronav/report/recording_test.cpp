// Tests of report::Recording: JSON round trips, the run-length map encoding, interpolation, and
// clear errors for malformed recordings.
#include "voronav/report/recording.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <numbers>
#include <random>

#include "voronav/core/error.hpp"
#include "voronav/report/example_recording.hpp"

namespace voronav::report {
namespace {

// A 3x2 map with one robot, a message to itself-free partner, a change and a plot.
Recording small() {
  Recording r;
  r.title = "small";
  r.map = OccupancyGrid(GridGeometry{3, 2, 0.5, {{1.0, -2.0}, 0.0}}, kFree);
  r.map[Cell{2, 0}] = kOccupied;
  r.map[Cell{0, 1}] = kOccupied;
  r.map[Cell{1, 1}] = kOccupied;
  r.map[Cell{2, 1}] = kUnknown;
  r.robots.push_back(
      {7, "a", 0.2, "#112233", {{0.0, {{1.2, -1.8}, 0.0}}, {2.0, {{1.6, -1.8}, 0.0}}}});
  r.robots.push_back({9, "", 0.25, "", {{1.0, {{1.4, -1.6}, 1.0}}}});
  r.paths.push_back({7, 0.0, "A*", {{1.2, -1.8}, {1.6, -1.8}}});
  r.messages.push_back({0.5, 7, 9, "Path", 24});
  r.obstacle_changes.push_back({1.5, {{1, 0}}, kOccupied});
  r.plots.push_back({"cov",
                     "time [s]",
                     "coverage [%]",
                     PlotKind::kLine,
                     true,
                     {},
                     {{"team", "", {0.0, 1.0}, {10.0, 20.0}}}});
  return r;
}

TEST(Recording, OccupancyIsRunLengthEncodedRowByRowFromTheBottom) {
  const std::string json = to_json(small());
  // Cells in index order: 0 0 100 | 100 100 -1.
  EXPECT_NE(json.find("\"occupancy\":[0,2,100,3,-1,1]"), std::string::npos) << json;
  EXPECT_NE(json.find("\"format\":\"voronav-recording\""), std::string::npos);
  EXPECT_NE(json.find("\"version\":1"), std::string::npos);
}

TEST(Recording, SmallRecordingRoundTrips) {
  const Recording r = small();
  const Recording back = from_json(to_json(r));
  EXPECT_EQ(back, r);
  const Vec2 kOrigin{1.0, -2.0};
  EXPECT_EQ(back.map.geometry().origin.position, kOrigin);
}

TEST(Recording, ExampleRoundTripsExactlyThroughAFile) {
  const Recording r = make_example_recording();
  const auto path = std::filesystem::temp_directory_path() / "voronav_report_roundtrip.json";
  save_recording(r, path.string());
  const Recording back = load_recording(path.string());
  std::filesystem::remove(path);
  EXPECT_EQ(back, r);  // doubles survive JSON exactly (shortest round-trip printing)
  EXPECT_EQ(to_json(back), to_json(r));
}

TEST(Recording, RandomRastersRoundTrip) {
  std::mt19937 rng(42);
  // Labels over the whole int32 range, extremes included.
  std::uniform_int_distribution<std::int32_t> label(std::numeric_limits<std::int32_t>::min(),
                                                    std::numeric_limits<std::int32_t>::max());
  for (int trial = 0; trial < 20; ++trial) {
    Recording r;
    const int w = 1 + static_cast<int>(rng() % 40), h = 1 + static_cast<int>(rng() % 30);
    r.map = OccupancyGrid(GridGeometry{w, h, 0.05, {}}, kFree);
    RasterLayer layer{"labels", RasterStyle::kLabels, "#000000", trial % 2 == 0,
                      GridMap<std::int32_t>(r.map.geometry(), 0)};
    for (std::size_t k = 0; k < r.map.size(); ++k) {
      const int v = static_cast<int>(rng() % 4);
      r.map[k] = v == 0 ? kOccupied : v == 1 ? kUnknown : static_cast<std::int8_t>(rng() % 101);
      layer.cells[k] = (rng() % 3 == 0) ? label(rng) : 0;
    }
    r.rasters.push_back(layer);
    EXPECT_EQ(from_json(to_json(r)), r) << "trial " << trial;
  }
}

// Markers, events, reveal times and a graph that appears at t: the fields of issue 20.
Recording with_story() {
  Recording r = small();
  r.graphs.push_back({"tree", "#9467bd", true, {{0, {1.2, -1.8}, "root"}, {1, {2.0, -1.2}, ""}},
                      {{0, 1}}});
  r.graph_appearances.push_back({0, 0.75});
  r.markers.push_back({"goal", {1.6, -1.8}, 7, "goal of a"});
  r.markers.push_back({"destination", {2.2, -1.2}, -1, "destination"});
  r.events.push_back({1.5, "change", "a cell becomes blocked", -1});
  r.events.push_back({4.0, "arrival", "a arrives", 7});
  r.reveal = GridMap<std::int32_t>(r.map.geometry(), 0);
  r.reveal[Cell{2, 1}] = -1;
  r.reveal[Cell{1, 1}] = 12;
  r.reveal_period_s = 0.25;
  return r;
}

TEST(Recording, MarkersEventsRevealAndGraphTimesRoundTrip) {
  const Recording r = with_story();
  const std::string json = to_json(r);
  EXPECT_NE(json.find("\"shown_from\":0.75"), std::string::npos) << json;
  EXPECT_NE(json.find("\"reveal\":{\"cells\":[0,4,12,1,-1,1],\"period_s\":0.25}"),
            std::string::npos)
      << json;
  const Recording back = from_json(json);
  EXPECT_EQ(back, r);
  EXPECT_EQ(back.markers[1].robot, -1);
  EXPECT_EQ(back.events[1].robot, 7);
  // The last event lies after every pose: the replay runs until it.
  EXPECT_DOUBLE_EQ(back.end_time(), 4.0);
}

TEST(Recording, BadMarkersEventsAndRevealAreRejected) {
  const auto fails_with = [](Recording r, const std::string& what) {
    try {
      (void)to_json(r);
      ADD_FAILURE() << "accepted; expected an error naming " << what;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  Recording r = with_story();
  r.markers[0].kind = "flag";
  fails_with(r, "markers[0].kind");
  r = with_story();
  r.markers[0].robot = 3;
  fails_with(r, "markers[0].robot");
  r = with_story();
  r.events[1].robot = 8;
  fails_with(r, "events[1].robot");
  r = with_story();
  r.events[0].t = std::numeric_limits<double>::quiet_NaN();
  fails_with(r, "events[0].t");
  r = with_story();
  r.reveal = GridMap<std::int32_t>(GridGeometry{2, 2, 0.5, {}}, 0);
  fails_with(r, "reveal.cells");
  r = with_story();
  r.reveal[Cell{0, 0}] = -2;
  fails_with(r, "reveal.cells");
  r = with_story();
  r.graph_appearances[0].graph = 5;
  fails_with(r, "graph_appearances[0]");
  EXPECT_THROW((void)from_json(R"({"format":"voronav-recording","version":1,
      "map":{"width":1,"height":1,"resolution":1,"occupancy":[0,1]},
      "events":[{"t":1}]})"),
               Error);
}

TEST(Recording, TimesSpanTracksMessagesAndChanges) {
  const Recording r = small();
  EXPECT_DOUBLE_EQ(r.start_time(), 0.0);
  EXPECT_DOUBLE_EQ(r.end_time(), 2.0);
  Recording empty;
  EXPECT_DOUBLE_EQ(empty.start_time(), 0.0);
  EXPECT_DOUBLE_EQ(empty.end_time(), 0.0);
  Recording late = small();
  late.obstacle_changes[0].t = 5.0;
  EXPECT_DOUBLE_EQ(late.end_time(), 5.0);
}

TEST(Recording, PoseAtInterpolatesAndClamps) {
  RobotTrack t{1, "", 0.3, "", {{1.0, {{0.0, 0.0}, 3.0}}, {3.0, {{2.0, 4.0}, -3.0}}}};
  const Pose2 mid = pose_at(t, 2.0);
  EXPECT_DOUBLE_EQ(mid.position.x, 1.0);
  EXPECT_DOUBLE_EQ(mid.position.y, 2.0);
  // From 3 rad to -3 rad the short way passes through pi, not through 0.
  EXPECT_NEAR(std::abs(mid.yaw), std::numbers::pi, 1e-12);
  EXPECT_EQ(pose_at(t, -10.0), t.poses.front().pose);
  EXPECT_EQ(pose_at(t, 10.0), t.poses.back().pose);
  RobotTrack empty;
  EXPECT_THROW((void)pose_at(empty, 0.0), Error);
}

// Expects from_json(text) to throw an Error whose message contains `needle`.
void expect_error(const std::string& text, const std::string& needle) {
  try {
    (void)from_json(text, "rec.json");
    ADD_FAILURE() << "no error for: " << text;
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos)
        << "message '" << e.what() << "' lacks '" << needle << "'";
    EXPECT_EQ(e.source(), "rec.json");
  }
}

std::string with_map(const std::string& map, const std::string& rest = "") {
  return R"({"format":"voronav-recording","version":1,"map":)" + map + rest + "}";
}
const std::string kMap = R"({"width":2,"height":1,"resolution":0.1,"occupancy":[0,2]})";

TEST(Recording, MalformedJsonNamesTheLine) {
  try {
    (void)from_json("{\n\"format\": \"voronav-recording\",\n\"version\": 1,\n  oops\n}", "x.json");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.source(), "x.json");
    EXPECT_EQ(e.line(), 4);
  }
  expect_error("", "invalid JSON");
  expect_error("[1,2]", "expected a JSON object");
  expect_error(R"({"format":"other","version":1})", "format");
  expect_error(R"({"format":"voronav-recording","version":2})", "unsupported version 2");
  expect_error(R"({"format":"voronav-recording","version":1})", "map: missing");
}

TEST(Recording, BadMapsAreRejected) {
  EXPECT_NO_THROW((void)from_json(with_map(kMap)));
  expect_error(with_map(R"({"width":0,"height":1,"resolution":0.1,"occupancy":[]})"), "positive");
  expect_error(with_map(R"({"width":2,"height":1,"resolution":-1,"occupancy":[0,2]})"),
               "map.resolution");
  expect_error(with_map(R"({"width":2,"height":1,"resolution":0.1,"occupancy":[0,1]})"),
               "holds 1 cells, expected 2");
  expect_error(with_map(R"({"width":2,"height":1,"resolution":0.1,"occupancy":[0,3]})"),
               "more than the 2 cells");
  expect_error(with_map(R"({"width":2,"height":1,"resolution":0.1,"occupancy":[0,2,5]})"), "pairs");
  expect_error(with_map(R"({"width":2,"height":1,"resolution":0.1,"occupancy":[101,2]})"),
               "map.occupancy[0]: expected an integer in [-1, 100]");
  expect_error(with_map(R"({"width":2,"height":1,"resolution":0.1,"occupancy":[0,0,0,2]})"),
               "map.occupancy[1]");
  expect_error(with_map(R"({"width":2,"height":1,"resolution":"a","occupancy":[0,2]})"),
               "expected a number");
  expect_error(with_map(R"({"width":100000,"height":100000,"resolution":1,"occupancy":[0,2]})"),
               "10^8");
  expect_error(with_map(kMap, R"(,"rasters":[{"name":"v","cells":[1,1]}])"), "rasters[0].cells");
  expect_error(with_map(kMap, R"(,"rasters":[{"name":"v","style":"x","cells":[1,2]}])"),
               "rasters[0].style");
  expect_error(with_map(kMap, R"(,"rasters":[{"name":"v","color":"red","cells":[1,2]}])"),
               "colour");
}

TEST(Recording, BadTracksMessagesAndPlotsAreRejected) {
  const std::string robot = R"({"id":1,"poses":[[0,0,0,0],[1,0.1,0,0]]})";
  EXPECT_NO_THROW((void)from_json(with_map(kMap, R"(,"robots":[)" + robot + "]")));
  expect_error(with_map(kMap, R"(,"robots":[{"id":1,"poses":[[1,0,0,0],[0,0,0,0]]}])"),
               "robots[0].poses[1].t: times must be non-decreasing");
  expect_error(with_map(kMap, R"(,"robots":[{"id":1,"poses":[]}])"), "at least one pose");
  expect_error(with_map(kMap, R"(,"robots":[{"id":1,"radius":0,"poses":[[0,0,0,0]]}])"), "radius");
  expect_error(with_map(kMap, R"(,"robots":[{"id":1,"poses":[[0,0,0]]}])"), "[t, x, y, yaw]");
  expect_error(with_map(kMap, R"(,"robots":[)" + robot + "," + robot + "]"), "duplicate robot id");
  expect_error(
      with_map(kMap, R"(,"robots":[)" + robot + R"(],"messages":[{"t":0,"from":1,"to":2}])"),
      "messages[0].to: unknown robot id 2");
  expect_error(with_map(kMap, R"(,"robots":[)" + robot + R"(],"paths":[{"robot":3,"points":[]}])"),
               "paths[0].robot");
  expect_error(with_map(kMap, R"(,"obstacle_changes":[{"t":1,"cells":[[2,0]]}])"),
               "outside the map");
  expect_error(with_map(kMap, R"(,"plots":[{"kind":"line","series":[{"x":[1,2],"y":[1]}]}])"),
               "x has 2 values but y has 1");
  expect_error(
      with_map(kMap, R"(,"plots":[{"kind":"bar","categories":["a"],"series":[{"y":[1,2]}]}])"),
      "one value per category");
  expect_error(with_map(kMap, R"(,"plots":[{"kind":"pie","series":[]}])"), "plots[0].kind");
  expect_error(
      with_map(kMap, R"(,"graphs":[{"name":"g","nodes":[{"id":1,"p":[0,0]}],"edges":[[1,2]]}])"),
      "does not exist");
  expect_error(with_map(kMap, R"(,"message_display_s":0)"), "message_display_s");
}

TEST(Recording, ValidateRejectsNonFiniteValuesAndMismatchedRasters) {
  Recording r = small();
  r.robots[0].poses[1].pose.position.x = std::nan("");
  EXPECT_THROW(validate(r), Error);
  EXPECT_THROW((void)to_json(r), Error);
  r = small();
  r.plots[0].series[0].y[1] = std::numeric_limits<double>::infinity();
  EXPECT_THROW(validate(r), Error);
  r = small();
  r.rasters.push_back({"v", RasterStyle::kMask, "#ff0000", true, GridMap<std::int32_t>(2, 2)});
  EXPECT_THROW(validate(r), Error);
  r = small();
  r.map[Cell{0, 0}] = 120;
  EXPECT_THROW(validate(r), Error);
  EXPECT_THROW(validate(Recording{}), Error);
  EXPECT_THROW((void)load_recording("/nonexistent/dir/rec.json"), Error);
}

}  // namespace
}  // namespace voronav::report
