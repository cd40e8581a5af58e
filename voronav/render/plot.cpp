#include "voronav/render/plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "voronav/core/error.hpp"
#include "voronav/render/internal/cairo_util.hpp"

namespace voronav::render {
namespace {

/// "Nice" tick step for a range (1, 2 or 5 times a power of ten), about `n` ticks.
double nice_step(double span, int n) {
  if (!(span > 0)) return 1.0;
  const double raw = span / n, mag = std::pow(10.0, std::floor(std::log10(raw)));
  const double f = raw / mag;
  return (f < 1.5 ? 1 : f < 3.5 ? 2 : f < 7.5 ? 5 : 10) * mag;
}

std::string format_tick(double v, double step) {
  char buf[32];
  if (std::abs(v) < step * 1e-9) v = 0;
  if (step >= 1 && std::abs(v) < 1e7)
    std::snprintf(buf, sizeof buf, "%.0f", v);
  else if (std::abs(v) >= 1e7 || step < 1e-4)
    std::snprintf(buf, sizeof buf, "%.2g", v);
  else {
    const int digits = std::clamp(static_cast<int>(std::ceil(-std::log10(step))), 0, 6);
    std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  }
  return buf;
}

}  // namespace

Plot::Plot(PlotOptions options) : options_(std::move(options)) {
  if (options_.width_px < 100 || options_.height_px < 80 || options_.width_px > 8192 ||
      options_.height_px > 8192)
    throw Error("render::Plot: size must be within 100x80 .. 8192x8192 pixels");
}

void Plot::line(const std::string& name, std::vector<double> x, std::vector<double> y, Color color,
                bool markers) {
  if (x.size() != y.size())
    throw Error("render::Plot", 0, "series '" + name + "': x and y sizes differ");
  series_.push_back({name, std::move(x), std::move(y), {}, color, Series::Kind::kLine, markers});
}

void Plot::scatter(const std::string& name, std::vector<double> x, std::vector<double> y,
                   Color color) {
  if (x.size() != y.size())
    throw Error("render::Plot", 0, "series '" + name + "': x and y sizes differ");
  series_.push_back({name, std::move(x), std::move(y), {}, color, Series::Kind::kScatter, true});
}

void Plot::categories(std::vector<std::string> names) {
  categories_ = std::move(names);
}

void Plot::bars(const std::string& name, std::vector<double> values, Color color) {
  if (values.size() != categories_.size())
    throw Error("render::Plot", 0,
                "bars '" + name + "': expected one value per category (" +
                    std::to_string(categories_.size()) + ")");
  std::vector<double> x(values.size());
  for (std::size_t i = 0; i < x.size(); ++i)
    x[i] = static_cast<double>(i);
  series_.push_back({name, std::move(x), std::move(values), {}, color, Series::Kind::kBars, false});
}

void Plot::error_bars(std::vector<double> err) {
  if (series_.empty() || err.size() != series_.back().y.size())
    throw Error("render::Plot", 0, "error_bars: expected one value per point of the last series");
  series_.back().err = std::move(err);
}

void Plot::save(const std::filesystem::path& path) const {
  const int W = options_.width_px, H = options_.height_px;
  const double left = 70, right = 20, top = options_.title.empty() ? 18 : 36, bottom = 52;
  double xmin = std::numeric_limits<double>::infinity(), xmax = -xmin, ymin = xmin, ymax = -xmin;
  std::size_t n_bar_series = 0;
  for (const auto& s : series_) {
    if (s.kind == Series::Kind::kBars) ++n_bar_series;
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
      const double e = s.err.empty() ? 0.0 : std::abs(s.err[i]);
      xmin = std::min(xmin, s.x[i]);
      xmax = std::max(xmax, s.x[i]);
      ymin = std::min(ymin, s.y[i] - e);
      ymax = std::max(ymax, s.y[i] + e);
    }
  }
  const bool bar_chart = n_bar_series > 0;
  if (bar_chart) {
    xmin = -0.5;
    xmax = static_cast<double>(categories_.size()) - 0.5;
  }
  if (!std::isfinite(xmin)) xmin = 0, xmax = 1, ymin = 0, ymax = 1;
  if (options_.y_from_zero || bar_chart) ymin = std::min(ymin, 0.0), ymax = std::max(ymax, 0.0);
  if (xmax <= xmin) xmin -= 0.5, xmax += 0.5;
  if (ymax <= ymin) ymin -= 0.5, ymax += 0.5;
  const double ystep = nice_step(ymax - ymin, 5);
  ymin = std::floor(ymin / ystep) * ystep;
  ymax = std::ceil(ymax / ystep) * ystep;
  const double xstep = nice_step(xmax - xmin, 6);
  const double pw = W - left - right, ph = H - top - bottom;
  auto px = [&](double x) { return left + (x - xmin) / (xmax - xmin) * pw; };
  auto py = [&](double y) { return top + (ymax - y) / (ymax - ymin) * ph; };

  internal::save_surface(path, W, H, [&](cairo_t* cr) {
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    // grid and y ticks
    cairo_set_font_size(cr, 11);
    cairo_set_line_width(cr, 1);
    for (double y = ymin; y <= ymax + ystep * 1e-6; y += ystep) {
      cairo_set_source_rgb(cr, 0.9, 0.9, 0.9);
      cairo_move_to(cr, left, py(y));
      cairo_line_to(cr, left + pw, py(y));
      cairo_stroke(cr);
      const std::string t = format_tick(y, ystep);
      cairo_text_extents_t e;
      cairo_text_extents(cr, t.c_str(), &e);
      cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
      cairo_move_to(cr, left - 6 - e.x_advance, py(y) + 4);
      cairo_show_text(cr, t.c_str());
    }
    // x ticks
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
    if (bar_chart) {
      for (std::size_t i = 0; i < categories_.size(); ++i) {
        cairo_text_extents_t e;
        cairo_text_extents(cr, categories_[i].c_str(), &e);
        cairo_move_to(cr, px(static_cast<double>(i)) - e.x_advance / 2, top + ph + 16);
        cairo_show_text(cr, categories_[i].c_str());
      }
    } else {
      for (double x = std::ceil(xmin / xstep) * xstep; x <= xmax + xstep * 1e-6; x += xstep) {
        const std::string t = format_tick(x, xstep);
        cairo_text_extents_t e;
        cairo_text_extents(cr, t.c_str(), &e);
        cairo_move_to(cr, px(x) - e.x_advance / 2, top + ph + 16);
        cairo_show_text(cr, t.c_str());
      }
    }
    // axes box
    cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
    cairo_rectangle(cr, left, top, pw, ph);
    cairo_stroke(cr);
    // labels and title
    cairo_set_font_size(cr, 12);
    if (!options_.x_label.empty()) {
      cairo_text_extents_t e;
      cairo_text_extents(cr, options_.x_label.c_str(), &e);
      cairo_move_to(cr, left + pw / 2 - e.x_advance / 2, H - 12);
      cairo_show_text(cr, options_.x_label.c_str());
    }
    if (!options_.y_label.empty()) {
      cairo_text_extents_t e;
      cairo_text_extents(cr, options_.y_label.c_str(), &e);
      cairo_save(cr);
      cairo_move_to(cr, 16, top + ph / 2 + e.x_advance / 2);
      cairo_rotate(cr, -std::numbers::pi / 2);
      cairo_show_text(cr, options_.y_label.c_str());
      cairo_restore(cr);
    }
    if (!options_.title.empty()) {
      cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
      cairo_set_font_size(cr, 14);
      cairo_move_to(cr, left, 22);
      cairo_show_text(cr, options_.title.c_str());
    }
    // data
    cairo_save(cr);
    cairo_rectangle(cr, left, top, pw, ph);
    cairo_clip(cr);
    std::size_t bar_index = 0;
    const double group_w = 0.8,
                 bar_w = n_bar_series ? group_w / static_cast<double>(n_bar_series) : 0;
    std::vector<std::pair<std::string, Color>> legend;
    for (const auto& s : series_) {
      if (!s.name.empty()) legend.emplace_back(s.name, s.color);
      internal::set_color(cr, s.color);
      if (s.kind == Series::Kind::kBars) {
        for (std::size_t i = 0; i < s.y.size(); ++i) {
          if (!std::isfinite(s.y[i])) continue;
          const double x0 = s.x[i] - group_w / 2 + bar_w * static_cast<double>(bar_index);
          cairo_rectangle(cr, px(x0), py(std::max(s.y[i], 0.0)), px(x0 + bar_w) - px(x0) - 1,
                          std::abs(py(s.y[i]) - py(0.0)));
        }
        cairo_fill(cr);
        ++bar_index;
        continue;
      }
      if (s.kind == Series::Kind::kLine) {
        cairo_set_line_width(cr, 2);
        bool pen = false;
        for (std::size_t i = 0; i < s.x.size(); ++i) {
          if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) {
            pen = false;
            continue;
          }
          if (pen)
            cairo_line_to(cr, px(s.x[i]), py(s.y[i]));
          else
            cairo_move_to(cr, px(s.x[i]), py(s.y[i]));
          pen = true;
        }
        cairo_stroke(cr);
      }
      for (std::size_t i = 0; i < s.x.size(); ++i) {
        if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
        if (s.markers) {
          cairo_arc(cr, px(s.x[i]), py(s.y[i]), 3, 0, 2 * std::numbers::pi);
          cairo_fill(cr);
        }
        if (!s.err.empty()) {
          cairo_set_line_width(cr, 1);
          cairo_move_to(cr, px(s.x[i]), py(s.y[i] - s.err[i]));
          cairo_line_to(cr, px(s.x[i]), py(s.y[i] + s.err[i]));
          cairo_stroke(cr);
        }
      }
    }
    cairo_restore(cr);
    if (!legend.empty()) {
      cairo_save(cr);
      cairo_translate(cr, -right, top - 8);
      internal::draw_legend(cr, legend, W, H, true);
      cairo_restore(cr);
    }
  });
}

}  // namespace voronav::render
