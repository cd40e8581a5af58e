#include "plan_picture.hpp"

#include <cstdio>
#include <string>

#include "voronav/render/figure.hpp"

namespace voronav::cli {

std::string plan_summary(const PlanPicture& pic, const std::string& unit) {
  char buf[160];
  if (pic.result == nullptr) return "planning query";
  if (!pic.result->ok())
    return std::string("no path: ") + std::string(planning::to_string(pic.result->status));
  const double res = unit == "m" ? pic.map.resolution() : 1.0;
  std::snprintf(buf, sizeof buf, "path of %.2f %s, %zu cells expanded",
                pic.result->length_cells * res, unit.c_str(), pic.result->expanded);
  return buf;
}

void save_plan_picture(const PlanPicture& pic, const std::filesystem::path& out,
                       const std::string& title, const std::string& scale_unit) {
  const std::string summary = plan_summary(pic, scale_unit);
  render::Figure fig(pic.map.geometry(), {.title = title.empty() ? summary : title + ": " + summary,
                                          .crop = render::known_bounds(pic.map),
                                          .scale_unit = scale_unit});
  fig.occupancy(pic.map);
  if (pic.show_inflation) {
    // Cells blocked only by the robot radius, in light red.
    BinaryGrid inflated_only(pic.map.geometry(), 0);
    const BinaryGrid raw = binarize(pic.map);
    for (std::size_t i = 0; i < raw.size(); ++i)
      inflated_only[i] = pic.planning_grid[i] != 0 && raw[i] == 0 ? 1 : 0;
    fig.binary(inflated_only, render::Color::hex(0xf4a6a6, 0.8));
  }
  std::vector<std::pair<std::string, render::Color>> legend;
  if (pic.result != nullptr && !pic.result->expanded_cells.empty()) {
    fig.cells(pic.result->expanded_cells, render::Color::hex(0x9ecae1, 0.7));
    legend.emplace_back("expanded", render::Color::hex(0x9ecae1));
  }
  if (pic.result != nullptr && pic.result->ok()) {
    fig.path(pic.result->path, render::colors::kBlue, 3.0);
    legend.emplace_back("path", render::colors::kBlue);
  }
  if (pic.show_inflation) legend.emplace_back("robot radius", render::Color::hex(0xf4a6a6));
  fig.marker(pic.start, render::colors::kGreen, 6, "start");
  fig.marker(pic.goal, render::colors::kRed, 6, "goal");
  fig.legend(std::move(legend));
  fig.save(out);
}

}  // namespace voronav::cli
