// Plot: small line, scatter and bar charts for metrics (coverage over time, traffic per run,
// benchmark ratios), saved as PNG or SVG. Axes with ticks, labels and a legend; nothing more,
// so that pictures in docs/ and in run folders come from the library without a plotting stack.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "voronav/render/color.hpp"

namespace voronav::render {

struct PlotOptions {
  int width_px = 720;
  int height_px = 420;
  std::string title{};
  std::string x_label{};
  std::string y_label{};
  bool y_from_zero = true;  ///< include 0 in the y range
};

class Plot {
 public:
  explicit Plot(PlotOptions options = {});

  /// A line through (x[i], y[i]); sizes must match (else voronav::Error). NaN points break the
  /// line.
  void line(const std::string& name, std::vector<double> x, std::vector<double> y, Color color,
            bool markers = false);
  /// Points without connecting lines.
  void scatter(const std::string& name, std::vector<double> x, std::vector<double> y, Color color);
  /// Grouped bars: one group per category, one bar per series added with bars().
  void categories(std::vector<std::string> names);
  void bars(const std::string& name, std::vector<double> values, Color color);
  /// An optional error bar per point of the last line/scatter series (±err).
  void error_bars(std::vector<double> err);

  void save(const std::filesystem::path& path) const;

 private:
  struct Series {
    std::string name;
    std::vector<double> x, y, err;
    Color color;
    enum class Kind { kLine, kScatter, kBars } kind;
    bool markers = false;
  };
  PlotOptions options_;
  std::vector<std::string> categories_;
  std::vector<Series> series_;
};

}  // namespace voronav::render
