// Tests of the synthetic example recording: it must be realistic enough to test the page, so its
// robots stay in free space, its coverage behaves like coverage, and its messages and re-plan are
// consistent with the tracks.
#include "voronav/report/example_recording.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "voronav/core/cell_iterators.hpp"
#include "voronav/core/error.hpp"

namespace voronav::report {
namespace {

// The occupancy at time t: the map with the changes up to t applied.
OccupancyGrid world_at(const Recording& r, double t) {
  OccupancyGrid g = r.map;
  for (const auto& c : r.obstacle_changes)
    if (c.t <= t)
      for (const Cell& cell : c.cells)
        g[cell] = c.value;
  return g;
}

bool disc_is_free(const OccupancyGrid& g, Vec2 p, double radius) {
  const auto c = g.geometry().world_to_cell(p);
  if (!c) return false;
  bool free = true;
  for_each_disc_cell(*c, radius / g.resolution(), [&](Cell q) {
    if (!g.contains(q) || g[q] != kFree) free = false;
  });
  return free;
}

TEST(ExampleRecording, IsValidAndDeterministic) {
  const Recording a = make_example_recording();
  EXPECT_NO_THROW(validate(a));
  EXPECT_EQ(a, make_example_recording());
  EXPECT_EQ(a.robots.size(), 3u);
  EXPECT_EQ(a.map.width(), 320);
  EXPECT_EQ(a.map.height(), 200);
  EXPECT_EQ(a.obstacle_changes.size(), 1u);
  EXPECT_GT(a.messages.size(), 50u);
  EXPECT_GT(a.end_time(), 30.0);
  EXPECT_LT(a.end_time(), 120.0);
}

TEST(ExampleRecording, RobotsStayInFreeSpaceAndApart) {
  const Recording r = make_example_recording();
  for (double t = r.start_time(); t <= r.end_time(); t += 0.1) {
    const OccupancyGrid g = world_at(r, t);
    for (const auto& robot : r.robots) {
      const Vec2 p = pose_at(robot, t).position;
      EXPECT_TRUE(disc_is_free(g, p, robot.radius - 0.1))
          << robot.name << " hits an obstacle at t = " << t << " at " << p.x << ", " << p.y;
    }
    for (std::size_t i = 0; i < r.robots.size(); ++i)
      for (std::size_t j = i + 1; j < r.robots.size(); ++j)
        EXPECT_GT(distance(pose_at(r.robots[i], t).position, pose_at(r.robots[j], t).position),
                  r.robots[i].radius + r.robots[j].radius)
            << "robots " << i << " and " << j << " collide at t = " << t;
  }
}

TEST(ExampleRecording, SpeedsMatchTheRoutes) {
  const Recording r = make_example_recording();
  const double speeds[] = {0.7, 0.8, 1.0};
  for (std::size_t i = 0; i < r.robots.size(); ++i) {
    const auto& p = r.robots[i].poses;
    for (std::size_t k = 1; k < p.size(); ++k) {
      const double dt = p[k].t - p[k - 1].t;
      ASSERT_GT(dt, 0.0);
      EXPECT_LE(distance(p[k].pose.position, p[k - 1].pose.position) / dt, speeds[i] + 1e-9);
    }
  }
}

TEST(ExampleRecording, CoverageIsMonotoneAndTheTeamCoversMost) {
  const Recording r = make_example_recording();
  ASSERT_GE(r.plots.size(), 2u);
  const Plot& cov = r.plots[0];
  EXPECT_TRUE(cov.time_axis);
  ASSERT_EQ(cov.series.size(), 4u);
  const Series& team = cov.series.back();
  for (const auto& s : cov.series) {
    EXPECT_TRUE(std::is_sorted(s.y.begin(), s.y.end())) << s.name;
    EXPECT_GE(s.y.front(), 0.0);
    EXPECT_LE(s.y.back(), 100.0);
  }
  for (std::size_t k = 0; k < team.y.size(); ++k)
    for (std::size_t s = 0; s + 1 < cov.series.size(); ++s)
      EXPECT_GE(team.y[k], cov.series[s].y[k]);
  EXPECT_GT(team.y.back(), 50.0);  // three robots visit four of six regions
  EXPECT_LT(team.y.front(), 10.0);
}

TEST(ExampleRecording, RobotOneRePlansAroundTheBox) {
  const Recording r = make_example_recording();
  const auto& change = r.obstacle_changes.front();
  std::vector<const PathRecord*> mine;
  for (const auto& p : r.paths)
    if (p.robot == 1) mine.push_back(&p);
  ASSERT_EQ(mine.size(), 2u);
  EXPECT_DOUBLE_EQ(mine[1]->t_start, change.t);
  // The first plan runs through the box, the repair path does not.
  auto crosses_box = [&](const std::vector<Vec2>& pts) {
    OccupancyGrid g = world_at(r, change.t);
    for (std::size_t k = 0; k + 1 < pts.size(); ++k) {
      const auto a = g.geometry().world_to_cell(pts[k]), b = g.geometry().world_to_cell(pts[k + 1]);
      bool hit = false;
      for_each_line_cell(*a, *b, [&](Cell c) {
        if (g[c] == kOccupied) hit = true;
      });
      if (hit) return true;
    }
    return false;
  };
  EXPECT_TRUE(crosses_box(mine[0]->points));
  EXPECT_FALSE(crosses_box(mine[1]->points));
  EXPECT_EQ(mine[1]->points.front(), pose_at(r.robots[1], change.t).position);
}

TEST(ExampleRecording, MessagesRespectRadioRangeAndTrafficAddsUp) {
  ExampleOptions o;
  const Recording r = make_example_recording(o);
  double bytes = 0;
  for (const auto& m : r.messages) {
    EXPECT_NE(m.from, m.to);
    EXPECT_LE(distance(pose_at(r.robots[static_cast<std::size_t>(m.from)], m.t).position,
                       pose_at(r.robots[static_cast<std::size_t>(m.to)], m.t).position),
              o.radio_range_m);
    bytes += static_cast<double>(m.bytes);
  }
  double bars = 0;
  for (const auto& s : r.plots[1].series)
    for (double v : s.y)
      bars += v;
  EXPECT_DOUBLE_EQ(bars, bytes);
  // A shorter radio range drops messages.
  o.radio_range_m = 5.0;
  EXPECT_LT(make_example_recording(o).messages.size(), r.messages.size());
}

TEST(ExampleRecording, BadOptionsAreRejected) {
  ExampleOptions o;
  o.sample_period_s = 0.0;
  EXPECT_THROW((void)make_example_recording(o), Error);
  o = {};
  o.sensor_range_m = std::nan("");
  EXPECT_THROW((void)make_example_recording(o), Error);
}

}  // namespace
}  // namespace voronav::report
