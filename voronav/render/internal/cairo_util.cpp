#include "voronav/render/internal/cairo_util.hpp"

#include <cairo-svg.h>

#include <algorithm>
#include <memory>

#include "voronav/core/error.hpp"

namespace voronav::render::internal {

void set_color(cairo_t* cr, Color c) {
  cairo_set_source_rgba(cr, c.r, c.g, c.b, c.a);
}

void stroke_polyline(cairo_t* cr, const std::vector<std::pair<double, double>>& px, Color color,
                     double width_px, bool closed) {
  if (px.empty()) return;
  cairo_save(cr);
  set_color(cr, color);
  cairo_set_line_width(cr, width_px);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_move_to(cr, px[0].first, px[0].second);
  for (std::size_t i = 1; i < px.size(); ++i)
    cairo_line_to(cr, px[i].first, px[i].second);
  if (px.size() == 1) cairo_line_to(cr, px[0].first, px[0].second);
  if (closed) cairo_close_path(cr);
  cairo_stroke(cr);
  cairo_restore(cr);
}

void draw_label(cairo_t* cr, double x, double y, const std::string& text, double size_px,
                Color color) {
  cairo_save(cr);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size_px);
  cairo_move_to(cr, x, y);
  cairo_text_path(cr, text.c_str());
  cairo_set_source_rgba(cr, 1, 1, 1, 0.85);
  cairo_set_line_width(cr, 2.5);
  cairo_stroke_preserve(cr);
  set_color(cr, color);
  cairo_fill(cr);
  cairo_restore(cr);
}

void draw_centered_text(cairo_t* cr, double x, double y, const std::string& text, double size_px,
                        Color color) {
  cairo_save(cr);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size_px);
  cairo_text_extents_t e;
  cairo_text_extents(cr, text.c_str(), &e);
  cairo_restore(cr);
  draw_label(cr, x - e.width / 2 - e.x_bearing, y - e.height / 2 - e.y_bearing, text, size_px,
             color);
}

void draw_legend(cairo_t* cr, const std::vector<std::pair<std::string, Color>>& entries, int w,
                 int h, bool top) {
  if (entries.empty()) return;
  cairo_save(cr);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, 12);
  double text_w = 0;
  for (const auto& [name, c] : entries) {
    cairo_text_extents_t e;
    cairo_text_extents(cr, name.c_str(), &e);
    text_w = std::max(text_w, e.x_advance);
  }
  const double line = 17, box_w = text_w + 34,
               box_h = line * static_cast<double>(entries.size()) + 8;
  const double x0 = w - box_w - 8, y0 = top ? 8 : h - box_h - 8;
  cairo_rectangle(cr, x0, y0, box_w, box_h);
  cairo_set_source_rgba(cr, 1, 1, 1, 0.88);
  cairo_fill_preserve(cr);
  cairo_set_source_rgba(cr, 0.3, 0.3, 0.3, 1);
  cairo_set_line_width(cr, 0.8);
  cairo_stroke(cr);
  double y = y0 + 4;
  for (const auto& [name, c] : entries) {
    cairo_rectangle(cr, x0 + 6, y + 3, 16, 10);
    set_color(cr, c);
    cairo_fill_preserve(cr);
    cairo_set_source_rgba(cr, 0.45, 0.45, 0.45, 1);  // a thin frame, so white "free" shows
    cairo_set_line_width(cr, 0.6);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    cairo_move_to(cr, x0 + 28, y + 12.5);
    cairo_show_text(cr, name.c_str());
    y += line;
  }
  cairo_restore(cr);
}

void save_surface(const std::filesystem::path& path, int w, int h,
                  const std::function<void(cairo_t*)>& draw) {
  const std::string ext = path.extension().string();
  const bool png = ext == ".png", svg = ext == ".svg";
  if (!png && !svg)
    throw Error(path.string(), 0, "picture format '" + ext + "': expected .png or .svg");
  std::error_code folder_error;  // an unreadable or over-long folder name is reported, not thrown
  if (path.has_parent_path() && !std::filesystem::is_directory(path.parent_path(), folder_error))
    throw Error(path.string(), 0, "the folder " + path.parent_path().string() + " does not exist");
  std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface(
      png ? cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h)
          : cairo_svg_surface_create(path.c_str(), w, h),
      cairo_surface_destroy);
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS)
    throw Error(path.string(), 0,
                std::string("cannot create the picture: ") +
                    cairo_status_to_string(cairo_surface_status(surface.get())));
  cairo_t* cr = cairo_create(surface.get());
  draw(cr);
  const cairo_status_t st = cairo_status(cr);
  cairo_destroy(cr);
  if (st != CAIRO_STATUS_SUCCESS)
    throw Error(path.string(), 0, std::string("drawing failed: ") + cairo_status_to_string(st));
  if (png) {
    const cairo_status_t ws = cairo_surface_write_to_png(surface.get(), path.c_str());
    if (ws != CAIRO_STATUS_SUCCESS)
      throw Error(path.string(), 0, std::string("cannot write PNG: ") + cairo_status_to_string(ws));
  } else {
    cairo_surface_finish(surface.get());
    if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS)
      throw Error(path.string(), 0, "cannot write SVG");
  }
}

}  // namespace voronav::render::internal
