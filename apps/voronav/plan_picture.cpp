#include "plan_picture.hpp"

#include "voronav/render/figure.hpp"

namespace voronav::cli {

void save_plan_picture(const PlanPicture& pic, const std::filesystem::path& out) {
  render::Figure fig(pic.map.geometry(), {.crop = render::known_bounds(pic.map)});
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
