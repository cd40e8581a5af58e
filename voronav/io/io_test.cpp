// Tests of the map formats: real bundled maps load with the documented pixel rules, every format
// round-trips, and malformed files fail with an error naming the file and line.
#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <random>

#include "voronav/core/error.hpp"
#include "voronav/io/floorplan.hpp"
#include "voronav/io/image.hpp"
#include "voronav/io/map_loader.hpp"
#include "voronav/io/movingai.hpp"
#include "voronav/io/ros_map.hpp"

namespace voronav::io {
namespace {

namespace fs = std::filesystem;
const fs::path kData = fs::path(VORONAV_SOURCE_DIR) / "data";

class TempDir {
 public:
  TempDir() {
    static int counter = 0;
    path_ = fs::temp_directory_path() /
            ("voronav_io_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    fs::create_directories(path_);
  }
  ~TempDir() { fs::remove_all(path_); }
  fs::path operator/(const std::string& name) const { return path_ / name; }

 private:
  fs::path path_;
};

void write_text(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

/// Expects load() to throw voronav::Error whose message contains every fragment.
template <typename F>
void expect_error(F&& load, std::initializer_list<std::string> fragments) {
  try {
    load();
    ADD_FAILURE() << "expected voronav::Error";
  } catch (const Error& e) {
    for (const auto& f : fragments)
      EXPECT_NE(std::string(e.what()).find(f), std::string::npos)
          << "message '" << e.what() << "' lacks '" << f << "'";
  }
}

TEST(RosMap, LoadsTurtlebotWorldWithMapServerRules) {
  const RosMap m = read_ros_map(kData / "ros_maps/turtlebot3_world/map.yaml");
  EXPECT_EQ(m.grid.width(), 384);
  EXPECT_EQ(m.grid.height(), 384);
  EXPECT_DOUBLE_EQ(m.grid.resolution(), 0.05);
  EXPECT_DOUBLE_EQ(m.grid.geometry().origin.position.x, -10.0);
  EXPECT_DOUBLE_EQ(m.metadata.free_thresh, 0.196);
  // Check every pixel against the trinary rule and the row flip, from the raw image.
  const GrayImage img = read_pgm(kData / "ros_maps/turtlebot3_world/map.pgm");
  int counts[3] = {0, 0, 0};
  for (int j = 0; j < img.height; ++j)
    for (int x = 0; x < img.width; ++x) {
      const double occ = 1.0 - img.at(x, j) / 255.0;
      const std::int8_t want = occ > 0.65 ? kOccupied : (occ < 0.196 ? kFree : kUnknown);
      ASSERT_EQ((m.grid[Cell{x, img.height - 1 - j}]), want) << x << "," << j;
      ++counts[want == kFree ? 0 : want == kOccupied ? 1 : 2];
    }
  EXPECT_GT(counts[0], 1000);
  EXPECT_GT(counts[1], 100);
  EXPECT_GT(counts[2], 1000);
}

TEST(RosMap, RoundTripAllModes) {
  TempDir dir;
  OccupancyGrid g(GridGeometry{7, 5, 0.1, {{1.5, -2.0}, 0.0}}, kFree);
  g[Cell{0, 0}] = kOccupied;
  g[Cell{6, 4}] = kUnknown;
  g[Cell{3, 2}] = kOccupied;
  // trinary PGM
  save_ros_map(g, dir / "t.yaml");
  EXPECT_EQ(load_ros_map(dir / "t.yaml"), g);
  // trinary PNG
  save_ros_map(g, dir / "p.yaml", {.image_name = "p.png"});
  EXPECT_EQ(load_ros_map(dir / "p.yaml"), g);
  // raw keeps every value 0..100
  OccupancyGrid r = g;
  r[Cell{1, 1}] = 37;
  r[Cell{2, 1}] = 99;
  save_ros_map(r, dir / "r.yaml", {.mode = RosMapMode::kRaw});
  EXPECT_EQ(load_ros_map(dir / "r.yaml"), r);
  // scale: unknown through alpha; intermediate values survive within one quantisation step
  OccupancyGrid s = g;
  s[Cell{1, 1}] = 50;
  save_ros_map(s, dir / "s.yaml",
               {.mode = RosMapMode::kScale,
                .occupied_thresh = 1.0,
                .free_thresh = 0.0,
                .image_name = "s.png"});
  const OccupancyGrid back = load_ros_map(dir / "s.yaml");
  EXPECT_EQ((back[Cell{6, 4}]), kUnknown);
  EXPECT_NEAR((back[Cell{1, 1}]), 50, 1);
  EXPECT_EQ((back[Cell{0, 0}]), kOccupied);
}

TEST(RosMap, UnknownSavesAs205AndRowsFlip) {
  TempDir dir;
  OccupancyGrid g(GridGeometry{2, 2, 1.0, {}}, kFree);
  g[Cell{0, 0}] = kUnknown;   // bottom-left = last image row
  g[Cell{1, 1}] = kOccupied;  // top-right = first image row
  save_ros_map(g, dir / "m.yaml");
  const GrayImage img = read_pgm(dir / "m.pgm");
  EXPECT_EQ(img.at(0, 1), 205);
  EXPECT_EQ(img.at(1, 0), 0);
  EXPECT_EQ(img.at(0, 0), 254);
}

TEST(RosMap, NegateInvertsShades) {
  TempDir dir;
  write_text(dir / "i.pgm", "P2\n2 1\n255\n0 255\n");
  write_text(dir / "m.yaml",
             "image: i.pgm\nresolution: 1\norigin: [0, 0, 0]\nnegate: 1\noccupied_thresh: 0.65\n"
             "free_thresh: 0.196\n");
  const OccupancyGrid g = load_ros_map(dir / "m.yaml");
  EXPECT_EQ((g[Cell{0, 0}]), kFree);
  EXPECT_EQ((g[Cell{1, 0}]), kOccupied);
}

TEST(RosMap, MalformedInputsNameFileAndLine) {
  TempDir dir;
  write_text(dir / "i.pgm", "P2\n2 2\n255\n0 255 255 0\n");
  const std::string ok_tail = "origin: [0, 0, 0]\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
  auto yaml = [&](const std::string& name, const std::string& text) {
    write_text(dir / name, text);
    return dir / name;
  };
  const auto missing_key = yaml("a.yaml", "image: i.pgm\n" + ok_tail);
  expect_error([&] { (void)load_ros_map(missing_key); }, {"a.yaml", "resolution"});
  const auto bad_number = yaml("b.yaml", "image: i.pgm\nresolution: abc\n" + ok_tail);
  expect_error([&] { (void)load_ros_map(bad_number); }, {"b.yaml:2", "resolution", "abc"});
  const auto negative = yaml("c.yaml", "image: i.pgm\nresolution: -1\n" + ok_tail);
  expect_error([&] { (void)load_ros_map(negative); }, {"c.yaml:2", "positive"});
  const auto no_image = yaml("d.yaml", "image: nothere.pgm\nresolution: 0.05\n" + ok_tail);
  expect_error([&] { (void)load_ros_map(no_image); }, {"d.yaml:1", "nothere.pgm", "not found"});
  const auto bad_origin = yaml(
      "e.yaml",
      "image: i.pgm\nresolution: 0.05\norigin: [0, 0]\noccupied_thresh: 0.65\nfree_thresh: 0.1\n");
  expect_error([&] { (void)load_ros_map(bad_origin); }, {"e.yaml:3", "origin"});
  const auto bad_mode = yaml("f.yaml", "image: i.pgm\nresolution: 0.05\nmode: fuzzy\n" + ok_tail);
  expect_error([&] { (void)load_ros_map(bad_mode); }, {"f.yaml:3", "fuzzy"});
  const auto bad_yaml = yaml("g.yaml", "image: [i.pgm\nresolution: 0.05\n");
  expect_error([&] { (void)load_ros_map(bad_yaml); }, {"g.yaml", "malformed YAML"});
  const auto thresholds = yaml(
      "h.yaml",
      "image: i.pgm\nresolution: 0.05\norigin: [0,0,0]\noccupied_thresh: 0.1\nfree_thresh: 0.5\n");
  expect_error([&] { (void)load_ros_map(thresholds); }, {"h.yaml", "free_thresh"});
  const auto nan_origin = yaml("k.yaml",
                               "image: i.pgm\nresolution: 0.05\norigin: [.nan, 0, "
                               "0]\noccupied_thresh: 0.65\nfree_thresh: 0.1\n");
  expect_error([&] { (void)load_ros_map(nan_origin); }, {"k.yaml:3", "finite"});
  expect_error([&] { (void)load_ros_map(dir / "none.yaml"); }, {"none.yaml", "cannot open"});
}

TEST(Image, MalformedPgm) {
  TempDir dir;
  write_text(dir / "trunc.pgm", std::string("P5\n4 4\n255\n") + std::string(5, '\0'));
  expect_error([&] { (void)read_pgm(dir / "trunc.pgm"); }, {"trunc.pgm", "truncated raster", "16"});
  write_text(dir / "magic.pgm", "P7\n1 1\n255\n0\n");
  expect_error([&] { (void)read_pgm(dir / "magic.pgm"); }, {"magic.pgm:1", "P2 or P5"});
  write_text(dir / "hdr.pgm", "P2\n# comment\nx 2\n255\n");
  expect_error([&] { (void)read_pgm(dir / "hdr.pgm"); }, {"hdr.pgm:3", "width"});
  write_text(dir / "val.pgm", "P2\n1 1\n10\n11\n");
  expect_error([&] { (void)read_pgm(dir / "val.pgm"); }, {"val.pgm", "exceeds maxval"});
  write_text(dir / "short.pgm", "P2\n2 2\n255\n1 2 3\n");
  expect_error([&] { (void)read_pgm(dir / "short.pgm"); }, {"short.pgm", "truncated"});
  write_text(dir / "huge.pgm", "P5\n100000 100000\n255\n");
  expect_error([&] { (void)read_pgm(dir / "huge.pgm"); }, {"huge.pgm", "image size"});
  write_text(dir / "bad.png", "\x89PNG\r\n\x1a\nthis is not a png");
  expect_error([&] { (void)read_image(dir / "bad.png"); }, {"bad.png", "PNG"});
  write_text(dir / "x.bmp", "BM....");
  expect_error([&] { (void)read_image(dir / "x.bmp"); }, {"x.bmp", "unsupported"});
}

TEST(Image, Pgm16BitAndAsciiScale) {
  TempDir dir;
  write_text(dir / "a.pgm", "P2\n3 1\n# max 1000\n1000\n0 500 1000\n");
  const GrayImage a = read_pgm(dir / "a.pgm");
  EXPECT_EQ(a.gray, (std::vector<std::uint8_t>{0, 128, 255}));
  std::string raw = "P5\n2 1\n65535\n";
  raw += std::string("\x00\x00\xff\xff", 4);
  write_text(dir / "b.pgm", raw);
  EXPECT_EQ(read_pgm(dir / "b.pgm").gray, (std::vector<std::uint8_t>{0, 255}));
}

TEST(MovingAi, LoadsArenaAndAllScenQueriesFit) {
  const OccupancyGrid g = load_movingai_map(kData / "movingai/arena.map");
  EXPECT_EQ(g.width(), 49);
  EXPECT_EQ(g.height(), 49);
  const auto q = load_movingai_scen(kData / "movingai/arena.map.scen");
  ASSERT_GT(q.size(), 100u);
  EXPECT_NO_THROW(check_scen_fits(q, g, "arena.map.scen"));
  EXPECT_EQ(q[0].start_x, 1);
  EXPECT_EQ(q[0].start_y, 11);
  EXPECT_DOUBLE_EQ(q[0].optimal_length, 1.0);
  EXPECT_EQ(q[0].line, 2);
  EXPECT_DOUBLE_EQ(q[0].optimal_rounding, 1e-5);  // "1": 6 significant digits (%g)
  // Every query's start and goal are passable in the file frame.
  for (const auto& s : q) {
    EXPECT_EQ(g[movingai_to_cell(s.start_x, s.start_y, g.height())], kFree);
    EXPECT_EQ(g[movingai_to_cell(s.goal_x, s.goal_y, g.height())], kFree);
  }
}

TEST(MovingAi, TerrainCharactersAndFlip) {
  TempDir dir;
  write_text(dir / "t.map", "type octile\nheight 2\nwidth 4\nmap\n.GS@\nOTW.\n");
  const OccupancyGrid g = load_movingai_map(dir / "t.map");
  // File row 0 (top) is grid row 1.
  EXPECT_EQ((g[Cell{0, 1}]), kFree);
  EXPECT_EQ((g[Cell{1, 1}]), kFree);
  EXPECT_EQ((g[Cell{2, 1}]), kFree);
  EXPECT_EQ((g[Cell{3, 1}]), kOccupied);
  EXPECT_EQ((g[Cell{0, 0}]), kOccupied);
  EXPECT_EQ((g[Cell{2, 0}]), kOccupied);
  EXPECT_EQ((g[Cell{3, 0}]), kFree);
  EXPECT_EQ(cell_to_movingai(Cell{3, 0}, 2), (std::pair<int, int>{3, 1}));
}

TEST(MovingAi, RoundTripRandomMapsAndScen) {
  TempDir dir;
  std::mt19937 rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    const int w = 1 + static_cast<int>(rng() % 40), h = 1 + static_cast<int>(rng() % 40);
    OccupancyGrid g(w, h, kFree);
    for (std::size_t i = 0; i < g.size(); ++i)
      g[i] = rng() % 3 == 0 ? kOccupied : kFree;
    save_movingai_map(g, dir / "r.map");
    ASSERT_EQ(load_movingai_map(dir / "r.map"), g);
  }
  std::vector<MovingAiQuery> q(3);
  for (int i = 0; i < 3; ++i)
    q[static_cast<std::size_t>(i)] = {i,      "maps/x.map",  10,  12,   i, 2 * i, 9 - i,
                                      11 - i, 1.0 / (i + 3), 0.0, i + 2};
  save_movingai_scen(q, dir / "r.scen");
  const auto back = load_movingai_scen(dir / "r.scen");
  ASSERT_EQ(back.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(back[static_cast<std::size_t>(i)].goal_y, 11 - i);
    EXPECT_DOUBLE_EQ(back[static_cast<std::size_t>(i)].optimal_length, 1.0 / (i + 3));
  }
}

TEST(MovingAi, MalformedFiles) {
  TempDir dir;
  write_text(dir / "a.map", "type octile\nheight 3\nwidth 2\nmap\n..\n..\n");
  expect_error([&] { (void)load_movingai_map(dir / "a.map"); }, {"a.map:7", "truncated", "row 3"});
  write_text(dir / "b.map", "type octile\nheight 2\nwidth 3\nmap\n...\n..\n");
  expect_error([&] { (void)load_movingai_map(dir / "b.map"); },
               {"b.map:6", "2 characters", "width 3"});
  write_text(dir / "c.map", "kind octile\n");
  expect_error([&] { (void)load_movingai_map(dir / "c.map"); }, {"c.map:1", "type octile"});
  write_text(dir / "d.map", "type octile\nheight x\n");
  expect_error([&] { (void)load_movingai_map(dir / "d.map"); }, {"d.map:2", "height", "'x'"});
  write_text(dir / "e.map", "type octile\nheight 1\nwidth 2\nmap\n.#\n");
  expect_error([&] { (void)load_movingai_map(dir / "e.map"); }, {"e.map:5", "'#'", "column 2"});
  write_text(dir / "f.map", "type octile\nheight 0\nwidth 2\nmap\n");
  expect_error([&] { (void)load_movingai_map(dir / "f.map"); }, {"f.map", "height and width"});
  write_text(dir / "r.scen", "version 1\n0\tm.map\t10\t10\t1\t1\t2\t2\t101.054\n");
  EXPECT_DOUBLE_EQ(load_movingai_scen(dir / "r.scen")[0].optimal_rounding, 0.001);
  write_text(dir / "a.scen", "version 2\n");
  expect_error([&] { (void)load_movingai_scen(dir / "a.scen"); }, {"a.scen:1", "version 1"});
  write_text(dir / "b.scen", "version 1\n0\tm.map\t10\t10\t1\t1\t2\t2\n");
  expect_error([&] { (void)load_movingai_scen(dir / "b.scen"); },
               {"b.scen:2", "9 tab-separated", "got 8"});
  write_text(dir / "c.scen", "version 1\n0\tm.map\t10\t10\t1\tq\t2\t2\t1.5\n");
  expect_error([&] { (void)load_movingai_scen(dir / "c.scen"); }, {"c.scen:2", "start y", "'q'"});
  write_text(dir / "d.scen", "version 1\n0\tm.map\t10\t10\t1\t1\t2\t2\tnan\n");
  expect_error([&] { (void)load_movingai_scen(dir / "d.scen"); }, {"d.scen:2", "optimal length"});
  // A query for another map size.
  write_text(dir / "e.scen", "version 1\n0\tm.map\t10\t10\t1\t1\t2\t2\t1.5\n");
  const OccupancyGrid g(5, 5, kFree);
  expect_error([&] { check_scen_fits(load_movingai_scen(dir / "e.scen"), g, dir / "e.scen"); },
               {"e.scen:2", "10x10", "5x5"});
}

TEST(Floorplan, WhiteFreeBlackOccupied) {
  const OccupancyGrid g = load_floorplan(kData / "floorplans/office_b.png");
  EXPECT_DOUBLE_EQ(g.resolution(), 0.05);
  std::size_t free = 0, occ = 0;
  for (auto v : g.data())
    (v == kFree ? free : occ) += 1;
  EXPECT_EQ(free + occ, g.size());  // a binary plan: no unknown cells with the defaults
  EXPECT_GT(free, g.size() / 10);
  EXPECT_GT(occ, 0u);
  TempDir dir;
  expect_error([&] { (void)load_floorplan(dir / "none.png"); }, {"none.png", "cannot open"});
  expect_error([&] { (void)load_floorplan(kData / "floorplans/office_b.png", {.resolution = 0}); },
               {"office_b.png", "resolution"});
}

TEST(MapLoader, DispatchesByExtension) {
  EXPECT_EQ(load_map(kData / "movingai/arena.map").format, MapFormat::kMovingAi);
  EXPECT_EQ(load_map(kData / "ros_maps/depot/depot.yaml").format, MapFormat::kRos);
  EXPECT_EQ(load_map(kData / "floorplans/lab_ipa.png").format, MapFormat::kImage);
  TempDir dir;
  write_text(dir / "m.txt", "x");
  expect_error([&] { (void)load_map(dir / "m.txt"); }, {"m.txt", "unknown map format"});
  expect_error([&] { (void)load_map(dir / "nope.yaml"); }, {"nope.yaml", "not found"});
}

}  // namespace
}  // namespace voronav::io
