#include "cli_common.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

#include "voronav/core/error.hpp"
#include "voronav/io/movingai.hpp"

namespace voronav::cli {

Vec2 parse_point(const std::string& text, const std::string& option) {
  const auto comma = text.find(',');
  auto fail = [&]() -> Vec2 {
    throw Error(option, 0, "expected two finite numbers 'X,Y', got '" + text + "'");
  };
  if (comma == std::string::npos) return fail();
  try {
    std::size_t used_x = 0, used_y = 0;
    const std::string xs = text.substr(0, comma), ys = text.substr(comma + 1);
    const double x = std::stod(xs, &used_x), y = std::stod(ys, &used_y);
    if (used_x != xs.size() || used_y != ys.size() || !std::isfinite(x) || !std::isfinite(y))
      return fail();
    return {x, y};
  } catch (const std::logic_error&) {
    return fail();
  }
}

Cell MapContext::to_cell(Vec2 p, const std::string& option) const {
  const auto& g = map.grid.geometry();
  std::optional<Cell> c;
  if (cell_coordinates) {
    if (p.x != std::floor(p.x) || p.y != std::floor(p.y) || std::abs(p.x) > 1e9 ||
        std::abs(p.y) > 1e9)
      throw Error(option, 0, "expected integer cell coordinates for this map");
    const int x = static_cast<int>(p.x), y = static_cast<int>(p.y);
    c = map.format == io::MapFormat::kMovingAi ? io::movingai_to_cell(x, y, g.height) : Cell{x, y};
  } else {
    c = g.world_to_cell(p);
  }
  if (!c || !g.contains(*c)) {
    std::ostringstream os;
    os << "point (" << p.x << ", " << p.y << ") " << frame_name() << " is outside the ";
    if (cell_coordinates) {
      os << g.width << "x" << g.height << " cell map";
    } else {  // in the unit the user gave: the map's extent in metres
      double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
      for (const Vec2 corner :
           {Vec2{0, 0}, Vec2{static_cast<double>(g.width), 0},
            Vec2{0, static_cast<double>(g.height)},
            Vec2{static_cast<double>(g.width), static_cast<double>(g.height)}}) {
        const Vec2 w = g.grid_to_world(corner);
        x0 = std::min(x0, w.x), x1 = std::max(x1, w.x), y0 = std::min(y0, w.y),
        y1 = std::max(y1, w.y);
      }
      os << "map, which spans x " << x0 << " .. " << x1 << " m, y " << y0 << " .. " << y1 << " m ("
         << g.width << "x" << g.height << " cells of " << g.resolution << " m)";
    }
    throw Error(option, 0, os.str());
  }
  return *c;
}

nlohmann::json MapContext::cell_json(Cell c) const {
  if (map.format == io::MapFormat::kMovingAi) {
    const auto [x, y] = io::cell_to_movingai(c, map.grid.height());
    return {x, y};
  }
  return {c.x, c.y};
}

const char* MapContext::cell_frame() const {
  return map.format == io::MapFormat::kMovingAi ? "movingai_y_down" : "grid_y_up";
}

nlohmann::json pose_json(const Pose2& p, bool with_frame) {
  nlohmann::json j{{"x", p.position.x}, {"y", p.position.y}, {"yaw", p.yaw}};
  if (with_frame) j["frame_id"] = "map";
  return j;
}

std::string MapContext::frame_name() const {
  if (!cell_coordinates) return "[m, world frame]";
  return map.format == io::MapFormat::kMovingAi ? "[cells, Moving AI x right / y down]"
                                                : "[cells, row 0 at the bottom]";
}

MapContext load_map_context(const std::filesystem::path& path, bool force_cells) {
  MapContext ctx{io::load_map(path), false};
  ctx.cell_coordinates = force_cells || ctx.map.format == io::MapFormat::kMovingAi;
  return ctx;
}

void print_json(const nlohmann::json& j) {
  std::cout << j.dump(2) << "\n";
}

std::filesystem::path bundled_data_dir() {
  namespace fs = std::filesystem;
  for (const fs::path& p : {fs::path(VORONAV_SOURCE_DIR) / "data", fs::path("data")})
    if (fs::exists(p / "README.md")) return p;
  return {};
}

}  // namespace voronav::cli
