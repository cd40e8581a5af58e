// Moving AI formats as they are in the wild (issue #16): space-separated "version 1.0" lines,
// scaled maps, the S and W terrain rules, and optimal lengths at the precision the file printed.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include "voronav/core/error.hpp"
#include "voronav/io/movingai.hpp"

namespace voronav::io {
namespace {

namespace fs = std::filesystem;

struct Dir {
  fs::path path;
  Dir() {
    path =
        fs::temp_directory_path() / ("voronav_movingai_" + std::to_string(std::random_device{}()));
    fs::create_directories(path);
  }
  ~Dir() { fs::remove_all(path); }
  fs::path operator/(const std::string& f) const { return path / f; }
};

void write(const fs::path& p, const std::string& text) {
  std::ofstream(p) << text;
}

TEST(MovingAiWild, SpaceSeparatedVersion10Lines) {
  Dir d;
  // bgmaps / wc3maps style: "version 1.0", single spaces; also runs of spaces and a trailing CR.
  write(d / "a.scen",
        "version 1.0\n0 maps/bgmaps/AR0011SR.map 512 512 1 2 3 4 1.41421356\n"
        "1  x.map   10 10  5 6 7 8   2.82842712\r\n");
  const auto q = load_movingai_scen(d / "a.scen");
  ASSERT_EQ(q.size(), 2u);
  EXPECT_EQ(q[0].map, "maps/bgmaps/AR0011SR.map");
  EXPECT_EQ(q[0].map_width, 512);
  EXPECT_EQ(q[0].start_y, 2);
  EXPECT_EQ(q[0].goal_y, 4);
  EXPECT_DOUBLE_EQ(q[0].optimal_length, 1.41421356);
  EXPECT_EQ(q[1].bucket, 1);
  EXPECT_EQ(q[1].goal_x, 7);
  EXPECT_EQ(q[1].line, 3);
  // "version 1" with tabs keeps a map name with a space whole.
  write(d / "b.scen", "version 1\n3\tmy map.map\t4\t4\t0\t0\t1\t1\t1.41421356\n");
  EXPECT_EQ(load_movingai_scen(d / "b.scen")[0].map, "my map.map");
  write(d / "c.scen", "version 1.0\n0 m.map 10 10 1 1 2\n");
  try {
    (void)load_movingai_scen(d / "c.scen");
    FAIL() << "7 columns accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("c.scen:2"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("got 7"), std::string::npos) << e.what();
  }
}

TEST(MovingAiWild, ScaledMap) {
  Dir d;
  // 3x2 map; the scenario says 6x4: every cell becomes a 2x2 block.
  write(d / "s.map", "type octile\nheight 2\nwidth 3\nmap\n.@.\n..W\n");
  write(d / "s.scen", "version 1\n0\ts.map\t6\t4\t0\t0\t5\t3\t7\n");
  const MovingAiTerrain t = load_movingai_terrain(d / "s.map");
  const auto q = load_movingai_scen(d / "s.scen");
  const OccupancyGrid g = load_movingai_map(d / "s.map");
  EXPECT_THROW(check_scen_fits(q, g, d / "s.scen"), Error);  // the strict check refuses
  EXPECT_NO_THROW(check_scen_fits(q, g, d / "s.scen", /*allow_scaling=*/true));
  const MovingAiTerrain s = scale_movingai_terrain(t, 6, 4);
  ASSERT_EQ(s.cells.width(), 6);
  ASSERT_EQ(s.cells.height(), 4);
  const char* want[4] = {"..@@..", "..@@..", "....WW", "....WW"};  // file rows, top first
  for (int fy = 0; fy < 4; ++fy)
    for (int x = 0; x < 6; ++x)
      EXPECT_EQ(s.cells[movingai_to_cell(x, fy, 4)], want[fy][x]) << x << "," << fy;
  // Coordinates beyond the size columns are still refused.
  write(d / "o.scen", "version 1\n0\ts.map\t6\t4\t0\t0\t6\t3\t7\n");
  EXPECT_THROW(check_scen_fits(load_movingai_scen(d / "o.scen"), g, d / "o.scen", true), Error);
}

TEST(MovingAiWild, SwampAndWaterRules) {
  Dir d;
  write(d / "t.map", "type octile\nheight 2\nwidth 5\nmap\n.SWW@\nGTWW.\n");
  const MovingAiTerrain t = load_movingai_terrain(d / "t.map");
  const BinaryGrid land = t.traversable(false), water = t.traversable(true);
  // File row 0 is voronav row 1. Swamp is land; water is only in the water grid.
  EXPECT_EQ((land[Cell{0, 1}]), 0);  // .
  EXPECT_EQ((land[Cell{1, 1}]), 0);  // S
  EXPECT_EQ((land[Cell{0, 0}]), 0);  // G
  EXPECT_EQ((land[Cell{2, 1}]), 1);  // W: not passable from land
  EXPECT_EQ((land[Cell{1, 0}]), 1);  // T
  EXPECT_EQ((water[Cell{2, 1}]), 0);
  EXPECT_EQ((water[Cell{3, 0}]), 0);
  EXPECT_EQ((water[Cell{1, 1}]), 1);  // S is not water
  EXPECT_EQ((water[Cell{4, 0}]), 1);  // '.' is not water
  EXPECT_TRUE(t.is_water({3, 1}));
  EXPECT_FALSE(t.is_water({1, 1}));
  // The plain loader keeps its meaning: land free, everything else (water too) occupied.
  const OccupancyGrid g = load_movingai_map(d / "t.map");
  EXPECT_EQ((g[Cell{1, 1}]), kFree);
  EXPECT_EQ((g[Cell{2, 1}]), kOccupied);
}

TEST(MovingAiWild, OptimalLengthAtPrintedPrecision) {
  MovingAiQuery q;
  q.optimal_length = 1001;
  q.optimal_rounding = last_digit_unit("1001");
  EXPECT_DOUBLE_EQ(q.optimal_rounding, 0.01);
  EXPECT_TRUE(matches_optimal(q, 1000.997));  // %g of 1000.997 is "1001"
  EXPECT_FALSE(matches_optimal(q, 1000.9));   // %g of 1000.9 is "1000.9"
  EXPECT_FALSE(matches_optimal(q, 1001.02));
  // The reproduction: 970x170 corner to corner is 800 + 169 sqrt 2 = 1039.002.
  q.optimal_length = 1039;
  q.optimal_rounding = last_digit_unit("1039");
  EXPECT_TRUE(matches_optimal(q, 800.0 + 169.0 * std::sqrt(2.0)));
  EXPECT_DOUBLE_EQ(last_digit_unit("262.764"), 0.001);       // 3 decimals (truncated files)
  EXPECT_DOUBLE_EQ(last_digit_unit("1039.41421356"), 1e-8);  // 8 decimals
  EXPECT_DOUBLE_EQ(last_digit_unit("0.5"), 1e-6);
  EXPECT_DOUBLE_EQ(last_digit_unit("1.5e+03"), 0.01);
  EXPECT_DOUBLE_EQ(last_digit_unit("0"), 0.0);
  // Read from a file: the column's own text decides.
  Dir d;
  write(d / "p.scen",
        "version 1\n0\tm.map\t9\t9\t0\t0\t1\t1\t1001\n0\tm.map\t9\t9\t0\t0\t1\t1\t1000.9\n");
  const auto qs = load_movingai_scen(d / "p.scen");
  EXPECT_TRUE(matches_optimal(qs[0], 1000.997));
  EXPECT_FALSE(matches_optimal(qs[1], 1000.997));
}

}  // namespace
}  // namespace voronav::io
