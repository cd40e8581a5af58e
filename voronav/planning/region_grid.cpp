#include "voronav/planning/region_grid.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "voronav/core/error.hpp"

namespace voronav::planning {

RegionGrid::RegionGrid(const BinaryGrid& cells, const RegionGridOptions& options)
    : r_(options.region_size), rule_(options.rule), cells_(cells.geometry()) {
  if (options.region_size < 1 || options.region_size > kMaxRegionSize)
    throw Error("region_size", 0,
                "expected a region size in 1.." + std::to_string(kMaxRegionSize) + " cells, got " +
                    std::to_string(options.region_size));
  const int w = cells.width(), h = cells.height();
  GridGeometry g = cells.geometry();
  g.width = w / r_ + (w % r_ != 0 ? 1 : 0);  // ceil without the overflow of (w + r - 1) / r
  g.height = h / r_ + (h % r_ != 0 ? 1 : 0);
  g.resolution = cells.resolution() * r_;
  blocked_ = BinaryGrid(g, 0);
  if (w == 0 || h == 0) return;
  const auto rw = static_cast<std::size_t>(g.width);
  if (rule_ == RegionRule::kAnyBlocked) {
    for (int y = 0; y < h; ++y) {
      const std::uint8_t* row = cells.data().data() + static_cast<std::size_t>(y) * w;
      std::uint8_t* out = blocked_.data().data() + static_cast<std::size_t>(y / r_) * rw;
      for (int x = 0; x < w; ++x)
        if (row[x] != 0) out[x / r_] = 1;
    }
    return;
  }
  std::vector<int> count(rw);
  for (int ry = 0; ry < g.height; ++ry) {
    std::fill(count.begin(), count.end(), 0);
    const int y1 = std::min(h, (ry + 1) * r_);
    for (int y = ry * r_; y < y1; ++y) {
      const std::uint8_t* row = cells.data().data() + static_cast<std::size_t>(y) * w;
      for (int x = 0; x < w; ++x)
        count[static_cast<std::size_t>(x / r_)] += row[x] != 0 ? 1 : 0;
    }
    for (int rx = 0; rx < g.width; ++rx) {
      const auto [lo, hi] = cell_box({rx, ry});
      const int n = (hi.x - lo.x + 1) * (hi.y - lo.y + 1);
      if (2 * count[static_cast<std::size_t>(rx)] > n) blocked_[Cell{rx, ry}] = 1;
    }
  }
}

std::pair<Cell, Cell> RegionGrid::cell_box(Cell region) const {
  const Cell lo{region.x * r_, region.y * r_};
  const Cell hi{std::min(cells_.width, lo.x + r_) - 1, std::min(cells_.height, lo.y + r_) - 1};
  return {lo, hi};
}

Cell RegionGrid::center_cell(Cell region) const {
  const auto [lo, hi] = cell_box(region);
  return {(lo.x + hi.x + 1) / 2, (lo.y + hi.y + 1) / 2};
}

Vec2 RegionGrid::center_world(Cell region) const {
  const auto [lo, hi] = cell_box(region);
  return cells_.grid_to_world({0.5 * (lo.x + hi.x + 1), 0.5 * (lo.y + hi.y + 1)});
}

}  // namespace voronav::planning
