#include "voronav/sim/scenario_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "voronav/core/error.hpp"
#include "voronav/io/ros_map.hpp"
#include "voronav/sim/scenarios.hpp"

namespace voronav::sim {
namespace {

namespace fs = std::filesystem;

/// A fresh folder per test under the system temp folder.
fs::path temp_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path d = fs::temp_directory_path() / (std::string("voronav_scenario_file_") +
                                                  info->test_suite_name() + "_" + info->name());
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

void write(const fs::path& p, const std::string& text) {
  std::ofstream(p) << text;
}

void expect_same_options(const NetSimOptions& a, const NetSimOptions& b) {
  EXPECT_EQ(a.method, b.method);
  EXPECT_EQ(a.sensing_range_m, b.sensing_range_m);
  EXPECT_EQ(a.speed_mps, b.speed_mps);
  EXPECT_EQ(a.robot_radius_m, b.robot_radius_m);
  EXPECT_EQ(a.dt_s, b.dt_s);
  EXPECT_EQ(a.time_limit_s, b.time_limit_s);
  EXPECT_EQ(a.radio.range_m, b.radio.range_m);
  EXPECT_EQ(a.radio.latency_s, b.radio.latency_s);
  EXPECT_EQ(a.radio.jitter_s, b.radio.jitter_s);
  EXPECT_EQ(a.radio.loss, b.radio.loss);
  EXPECT_EQ(a.radio.duplicate, b.radio.duplicate);
  EXPECT_EQ(a.radio.reorder, b.radio.reorder);
  EXPECT_EQ(a.radio.reorder_delay_s, b.radio.reorder_delay_s);
  EXPECT_EQ(a.radio.seed, b.radio.seed);
  EXPECT_EQ(a.points.min_site_separation_cells, b.points.min_site_separation_cells);
  EXPECT_EQ(a.points.close_point_spacing_m, b.points.close_point_spacing_m);
  EXPECT_EQ(a.path_wait_s, b.path_wait_s);
  EXPECT_EQ(a.bridge_wait_s, b.bridge_wait_s);
  EXPECT_EQ(a.search_timeout_s, b.search_timeout_s);
  EXPECT_EQ(a.max_search_attempts, b.max_search_attempts);
  EXPECT_EQ(a.link_timeout_s, b.link_timeout_s);
  EXPECT_EQ(a.link_retries, b.link_retries);
  EXPECT_EQ(a.hop_limit, b.hop_limit);
  EXPECT_EQ(a.repair_hops, b.repair_hops);
  EXPECT_EQ(a.repair_expand_hops, b.repair_expand_hops);
  EXPECT_EQ(a.collect_s, b.collect_s);
  EXPECT_EQ(a.repair_timeout_s, b.repair_timeout_s);
  EXPECT_EQ(a.repair_resend_s, b.repair_resend_s);
  EXPECT_EQ(a.repair_check_answer, b.repair_check_answer);
  EXPECT_EQ(a.repair_rejoin_m, b.repair_rejoin_m);
  EXPECT_EQ(a.repair_share_blocks, b.repair_share_blocks);
  EXPECT_EQ(a.repair_check_seen, b.repair_check_seen);
  EXPECT_EQ(a.repair_share_met_blocks, b.repair_share_met_blocks);
  EXPECT_EQ(a.repair_fix_answer, b.repair_fix_answer);
  EXPECT_EQ(a.repair_fix_seen_only, b.repair_fix_seen_only);
  EXPECT_EQ(a.repair_walk_keep_ratio, b.repair_walk_keep_ratio);
  EXPECT_EQ(a.repair_sense_walk, b.repair_sense_walk);
  EXPECT_EQ(a.repair_sense_wait_s, b.repair_sense_wait_s);
  EXPECT_EQ(a.path_fallback_after_retries, b.path_fallback_after_retries);
  EXPECT_EQ(a.search_timeout_per_m, b.search_timeout_per_m);
  EXPECT_EQ(a.search_activity_s, b.search_activity_s);
  EXPECT_EQ(a.keep_bridge_on_new_search, b.keep_bridge_on_new_search);
  EXPECT_EQ(a.source_straight_start, b.source_straight_start);
  EXPECT_EQ(a.frontier_by_points, b.frontier_by_points);
  EXPECT_EQ(a.walk_replan_whole_map, b.walk_replan_whole_map);
  EXPECT_EQ(a.seed, b.seed);
}

TEST(ScenarioFile, PaperRunWithEveryOptionSetRoundTripsExactly) {
  const fs::path d = temp_dir();
  NetSimScenario sc = make_paper_run(2, 1, 1);
  ObstacleChange at;  // at a simulated time (the paper runs' changes)
  at.at_s = 12.5;
  at.cells = {Cell{3, 4}, Cell{3, 5}};
  sc.changes.push_back(at);
  ObstacleChange after;  // after the first route, not a short decimal
  after.after_route_s = 0.1 + 0.2;
  after.cells = {Cell{7, 8}};
  after.value = kFree;
  sc.changes.push_back(after);
  sc.source = 3;
  NetSimOptions o;
  o.method = Method::kCentralized;
  o.sensing_range_m = 3.3;
  o.speed_mps = 0.7;
  o.robot_radius_m = 0.15;
  o.dt_s = 0.1;
  o.time_limit_s = 123.456;
  o.radio = {.range_m = 17.5,
             .latency_s = 1.0 / 3.0,
             .jitter_s = 0.002,
             .loss = 0.05,
             .duplicate = 0.01,
             .reorder = 0.02,
             .reorder_delay_s = 0.07,
             .seed = 18446744073709551615ull};
  o.points.min_site_separation_cells = 3.0;
  o.points.close_point_spacing_m = 1.25;
  o.path_wait_s = 0.25;
  o.bridge_wait_s = 2.5;
  o.search_timeout_s = 45.0;
  o.max_search_attempts = 5;
  o.link_timeout_s = 0.4;
  o.link_retries = 3;
  o.hop_limit = 20;
  o.repair_hops = 3;
  o.repair_expand_hops = 12;
  o.collect_s = 2.25;
  o.repair_timeout_s = 9.5;
  o.repair_resend_s = 2.5;
  o.repair_check_answer = false;
  o.repair_rejoin_m = 1.75;
  o.repair_share_blocks = false;
  o.repair_check_seen = false;
  o.repair_share_met_blocks = !o.repair_share_met_blocks;
  o.repair_fix_answer = !o.repair_fix_answer;
  o.repair_fix_seen_only = !o.repair_fix_seen_only;
  o.repair_walk_keep_ratio = 1.25;
  o.repair_sense_walk = !o.repair_sense_walk;
  o.repair_sense_wait_s = 42.5;
  o.path_fallback_after_retries = false;
  o.search_timeout_per_m = 2.75;
  o.search_activity_s = 31.5;
  o.keep_bridge_on_new_search = true;
  o.source_straight_start = true;
  o.frontier_by_points = true;
  o.walk_replan_whole_map = true;
  o.seed = 42;
  const fs::path path = d / "paper.yaml";
  save_netsim_scenario(path.string(), sc, o);
  EXPECT_TRUE(fs::exists(d / "paper_world.yaml"));
  EXPECT_TRUE(fs::exists(d / "paper_world.pgm"));

  const auto f = load_netsim_scenario(path.string());
  EXPECT_TRUE(f.has_method);
  EXPECT_EQ(fs::path(f.world_path), (d / "paper_world.yaml").lexically_normal());
  EXPECT_EQ(f.scenario.world.geometry(), sc.world.geometry());
  EXPECT_TRUE(f.scenario.world == sc.world);
  EXPECT_EQ(f.scenario.robots, sc.robots);
  EXPECT_EQ(f.scenario.source, sc.source);
  EXPECT_EQ(f.scenario.destination, sc.destination);
  ASSERT_EQ(f.scenario.changes.size(), sc.changes.size());
  for (std::size_t i = 0; i < sc.changes.size(); ++i) {
    EXPECT_EQ(f.scenario.changes[i].after_route_s, sc.changes[i].after_route_s);
    EXPECT_EQ(f.scenario.changes[i].at_s, sc.changes[i].at_s);
    EXPECT_EQ(f.scenario.changes[i].cells, sc.changes[i].cells);
    EXPECT_EQ(f.scenario.changes[i].value, sc.changes[i].value);
  }
  expect_same_options(f.options, o);
}

// A 10 m x 10 m room at 0.5 m/cell with a wall ring and one pillar at cells (9..10, 9..10).
class MalformedScenario : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = temp_dir();
    OccupancyGrid g(GridGeometry{20, 20, 0.5, {}}, kFree);
    for (int i = 0; i < 20; ++i)
      g[Cell{i, 0}] = g[Cell{i, 19}] = g[Cell{0, i}] = g[Cell{19, i}] = kOccupied;
    for (int y = 9; y <= 10; ++y)
      for (int x = 9; x <= 10; ++x)
        g[Cell{x, y}] = kOccupied;
    io::save_ros_map(g, dir_ / "room.yaml");
  }
  /// Loads `text` and expects an error "<file>:<line>: ..." whose message contains `needle`.
  void expect_error(const std::string& text, int line, const std::string& needle) {
    const fs::path p = dir_ / "bad.yaml";
    write(p, text);
    try {
      (void)load_netsim_scenario(p.string());
      ADD_FAILURE() << "no error for:\n" << text;
    } catch (const Error& e) {
      EXPECT_EQ(e.source(), p.string());
      EXPECT_EQ(e.line(), line) << e.what();
      const std::string prefix = p.string() + ":" + std::to_string(line) + ":";
      EXPECT_EQ(std::string(e.what()).rfind(prefix, 0), 0u) << e.what();
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  }
  fs::path dir_;
};

const char* const kGood =
    "world: room.yaml\n"                    // 1
    "robots:\n"                             // 2
    "  - [1.25, 1.25]\n"                    // 3
    "  - [8.25, 8.25]\n"                    // 4
    "destination: [8.75, 1.25]\n"           // 5
    "changes:\n"                            // 6
    "  - after_route_s: 2\n"                // 7
    "    value: occupied\n"                 // 8
    "    rect: [5.0, 0.5, 5.5, 9.5]\n"      // 9
    "options:\n"                            // 10
    "  sensing_range_m: 2.5\n"              // 11
    "  radio: {range_m: 12, loss: 0.1}\n";  // 12

TEST_F(MalformedScenario, GoodFileLoads) {
  write(dir_ / "good.yaml", kGood);
  const auto f = load_netsim_scenario((dir_ / "good.yaml").string());
  EXPECT_FALSE(f.has_method);
  EXPECT_EQ(f.scenario.robots.size(), 2u);
  EXPECT_EQ(f.scenario.destination, (Vec2{8.75, 1.25}));
  ASSERT_EQ(f.scenario.changes.size(), 1u);
  EXPECT_EQ(f.scenario.changes[0].cells.size(), 18u);  // x = 5.25 only; y = 0.75..9.25
  EXPECT_EQ(f.options.sensing_range_m, 2.5);
  EXPECT_EQ(f.options.radio.range_m, 12.0);
  EXPECT_EQ(f.options.radio.loss, 0.1);
  EXPECT_EQ(f.options.speed_mps, NetSimOptions{}.speed_mps);
}

TEST_F(MalformedScenario, MissingWorld) {
  expect_error("robots: [[1.25, 1.25]]\ndestination: [8.75, 1.25]\n", 1, "missing key 'world'");
}

TEST_F(MalformedScenario, UnknownKey) {
  std::string t = kGood;
  t.replace(t.find("  sensing_range_m"), 2, "  speed: 3\n  ");
  expect_error(t, 11, "unknown key 'speed'");
  expect_error(std::string(kGood) + "robot: 3\n", 13, "unknown key 'robot'");
}

TEST_F(MalformedScenario, RobotInObstacle) {
  std::string t = kGood;
  t.replace(t.find("[8.25, 8.25]"), 12, "[4.75, 5.25]");  // cell (9, 10): the pillar
  expect_error(t, 4, "robots[1]: [4.75, 5.25] is inside an obstacle");
}

TEST_F(MalformedScenario, NanCoordinate) {
  std::string t = kGood;
  t.replace(t.find("[1.25, 1.25]"), 12, "[1.25, .nan]");
  expect_error(t, 3, "robots[0] y: expected a finite number");
}

TEST_F(MalformedScenario, OutOfMapDestination) {
  std::string t = kGood;
  t.replace(t.find("[8.75, 1.25]"), 12, "[8.75, -1.5]");
  expect_error(t, 5, "destination: [8.75, -1.5] is outside the map");
}

TEST_F(MalformedScenario, BadChangeValue) {
  std::string t = kGood;
  t.replace(t.find("occupied"), 8, "closed");
  expect_error(t, 8, "changes[0].value: expected occupied or free, got 'closed'");
}

TEST_F(MalformedScenario, WorldFileMissing) {
  std::string t = kGood;
  t.replace(t.find("room.yaml"), 9, "nothing.yaml");
  expect_error(t, 1, "world: map file 'nothing.yaml' not found");
}

TEST_F(MalformedScenario, WorldFileNameTooLongIsAnErrorNotAFileSystemException) {
  // Found by fuzz_netsim_scenario: a name longer than NAME_MAX made std::filesystem throw.
  std::string t = kGood;
  const std::string name(400, 'w');
  t.replace(t.find("room.yaml"), 9, name);
  expect_error(t, 1, "world: map file '" + name + "' not found");
}

TEST_F(MalformedScenario, NegativeAndBadNumbersNameTheField) {
  std::string t = kGood;
  t.replace(t.find("2.5"), 3, "-1");
  expect_error(t, 11, "options.sensing_range_m: expected a number > 0");
  t = kGood;
  t.replace(t.find("loss: 0.1"), 9, "loss: 1.5");
  expect_error(t, 12, "options.radio.loss: expected a probability");
  t = kGood;
  t.replace(t.find("after_route_s: 2"), 16, "after_route_s: x");
  expect_error(t, 7, "changes[0].after_route_s: expected a number, got 'x'");
}

TEST_F(MalformedScenario, PlacementOnAnyGrid) {
  write(dir_ / "placed.yaml",
        "world: room.yaml\nplacement: {robots: 5, seed: 3}\nchanges:\n"
        "  - {after_route_s: 1.5, value: free, cells: [[9, 9]]}\n");
  const auto f = load_netsim_scenario((dir_ / "placed.yaml").string());
  EXPECT_EQ(f.scenario.robots.size(), 5u);
  EXPECT_NO_THROW(f.scenario.validate());
  EXPECT_GT(distance(f.scenario.robots[0], f.scenario.destination), 1.0);
  ASSERT_EQ(f.scenario.changes.size(), 1u);
  EXPECT_EQ(f.scenario.changes[0].value, kFree);
  EXPECT_EQ(f.scenario.changes[0].cells, (std::vector<Cell>{{9, 9}}));
  expect_error("world: room.yaml\nplacement: {robots: 0}\n", 2,
               "placement.robots: expected an integer in 1..100000");
}

// The bundled example scenarios on the real ROS maps: both methods reach the destination; the
// decentralized route is built by relays.
TEST(ScenarioFile, ExamplesOnTheRosMapsSucceedWithBothMethods) {
  for (const char* name : {"turtlebot3_world.yaml", "depot.yaml"}) {
    const auto f =
        load_netsim_scenario((fs::path(VORONAV_SOURCE_DIR) / "data/netsim" / name).string());
    EXPECT_FALSE(f.scenario.changes.empty()) << name;
    for (const Method m : {Method::kCentralized, Method::kDecentralized}) {
      NetSimOptions o = f.options;
      o.method = m;
      const auto r = run_netsim(f.scenario, o);
      EXPECT_TRUE(r.metrics.success) << name << " " << to_string(m);
      if (m == Method::kDecentralized) {
        EXPECT_EQ(r.metrics.route_found_by, RouteFoundBy::kRelays) << name;
      }
    }
  }
}

}  // namespace
}  // namespace voronav::sim
