// Figure: a picture of a grid map and what lies on it (rasters of occupancy, distance, labels;
// cells, paths, points, circles, segments, text), saved as PNG or SVG by file extension. Drawing
// calls are recorded and replayed at save(), so one Figure can be written in both formats.
// Coordinates: Cell overloads draw at cell centres; Vec2 overloads take world metres and use the
// grid's GridGeometry (resolution, origin), so anything in the world frame lands where it is.
// One figure style for every picture the tool writes (issue 20): save() refuses a figure without
// a title, and draws a scale bar (metres, or cells for Moving AI maps), a key of the occupancy
// greys when the map was drawn, the legend entries, and a colour bar for every colour scale.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "voronav/core/grid_map.hpp"
#include "voronav/core/occupancy.hpp"
#include "voronav/render/color.hpp"

struct _cairo;  // cairo_t, kept out of the public header

namespace voronav::render {

/// A rectangle of cells, [x0, x1) x [y0, y1).
struct CellBox {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

/// The bounding box of the known (not unknown) cells of `grid`, grown by `margin` cells and
/// clipped to the grid; the whole grid when nothing is known. Maps from SLAM are mostly unknown
/// space around the building: cropping to this box makes the building fill the picture.
[[nodiscard]] CellBox known_bounds(const OccupancyGrid& grid, int margin = 5);

struct FigureOptions {
  /// Pixels per cell; 0 = automatic: the larger side of the map becomes `auto_side_px`.
  double pixels_per_cell = 0.0;
  int auto_side_px = 900;
  int max_side_px = 8192;  ///< hard limit for huge maps (pixels_per_cell is reduced to fit)
  std::string title{};     ///< drawn in a band above the map; required by save()
  /// Draw only these cells of the grid (e.g. known_bounds(map)); empty box = the whole grid.
  CellBox crop{};
  /// Unit of the scale bar in the lower-left corner: "m" (world metres, from the resolution),
  /// "cells" (Moving AI maps, whose cells have no size), or "" for none (a diagram that is not a
  /// map, such as the (M,D) network).
  std::string scale_unit = "m";
  /// The key of the occupancy greys in the legend when occupancy() was drawn. Off only for
  /// pixel-exact tests of tiny figures, where the box would cover the map.
  bool occupancy_key = true;
};

class Figure {
 public:
  explicit Figure(const GridGeometry& geometry, FigureOptions options = {});

  // Rasters (one pixel block per cell); each must have the size of the figure's grid.
  /// free white, occupied black, unknown light grey, 1..99 grey by probability.
  void occupancy(const OccupancyGrid& grid);
  /// Cells with value != 0 in `on`, cells with 0 in `off` (transparent by default).
  void binary(const BinaryGrid& grid, Color on, Color off = colors::kTransparent);
  /// Scalar field with the viridis map over [lo, hi]; non-finite values are left transparent.
  void scalar(const GridMap<float>& field, double lo, double hi, double alpha = 1.0);
  /// Label raster: label < 0 transparent, others by palette(label).
  void labels(const GridMap<std::int32_t>& labels, double alpha = 0.55);
  void cells(std::span<const Cell> cells, Color color);

  // Vector shapes in grid terms (cell centres).
  void path(std::span<const Cell> path, Color color, double width_px = 2.5);
  void marker(Cell c, Color color, double radius_px = 6.0, const std::string& label = "");
  void cell_text(Cell c, const std::string& text, Color color, double size_px = 10.0);

  // Vector shapes in world metres.
  void polyline(std::span<const Vec2> points, Color color, double width_px = 2.0,
                bool closed = false);
  void segment(Vec2 a, Vec2 b, Color color, double width_px = 1.5);
  void point(Vec2 p, Color color, double radius_px = 3.0);
  void circle(Vec2 centre, double radius_m, Color fill, Color stroke = colors::kTransparent,
              double stroke_px = 1.0);
  /// An arrow from a to b [m] (headings, velocities).
  void arrow(Vec2 a, Vec2 b, Color color, double width_px = 1.5);
  void text(Vec2 p, const std::string& text, Color color, double size_px = 12.0);

  /// Entries of the legend box in the lower-right corner (calls add up). When occupancy() was
  /// drawn, the key of its greys (free, occupied, unknown where present) comes first.
  void legend(std::vector<std::pair<std::string, Color>> entries);
  /// A colour bar in the upper-right corner for a scalar() layer: viridis from lo to hi, with
  /// `label` (including the unit, e.g. "clearance [m]").
  void colorbar(double lo, double hi, const std::string& label);

  /// Writes .png or .svg (by extension); throws voronav::Error otherwise, on write failure, or
  /// when the figure has no title.
  void save(const std::filesystem::path& path) const;
  /// The scale bar save() draws: its length in the figure's unit and in pixels (0 without one).
  [[nodiscard]] std::pair<double, double> scale_bar() const;

  [[nodiscard]] int width_px() const { return width_px_; }
  [[nodiscard]] int height_px() const { return height_px_; }
  [[nodiscard]] double pixels_per_cell() const { return ppc_; }
  /// Pixel position of a world point / of a cell centre.
  [[nodiscard]] std::pair<double, double> to_pixel(Vec2 world) const;
  [[nodiscard]] std::pair<double, double> to_pixel(Cell c) const;

 private:
  using Op = std::function<void(_cairo*)>;
  /// Throws voronav::Error when a raster's size differs from the figure's grid.
  void check_raster(int width, int height, const char* what) const;
  void raster(std::function<std::uint32_t(Cell)> argb);

  GridGeometry geometry_;                 ///< of the drawn part (the crop)
  Cell offset_{};                         ///< grid cell of the crop's cell (0, 0)
  int grid_width_ = 0, grid_height_ = 0;  ///< of the whole grid (rasters must match)
  FigureOptions options_;
  double ppc_ = 1.0;
  int header_px_ = 0;
  int width_px_ = 0, height_px_ = 0;
  std::vector<Op> ops_;
  std::vector<std::pair<std::string, Color>> legend_;
  bool occupancy_drawn_ = false, unknown_drawn_ = false;
  struct ColorBar {
    double lo = 0.0, hi = 1.0;
    std::string label;
  };
  std::vector<ColorBar> colorbars_;
};

}  // namespace voronav::render
