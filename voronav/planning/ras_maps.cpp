#include "voronav/planning/ras_maps.hpp"

#include <algorithm>

namespace voronav::planning {
namespace {

// Blocks the image-frame rectangle [x0, x1) x [y0, y1) (y down), clipped to the grid.
void block(BinaryGrid& g, int x0, int y0, int x1, int y1) {
  const int h = g.height();
  for (int y = std::max(0, y0); y < std::min(h, y1); ++y)
    for (int x = std::max(0, x0); x < std::min(g.width(), x1); ++x)
      g[Cell{x, h - 1 - y}] = 1;
}

// 4x4 dots on a square lattice of the given pitch inside [x0, x1) x [y0, y1) (image frame).
void dots(BinaryGrid& g, int x0, int y0, int x1, int y1, int pitch) {
  for (int y = y0; y < y1; y += pitch)
    for (int x = x0; x < x1; x += pitch)
      block(g, x, y, std::min(x + 4, x1), std::min(y + 4, y1));
}

Cell image_cell(const BinaryGrid& g, int x, int y) {
  return {x, g.height() - 1 - y};
}

}  // namespace

RasStandInMap ras_table3_map() {
  RasStandInMap m{"ras_table3", BinaryGrid(512, 512, 0), {}, {}};
  BinaryGrid& g = m.grid;
  block(g, 0, 352, 320, 368);    // lower wall, open on the right
  block(g, 192, 176, 512, 192);  // upper wall, open on the left
  block(g, 256, 64, 288, 176);   // a pillar between the upper wall and the top
  block(g, 96, 416, 128, 512);   // a stub from the bottom edge
  block(g, 256, 224, 320, 288);  // a block in the middle corridor
  m.start = image_cell(g, 40, 472);
  m.goal = image_cell(g, 472, 40);
  return m;
}

RasStandInMap ras_table4_map() {
  RasStandInMap m{"ras_table4", BinaryGrid(1000, 1000, 0), {}, {}};
  BinaryGrid& g = m.grid;
  // Outer wall, 4 cells thick.
  block(g, 0, 0, 1000, 4);
  block(g, 0, 996, 1000, 1000);
  block(g, 0, 0, 4, 1000);
  block(g, 996, 0, 1000, 1000);
  // First wall from the top down to y = 850; second wall from the bottom up to y = 150.
  block(g, 396, 0, 412, 850);
  block(g, 596, 150, 612, 1000);
  // Furniture-like blocks in the open areas.
  block(g, 150, 450, 250, 550);
  block(g, 40, 650, 200, 680);
  block(g, 450, 300, 540, 420);
  block(g, 700, 450, 860, 520);
  block(g, 800, 100, 830, 380);
  // The dot field under the first wall: 4x4 dots, gaps 4, 8 and 32 cells deeper down.
  dots(g, 300, 850, 540, 890, 8);
  dots(g, 300, 890, 540, 930, 12);
  dots(g, 300, 930, 540, 996, 36);
  m.start = image_cell(g, 100, 250);
  m.goal = image_cell(g, 700, 250);
  return m;
}

}  // namespace voronav::planning
