// Cairo helpers shared by Figure and Plot (not installed): colours, labelled text with a halo,
// legends, and writing a surface to PNG or SVG by extension.
#pragma once

#include <cairo.h>

#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "voronav/render/color.hpp"

namespace voronav::render::internal {

void set_color(cairo_t* cr, Color c);
void stroke_polyline(cairo_t* cr, const std::vector<std::pair<double, double>>& px, Color color,
                     double width_px, bool closed);
/// Text with its baseline-left at (x, y) and a thin white halo so it reads on any background.
void draw_label(cairo_t* cr, double x, double y, const std::string& text, double size_px,
                Color color);
void draw_centered_text(cairo_t* cr, double x, double y, const std::string& text, double size_px,
                        Color color);
void draw_legend(cairo_t* cr, const std::vector<std::pair<std::string, Color>>& entries, int w,
                 int h, bool top);
/// Creates a PNG or SVG surface of w x h pixels, calls draw, writes the file.
void save_surface(const std::filesystem::path& path, int w, int h,
                  const std::function<void(cairo_t*)>& draw);

}  // namespace voronav::render::internal
