// Tests of pictures: pixels land where the grid geometry says (row 0 at the bottom, world
// metres through the origin), both formats are written, and bad requests fail clearly.
#include <cairo.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "voronav/core/error.hpp"
#include "voronav/render/figure.hpp"
#include "voronav/render/plot.hpp"

namespace voronav::render {
namespace {

namespace fs = std::filesystem;

fs::path temp(const std::string& name) {
  return fs::temp_directory_path() / ("voronav_render_" + std::to_string(::getpid()) + "_" + name);
}

struct Png {
  explicit Png(const fs::path& p) : s(cairo_image_surface_create_from_png(p.c_str())) {}
  ~Png() { cairo_surface_destroy(s); }
  /// (r, g, b) 0..255 of pixel (x, y).
  std::array<int, 3> rgb(int x, int y) const {
    const auto* row = cairo_image_surface_get_data(s) + y * cairo_image_surface_get_stride(s);
    const std::uint32_t v = reinterpret_cast<const std::uint32_t*>(row)[x];
    return {static_cast<int>((v >> 16) & 0xff), static_cast<int>((v >> 8) & 0xff),
            static_cast<int>(v & 0xff)};
  }
  int width() const { return cairo_image_surface_get_width(s); }
  int height() const { return cairo_image_surface_get_height(s); }
  cairo_surface_t* s;
};

TEST(Figure, OccupancyRowZeroIsAtTheBottom) {
  OccupancyGrid g(GridGeometry{4, 3, 0.5, {{-1.0, 2.0}, 0.0}}, kFree);
  g[Cell{0, 0}] = kOccupied;
  g[Cell{3, 2}] = kUnknown;
  Figure f(g.geometry(),
           {.pixels_per_cell = 10, .title = "occupancy", .scale_unit = "", .occupancy_key = false});
  f.occupancy(g);
  const fs::path p = temp("occ.png");
  f.save(p);
  const Png png(p);
  ASSERT_EQ(png.width(), 40);
  ASSERT_EQ(png.height(), 28 + 30);                                     // title band + map
  EXPECT_EQ(png.rgb(5, 28 + 25), (std::array<int, 3>{0, 0, 0}));        // cell (0,0): bottom-left
  EXPECT_EQ(png.rgb(35, 28 + 5), (std::array<int, 3>{205, 205, 205}));  // cell (3,2): top-right
  EXPECT_EQ(png.rgb(15, 28 + 15), (std::array<int, 3>{255, 255, 255}));
  fs::remove(p);
}

TEST(Figure, WorldShapesUseTheGeometry) {
  const GridGeometry geo{10, 10, 0.1, {{5.0, 5.0}, 0.0}};
  Figure f(geo, {.pixels_per_cell = 4, .title = "circle", .scale_unit = ""});
  // World point (5.55, 5.15) is cell (5, 1): pixel centre (22, 28 + 40 - 6) = (22, 62).
  EXPECT_NEAR(f.to_pixel(Vec2{5.55, 5.15}).first, 22, 1e-9);
  EXPECT_NEAR(f.to_pixel(Vec2{5.55, 5.15}).second, 62, 1e-9);
  EXPECT_NEAR(f.to_pixel(Cell{5, 1}).first, f.to_pixel(Vec2{5.55, 5.15}).first, 1e-9);
  EXPECT_NEAR(f.to_pixel(Cell{5, 1}).second, f.to_pixel(Vec2{5.55, 5.15}).second, 1e-9);
  f.circle({5.55, 5.15}, 0.1, colors::kRed);
  const fs::path p = temp("circle.png");
  f.save(p);
  const Png png(p);
  EXPECT_EQ(png.rgb(22, 62), (std::array<int, 3>{0xd6, 0x27, 0x28}));
  EXPECT_EQ(png.rgb(2, 2), (std::array<int, 3>{255, 255, 255}));
  fs::remove(p);
}

TEST(Figure, PathAndSvg) {
  const BinaryGrid b(20, 20, 0);
  Figure f(b.geometry(), {.pixels_per_cell = 5, .title = "path"});
  f.binary(b, colors::kBlack);
  const std::vector<Cell> path = {{0, 10}, {19, 10}};
  f.path(path, colors::kBlue, 3);
  f.marker({0, 10}, colors::kGreen, 4, "start");
  f.legend({{"path", colors::kBlue}});
  const fs::path png = temp("path.png"), svg = temp("path.svg");
  f.save(png);
  f.save(svg);
  const Png img(png);
  EXPECT_EQ(img.height(), 100 + 28);  // title band
  // The path row: y = 28 + (20 - 10.5) * 5 = 75.5; pixel x = 50 lies on it.
  EXPECT_EQ(img.rgb(50, 75), (std::array<int, 3>{0x1f, 0x77, 0xb4}));
  std::ifstream in(svg);
  std::stringstream ss;
  ss << in.rdbuf();
  EXPECT_NE(ss.str().find("<svg"), std::string::npos);
  fs::remove(png);
  fs::remove(svg);
}

TEST(Figure, CropToKnownCells) {
  OccupancyGrid g(GridGeometry{50, 40, 0.1, {{-2.0, 1.0}, 0.0}}, kUnknown);
  for (int y = 10; y < 20; ++y)
    for (int x = 20; x < 30; ++x)
      g[Cell{x, y}] = kFree;
  g[Cell{20, 10}] = kOccupied;
  const CellBox b = known_bounds(g, 2);
  EXPECT_EQ(b.x0, 18);
  EXPECT_EQ(b.y0, 8);
  EXPECT_EQ(b.x1, 32);
  EXPECT_EQ(b.y1, 22);
  Figure f(g.geometry(), {.pixels_per_cell = 10,
                          .title = "crop",
                          .crop = b,
                          .scale_unit = "",
                          .occupancy_key = false});
  EXPECT_EQ(f.width_px(), 140);
  EXPECT_EQ(f.height_px(), 28 + 140);
  // Cell (20, 10) is crop cell (2, 2): pixel centre (25, 28 + 140 - 25); its world centre agrees.
  EXPECT_NEAR(f.to_pixel(Cell{20, 10}).first, 25, 1e-9);
  EXPECT_NEAR(f.to_pixel(g.geometry().cell_center(Cell{20, 10})).second, 143, 1e-9);
  f.occupancy(g);
  const fs::path p = temp("crop.png");
  f.save(p);
  const Png png(p);
  EXPECT_EQ(png.rgb(25, 143), (std::array<int, 3>{0, 0, 0}));
  EXPECT_EQ(png.rgb(45, 123), (std::array<int, 3>{255, 255, 255}));
  EXPECT_EQ(png.rgb(5, 33), (std::array<int, 3>{205, 205, 205}));
  fs::remove(p);
  EXPECT_THROW(Figure(g.geometry(), {.crop = {0, 0, 60, 10}}), Error);
  EXPECT_EQ(known_bounds(OccupancyGrid(4, 4, kUnknown)).x1, 4);
}

TEST(Figure, Errors) {
  EXPECT_THROW(Figure(GridGeometry{0, 5, 1.0, {}}), Error);
  // A picture must say what it shows.
  try {
    Figure(GridGeometry{5, 5, 1.0, {}}).save(temp("untitled.png"));
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("title"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("untitled.png"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(temp("untitled.png")));
  Figure f(GridGeometry{5, 5, 1.0, {}}, {.title = "errors"});
  EXPECT_THROW(f.colorbar(0.0, std::numeric_limits<double>::infinity(), "x"), Error);
  try {
    f.save(temp("x.bmp"));
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(".png or .svg"), std::string::npos);
  }
  EXPECT_THROW(f.save("/nonexistent-folder/x.png"), Error);
  // A raster of another size would be read out of bounds: refused with both sizes named.
  try {
    f.occupancy(OccupancyGrid(4, 5, kFree));
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("4x5"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("5x5"), std::string::npos) << e.what();
  }
  EXPECT_THROW(f.binary(BinaryGrid(5, 6, 0), colors::kBlack), Error);
}

// Every map picture carries a scale bar of a round length (1, 2 or 5 times a power of ten) about
// a fifth of the width, a colour bar per colour scale, and the occupancy key.
TEST(Figure, ScaleBarColourBarAndKey) {
  OccupancyGrid g(GridGeometry{200, 100, 0.05, {}}, kFree);  // 10 m x 5 m
  Figure f(g.geometry(), {.pixels_per_cell = 4, .title = "scale"});
  const auto [len, px] = f.scale_bar();
  EXPECT_DOUBLE_EQ(len, 2.0);  // 0.22 * 800 px = 176 px = 2.2 m: the round length below is 2 m
  EXPECT_NEAR(px, len * 4 / 0.05, 1e-9);
  f.occupancy(g);
  GridMap<float> field(g.geometry(), 0.0f);
  f.scalar(field, 0.0, 3.0, 0.5);
  f.colorbar(0.0, 3.0, "clearance [m]");
  const fs::path p = temp("scale.png");
  f.save(p);
  const Png png(p);
  // The bar's horizontal stroke, 12 px above the bottom, 10 px from the left edge onwards.
  const int y = png.height() - 12;
  EXPECT_LT(png.rgb(10 + static_cast<int>(px / 2), y)[0], 60);
  // The colour bar: viridis from yellow (top, hi) to purple (bottom, lo).
  int x = png.width() - 1;  // the middle of the bar: the first yellow pixel from the right, + 7
  const auto yellow = [](std::array<int, 3> c) { return c[0] + c[1] > 300 && c[2] < 120; };
  while (x > png.width() - 160 && !yellow(png.rgb(x, 28 + 12)))
    --x;
  x -= 7;
  const auto top = png.rgb(x, 28 + 12), bottom = png.rgb(x, 28 + 10 + 135);
  EXPECT_GT(top[0] + top[1], 300) << "top " << top[0] << "," << top[1] << "," << top[2];
  EXPECT_LT(bottom[1], 80) << "bottom " << bottom[0] << "," << bottom[1] << "," << bottom[2];
  fs::remove(p);
  // Moving AI maps: cells.
  Figure c(GridGeometry{50, 50, 1.0, {}},
           {.pixels_per_cell = 8, .title = "cells", .scale_unit = "cells"});
  EXPECT_DOUBLE_EQ(c.scale_bar().first, 10.0);  // 0.22 * 400 px / 8 px = 11 cells -> 10 cells
  EXPECT_EQ(Figure(GridGeometry{5, 5, 1.0, {}}, {.title = "d", .scale_unit = ""}).scale_bar().first,
            0.0);
}

TEST(Figure, HugeMapIsScaledDown) {
  Figure f(GridGeometry{100000, 50, 1.0, {}});
  EXPECT_LE(f.width_px(), 8192);
}

TEST(Plot, LinesBarsAndErrors) {
  Plot p({.title = "coverage", .x_label = "time [s]", .y_label = "coverage [%]"});
  p.line("a", {0, 1, 2}, {0, 50, 90}, colors::kBlue, true);
  p.error_bars({0, 5, 5});
  const fs::path out = temp("plot.png");
  p.save(out);
  const Png png(out);
  EXPECT_EQ(png.width(), 720);
  fs::remove(out);
  EXPECT_THROW(p.line("bad", {0, 1}, {1}, colors::kRed), Error);
  Plot b;
  b.categories({"A*", "RAS"});
  EXPECT_THROW(b.bars("t", {1.0}, colors::kRed), Error);
  b.bars("t", {1.0, 0.5}, colors::kRed);
  const fs::path out2 = temp("bars.svg");
  b.save(out2);
  EXPECT_TRUE(fs::exists(out2));
  fs::remove(out2);
}

}  // namespace
}  // namespace voronav::render
