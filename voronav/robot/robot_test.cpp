#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "voronav/core/error.hpp"
#include "voronav/robot/diff_drive.hpp"
#include "voronav/robot/laser.hpp"
#include "voronav/robot/reactive_controller.hpp"

namespace voronav::robot {
namespace {

constexpr double kPi = std::numbers::pi;

// A walled box: `w` x `h` cells of `res` m, border cells blocked.
BinaryGrid box_world(int w, int h, double res) {
  BinaryGrid g(GridGeometry{w, h, res, {}}, 0);
  for (int x = 0; x < w; ++x)
    g[Cell{x, 0}] = g[Cell{x, h - 1}] = 1;
  for (int y = 0; y < h; ++y)
    g[Cell{0, y}] = g[Cell{w - 1, y}] = 1;
  return g;
}

TEST(Odometry, EncoderVelocityMatchesEquations1To6) {
  DiffDriveOptions o;  // r = 0.033, D = 0.20, 4096 ticks
  // Left turns 90 deg, right 180 deg in T = 0.5 s.
  const BodyVelocity b = velocity_from_encoders({0, 0}, {1024, 2048}, 0.5, o);
  const double vl = kPi / 2 / 0.5 * 0.033, vr = kPi / 0.5 * 0.033;
  EXPECT_NEAR(b.v, (vl + vr) / 2, 1e-12);
  EXPECT_NEAR(b.omega, (vr - vl) / 0.20, 1e-12);
  EXPECT_THROW((void)velocity_from_encoders({}, {}, 0.0, o), Error);
  EXPECT_THROW((void)velocity_from_encoders({}, {}, std::nan(""), o), Error);
}

TEST(Odometry, RungeKuttaStepIsEquations7To9) {
  const Pose2 p{{1.0, 2.0}, 0.3};
  const Pose2 q = runge_kutta_step(p, {0.5, 0.2}, 0.1);
  EXPECT_NEAR(q.position.x, 1.0 + 0.1 * 0.5 * std::cos(0.3 + 0.01), 1e-15);
  EXPECT_NEAR(q.position.y, 2.0 + 0.1 * 0.5 * std::sin(0.3 + 0.01), 1e-15);
  EXPECT_NEAR(q.yaw, 0.32, 1e-15);
}

TEST(Odometry, StraightMotionEqualsClosedForm) {
  const BinaryGrid world(GridGeometry{200, 200, 0.05, {{-5.0, -5.0}, 0.0}}, 0);
  DiffDriveRobot robot({}, {{0.0, 0.0}, 0.0});
  robot.command({0.2, 0.0});
  for (int k = 0; k < 100; ++k)
    ASSERT_TRUE(robot.step(0.1, world));
  EXPECT_NEAR(robot.true_pose().position.x, 2.0, 1e-9);
  EXPECT_NEAR(robot.true_pose().position.y, 0.0, 1e-12);
  // Odometry: only encoder quantisation (2 pi r / 4096 = 0.05 mm per tick) separates it.
  EXPECT_NEAR(robot.odometry_pose().position.x, 2.0, 1e-4);
  EXPECT_NEAR(robot.odometry_pose().position.y, 0.0, 1e-4);
  EXPECT_NEAR(robot.distance_travelled(), 2.0, 1e-9);
  EXPECT_EQ(robot.collisions(), 0);
}

TEST(Odometry, CircularMotionEqualsClosedForm) {
  const BinaryGrid world(GridGeometry{200, 200, 0.05, {{-5.0, -5.0}, 0.0}}, 0);
  const double v = 0.2, w = 0.4, R = v / w;  // radius 0.5 m
  DiffDriveRobot robot({}, {{0.0, 0.0}, 0.0});
  robot.command({v, w});
  const double dt = 0.05;
  for (int k = 1; k <= 400; ++k) {
    ASSERT_TRUE(robot.step(dt, world));
    const double t = k * dt;
    const double x = R * std::sin(w * t), y = R * (1 - std::cos(w * t));
    ASSERT_NEAR(robot.true_pose().position.x, x, 1e-9) << t;
    ASSERT_NEAR(robot.true_pose().position.y, y, 1e-9) << t;
    // RK2 with exact encoder increments: error per step O(v T^3 w^2), plus tick quantisation.
    ASSERT_NEAR(robot.odometry_pose().position.x, x, 2e-3) << t;
    ASSERT_NEAR(robot.odometry_pose().position.y, y, 2e-3) << t;
    ASSERT_NEAR(std::abs(wrap_angle(robot.odometry_pose().yaw - w * t)), 0.0, 2e-3) << t;
  }
}

TEST(Odometry, SlipMakesOdometryDriftFromGroundTruthDeterministically) {
  const BinaryGrid world(GridGeometry{400, 400, 0.05, {{-10.0, -10.0}, 0.0}}, 0);
  DiffDriveOptions o;
  o.slip_stddev = 0.05;
  o.encoder_noise_ticks = 2.0;
  const auto run = [&](std::uint64_t seed) {
    DiffDriveRobot robot(o, {}, seed);
    robot.command({0.3, 0.1});
    for (int k = 0; k < 300; ++k)
      robot.step(0.1, world);
    return robot;
  };
  const DiffDriveRobot a = run(7), b = run(7);
  EXPECT_EQ(a.true_pose(), b.true_pose());
  EXPECT_GT(distance(a.true_pose().position, a.odometry_pose().position), 1e-3);
}

TEST(DiffDrive, LimitsAndNaNCommands) {
  DiffDriveRobot robot({}, {});
  robot.command({5.0, -9.0});
  EXPECT_DOUBLE_EQ(robot.commanded().v, 0.3);
  EXPECT_DOUBLE_EQ(robot.commanded().omega, -1.0);
  robot.command({std::nan(""), 0.5});
  EXPECT_DOUBLE_EQ(robot.commanded().v, 0.0);
  DiffDriveOptions bad;
  bad.wheel_radius = -1;
  EXPECT_THROW(DiffDriveRobot(bad, {}), Error);
  bad = {};
  bad.ticks_per_revolution = 0;
  EXPECT_THROW(bad.validate(), Error);
  EXPECT_THROW(DiffDriveRobot({}, {{std::nan(""), 0.0}, 0.0}), Error);
}

TEST(DiffDrive, CollisionStopsTheRobotAndIsCounted) {
  const BinaryGrid world = box_world(40, 40, 0.1);  // free interior [0.1, 3.9]
  DiffDriveRobot robot({}, {{2.0, 2.0}, 0.0});
  robot.command({0.3, 0.0});
  int stopped = 0;
  for (int k = 0; k < 200; ++k) {
    if (!robot.step(0.1, world)) {
      ++stopped;
      robot.command({0.3, 0.0});  // keep pushing
    }
    // The body never enters the wall.
    ASSERT_LE(robot.true_pose().position.x, 3.9 - 0.12 + 1e-9);
  }
  EXPECT_GT(robot.collisions(), 0);
  EXPECT_EQ(robot.collisions(), stopped);
  // Another robot is an obstacle too.
  const Disc other{{2.5, 2.0}, 0.12};
  DiffDriveRobot r2({}, {{2.0, 2.0}, 0.0});
  r2.command({0.3, 0.0});
  for (int k = 0; k < 30; ++k)
    r2.step(0.1, world, std::span(&other, 1));
  EXPECT_GT(r2.collisions(), 0);
  EXPECT_LT(r2.true_pose().position.x, 2.5 - 0.24 + 1e-9);
}

TEST(Laser, RayCastingEqualsAnalyticBoxWorld) {
  // 10 x 10 m box, 0.1 m cells, origin shifted: free interior x, y in [-4.9, 4.9].
  BinaryGrid world = box_world(100, 100, 0.1);
  BinaryGrid shifted(GridGeometry{100, 100, 0.1, {{-5.0, -5.0}, 0.0}}, 0);
  for (std::size_t i = 0; i < world.size(); ++i)
    shifted[i] = world[i];
  LaserOptions o;
  o.beams = 720;
  o.range_max = 30.0;
  const Pose2 pose{{0.7, -1.3}, 0.4};
  const LaserScan scan = cast_scan(shifted, pose, o);
  ASSERT_EQ(scan.ranges.size(), 720u);
  EXPECT_NEAR(scan.angle(0), -kPi, 1e-12);
  EXPECT_NEAR(scan.angle_increment, 2 * kPi / 720, 1e-12);
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    const double a = pose.yaw + scan.angle(i);
    const double c = std::cos(a), s = std::sin(a);
    double expected = 1e9;
    if (c > 1e-12) expected = std::min(expected, (4.9 - 0.7) / c);
    if (c < -1e-12) expected = std::min(expected, (-4.9 - 0.7) / c);
    if (s > 1e-12) expected = std::min(expected, (4.9 + 1.3) / s);
    if (s < -1e-12) expected = std::min(expected, (-4.9 + 1.3) / s);
    ASSERT_NEAR(scan.ranges[i], expected, 1e-5) << "beam " << i;
    const Vec2 e = scan.endpoint(i);
    ASSERT_NEAR(std::max(std::abs(e.x), std::abs(e.y)), 4.9, 1e-5);
  }
  // Short range: nothing is hit, every beam reports range_max.
  o.range_max = 2.0;
  const LaserScan short_scan = cast_scan(shifted, {{0.0, 0.0}, 0.0}, o);
  for (std::size_t i = 0; i < short_scan.ranges.size(); ++i) {
    EXPECT_FLOAT_EQ(short_scan.ranges[i], 2.0f);
    EXPECT_FALSE(short_scan.hit(i));
  }
}

TEST(Laser, DiscsAndNoiseAndBadOptions) {
  const BinaryGrid world = box_world(100, 100, 0.1);
  const Disc other{{7.0, 5.0}, 0.5};
  EXPECT_NEAR(cast_ray(world, {5.0, 5.0}, 0.0, 10.0, std::span(&other, 1)), 1.5, 1e-12);
  EXPECT_NEAR(cast_ray(world, {5.0, 5.0}, kPi, 10.0, std::span(&other, 1)), 4.9, 1e-9);
  LaserOptions o;
  o.range_max = 10.0;
  const LaserScan exact = cast_scan(world, {{5.0, 5.0}, 0.0}, o);
  o.noise_stddev = 0.02;
  std::mt19937_64 rng(3);
  const LaserScan noisy = cast_scan(world, {{5.0, 5.0}, 0.0}, o, {}, &rng);
  double sq = 0;
  for (std::size_t i = 0; i < noisy.ranges.size(); ++i)
    sq += std::pow(noisy.ranges[i] - exact.ranges[i], 2);
  EXPECT_GT(std::sqrt(sq / 360.0), 0.005);
  EXPECT_LT(std::sqrt(sq / 360.0), 0.05);
  o = {};
  o.beams = 0;
  EXPECT_THROW((void)cast_scan(world, {}, o), Error);
  o = {};
  o.range_max = std::nan("");
  EXPECT_THROW((void)cast_scan(world, {}, o), Error);
  EXPECT_THROW((void)cast_scan(world, {{std::nan(""), 1.0}, 0.0}, LaserOptions{}), Error);
}

// A synthetic scan: every beam returns `far`, except beams whose angle lies in [lo, hi].
LaserScan synthetic_scan(std::initializer_list<std::pair<double, double>> blocked, double near) {
  LaserScan s;
  s.angle_min = -kPi;
  s.angle_increment = 2 * kPi / 360;
  s.range_max = 3.0;
  s.ranges.assign(360, 3.0f);
  for (std::size_t i = 0; i < 360; ++i)
    for (auto [lo, hi] : blocked)
      if (s.angle(i) >= lo && s.angle(i) <= hi) s.ranges[i] = static_cast<float>(near);
  return s;
}

TEST(Controller, EachTable1RowMapsToItsHeading) {
  // Expected headings as printed in seed 004, Table 1.
  const std::pair<unsigned, Heading> rows[] = {
      {0b0000, Heading::kForward},       {0b1000, Heading::kRight}, {0b0001, Heading::kLeft},
      {0b1001, Heading::kForward},       {0b0100, Heading::kRight}, {0b0010, Heading::kLeft},
      {0b0110, Heading::kForwardOrLeft}, {0b1100, Heading::kLeft},  {0b0011, Heading::kRight},
      {0b1010, Heading::kRight},         {0b1110, Heading::kRight}, {0b0101, Heading::kLeft},
      {0b0111, Heading::kLeft},          {0b1111, Heading::kRight}};
  for (auto [bits, h] : rows) {
    EXPECT_EQ(table1_heading(static_cast<std::uint8_t>(bits)), h) << bits;
  }
  int sic = 0;
  for (const Table1Row& r : kTable1)
    sic += r.sic ? 1 : 0;
  EXPECT_EQ(sic, 2);
  EXPECT_EQ(table1_heading(0b1100, Table1Variant::kCorrected), Heading::kRight);
  EXPECT_EQ(table1_heading(0b0011, Table1Variant::kCorrected), Heading::kLeft);
  EXPECT_EQ(table1_heading(0b1011), Heading::kLeft);
  EXPECT_EQ(table1_heading(0b1101), Heading::kRight);
  EXPECT_THROW((void)table1_heading(16), Error);
}

TEST(Controller, SectorsFollowTheRosConvention) {
  const SectorOptions s;
  const double d = kPi / 180;
  EXPECT_EQ(obs_bits(synthetic_scan({}, 0.2), s, 0.4), 0b0000);
  EXPECT_EQ(obs_bits(synthetic_scan({{60 * d, 70 * d}}, 0.2), s, 0.4), kObsL);
  EXPECT_EQ(obs_bits(synthetic_scan({{10 * d, 20 * d}}, 0.2), s, 0.4), kObsFL);
  EXPECT_EQ(obs_bits(synthetic_scan({{-20 * d, -10 * d}}, 0.2), s, 0.4), kObsFR);
  EXPECT_EQ(obs_bits(synthetic_scan({{-70 * d, -60 * d}}, 0.2), s, 0.4), kObsR);
  EXPECT_EQ(obs_bits(synthetic_scan({{-100 * d, 100 * d}}, 0.2), s, 0.4), 0b1111);
  // Behind the robot is not part of any sector; beyond the distance is not counted.
  EXPECT_EQ(obs_bits(synthetic_scan({{120 * d, 170 * d}}, 0.2), s, 0.4), 0);
  EXPECT_EQ(obs_bits(synthetic_scan({{-100 * d, 100 * d}}, 0.5), s, 0.4), 0);
  // Counter threshold: a single beam is not enough when 3 are required.
  SectorOptions s3;
  s3.counter_threshold = 3;
  EXPECT_EQ(obs_bits(synthetic_scan({{10 * d, 10.5 * d}}, 0.2), s3, 0.4), 0);
}

TEST(Controller, ReactsAsTheRulesSay) {
  const double d = kPi / 180;
  ReactiveController c;
  // Front-left obstacle within obs_dist: turn right on the spot (Table 1 FL -> R).
  BodyVelocity cmd = c.update(synthetic_scan({{10 * d, 20 * d}}, 0.3), 0.1);
  EXPECT_EQ(c.mode(), ControllerMode::kAvoid);
  EXPECT_DOUBLE_EQ(cmd.v, 0.0);
  EXPECT_DOUBLE_EQ(cmd.omega, -0.3);
  // Obstacle in front but farther than obs_dist: approach slowly.
  ReactiveController c2;
  cmd = c2.update(synthetic_scan({{-5 * d, 5 * d}}, 0.8), 0.1);
  EXPECT_DOUBLE_EQ(cmd.v, 0.1);
  // Nothing near: drive at drive_velocity.
  cmd = c2.update(synthetic_scan({}, 3.0), 0.1);
  EXPECT_DOUBLE_EQ(cmd.v, 0.3);
  EXPECT_EQ(c2.mode(), ControllerMode::kRandom);
  // Wall on the left at 0.5 m (farther than desired 0.3 m): follow it, turning toward it.
  ReactiveController c3;
  cmd = c3.update(synthetic_scan({{45 * d, 135 * d}}, 0.5), 0.1);
  EXPECT_EQ(c3.mode(), ControllerMode::kWallFollowLeft);
  EXPECT_GT(cmd.omega, 0.0);
  cmd = c3.update(synthetic_scan({{45 * d, 135 * d}}, 0.2), 0.1);
  EXPECT_LT(cmd.omega, 0.0);
  // Wall lost for longer than wall_lost_time: back to random driving.
  for (int k = 0; k < 40; ++k)
    c3.update(synthetic_scan({}, 3.0), 0.1);
  EXPECT_EQ(c3.mode(), ControllerMode::kRandom);
  ReactiveControllerOptions bad;
  bad.obs_dist = -1;
  EXPECT_THROW(ReactiveController{bad}, Error);
}

TEST(Controller, DrivesWithoutCollisionsInAClutteredBox) {
  BinaryGrid world = box_world(120, 120, 0.05);  // 6 x 6 m
  for (int y = 40; y < 60; ++y)
    for (int x = 50; x < 70; ++x)
      world[Cell{x, y}] = 1;  // a 1 x 1 m block
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    DiffDriveRobot robot({}, {{1.0, 1.0}, 0.3 * static_cast<double>(seed)});
    ReactiveControllerOptions co;
    co.seed = seed;
    ReactiveController c(co);
    for (int k = 0; k < 2000; ++k) {  // 200 s
      const LaserScan scan = cast_scan(world, robot.true_pose(), LaserOptions{});
      robot.command(c.update(scan, 0.1));
      robot.step(0.1, world);
    }
    EXPECT_EQ(robot.collisions(), 0) << "seed " << seed;
    EXPECT_GT(robot.distance_travelled(), 20.0) << "seed " << seed;
  }
}

// The two "sic" rows of Table 1 turn toward the obstacle: in front of a wall the printed table
// makes the robot turn back and forth on the spot, the corrected one drives on.
TEST(Controller, PaperTableDithersInFrontOfAWallCorrectedDoesNot) {
  const BinaryGrid world = box_world(120, 120, 0.05);
  const auto travelled = [&](Table1Variant variant) {
    DiffDriveRobot robot({}, {{1.95, 0.43}, -1.0});  // 0.38 m from the bottom wall, facing it
    ReactiveControllerOptions co;
    co.table = variant;
    co.avoid_escape = AvoidEscape::kSpin;  // rule 2 as written: the table alone decides
    ReactiveController c(co);
    for (int k = 0; k < 600; ++k) {
      robot.command(c.update(cast_scan(world, robot.true_pose(), LaserOptions{}), 0.1));
      robot.step(0.1, world);
    }
    EXPECT_EQ(robot.collisions(), 0);
    return robot.distance_travelled();
  };
  EXPECT_LT(travelled(Table1Variant::kPaper), 0.2);
  EXPECT_GT(travelled(Table1Variant::kCorrected), 5.0);
}

// corridor_length: hand-computed entries of a disc of radius 0.16 m into single returns.
TEST(Controller, CorridorLengthIsWhereTheDiscTouchesAReturn) {
  const double d = kPi / 180;
  // A return straight ahead at 1 m: the disc touches it after 1 - 0.16 = 0.84 m.
  EXPECT_NEAR(corridor_length(synthetic_scan({{-0.4 * d, 0.4 * d}}, 1.0), 0.0, 0.16, 2.0), 0.84,
              1e-6);
  // Beside the centre, just behind it (91 deg, 0.14 m): never closer when driving on: the cap.
  EXPECT_DOUBLE_EQ(corridor_length(synthetic_scan({{90.5 * d, 91.5 * d}}, 0.14), 0.0, 0.16, 2.0),
                   2.0);
  // 45 deg at 0.2 m: along = lateral = 0.1414; enters at 0.1414 - sqrt(0.16^2 - 0.1414^2).
  const double a = 0.2 * std::cos(45 * d);
  EXPECT_NEAR(corridor_length(synthetic_scan({{44.6 * d, 45.4 * d}}, 0.2), 0.0, 0.16, 2.0),
              a - std::sqrt(0.16 * 0.16 - a * a), 1e-3);
  // The same return seen along bearing 45 deg: the disc touches it at 0.2 - 0.16 m.
  EXPECT_NEAR(corridor_length(synthetic_scan({{44.6 * d, 45.4 * d}}, 0.2), 45 * d, 0.16, 2.0), 0.04,
              1e-3);
}

// Rule 2 as written turns on the spot until an 80 deg front cone is clear within obs_dist. In a
// 0.5 m wide passage no heading clears it (the cone's edge beams meet the walls at
// 0.25 / sin 40 deg = 0.39 m), so the robot spins for ever (AvoidEscape::kSpin); the corridor
// escape drives out along the passage.
TEST(Controller, CorridorEscapeLeavesAPassageWhereRule2Spins) {
  BinaryGrid world = box_world(140, 60, 0.05);  // 7 x 3 m
  for (int x = 0; x < 140; ++x)
    for (int y = 0; y < 60; ++y)
      if (y < 25 || y >= 35) world[Cell{x, y}] = 1;  // free rows 25..34: y in [1.25, 1.75) m
  const auto run = [&](AvoidEscape escape) {
    DiffDriveRobot robot({}, {{3.5, 1.5}, 0.3});
    ReactiveControllerOptions co;
    co.avoid_escape = escape;
    ReactiveController c(co);
    for (int k = 0; k < 600; ++k) {  // 60 s
      robot.command(c.update(cast_scan(world, robot.true_pose(), LaserOptions{}), 0.1));
      robot.step(0.1, world);
    }
    EXPECT_EQ(robot.collisions(), 0);
    return std::pair{distance(robot.true_pose().position, Vec2{3.5, 1.5}), c.escapes()};
  };
  const auto [spin_moved, spin_escapes] = run(AvoidEscape::kSpin);
  EXPECT_LT(spin_moved, 0.05);
  EXPECT_EQ(spin_escapes, 0);
  const auto [escape_moved, escapes] = run(AvoidEscape::kCorridor);
  EXPECT_GT(escape_moved, 0.8);
  EXPECT_GE(escapes, 1);
  EXPECT_EQ(parse_avoid_escape("spin"), AvoidEscape::kSpin);
  EXPECT_THROW((void)parse_avoid_escape("twirl"), Error);
}

}  // namespace
}  // namespace voronav::robot
