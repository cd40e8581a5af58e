// Tests of the team bans of ExplorationOptions::share_bans (internal/team_bans.hpp) on a
// hand-made 2 x 1 m map: a frontier cell whose one unknown neighbour is seen from the target cell
// along a free line, or hidden behind an occupied cell on that line.
#include "voronav/exploration/internal/team_bans.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace voronav::exploration::internal {
namespace {

constexpr double kRange = 3.0;   // [m] the laser's range
constexpr double kPeriod = 1.0;  // [s] the mapping scan period

struct Case {
  OccupancyGrid map;
  GridMap<float> log_odds;  // 0 = unknown
  Frontier frontier;
};

// Free x < 10, occupied x >= 10 except the unknown cell (10, 5); frontier cell (9, 5), target
// (5, 5); with `hidden`, (7, 5), on the line from the target to the unknown cell, is occupied.
Case make_case(bool hidden) {
  const GridGeometry g{20, 10, 0.1, {}};
  Case k{OccupancyGrid(g, kFree), GridMap<float>(g, -2.0F), {}};
  for (int y = 0; y < 10; ++y)
    for (int x = 10; x < 20; ++x) {
      k.map[Cell{x, y}] = kOccupied;
      k.log_odds[Cell{x, y}] = 2.0F;
    }
  k.map[Cell{10, 5}] = kUnknown;
  k.log_odds[Cell{10, 5}] = 0.0F;
  if (hidden) {
    k.map[Cell{7, 5}] = kOccupied;
    k.log_odds[Cell{7, 5}] = 2.0F;
  }
  k.frontier.cells = {Cell{9, 5}};
  k.frontier.target = Cell{5, 5};
  k.frontier.centroid = g.cell_center(Cell{9, 5});
  return k;
}

TEST(TeamBans, AFrontierIsObservableOnlyAlongAFreeLineWithinRange) {
  const Case seen = make_case(false), hidden = make_case(true);
  EXPECT_TRUE(TeamBans::observable_from_target(seen.map, seen.frontier, kRange));
  EXPECT_FALSE(TeamBans::observable_from_target(hidden.map, hidden.frontier, kRange));
  // The unknown cell is 0.5 m from the target: out of a 0.4 m range.
  EXPECT_FALSE(TeamBans::observable_from_target(seen.map, seen.frontier, 0.4));
}

TEST(TeamBans, AReachedGoalIsBannedAfterAScanAndUntilTheMapAroundItChanges) {
  Case k = make_case(true);
  const Vec2 goal = k.map.geometry().cell_center(k.frontier.target);
  const std::vector<Frontier> fr{k.frontier};
  TeamBans bans;
  bans.reached(goal, 10.0);
  EXPECT_EQ(bans.update(k.map, k.log_odds, fr, kRange, 10.5, kPeriod), 0);  // no scan yet
  EXPECT_FALSE(bans.banned(goal));
  EXPECT_EQ(bans.update(k.map, k.log_odds, fr, kRange, 11.0, kPeriod), 1);
  EXPECT_TRUE(bans.banned(goal));
  EXPECT_TRUE(bans.banned(goal + Vec2{0.0, 0.4}));
  EXPECT_FALSE(bans.banned(goal + Vec2{0.0, 0.6}));
  // Judged once: no second ban, and the ban holds while the map around it stays.
  EXPECT_EQ(bans.update(k.map, k.log_odds, fr, kRange, 20.0, kPeriod), 0);
  EXPECT_TRUE(bans.banned(goal));
  // A cell within 1 m of the goal becomes unknown (or known): new information lifts the ban.
  k.log_odds[Cell{5, 9}] = 0.0F;
  EXPECT_EQ(bans.update(k.map, k.log_odds, fr, kRange, 21.0, kPeriod), 0);
  EXPECT_FALSE(bans.banned(goal));
}

TEST(TeamBans, NoBanWhenTheFrontierCanBeSeenOrIsGone) {
  const Case seen = make_case(false);
  const Vec2 goal = seen.map.geometry().cell_center(seen.frontier.target);
  TeamBans bans;
  bans.reached(goal, 0.0);
  const std::vector<Frontier> fr{seen.frontier};
  EXPECT_EQ(bans.update(seen.map, seen.log_odds, fr, kRange, 5.0, kPeriod), 0);
  EXPECT_FALSE(bans.banned(goal));
  const Case hidden = make_case(true);
  bans.reached(goal, 0.0);
  EXPECT_EQ(bans.update(hidden.map, hidden.log_odds, {}, kRange, 5.0, kPeriod), 0);  // gone
  EXPECT_FALSE(bans.banned(goal));
}

}  // namespace
}  // namespace voronav::exploration::internal
