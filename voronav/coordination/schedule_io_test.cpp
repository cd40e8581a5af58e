#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "voronav/coordination/coordinator.hpp"
#include "voronav/coordination/scenario.hpp"
#include "voronav/coordination/schedule_io.hpp"
#include "voronav/core/error.hpp"

namespace voronav::coordination {
namespace {

namespace fs = std::filesystem;

Schedule sample() {
  Schedule s;
  s.agents.push_back({7, TimedPath({{-10, 0}, {10, 0}}, {1.0, kInfinity}), 0.5});
  s.agents.push_back({9, TimedPath({{0, -10}, {0, 3}, {2, 10}}, {1.5, 0.75}), 0.25});
  s.delays = {0.0, 2.125};
  s.at_start = AtStart::kAppear;
  s.at_goal = AtGoal::kLeave;
  s.valid = true;
  return s;
}

void expect_same(const Schedule& a, const Schedule& b) {
  ASSERT_EQ(a.agents.size(), b.agents.size());
  EXPECT_EQ(a.at_start, b.at_start);
  EXPECT_EQ(a.at_goal, b.at_goal);
  EXPECT_EQ(a.valid, b.valid);
  for (std::size_t i = 0; i < a.agents.size(); ++i) {
    EXPECT_EQ(a.agents[i].id, b.agents[i].id);
    EXPECT_DOUBLE_EQ(a.agents[i].radius, b.agents[i].radius);
    EXPECT_DOUBLE_EQ(a.agents[i].path.limits().v_max, b.agents[i].path.limits().v_max);
    EXPECT_EQ(a.agents[i].path.limits().a_max, b.agents[i].path.limits().a_max);
    EXPECT_EQ(a.agents[i].path.nodes(), b.agents[i].path.nodes());
    EXPECT_DOUBLE_EQ(a.delays[i], b.delays[i]);
  }
}

TEST(ScheduleIo, JsonAndYamlRoundTrip) {
  const Schedule s = sample();
  expect_same(s, parse_schedule(schedule_to_json(s), "mem.json"));
  expect_same(s, parse_schedule(schedule_to_yaml(s), "mem.yaml"));
  const fs::path dir = fs::temp_directory_path() / "voronav_schedule_io_test";
  fs::create_directories(dir);
  write_schedule(dir / "s.json", s);
  write_schedule(dir / "s.yml", s);
  expect_same(s, read_schedule(dir / "s.json"));
  expect_same(s, read_schedule(dir / "s.yml"));
  EXPECT_THROW(write_schedule(dir / "s.txt", s), Error);
  fs::remove_all(dir);
}

TEST(ScheduleIo, MalformedInputNamesTheProblem) {
  auto fails_with = [](const std::string& text, const std::string& needle) {
    try {
      (void)parse_schedule(text, "bad.json");
      ADD_FAILURE() << "no error for " << text;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
      EXPECT_EQ(e.source(), "bad.json");
    }
  };
  fails_with("[1, 2]", "agents");
  fails_with("{\"agents\": 3}", "agents");
  fails_with("{\"agents\": [{\"id\": 1, \"radius\": 0.5, \"v_max\": 1, \"delay\": 0}]}", "path");
  fails_with(
      "{\"agents\": [{\"id\": 1, \"radius\": 0.5, \"v_max\": 1, \"delay\": -2, "
      "\"path\": [[0, 0]]}]}",
      "delay");
  fails_with(
      "{\"agents\": [{\"id\": 1, \"radius\": 0.5, \"v_max\": \"x\", \"delay\": 0, "
      "\"path\": [[0, 0]]}]}",
      "v_max");
  fails_with(
      "{\"agents\": [{\"id\": 1, \"radius\": 0.5, \"v_max\": 0, \"delay\": 0, "
      "\"path\": [[0, 0]]}]}",
      "v_max");
  fails_with(
      "{\"agents\": [{\"id\": 1, \"radius\": 0.5, \"v_max\": 1, \"delay\": 0, "
      "\"path\": [[0, 0, 3]]}]}",
      "[x, y]");
  fails_with("{\"at_start\": \"sit\", \"agents\": []}", "at_start");
  fails_with("{agents: [", "not valid");
  EXPECT_THROW((void)read_schedule("/nonexistent/schedule.json"), Error);
}

TEST(Scenario, BundledScenarioPlansAndCoordinates) {
  const Scenario sc =
      load_scenario(fs::path(VORONAV_SOURCE_DIR) / "data/coordination/arena_four.yaml");
  ASSERT_EQ(sc.robots.size(), 4u);
  EXPECT_TRUE(sc.cell_coordinates);
  EXPECT_DOUBLE_EQ(sc.robots[1].limits.v_max, 2.0);
  EXPECT_DOUBLE_EQ(sc.robots[1].limits.a_max, 1.0);
  const auto planned = plan_agents(sc);
  ASSERT_EQ(planned.agents.size(), 4u);
  // Moving AI (3, 5) with y down is cell (3, 49 - 1 - 5) with row 0 at the bottom.
  EXPECT_EQ(planned.agents[0].path.nodes().front(), (Vec2{3.5, 43.5}));
  EXPECT_EQ(planned.agents[0].path.nodes().back(), (Vec2{45.5, 36.5}));
  CoordinateOptions o;
  o.map = sc.map_options;
  o.search.kind = SearchKind::kExhaustive;
  const auto r = coordinate(planned.agents, o);
  EXPECT_TRUE(r.valid);
}

TEST(Scenario, MapfFirstKRows) {
  const fs::path d = fs::path(VORONAV_SOURCE_DIR) / "data/mapf";
  const Scenario sc = load_mapf(d / "random-32-32-20.map", d / "random-32-32-20-random-1.scen", 12);
  ASSERT_EQ(sc.robots.size(), 12u);
  const auto planned = plan_agents(sc);
  CoordinateOptions o;
  o.map.at_start = AtStart::kAppear;
  o.map.at_goal = AtGoal::kLeave;
  const auto r = coordinate(planned.agents, o);
  EXPECT_EQ(r.status, ResolveStatus::kOk);
  EXPECT_TRUE(r.valid);
  EXPECT_THROW((void)load_mapf(d / "random-32-32-20.map", d / "random-32-32-20-random-1.scen", 0),
               Error);
}

TEST(Scenario, MalformedScenariosNameFileAndField) {
  const fs::path dir = fs::temp_directory_path() / "voronav_scenario_test";
  fs::create_directories(dir);
  auto fails_with = [&](const std::string& text, const std::string& needle) {
    const fs::path p = dir / "s.yaml";
    std::ofstream(p) << text;
    try {
      (void)plan_agents(load_scenario(p));
      ADD_FAILURE() << "no error for " << text;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
      EXPECT_NE(e.source().find("s.yaml"), std::string::npos) << e.what();
    }
  };
  fails_with("robots: []\n", "robots");
  fails_with("robots:\n  - {id: 1, start: [0, 0], goal: [1, 1]}\n", "map");
  fails_with("robots:\n  - {id: 1, path: [[0, 0], [1, .nan]]}\n", "path");
  fails_with("robots:\n  - {id: 1, path: [[0, 0]], radius: -1}\n", "radius");
  fails_with("robots:\n  - {id: 1, path: [[0, 0]], a_max: 0}\n", "a_max");
  fails_with("at_goal: fly\nrobots:\n  - {id: 1, path: [[0, 0]]}\n", "at_goal");
  fails_with("map: missing.map\nrobots: [{id: 1, start: [0, 0], goal: [5, 5]}]\n", "missing.map");
  const std::string arena = (fs::path(VORONAV_SOURCE_DIR) / "data/movingai/arena.map").string();
  // (0, 0) is a wall cell of the arena.
  fails_with("map: " + arena + "\nrobots: [{id: 1, start: [0, 0], goal: [5, 5]}]\n", "robot 1");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace voronav::coordination
