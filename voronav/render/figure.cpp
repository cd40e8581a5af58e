#include "voronav/render/figure.hpp"

#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "voronav/core/error.hpp"
#include "voronav/render/internal/cairo_util.hpp"

namespace voronav::render {
namespace {

std::uint32_t argb(Color c) {
  const auto ch = [&](double v) {
    return static_cast<std::uint32_t>(std::lround(std::clamp(v * c.a, 0.0, 1.0) * 255.0));
  };
  return (static_cast<std::uint32_t>(std::lround(std::clamp(c.a, 0.0, 1.0) * 255.0)) << 24) |
         (ch(c.r) << 16) | (ch(c.g) << 8) | ch(c.b);
}

}  // namespace

CellBox known_bounds(const OccupancyGrid& grid, int margin) {
  CellBox b{grid.width(), grid.height(), -1, -1};
  for (int y = 0; y < grid.height(); ++y)
    for (int x = 0; x < grid.width(); ++x)
      if (grid[Cell{x, y}] != kUnknown) {
        b.x0 = std::min(b.x0, x);
        b.y0 = std::min(b.y0, y);
        b.x1 = std::max(b.x1, x + 1);
        b.y1 = std::max(b.y1, y + 1);
      }
  if (b.x1 < 0) return {0, 0, grid.width(), grid.height()};
  return {std::max(0, b.x0 - margin), std::max(0, b.y0 - margin),
          std::min(grid.width(), b.x1 + margin), std::min(grid.height(), b.y1 + margin)};
}

Figure::Figure(const GridGeometry& geometry, FigureOptions options)
    : geometry_(geometry), options_(std::move(options)) {
  if (geometry_.empty()) throw Error("render::Figure: the grid is empty (0 cells)");
  grid_width_ = geometry.width;
  grid_height_ = geometry.height;
  const CellBox& c = options_.crop;
  if (c.x1 > c.x0 || c.y1 > c.y0) {
    if (c.x0 < 0 || c.y0 < 0 || c.x1 > geometry.width || c.y1 > geometry.height || c.x1 <= c.x0 ||
        c.y1 <= c.y0)
      throw Error("render::Figure: crop box is empty or outside the grid");
    offset_ = {c.x0, c.y0};
    geometry_.width = c.x1 - c.x0;
    geometry_.height = c.y1 - c.y0;
    geometry_.origin.position = geometry.origin.transform(
        Vec2{static_cast<double>(c.x0), static_cast<double>(c.y0)} * geometry.resolution);
  }
  const int side = std::max(geometry_.width, geometry_.height);
  ppc_ = options_.pixels_per_cell > 0 ? options_.pixels_per_cell
                                      : static_cast<double>(options_.auto_side_px) / side;
  ppc_ = std::min(ppc_, static_cast<double>(options_.max_side_px) / side);
  header_px_ = options_.title.empty() ? 0 : 28;
  width_px_ = std::max(1, static_cast<int>(std::ceil(geometry_.width * ppc_)));
  height_px_ = std::max(1, static_cast<int>(std::ceil(geometry_.height * ppc_))) + header_px_;
  ops_.push_back([w = width_px_, h = height_px_](cairo_t* cr) {
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_rectangle(cr, 0, 0, w, h);
    cairo_fill(cr);
  });
  if (!options_.title.empty())
    ops_.push_back([t = options_.title](cairo_t* cr) {
      cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
      cairo_set_font_size(cr, 15);
      cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
      cairo_move_to(cr, 8, 19);
      cairo_show_text(cr, t.c_str());
    });
}

std::pair<double, double> Figure::to_pixel(Vec2 world) const {
  const Vec2 g = geometry_.world_to_grid(world);
  return {g.x * ppc_, header_px_ + (geometry_.height - g.y) * ppc_};
}

std::pair<double, double> Figure::to_pixel(Cell c) const {
  c = c - offset_;
  return {(c.x + 0.5) * ppc_, header_px_ + (geometry_.height - c.y - 0.5) * ppc_};
}

void Figure::raster(std::function<std::uint32_t(Cell)> colour_of) {
  const int w = geometry_.width, h = geometry_.height;
  auto surface = std::shared_ptr<cairo_surface_t>(
      cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h), cairo_surface_destroy);
  cairo_surface_flush(surface.get());
  unsigned char* data = cairo_image_surface_get_data(surface.get());
  const int stride = cairo_image_surface_get_stride(surface.get());
  for (int y = 0; y < h; ++y) {
    auto* row =
        reinterpret_cast<std::uint32_t*>(data + static_cast<std::ptrdiff_t>(h - 1 - y) * stride);
    for (int x = 0; x < w; ++x)
      row[x] = colour_of(Cell{x, y} + offset_);
  }
  cairo_surface_mark_dirty(surface.get());
  ops_.push_back([surface, s = ppc_, top = header_px_](cairo_t* cr) {
    cairo_save(cr);
    cairo_translate(cr, 0, top);
    cairo_scale(cr, s, s);
    cairo_set_source_surface(cr, surface.get(), 0, 0);
    cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_NEAREST);
    cairo_paint(cr);
    cairo_restore(cr);
  });
}

void Figure::check_raster(int width, int height, const char* what) const {
  if (width != grid_width_ || height != grid_height_)
    throw Error("render::Figure", 0,
                std::string(what) + ": raster is " + std::to_string(width) + "x" +
                    std::to_string(height) + " cells, the figure's grid is " +
                    std::to_string(grid_width_) + "x" + std::to_string(grid_height_));
}

void Figure::occupancy(const OccupancyGrid& grid) {
  check_raster(grid.width(), grid.height(), "occupancy");
  occupancy_drawn_ = true;
  for (int y = offset_.y; y < offset_.y + geometry_.height && !unknown_drawn_; ++y)
    for (int x = offset_.x; x < offset_.x + geometry_.width; ++x)
      if (grid[Cell{x, y}] < 0) {
        unknown_drawn_ = true;
        break;
      }
  raster([&grid](Cell c) {
    const int v = grid[c];
    if (v < 0 || v > 100) return argb(colors::kUnknown);
    if (v == 0) return argb(colors::kWhite);
    if (v == 100) return argb(colors::kBlack);
    const double s = 1.0 - v / 100.0;
    return argb({s, s, s, 1});
  });
}

void Figure::binary(const BinaryGrid& grid, Color on, Color off) {
  check_raster(grid.width(), grid.height(), "binary");
  const std::uint32_t a = argb(on), b = argb(off);
  raster([&](Cell c) { return grid[c] != 0 ? a : b; });
}

void Figure::scalar(const GridMap<float>& field, double lo, double hi, double alpha) {
  check_raster(field.width(), field.height(), "scalar");
  const double span = hi > lo ? hi - lo : 1.0;
  raster([&](Cell c) {
    const float v = field[c];
    if (!std::isfinite(v)) return argb(colors::kTransparent);
    return argb(viridis((v - lo) / span).with_alpha(alpha));
  });
}

void Figure::labels(const GridMap<std::int32_t>& labels, double alpha) {
  check_raster(labels.width(), labels.height(), "labels");
  raster([&](Cell c) {
    const std::int32_t l = labels[c];
    return l < 0 ? argb(colors::kTransparent) : argb(palette(l).with_alpha(alpha));
  });
}

void Figure::cells(std::span<const Cell> cells, Color color) {
  std::vector<std::pair<double, double>> px;
  px.reserve(cells.size());
  for (Cell c : cells)
    px.push_back(to_pixel(c));
  ops_.push_back([px = std::move(px), color, s = ppc_](cairo_t* cr) {
    internal::set_color(cr, color);
    for (auto [x, y] : px)
      cairo_rectangle(cr, x - s / 2, y - s / 2, s, s);
    cairo_fill(cr);
  });
}

void Figure::path(std::span<const Cell> path, Color color, double width_px) {
  std::vector<std::pair<double, double>> px;
  for (Cell c : path)
    px.push_back(to_pixel(c));
  ops_.push_back([px = std::move(px), color, width_px](cairo_t* cr) {
    internal::stroke_polyline(cr, px, color, width_px, false);
  });
}

void Figure::marker(Cell c, Color color, double radius_px, const std::string& label) {
  const auto [x, y] = to_pixel(c);
  ops_.push_back([=](cairo_t* cr) {
    cairo_arc(cr, x, y, radius_px, 0, 2 * std::numbers::pi);
    internal::set_color(cr, color);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_set_line_width(cr, 1.5);
    cairo_stroke(cr);
    if (!label.empty())
      internal::draw_label(cr, x + radius_px + 3, y - radius_px, label, 13, color);
  });
}

void Figure::cell_text(Cell c, const std::string& text, Color color, double size_px) {
  const auto [x, y] = to_pixel(c);
  ops_.push_back(
      [=](cairo_t* cr) { internal::draw_centered_text(cr, x, y, text, size_px, color); });
}

void Figure::polyline(std::span<const Vec2> points, Color color, double width_px, bool closed) {
  std::vector<std::pair<double, double>> px;
  for (Vec2 p : points)
    px.push_back(to_pixel(p));
  ops_.push_back([px = std::move(px), color, width_px, closed](cairo_t* cr) {
    internal::stroke_polyline(cr, px, color, width_px, closed);
  });
}

void Figure::segment(Vec2 a, Vec2 b, Color color, double width_px) {
  const Vec2 pts[2] = {a, b};
  polyline(pts, color, width_px);
}

void Figure::point(Vec2 p, Color color, double radius_px) {
  const auto [x, y] = to_pixel(p);
  ops_.push_back([=](cairo_t* cr) {
    internal::set_color(cr, color);
    cairo_arc(cr, x, y, radius_px, 0, 2 * std::numbers::pi);
    cairo_fill(cr);
  });
}

void Figure::circle(Vec2 centre, double radius_m, Color fill, Color stroke, double stroke_px) {
  const auto [x, y] = to_pixel(centre);
  const double r = radius_m / geometry_.resolution * ppc_;
  ops_.push_back([=](cairo_t* cr) {
    cairo_arc(cr, x, y, std::max(r, 0.5), 0, 2 * std::numbers::pi);
    internal::set_color(cr, fill);
    cairo_fill_preserve(cr);
    internal::set_color(cr, stroke);
    cairo_set_line_width(cr, stroke_px);
    cairo_stroke(cr);
  });
}

void Figure::arrow(Vec2 a, Vec2 b, Color color, double width_px) {
  const auto [x0, y0] = to_pixel(a);
  const auto [x1, y1] = to_pixel(b);
  ops_.push_back([=](cairo_t* cr) {
    internal::set_color(cr, color);
    cairo_set_line_width(cr, width_px);
    cairo_move_to(cr, x0, y0);
    cairo_line_to(cr, x1, y1);
    cairo_stroke(cr);
    const double ang = std::atan2(y1 - y0, x1 - x0), head = 4 + 2 * width_px;
    cairo_move_to(cr, x1, y1);
    cairo_line_to(cr, x1 - head * std::cos(ang - 0.45), y1 - head * std::sin(ang - 0.45));
    cairo_line_to(cr, x1 - head * std::cos(ang + 0.45), y1 - head * std::sin(ang + 0.45));
    cairo_close_path(cr);
    cairo_fill(cr);
  });
}

void Figure::text(Vec2 p, const std::string& text, Color color, double size_px) {
  const auto [x, y] = to_pixel(p);
  ops_.push_back([=](cairo_t* cr) { internal::draw_label(cr, x, y, text, size_px, color); });
}

void Figure::legend(std::vector<std::pair<std::string, Color>> entries) {
  for (auto& e : entries)
    legend_.push_back(std::move(e));
}

void Figure::colorbar(double lo, double hi, const std::string& label) {
  if (!std::isfinite(lo) || !std::isfinite(hi))
    throw Error("render::Figure::colorbar: lo and hi must be finite");
  colorbars_.push_back({lo, hi, label});
}

namespace {
// 1, 2 or 5 times a power of ten, the largest not above `raw`.
double nice_length(double raw) {
  if (!(raw > 0.0) || !std::isfinite(raw)) return 0.0;
  const double e = std::pow(10.0, std::floor(std::log10(raw)));
  const double f = raw / e;
  return (f >= 5.0 ? 5.0 : f >= 2.0 ? 2.0 : 1.0) * e;
}
std::string short_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}
}  // namespace

std::pair<double, double> Figure::scale_bar() const {
  if (options_.scale_unit.empty()) return {0.0, 0.0};
  // Cells per unit: 1/resolution for metres, 1 for cells.
  const double cells_per_unit = options_.scale_unit == "m" ? 1.0 / geometry_.resolution : 1.0;
  const double px_per_unit = ppc_ * cells_per_unit;
  const double len = nice_length(0.22 * width_px_ / px_per_unit);
  return {len, len * px_per_unit};
}

void Figure::save(const std::filesystem::path& path) const {
  if (options_.title.empty())
    throw Error(path.string(), 0,
                "render::Figure: a picture needs a title (FigureOptions::title) saying what it "
                "shows");
  internal::save_surface(path, width_px_, height_px_, [this](cairo_t* cr) {
    for (const auto& op : ops_)
      op(cr);
    // Scale bar, lower left.
    if (const auto [len, px] = scale_bar(); len > 0.0 && px >= 4.0) {
      const double x0 = 10, y0 = height_px_ - 12.0;
      const std::string text = short_number(len) + " " + options_.scale_unit;
      cairo_set_source_rgba(cr, 1, 1, 1, 0.85);
      cairo_rectangle(cr, x0 - 6, y0 - 18, px + 16 + 9.0 * static_cast<double>(text.size()), 26);
      cairo_fill(cr);
      cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
      cairo_set_line_width(cr, 2.0);
      cairo_move_to(cr, x0, y0 - 6);
      cairo_line_to(cr, x0, y0);
      cairo_line_to(cr, x0 + px, y0);
      cairo_line_to(cr, x0 + px, y0 - 6);
      cairo_stroke(cr);
      internal::draw_label(cr, x0 + px + 6, y0 + 2, text, 12.0, colors::kBlack);
    }
    // Colour bars, upper right, one under the other; the box grows to hold the label.
    double top = header_px_ + 10.0;
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, 11.0);
    for (const auto& cb : colorbars_) {
      cairo_text_extents_t ext;
      cairo_text_extents(cr, cb.label.c_str(), &ext);
      const double bw = 14, bh = std::min(140.0, 0.35 * (height_px_ - header_px_));
      const double box_w = std::max(bw + 64, ext.x_advance + 12);
      const double bx = width_px_ - box_w - 6, x = bx + 8;
      cairo_set_source_rgba(cr, 1, 1, 1, 0.85);
      cairo_rectangle(cr, bx, top - 6, box_w, bh + 30);
      cairo_fill(cr);
      for (int k = 0; k < static_cast<int>(bh); ++k) {
        internal::set_color(cr, viridis(1.0 - k / std::max(1.0, bh - 1)));
        cairo_rectangle(cr, x, top + k, bw, 1.0);
        cairo_fill(cr);
      }
      cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
      cairo_set_line_width(cr, 1.0);
      cairo_rectangle(cr, x, top, bw, bh);
      cairo_stroke(cr);
      internal::draw_label(cr, x + bw + 4, top + 9, short_number(cb.hi), 11.0, colors::kBlack);
      internal::draw_label(cr, x + bw + 4, top + bh, short_number(cb.lo), 11.0, colors::kBlack);
      internal::draw_label(cr, bx + 4, top + bh + 18, cb.label, 11.0, colors::kBlack);
      top += bh + 40;
    }
    // Legend, lower right: the occupancy key first.
    std::vector<std::pair<std::string, Color>> entries;
    if (occupancy_drawn_ && options_.occupancy_key) {
      entries.emplace_back("free", colors::kWhite);
      entries.emplace_back("occupied", colors::kBlack);
      if (unknown_drawn_) entries.emplace_back("unknown", colors::kUnknown);
    }
    entries.insert(entries.end(), legend_.begin(), legend_.end());
    if (!entries.empty()) internal::draw_legend(cr, entries, width_px_, height_px_, /*top=*/false);
  });
}

}  // namespace voronav::render
