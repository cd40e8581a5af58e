#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>

#include "voronav/coordination/collision_map.hpp"
#include "voronav/coordination/coordinator.hpp"
#include "voronav/coordination/internal/critical_moves.hpp"
#include "voronav/coordination/internal/ga_operators.hpp"
#include "voronav/coordination/md_network.hpp"
#include "voronav/coordination/paper_networks.hpp"
#include "voronav/coordination/priority_search.hpp"
#include "voronav/coordination/timed_path.hpp"
#include "voronav/coordination/verify.hpp"
#include "voronav/core/error.hpp"

namespace voronav::coordination {
namespace {

Agent make_agent(int id, std::vector<Vec2> nodes, double v = 1.0, double a = kInfinity,
                 double r = 0.5) {
  return Agent{id, TimedPath(std::move(nodes), {v, a}), r};
}

// ---------------------------------------------------------------- timed paths (eq. 2)

TEST(TimedPath, InstantaneousAcceleration) {
  const TimedPath p({{0, 0}, {3, 0}, {3, 4}}, {2.0, kInfinity});
  EXPECT_DOUBLE_EQ(p.length(), 7.0);
  EXPECT_DOUBLE_EQ(p.travel_time(), 3.5);
  EXPECT_DOUBLE_EQ(p.arc_at(1.0), 2.0);
  EXPECT_EQ(p.position(2.0), (Vec2{3, 1}));
  EXPECT_EQ(p.position(-1.0), (Vec2{0, 0}));
  EXPECT_EQ(p.position(100.0), (Vec2{3, 4}));
  EXPECT_DOUBLE_EQ(p.speed(1.0), 2.0);
}

TEST(TimedPath, TrapezoidalProfile) {
  // v = 1, a = 0.5: accelerate 2 s over 1 m, cruise 8 m, decelerate 2 s over 1 m.
  const TimedPath p({{0, 0}, {10, 0}}, {1.0, 0.5});
  EXPECT_DOUBLE_EQ(p.travel_time(), 12.0);
  EXPECT_DOUBLE_EQ(p.arc_at(2.0), 1.0);
  EXPECT_DOUBLE_EQ(p.arc_at(1.0), 0.25);
  EXPECT_DOUBLE_EQ(p.arc_at(6.0), 5.0);
  EXPECT_DOUBLE_EQ(p.arc_at(11.0), 10.0 - 0.25);
  EXPECT_DOUBLE_EQ(p.speed(1.0), 0.5);
  for (double s = 0.0; s <= 10.0; s += 0.37)
    EXPECT_NEAR(p.arc_at(p.time_at_arc(s)), s, 1e-12);
}

TEST(TimedPath, TriangularProfileWhenTooShortForVmax) {
  // v = 2, a = 1, length 1: peak speed 1 at t = 1, arrival at t = 2.
  const TimedPath p({{0, 0}, {0, 1}}, {2.0, 1.0});
  EXPECT_DOUBLE_EQ(p.travel_time(), 2.0);
  EXPECT_DOUBLE_EQ(p.arc_at(1.0), 0.5);
  EXPECT_DOUBLE_EQ(p.speed(1.0), 1.0);
  for (double s = 0.0; s <= 1.0; s += 0.05)
    EXPECT_NEAR(p.arc_at(p.time_at_arc(s)), s, 1e-12);
}

TEST(TimedPath, SingleNodeIsAParkedRobot) {
  const TimedPath p({{1, 2}}, {1.0, 1.0});
  EXPECT_DOUBLE_EQ(p.travel_time(), 0.0);
  EXPECT_EQ(p.position(5.0), (Vec2{1, 2}));
}

TEST(TimedPath, RejectsBadInput) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(TimedPath({}, {1.0, 1.0}), Error);
  EXPECT_THROW(TimedPath({{0, 0}, {nan, 0}}, {1.0, 1.0}), Error);
  EXPECT_THROW(TimedPath({{0, 0}, {1, 0}}, {0.0, 1.0}), Error);
  EXPECT_THROW(TimedPath({{0, 0}, {1, 0}}, {nan, 1.0}), Error);
  EXPECT_THROW(TimedPath({{0, 0}, {1, 0}}, {kInfinity, 1.0}), Error);
  EXPECT_THROW(TimedPath({{0, 0}, {1, 0}}, {1.0, -1.0}), Error);
  EXPECT_THROW(TimedPath({{0, 0}, {1, 0}}, {1.0, nan}), Error);
}

TEST(TimedPath, ResampleKeepsVerticesAndSpacing) {
  const TimedPath p({{0, 0}, {1, 0}, {1, 0.3}}, {1.0, kInfinity});
  std::vector<double> arcs;
  const auto nodes = resample(p, 0.25, &arcs);
  ASSERT_EQ(nodes.size(), 1u + 4u + 2u);
  EXPECT_EQ(nodes[4], (Vec2{1, 0}));
  EXPECT_EQ(nodes.back(), (Vec2{1, 0.3}));
  for (std::size_t i = 1; i < arcs.size(); ++i)
    EXPECT_LE(arcs[i] - arcs[i - 1], 0.25 + 1e-12);
  EXPECT_THROW((void)resample(p, 0.0, nullptr), Error);
}

// ---------------------------------------------------------------- eq. 5 and the collision map

TEST(CollisionMap, Eq5SegmentIntervalHandComputed) {
  // Points (x, 0.5), x in [-2, 2], closer than 1 to the origin: |x| < sqrt(0.75).
  const auto iv = collision_interval({0, 0}, {-2, 0.5}, {2, 0.5}, 1.0);
  ASSERT_TRUE(iv.has_value());
  EXPECT_NEAR(iv->first, (2.0 - std::sqrt(0.75)) / 4.0, 1e-12);
  EXPECT_NEAR(iv->second, (2.0 + std::sqrt(0.75)) / 4.0, 1e-12);
  EXPECT_FALSE(collision_interval({0, 0}, {-2, 1.5}, {2, 1.5}, 1.0).has_value());  // disc < 0
  EXPECT_FALSE(collision_interval({0, 0}, {-2, 1.0}, {2, 1.0}, 1.0).has_value());  // tangent
  EXPECT_FALSE(collision_interval({0, 0}, {2, 0}, {4, 0}, 1.0).has_value());  // beyond lambda=0
  const auto clipped = collision_interval({0, 0}, {0.5, 0}, {4.5, 0}, 1.0);
  ASSERT_TRUE(clipped.has_value());
  EXPECT_DOUBLE_EQ(clipped->first, 0.0);
  EXPECT_NEAR(clipped->second, 0.125, 1e-12);
  EXPECT_TRUE(collision_interval({0, 0}, {0.1, 0}, {0.1, 0}, 1.0).has_value());  // point segment
}

TEST(CollisionMap, Table3Classification) {
  // The six orderings of Table 3.
  auto box = [](double t1, double t2, double t3, double t4) {
    CollisionBox b;
    b.t1 = t1, b.t2 = t2, b.t3 = t3, b.t4 = t4;
    return classify(b);
  };
  EXPECT_EQ(box(1, 3, 4, 2), BoxCase::kHighFirst);  // T1 < T4 < T2 < T3
  EXPECT_EQ(box(1, 2, 4, 3), BoxCase::kCollision);  // T1 < T2 < T4 < T3
  EXPECT_EQ(box(1, 2, 3, 4), BoxCase::kCollision);  // T1 < T2 < T3 < T4
  EXPECT_EQ(box(2, 1, 3, 4), BoxCase::kCollision);  // T2 < T1 < T3 < T4
  EXPECT_EQ(box(2, 1, 4, 3), BoxCase::kCollision);  // T2 < T1 < T4 < T3
  EXPECT_EQ(box(3, 1, 2, 4), BoxCase::kLowFirst);   // T2 < T3 < T1 < T4
  // Delaying the low robot by D turns a collision into "high first".
  CollisionBox b;
  b.t1 = 1, b.t2 = 2, b.t3 = 3, b.t4 = 4;
  EXPECT_EQ(classify(b, 0.0, b.d()), BoxCase::kHighFirst);
  EXPECT_EQ(classify(b, 0.0, b.d() - 0.01), BoxCase::kCollision);
}

TEST(CollisionMap, CrossingRobotsGiveOneBoxWithHandComputedTimes) {
  // A1 along x, A2 along y, both through the origin at t = 10 (v = 1, r = 0.5 each).
  const auto a1 = make_agent(1, {{-10, 0}, {10, 0}});
  const auto a2 = make_agent(2, {{0, -10}, {0, 10}});
  const auto boxes = collision_boxes(a1, 0, a2, 1, 0.25, {});
  ASSERT_EQ(boxes.size(), 1u);
  // Collision nodes |x| < 1.25 on a 0.25 grid: x in [-1, 1], widened by h/2 = 0.125.
  EXPECT_NEAR(boxes[0].t1, 8.875, 1e-9);
  EXPECT_NEAR(boxes[0].t4, 11.125, 1e-9);
  EXPECT_NEAR(boxes[0].t2, 8.875, 1e-9);
  EXPECT_NEAR(boxes[0].t3, 11.125, 1e-9);
  EXPECT_NEAR(boxes[0].m(), 2.25, 1e-9);
  EXPECT_NEAR(boxes[0].d(), 2.25, 1e-9);
  EXPECT_NEAR(boxes[0].l_s, 8.875 / 20.0, 1e-9);
  EXPECT_EQ(classify(boxes[0]), BoxCase::kCollision);
  // Collision points: every node pair closer than 1.25 (81 - 4*... counted by brute force).
  int expected = 0;
  for (int i = -4; i <= 4; ++i) {
    for (int j = -4; j <= 4; ++j)
      expected += (0.0625 * (i * i + j * j) < 1.5625) ? 1 : 0;
  }
  EXPECT_EQ(static_cast<int>(collision_points(a1, a2, 0.25).size()), expected);
}

TEST(CollisionMap, ExactRegionMatchesEq5) {
  const auto a1 = make_agent(1, {{-10, 0}, {10, 0}});
  const auto a2 = make_agent(2, {{0, -10}, {0, 10}});
  const auto region = collision_region(a1, a2, 0.5);
  ASSERT_EQ(region.size(), 41u);
  EXPECT_TRUE(region[0].intervals.empty());
  ASSERT_EQ(region[20].intervals.size(), 1u);  // t = 10: A1 at the origin, |y| < 1
  EXPECT_NEAR(region[20].intervals[0].first, 9.0 / 20.0, 1e-12);
  EXPECT_NEAR(region[20].intervals[0].second, 11.0 / 20.0, 1e-12);
  EXPECT_THROW((void)collision_region(a1, a2, 0.0), Error);
}

TEST(CollisionMap, FarApartPathsHaveNoBoxes) {
  const auto a1 = make_agent(1, {{0, 0}, {10, 0}});
  const auto a2 = make_agent(2, {{0, 5}, {10, 5}});
  EXPECT_TRUE(collision_boxes(a1, 0, a2, 1, 0.25, {}).empty());
}

// ---------------------------------------------------------------- (M,D) network and resolution

TEST(MdNetwork, DelayUpdateRulesAndConstantSum) {
  MdNetwork net({10.0, 10.0});
  net.add_box(0, 1, 3.0, 5.0);
  // Section 3.1.2: delaying the low robot by T2d: M + T2d, D - T2d.
  auto [m1, d1] = net.oriented(0, 0, 0.0, 2.0);
  EXPECT_DOUBLE_EQ(m1, 5.0);
  EXPECT_DOUBLE_EQ(d1, 3.0);
  // Delaying the high robot by T1d: M - T1d, D + T1d.
  auto [m2, d2] = net.oriented(0, 0, 2.0, 0.0);
  EXPECT_DOUBLE_EQ(m2, 1.0);
  EXPECT_DOUBLE_EQ(d2, 7.0);
  EXPECT_DOUBLE_EQ(m1 + d1, 8.0);
  EXPECT_DOUBLE_EQ(m2 + d2, 8.0);
  // Symmetry: with robot 1 on top, M and D swap.
  auto [m3, d3] = net.oriented(0, 1);
  EXPECT_DOUBLE_EQ(m3, 5.0);
  EXPECT_DOUBLE_EQ(d3, 3.0);
  EXPECT_DOUBLE_EQ(net.shared_time(0, 1), 8.0);
  EXPECT_THROW(net.add_box(0, 0, 1.0, 1.0), Error);
  EXPECT_THROW(net.add_box(0, 1, -1.0, -1.0), Error);
  EXPECT_THROW(net.add_box(0, 1, std::nan(""), 1.0), Error);
  EXPECT_THROW(MdNetwork({1.0, -2.0}), Error);
}

TEST(MdNetwork, ResolutionDelaysByMaxDAndUpdatesArcs) {
  // Three robots in a chain: 0 -> 1 (M 4, D 6), 0 -> 2 (M 2, D 3), 1 -> 2 (M 5, D 4).
  MdNetwork net({50.0, 40.0, 30.0});
  net.add_box(0, 1, 4.0, 6.0);
  net.add_box(0, 2, 2.0, 3.0);
  net.add_box(1, 2, 5.0, 4.0);
  const std::vector<int> order{0, 1, 2};
  const Resolution r = resolve(net, order);
  ASSERT_EQ(r.status, ResolveStatus::kOk);
  EXPECT_DOUBLE_EQ(r.delays[0], 0.0);
  EXPECT_DOUBLE_EQ(r.delays[1], 6.0);
  // Robot 2: arcs (2, 3) from 0 and (5 - 6, 4 + 6) = (-1, 10) from 1: only the first collides,
  // delay 3 makes the second (-1 + 3, 10 - 3) = (2, 7) collide: delay 10 in the end.
  EXPECT_DOUBLE_EQ(r.delays[2], 10.0);
  EXPECT_DOUBLE_EQ(r.makespan, 50.0);
  EXPECT_DOUBLE_EQ(r.sum_of_arrivals, 50.0 + 46.0 + 40.0);
  for (const auto& arc : network_for_order(net, order, r.delays)) {
    EXPECT_FALSE(arc.m > 0.0 && arc.d > 0.0) << arc.high << "->" << arc.low;
  }
}

TEST(MdNetwork, SymmetryRuleEqualsRecomputation) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 10.0);
  for (int trial = 0; trial < 30; ++trial) {
    const auto a = make_agent(1, {{u(rng), u(rng)}, {u(rng), u(rng)}, {u(rng), u(rng)}}, 1.0, 0.8);
    const auto b = make_agent(2, {{u(rng), u(rng)}, {u(rng), u(rng)}}, 1.5, kInfinity, 0.4);
    for (const auto mode : {AtStart::kWait, AtStart::kAppear}) {
      CollisionMapOptions o;
      o.at_start = mode;
      o.at_goal = mode == AtStart::kWait ? AtGoal::kStay : AtGoal::kLeave;
      auto ab = collision_boxes(a, 0, b, 1, 0.2, o);
      auto ba = collision_boxes(b, 1, a, 0, 0.2, o);
      ASSERT_EQ(ab.size(), ba.size());
      std::vector<std::pair<double, double>> x, y;
      for (const auto& box : ab)
        x.emplace_back(box.d(), box.m());  // swapped
      for (const auto& box : ba)
        y.emplace_back(box.m(), box.d());
      std::sort(x.begin(), x.end());
      std::sort(y.begin(), y.end());
      for (std::size_t k = 0; k < x.size(); ++k) {
        EXPECT_DOUBLE_EQ(x[k].first, y[k].first);
        EXPECT_DOUBLE_EQ(x[k].second, y[k].second);
      }
    }
  }
}

TEST(Coordinate, TwoRobotCrossingDelayEqualsAnalyticValue) {
  // Crossing at right angles through the origin at t = 10. The exact minimal delay of the low
  // robot is sqrt(2) (|p1 - p2|^2 = u^2 + (u - d)^2 >= 1 for all u iff d^2 / 2 >= 1); the
  // collision box of the paper gives 2 (r1 + r2) / v = 2 plus h on our node grid.
  for (const double a_max : {kInfinity, 1.0}) {
    const std::vector<Agent> agents{make_agent(1, {{-10, 0}, {10, 0}}, 1.0, a_max),
                                    make_agent(2, {{0, -10}, {0, 10}}, 1.0, a_max)};
    CoordinateOptions o;
    o.search.kind = SearchKind::kNone;
    o.map.node_spacing = 0.25;
    const auto r = coordinate(agents, o);
    ASSERT_EQ(r.status, ResolveStatus::kOk);
    EXPECT_TRUE(r.valid);
    EXPECT_EQ(r.repairs, 0);
    EXPECT_DOUBLE_EQ(r.delays[0], 0.0);
    EXPECT_NEAR(r.delays[1], 2.25, 1e-9);
    const double travel = a_max == 1.0 ? 21.0 : 20.0;
    EXPECT_NEAR(r.makespan, travel + 2.25, 1e-9);
    o.map.node_spacing = 0.05;
    EXPECT_NEAR(coordinate(agents, o).delays[1], 2.05, 1e-9);
  }
}

TEST(Verify, FindsOverlapsExactlyAroundTheAnalyticDelay) {
  const std::vector<Agent> agents{make_agent(1, {{-10, 0}, {10, 0}}),
                                  make_agent(2, {{0, -10}, {0, 10}})};
  const std::vector<double> none{0.0, 0.0};
  const auto v0 = verify_schedule(agents, none);
  EXPECT_FALSE(v0.valid);
  ASSERT_EQ(v0.conflicts.size(), 1u);
  EXPECT_GT(v0.conflicts[0].time, 9.0);
  EXPECT_LT(v0.conflicts[0].time, 10.0 + 1e-9);
  const std::vector<double> below{0.0, std::sqrt(2.0) - 0.01};
  const std::vector<double> above{0.0, std::sqrt(2.0) + 1e-3};
  EXPECT_FALSE(verify_schedule(agents, below).valid);
  EXPECT_TRUE(verify_schedule(agents, above).valid);
  EXPECT_GT(verify_schedule(agents, above).min_clearance, 0.0);
  EXPECT_THROW((void)verify_schedule(agents, std::vector<double>{0.0}), Error);
  EXPECT_THROW((void)verify_schedule(agents, std::vector<double>{0.0, std::nan("")}), Error);
}

TEST(Verify, AtStartAndAtGoalModes) {
  // Robot 2 is parked on robot 1's path.
  const std::vector<Agent> agents{make_agent(1, {{-5, 0}, {5, 0}}), make_agent(2, {{0, 0}})};
  const std::vector<double> d{0.0, 0.0};
  EXPECT_FALSE(verify_schedule(agents, d).valid);
  VerifyOptions gone;
  gone.at_start = AtStart::kAppear;
  gone.at_goal = AtGoal::kLeave;
  EXPECT_TRUE(verify_schedule(agents, d, gone).valid);  // robot 2 is never in the world
}

TEST(Coordinate, RobotParkedOnAPathHasNoDelayScheduleInOneOrder) {
  // Robot 2 ends on robot 1's path and stays there.
  const std::vector<Agent> agents{make_agent(1, {{-5, 0}, {5, 0}}),
                                  make_agent(2, {{0, -5}, {0, 0}})};
  const MdNetwork net = build_network(agents);
  const std::vector<int> ok_order{0, 1}, bad_order{1, 0};
  EXPECT_EQ(resolve(net, ok_order).status, ResolveStatus::kOk);
  const auto bad = resolve(net, bad_order);
  EXPECT_EQ(bad.status, ResolveStatus::kNoDelaySchedule);
  EXPECT_EQ(bad.blocked, 0);
  EXPECT_EQ(bad.blocked_by, 1);
  EXPECT_TRUE(std::isinf(bad.makespan));
  CoordinateOptions o;
  o.search.kind = SearchKind::kExhaustive;
  const auto r = coordinate(agents, o);
  EXPECT_TRUE(r.valid);
  EXPECT_EQ(r.order, ok_order);
  o.search.kind = SearchKind::kNone;
  const std::vector<Agent> swapped{agents[1], agents[0]};
  const auto r2 = coordinate(swapped, o);
  EXPECT_EQ(r2.status, ResolveStatus::kNoDelaySchedule);
  EXPECT_FALSE(r2.valid);
  EXPECT_NE(r2.message.find("no delay-only schedule"), std::string::npos);
  // With "leave" the parked goal is no obstacle: both orders work.
  o.map.at_goal = AtGoal::kLeave;
  EXPECT_TRUE(coordinate(swapped, o).valid);
}

// ---------------------------------------------------------------- priority search

class Table4 : public ::testing::TestWithParam<EdfCost> {};

TEST_P(Table4, EdfReproducesTheTable) {
  const MdNetwork net =
      GetParam() == EdfCost::kSharedTime ? table4_network() : table4_network_delay_reading();
  const EdfResult r = bottom_level_edf(net, EdfOptions{GetParam()});
  EXPECT_DOUBLE_EQ(r.deadline, 55.0);
  EXPECT_EQ(r.removal_order, (std::vector<int>{3, 2, 4, 0, 1}));  // A4, A3, A5, A1, A2
  EXPECT_TRUE(r.urgent_group.empty());
  EXPECT_EQ(r.order, (std::vector<int>{1, 0, 4, 2, 3}));  // {2-1-5-3-4}
  // The completion times of Table 4, round by round (NaN = removed).
  const double x = std::numeric_limits<double>::quiet_NaN();
  const std::vector<std::vector<double>> table{{74, 80, 56, 53, 59},
                                               {63, 80, 49, x, 59},
                                               {56, 72, x, x, 51},
                                               {47, 68, x, x, x},
                                               {x, 55, x, x, x}};
  ASSERT_EQ(r.rounds.size(), table.size());
  for (std::size_t k = 0; k < table.size(); ++k) {
    for (std::size_t i = 0; i < 5; ++i) {
      if (std::isnan(table[k][i])) {
        EXPECT_TRUE(std::isnan(r.rounds[k].completion[i]));
      } else {
        EXPECT_DOUBLE_EQ(r.rounds[k].completion[i], table[k][i]) << "round " << k << " A" << i + 1;
      }
    }
  }
  // The EDF order is optimal here: makespan = the largest travel time.
  const auto res = resolve(net, r.order);
  EXPECT_DOUBLE_EQ(res.makespan, 55.0);
  SearchOptions so;
  so.kind = SearchKind::kExhaustive;
  so.edf_reduction = false;
  EXPECT_DOUBLE_EQ(search_priority(net, so).resolution.makespan, 55.0);
}
INSTANTIATE_TEST_SUITE_P(Readings, Table4,
                         ::testing::Values(EdfCost::kSharedTime, EdfCost::kDelay));

TEST(Search, ExhaustiveIsOptimalOnSmallNetworks) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const MdNetwork net = random_network(5, 10, seed);
    std::vector<int> order(5);
    std::iota(order.begin(), order.end(), 0);
    Resolution best = resolve(net, order);
    while (std::next_permutation(order.begin(), order.end())) {
      const Resolution r = resolve(net, order);
      if (better(r, best)) best = r;
    }
    SearchOptions so;
    so.kind = SearchKind::kExhaustive;
    so.edf_reduction = false;
    const auto s = search_priority(net, so);
    EXPECT_DOUBLE_EQ(s.resolution.makespan, best.makespan) << seed;
    EXPECT_NEAR(s.resolution.sum_of_arrivals, best.sum_of_arrivals, 1e-9) << seed;
  }
  SearchOptions big;
  big.kind = SearchKind::kExhaustive;
  big.edf_reduction = false;
  EXPECT_THROW((void)search_priority(random_network(12, 30, 1), big), Error);
}

TEST(Search, GaNeverWorseThanEdfSeed) {
  for (std::uint64_t seed = 1; seed <= 15; ++seed) {
    const MdNetwork net = random_network(30, 90, seed);
    const auto edf = bottom_level_edf(net);
    const auto edf_res = resolve(net, edf.order);
    SearchOptions so;
    so.kind = SearchKind::kGa;
    so.ga.seed = seed;
    const auto ga = search_priority(net, so);
    check_order(ga.order, net.size());
    EXPECT_FALSE(better(edf_res, ga.resolution)) << seed;
    if (ga.urgent_group.size() > 1) {
      EXPECT_GE(ga.rounds, 1);
    }
  }
}

TEST(Search, GaFindsExhaustiveOptimumForUpTo8Robots) {
  int found = 0, total = 0;
  for (int n = 4; n <= 8; ++n) {
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
      const MdNetwork net = random_network(n, 3 * n, 100 * n + seed);
      SearchOptions ex;
      ex.kind = SearchKind::kExhaustive;
      ex.edf_reduction = false;
      SearchOptions ga;
      ga.kind = SearchKind::kGa;
      ga.edf_reduction = false;
      ga.ga.seed = seed;
      const double opt = search_priority(net, ex).resolution.makespan;
      const double got = search_priority(net, ga).resolution.makespan;
      EXPECT_GE(got, opt - 1e-9);
      found += std::abs(got - opt) < 1e-9 ? 1 : 0;
      ++total;
    }
  }
  EXPECT_EQ(found, total);
}

TEST(Search, GaIsDeterministicPerSeed) {
  const MdNetwork net = random_network(20, 60, 3);
  SearchOptions so;
  so.ga.seed = 42;
  so.edf_reduction = false;
  EXPECT_EQ(search_priority(net, so).order, search_priority(net, so).order);
  EXPECT_EQ(parse_search_kind("ga"), SearchKind::kGa);
  EXPECT_THROW((void)parse_search_kind("tabu"), Error);
  so.ga.mutation_rate = 2.0;
  EXPECT_THROW((void)search_priority(net, so), Error);
}

// The GA's incremental 3-opt evaluation (issue #16) must equal a full resolve() bit for bit: same
// delays, completions, makespan and sum (or a cut exactly when the makespan exceeds the cutoff).
TEST(MdNetwork, MoveEvaluatorEqualsFullResolveBitwise) {
  int cuts = 0, kept = 0, blocked = 0, partial = 0;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const int n = 25;
    MdNetwork net = random_network(n, 90, seed);
    if (seed % 2 == 0) {  // boxes no start delay resolves in one orientation
      net.add_box(1, 7, 3.0, kInfinity);
      net.add_box(12, 4, 2.0, kInfinity);
    }
    MoveEvaluator ev(net);
    std::mt19937_64 rng(seed);
    auto uniform = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    std::vector<int> order(static_cast<std::size_t>(n));
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), rng);
    Resolution base = resolve(net, order);
    for (int it = 0; it < 300; ++it) {
      const int i = uniform(0, n - 1);
      const int j = uniform(i, std::min(n - 1, i + uniform(0, n - 1)));
      const int len = j - i + 1;
      if (len >= n) continue;
      const int k = uniform(0, n - len);
      if (k == i) continue;
      std::vector<int> rest;
      for (int p = 0; p < n; ++p) {
        if (p < i || p > j) rest.push_back(order[static_cast<std::size_t>(p)]);
      }
      std::vector<int> cand(rest.begin(), rest.begin() + k);
      cand.insert(cand.end(), order.begin() + i, order.begin() + j + 1);
      cand.insert(cand.end(), rest.begin() + k, rest.end());
      const int from = std::min(i, k), to = std::max(j + 1, k + len);
      const Resolution full = resolve(net, cand);
      const Resolution r = ev.resolve_move(order, base, cand, from, to, kInfinity);
      ASSERT_EQ(r.status, full.status) << seed << " move " << it;
      ASSERT_FALSE(r.cut);
      EXPECT_EQ(r.delays, full.delays) << seed << " move " << it;
      EXPECT_EQ(r.completion, full.completion);
      EXPECT_EQ(r.makespan, full.makespan);
      EXPECT_EQ(r.sum_of_arrivals, full.sum_of_arrivals);
      EXPECT_EQ(r.blocked, full.blocked);
      blocked += full.status != ResolveStatus::kOk ? 1 : 0;
      partial += ev.last_resolved() < n - from ? 1 : 0;
      // With the GA's cutoff: a cut when the full makespan exceeds it; an order no delay
      // resolves may also be cut (some robot above the blocked one exceeded the cutoff first).
      const double cutoff = base.makespan + 1e-9;
      const Resolution c = ev.resolve_move(order, base, cand, from, to, cutoff);
      if (full.status == ResolveStatus::kOk) {
        ASSERT_EQ(c.cut, full.makespan > cutoff) << seed << " move " << it;
      }
      if (c.cut) {
        ++cuts;
        EXPECT_EQ(c.makespan, kInfinity);
      } else {
        EXPECT_EQ(c.status, full.status);
        EXPECT_EQ(c.delays, full.delays);
        EXPECT_EQ(c.sum_of_arrivals, full.sum_of_arrivals);
      }
      if (full.status == ResolveStatus::kOk &&
          (base.status != ResolveStatus::kOk || better(full, base))) {
        order = cand;  // walk like the 3-opt: the next moves start from the better order
        base = full;
        ++kept;
      }
    }
  }
  // Orders that are not permutations are refused.
  const MdNetwork net = random_network(4, 6, 1);
  MoveEvaluator ev(net);
  const std::vector<int> good{0, 1, 2, 3};
  const Resolution base = resolve(net, good);
  EXPECT_THROW((void)ev.resolve_move(good, base, std::vector<int>{0, 1, 1, 3}, 1, 3, kInfinity),
               Error);
  EXPECT_THROW((void)ev.resolve_move(good, base, std::vector<int>{0, 1, 4, 3}, 1, 3, kInfinity),
               Error);
  // Every branch was exercised: cuts, accepted moves, unresolvable orders, partial re-resolution.
  EXPECT_GT(cuts, 100);
  EXPECT_GT(kept, 10);
  EXPECT_GT(blocked, 10);
  EXPECT_GT(partial, 100);
}

// The incremental evaluation on dense networks (as the MAPF maps give: ~8 boxes per robot,
// several per pair) over thousands of random segment moves of a 3-opt walk, with the GA's cutoff
// and without: bitwise the full resolve(), and most moves re-resolve only part of the order.
TEST(MdNetwork, MoveEvaluatorEqualsFullResolveOnDenseNetworks) {
  int partial = 0;
  int compared = 0;
  for (std::uint64_t seed = 11; seed <= 16; ++seed) {
    const int n = 40;
    const MdNetwork net = random_network(n, 160, seed);
    MoveEvaluator ev(net);
    std::mt19937_64 rng(seed);
    std::vector<int> order(static_cast<std::size_t>(n));
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), rng);
    Resolution base = resolve(net, order);
    internal::SegmentMove mv;
    std::vector<int> cand;
    int from = 0, to = 0;
    for (int it = 0; it < 1500; ++it) {
      if (!internal::random_segment_move(n, rng, mv)) continue;
      internal::apply_segment_move(order, mv, cand, from, to);
      const Resolution full = resolve(net, cand);
      const Resolution r = ev.resolve_move(order, base, cand, from, to, kInfinity);
      ASSERT_EQ(r.status, full.status) << seed << " move " << it;
      ASSERT_EQ(r.delays, full.delays) << seed << " move " << it;
      ASSERT_EQ(r.completion, full.completion);
      ASSERT_EQ(r.sum_of_arrivals, full.sum_of_arrivals);
      partial += ev.last_resolved() < n - from ? 1 : 0;
      const Resolution c = ev.resolve_move(order, base, cand, from, to, base.makespan + 1e-9);
      if (full.status == ResolveStatus::kOk) {
        ASSERT_EQ(c.cut, full.makespan > base.makespan + 1e-9) << seed << " move " << it;
        if (!c.cut) {
          ASSERT_EQ(c.delays, full.delays);
        }
      }
      ++compared;
      if (full.status == ResolveStatus::kOk && better(full, base)) {
        order = cand;
        base = full;
      }
    }
  }
  EXPECT_GT(compared, 5000);
  EXPECT_GT(partial, 1000);
}

// The GA operators shared by the delay GA and the SIPP GA (internal/ga_operators.hpp).
TEST(GaOperators, ChildrenArePermutationsKeepingWhatTheyMust) {
  const int n = 12;
  internal::GaRng rng(5);
  std::vector<double> weight(static_cast<std::size_t>(n * n), 0.0);
  weight[static_cast<std::size_t>(3 * n + 9)] = 5.0;  // 3 -> 9 is the heaviest edge out of 3
  const internal::GaOperators ops(n, weight);
  auto is_perm = [&](std::vector<int> v) {
    std::sort(v.begin(), v.end());
    for (int k = 0; k < n; ++k)
      if (v[static_cast<std::size_t>(k)] != k) return false;
    return static_cast<int>(v.size()) == n;
  };
  int moves = 0;
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<int> a(static_cast<std::size_t>(n)), b(static_cast<std::size_t>(n));
    std::iota(a.begin(), a.end(), 0);
    std::shuffle(a.begin(), a.end(), rng);
    std::iota(b.begin(), b.end(), 0);
    std::shuffle(b.begin(), b.end(), rng);
    // DPX: every edge common to both parents is in the child.
    const std::vector<int> c = ops.dpx(a, b, rng);
    ASSERT_TRUE(is_perm(c));
    const auto sa = ops.successors(a), sb = ops.successors(b), sc = ops.successors(c);
    for (int v = 0; v < n; ++v) {
      if (sa[static_cast<std::size_t>(v)] >= 0 &&
          sa[static_cast<std::size_t>(v)] == sb[static_cast<std::size_t>(v)]) {
        EXPECT_EQ(sc[static_cast<std::size_t>(v)], sa[static_cast<std::size_t>(v)]);
      }
    }
    EXPECT_TRUE(is_perm(ops.mutate(a, 4, 7, rng)));
    // Segment move: a permutation that differs from the parent only inside [from, to).
    std::vector<int> cand;
    int from = -1, to = -1;
    if (!internal::GaOperators::segment_move(a, rng, cand, from, to)) continue;
    ++moves;
    ASSERT_TRUE(is_perm(cand));
    ASSERT_LE(0, from);
    ASSERT_LT(from, to);
    ASSERT_LE(to, n);
    EXPECT_NE(cand, a);
    for (int p = 0; p < n; ++p) {
      if (p < from || p >= to) {
        EXPECT_EQ(cand[static_cast<std::size_t>(p)], a[static_cast<std::size_t>(p)]);
      }
    }
  }
  EXPECT_GT(moves, 100);
  // Greedy reconnection: the parents share no edge (every fragment is one node) and neither has
  // 3 -> 9, the only weighted edge; so whenever 9 is still free when 3 is placed, 9 follows 3.
  const std::vector<int> p1{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11};
  const std::vector<int> p2{11, 10, 9, 8, 7, 6, 5, 4, 3, 2, 1, 0};
  int followed = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const std::vector<int> c = ops.dpx(p1, p2, rng);
    const auto at = [&](int v) { return std::find(c.begin(), c.end(), v) - c.begin(); };
    if (at(9) > at(3)) {
      EXPECT_EQ(at(9), at(3) + 1);
      ++followed;
    }
  }
  EXPECT_GT(followed, 5);
}

// ---------------------------------------------------------------- property test

std::vector<Agent> random_scenario(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> pos(0.0, 12.0), rad(0.2, 0.6), vel(0.5, 1.5);
  std::uniform_int_distribution<int> kind(0, 2);
  std::vector<Agent> agents;
  for (int i = 0; i < n; ++i) {
    std::vector<Vec2> nodes{{pos(rng), pos(rng)}};
    const int bends = kind(rng);
    for (int b = 0; b <= bends; ++b)
      nodes.push_back({pos(rng), pos(rng)});
    const double a = kind(rng) == 0 ? kInfinity : vel(rng);
    agents.push_back(make_agent(i + 1, nodes, vel(rng), a, rad(rng)));
  }
  return agents;
}

TEST(Property, EveryReturnedScheduleIsCollisionFreeInContinuousTime) {
  std::mt19937 rng(2024);
  int valid = 0, blocked = 0;
  for (int trial = 0; trial < 80; ++trial) {
    const int n = 3 + trial % 6;
    const auto agents = random_scenario(rng, n);
    CoordinateOptions o;
    o.search.kind = trial % 3 == 0 ? SearchKind::kGa
                                   : (trial % 3 == 1 ? SearchKind::kEdf : SearchKind::kExhaustive);
    if (trial % 2 == 1) {
      o.map.at_start = AtStart::kAppear;
      o.map.at_goal = AtGoal::kLeave;
    }
    const auto r = coordinate(agents, o);
    if (r.status != ResolveStatus::kOk) {
      EXPECT_FALSE(r.valid);
      ++blocked;
      continue;
    }
    ASSERT_TRUE(r.valid) << "trial " << trial << ": " << r.message;
    EXPECT_EQ(r.repairs, 0) << "the boxes are conservative; trial " << trial;
    // Independent re-check with the same presence rules.
    VerifyOptions v;
    v.at_start = o.map.at_start;
    v.at_goal = o.map.at_goal;
    EXPECT_TRUE(verify_schedule(agents, r.delays, v).valid);
    ++valid;
  }
  EXPECT_GT(valid, 40);
}

TEST(Property, CoarseNodeSpacingIsRepairedAndReported) {
  // The paper's literal rule with coarse nodes misses conflicts; the verifier catches them.
  std::mt19937 rng(5);
  int repaired = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const auto agents = random_scenario(rng, 5);
    CoordinateOptions o;
    o.search.kind = SearchKind::kEdf;
    o.map.at_start = AtStart::kAppear;
    o.map.at_goal = AtGoal::kLeave;
    o.map.node_spacing = 1.0;
    o.map.paper_literal = true;
    const auto r = coordinate(agents, o);
    if (r.status != ResolveStatus::kOk) continue;
    EXPECT_EQ(static_cast<int>(r.missed.size()), r.repairs);
    repaired += r.repairs > 0 && r.valid ? 1 : 0;
    if (r.valid) {
      VerifyOptions v{o.map.at_start, o.map.at_goal};
      EXPECT_TRUE(verify_schedule(agents, r.delays, v).valid);
    }
  }
  EXPECT_GT(repaired, 0);
}

}  // namespace
}  // namespace voronav::coordination
