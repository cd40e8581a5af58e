// The continuous-time checker (issue #16): exact minimum per piece pair, contact accepted,
// min_clearance exact, the map checked.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "voronav/coordination/trajectory.hpp"
#include "voronav/coordination/verify.hpp"

namespace voronav::coordination {
namespace {

Agent agent(int id, std::vector<Vec2> nodes, double a = kInfinity, double r = 0.5) {
  return Agent{id, TimedPath(std::move(nodes), {1.0, a}), r};
}

TEST(Verify, TouchingDiscsWaitingLongAreValid) {
  // Two radius-0.5 discs at (0,0) and (1,0) wait 20 s (contact), then move apart.
  const std::vector<Agent> agents{agent(1, {{0, 0}, {-5, 0}}), agent(2, {{1, 0}, {6, 0}})};
  const std::vector<double> delays{20.0, 20.0};
  const Verification v = verify_schedule(agents, delays);
  EXPECT_TRUE(v.valid);
  EXPECT_EQ(v.undecided_pairs, 0);
  EXPECT_NEAR(v.min_clearance, 0.0, 1e-12);
  // One of them 1e-3 closer: a real overlap, found at once.
  const std::vector<Agent> closer{agent(1, {{0.001, 0}, {-5, 0}}), agent(2, {{1, 0}, {6, 0}})};
  const Verification w = verify_schedule(closer, delays);
  EXPECT_FALSE(w.valid);
  ASSERT_EQ(w.conflicts.size(), 1u);
  EXPECT_NEAR(w.conflicts[0].distance, 0.999, 1e-12);
}

TEST(Verify, MinClearanceIsTheExactMinimum) {
  // A along the x axis, B up the line x = 5 departing d seconds later: the centre distance is
  // minimal at t = 5 + d/2 and equals d / sqrt(2) (hand computed).
  for (const double d : {0.6616, 2.0, 3.5}) {
    const std::vector<Agent> agents{agent(1, {{0, 0}, {10, 0}}), agent(2, {{5, -5}, {5, 5}})};
    const std::vector<double> delays{0.0, d};
    VerifyOptions o;
    o.at_start = AtStart::kAppear;
    o.at_goal = AtGoal::kLeave;
    const Verification v = verify_schedule(agents, delays, o);
    EXPECT_NEAR(v.min_clearance, d / std::sqrt(2.0) - 1.0, 1e-12) << d;
    EXPECT_EQ(v.valid, d / std::sqrt(2.0) >= 1.0) << d;
  }
  // Sampling misses this one: minimum 0.4678 below the radii sum at t = 5.3308.
  const std::vector<Agent> agents{agent(1, {{0, 0}, {10, 0}}), agent(2, {{5, -5}, {5, 5}})};
  const std::vector<double> delays{0.0, 0.6616};
  VerifyOptions o;
  o.at_start = AtStart::kAppear;
  o.at_goal = AtGoal::kLeave;
  const Verification v = verify_schedule(agents, delays, o);
  ASSERT_EQ(v.conflicts.size(), 1u);
  EXPECT_NEAR(v.conflicts[0].distance, 0.6616 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(v.conflicts[0].time, 5.0 + 0.6616 / 2.0, 1e-9);
}

TEST(Verify, AcceleratingPiecesMatchDenseSampling) {
  // Finite a_max: pieces with acceleration; the exact minimum is never above a dense sample and
  // within the sampling error of it.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-5.0, 5.0);
  for (int k = 0; k < 20; ++k) {
    const Agent a = agent(1, {{u(rng), u(rng)}, {u(rng), u(rng)}, {u(rng), u(rng)}}, 0.7);
    const Agent b = agent(2, {{u(rng), u(rng)}, {u(rng), u(rng)}}, 1.3);
    const double da = std::abs(u(rng)), db = std::abs(u(rng));
    const Trajectory ta = trajectory_of(a.path, da, AtStart::kWait, AtGoal::kStay);
    const Trajectory tb = trajectory_of(b.path, db, AtStart::kWait, AtGoal::kStay);
    const double end = std::max(ta.end_time(), tb.end_time());
    double sampled = kInfinity;
    for (double t = 0.0; t <= end; t += 5e-4) {
      // the trajectory agrees with the timed path
      ASSERT_NEAR((ta.position(t) - a.path.position(t - da)).norm(), 0.0, 1e-9);
      sampled = std::min(sampled, (a.path.position(t - da) - b.path.position(t - db)).norm());
    }
    const MinDistance exact = min_distance(ta, tb, 0.0, kInfinity);
    EXPECT_LE(exact.distance, sampled + 1e-12);
    EXPECT_GE(exact.distance, sampled - 1e-3);  // relative speed <= 2, half a step
  }
}

TEST(Verify, WaypointTrajectories) {
  // Robot 1 waits at (0,0) until t = 3 then goes right; robot 2 passes over (0,0) at t = 1.
  const std::vector<TimedWaypoint> w1{{0.0, {0, 0}}, {3.0, {0, 0}}, {6.0, {3, 0}}};
  const std::vector<TimedWaypoint> w2{{0.0, {0, -3}}, {6.0, {0, 3}}};
  std::vector<Trajectory> tr{trajectory_of(w1, AtStart::kWait, AtGoal::kStay),
                             trajectory_of(w2, AtStart::kWait, AtGoal::kStay)};
  const std::vector<double> radii{0.5, 0.5};
  EXPECT_FALSE(verify_trajectories(tr, radii).valid);
  // Robot 2 later: passes x = 0 at t = 7 when robot 1 is at (3, 0): clear (distance 3).
  const std::vector<TimedWaypoint> w3{{4.0, {0, -3}}, {10.0, {0, 3}}};
  tr[1] = trajectory_of(w3, AtStart::kAppear, AtGoal::kLeave);
  const Verification v = verify_trajectories(tr, radii);
  EXPECT_TRUE(v.valid);
  // At t = 4 robot 2 appears at (0,-3) while robot 1 is at (1,0): distance sqrt(10) is not the
  // minimum; the minimum is along the way, computed exactly against dense sampling.
  double sampled = kInfinity;
  for (double t = 4.0; t <= 10.0; t += 1e-5)
    sampled = std::min(sampled, (tr[0].position(t) - tr[1].position(t)).norm());
  EXPECT_NEAR(v.min_clearance, sampled - 1.0, 1e-8);
  const std::vector<TimedWaypoint> bad{{1.0, {0, 0}}, {1.0, {1, 0}}};
  EXPECT_THROW((void)trajectory_of(bad, AtStart::kWait, AtGoal::kStay), Error);
}

TEST(Verify, MapWallsAreChecked) {
  BinaryGrid g(5, 3);
  g[Cell{2, 1}] = 1;  // a wall cell in the middle row
  const std::vector<double> radii{0.5};
  // Along the middle row through the wall: hit.
  std::vector<Trajectory> tr{trajectory_of(TimedPath({{0.5, 1.5}, {4.5, 1.5}}, {1.0, kInfinity}),
                                           0.0, AtStart::kWait, AtGoal::kStay)};
  Verification v;
  check_map(v, tr, radii, g);
  EXPECT_FALSE(v.valid);
  ASSERT_EQ(v.wall_hits.size(), 1u);
  EXPECT_EQ(v.wall_hits[0].cell, (Cell{2, 1}));
  // Along the bottom row: touches the wall cell and the map border, never enters: valid.
  tr[0] = trajectory_of(TimedPath({{0.5, 0.5}, {4.5, 0.5}}, {1.0, kInfinity}), 0.0, AtStart::kWait,
                        AtGoal::kStay);
  Verification w;
  check_map(w, tr, radii, g);
  EXPECT_TRUE(w.valid);
  EXPECT_TRUE(w.wall_hits.empty());
}

}  // namespace
}  // namespace voronav::coordination
