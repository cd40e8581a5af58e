#include <cmath>

#include "voronav/core/error.hpp"
#include "voronav/exploration/explorer.hpp"

namespace voronav::exploration {

OccupancyGrid paper_world(double resolution) {
  if (!(resolution > 0.0) || resolution > 1.0 || !std::isfinite(resolution))
    throw Error("paper_world", 0, "resolution must be in (0, 1] m/cell");
  const int n = static_cast<int>(std::lround(20.0 / resolution));
  OccupancyGrid g(GridGeometry{n, n, resolution, {}}, kFree);
  struct Box {
    double x0, y0, x1, y1;
  };
  struct Circle {
    double x, y, r;
  };
  // Outer walls (0.2 m thick), rectangular blocks, partial walls.
  const Box boxes[] = {
      {0.0, 0.0, 20.0, 0.2},    {0.0, 19.8, 20.0, 20.0}, {0.0, 0.0, 0.2, 20.0},
      {19.8, 0.0, 20.0, 20.0},  {4.0, 4.0, 6.0, 5.5},    {9.0, 3.0, 11.0, 4.0},
      {14.0, 5.0, 16.5, 7.0},   {4.0, 10.0, 5.5, 12.5},  {10.0, 10.0, 13.0, 11.0},
      {15.0, 13.0, 17.0, 15.0}, {7.0, 15.0, 9.0, 17.0},  {0.2, 14.0, 3.0, 14.2},
      {11.0, 13.0, 11.2, 18.5}, {16.0, 0.2, 16.2, 2.5},
  };
  const Circle circles[] = {{8.0, 8.0, 0.8}, {13.5, 16.0, 0.7}, {17.0, 9.5, 0.6}, {2.5, 7.5, 0.5}};
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      const Vec2 c = g.geometry().cell_center({x, y});
      bool occ = false;
      for (const Box& b : boxes)
        occ = occ || (c.x > b.x0 && c.x < b.x1 && c.y > b.y0 && c.y < b.y1);
      for (const Circle& k : circles)
        occ = occ || distance(c, {k.x, k.y}) < k.r;
      if (occ) g[Cell{x, y}] = kOccupied;
    }
  }
  return g;
}

}  // namespace voronav::exploration
