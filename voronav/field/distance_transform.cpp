#include "voronav/field/distance_transform.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace voronav::field {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// 1-D squared distance transform of f (lower envelope of parabolas, FH 2012 Algorithm 1), also
// returning for each output position the argmin position. Uses double internally for exactness
// on integer inputs up to grids of ~10^7 cells per side.
struct Envelope1D {
  std::vector<int> v;
  std::vector<double> z;
  void run(const double* f, int n, double* d, int* arg) {
    v.resize(static_cast<std::size_t>(n));
    z.resize(static_cast<std::size_t>(n) + 1);
    int k = -1;
    for (int q = 0; q < n; ++q) {
      if (std::isinf(f[q])) continue;
      if (k < 0) {
        k = 0;
        v[0] = q;
        z[0] = -HUGE_VAL;
        z[1] = HUGE_VAL;
        continue;
      }
      double s;
      while (true) {
        const int p = v[static_cast<std::size_t>(k)];
        s = ((f[q] + double(q) * q) - (f[p] + double(p) * p)) / (2.0 * (q - p));
        if (s <= z[static_cast<std::size_t>(k)] && k > 0) {
          --k;
          continue;
        }
        if (s <= z[static_cast<std::size_t>(k)]) {  // k == 0: q dominates everything
          v[0] = q;
          z[0] = -HUGE_VAL;
          z[1] = HUGE_VAL;
          s = std::nan("");
        }
        break;
      }
      if (std::isnan(s)) continue;
      ++k;
      v[static_cast<std::size_t>(k)] = q;
      z[static_cast<std::size_t>(k)] = s;
      z[static_cast<std::size_t>(k) + 1] = HUGE_VAL;
    }
    if (k < 0) {
      for (int q = 0; q < n; ++q) {
        d[q] = HUGE_VAL;
        arg[q] = -1;
      }
      return;
    }
    int j = 0;
    for (int q = 0; q < n; ++q) {
      while (z[static_cast<std::size_t>(j) + 1] < q) ++j;
      const int p = v[static_cast<std::size_t>(j)];
      d[q] = double(q - p) * (q - p) + f[p];
      arg[q] = p;
    }
  }
};

}  // namespace

double DistanceField::distance_m(Cell c) const {
  return std::sqrt(static_cast<double>(squared_distance[c])) * squared_distance.resolution();
}

DistanceField distance_transform(const BinaryGrid& blocked, const DistanceTransformOptions& options) {
  const GridGeometry& g = blocked.geometry();
  const int w = g.width, h = g.height;
  DistanceField out{GridMap<float>(g, kInf), GridMap<std::int32_t>(g, kNoSite)};
  if (blocked.empty()) return out;

  // With a blocked border, pad by one cell on each side so the border acts as sites.
  const int pad = options.border_is_blocked ? 1 : 0;
  const int W = w + 2 * pad, H = h + 2 * pad;
  auto is_site = [&](int x, int y) {
    if (x < pad || y < pad || x >= w + pad || y >= h + pad) return true;
    return blocked[Cell{x - pad, y - pad}] != 0;
  };

  // Pass 1: along each column, distance to the nearest site in that column (row index kept).
  // The input is binary (0 at sites, +inf elsewhere), so the lower envelope of FH's parabolas is
  // simply the nearest site, the lower row on a tie (Envelope1D picks the lower parabola where
  // two meet); two row-major sweeps (last site above, next site below) find it without the
  // column-strided envelope. Same distances and rows, fewer operations and cache misses.
  std::vector<double> col_d(static_cast<std::size_t>(W) * H);
  std::vector<int> col_arg(static_cast<std::size_t>(W) * H);
  {
    std::vector<int> near(static_cast<std::size_t>(W), -1);
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) {
        if (is_site(x, y)) near[static_cast<std::size_t>(x)] = y;
        col_arg[static_cast<std::size_t>(y) * W + x] = near[static_cast<std::size_t>(x)];
      }
    std::fill(near.begin(), near.end(), -1);
    for (int y = H - 1; y >= 0; --y)
      for (int x = 0; x < W; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * W + x;
        if (col_arg[i] == y) near[static_cast<std::size_t>(x)] = y;  // a site
        const int above = col_arg[i], below = near[static_cast<std::size_t>(x)];
        const int p = above < 0 ? below : (below < 0 || y - above <= below - y ? above : below);
        col_arg[i] = p;
        col_d[i] = p < 0 ? HUGE_VAL : double(y - p) * (y - p);
      }
  }
  // Pass 2: along each row over the column results.
  {
    std::vector<double> d(static_cast<std::size_t>(W));
    std::vector<int> arg(static_cast<std::size_t>(W));
    Envelope1D env;
    for (int y = pad; y < h + pad; ++y) {
      const double* f = &col_d[static_cast<std::size_t>(y) * W];
      env.run(f, W, d.data(), arg.data());
      for (int x = pad; x < w + pad; ++x) {
        const Cell c{x - pad, y - pad};
        const double dd = d[static_cast<std::size_t>(x)];
        if (std::isinf(dd)) continue;
        out.squared_distance[c] = static_cast<float>(dd);
        const int sx = arg[static_cast<std::size_t>(x)];
        const int sy = col_arg[static_cast<std::size_t>(y) * W + sx];
        const Cell site{sx - pad, sy - pad};
        out.nearest[c] =
            g.contains(site) ? static_cast<std::int32_t>(g.index(site)) : kNoSite;  // border site
      }
    }
  }
  return out;
}

namespace {

/// inflate() for a small radius, without the EDT: every cell closer than r (squared distance in
/// cells < r2, as the EDT's exact integer squared distances compare) to a blocked cell. Only
/// blocked cells with a free 4-neighbour (or on the grid's edge) are spread: the nearest blocked
/// cell of a free cell always has one (its neighbour toward the free cell is strictly closer, so
/// it is not blocked). Same grid as the EDT path, much less work for the one- to few-cell radii
/// of robots (scenario 4's centralized run 4x less CPU: docs/reproductions/networked.md, stop 17).
constexpr double kDilateMaxR2 = 64.0;  // up to 8 cells; exact integers in the EDT's float

BinaryGrid dilate(const BinaryGrid& blocked, double r2) {
  const GridGeometry& g = blocked.geometry();
  const int w = g.width, h = g.height;
  std::vector<Cell> offs;
  const int k = static_cast<int>(std::ceil(std::sqrt(r2)));
  for (int dy = -k; dy <= k; ++dy)
    for (int dx = -k; dx <= k; ++dx)
      if ((dx != 0 || dy != 0) && static_cast<double>(dx * dx + dy * dy) < r2)
        offs.push_back({dx, dy});
  BinaryGrid out(g, 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (blocked[Cell{x, y}] == 0) continue;
      out[Cell{x, y}] = 1;
      const bool inner = x > 0 && y > 0 && x + 1 < w && y + 1 < h && blocked[Cell{x - 1, y}] != 0 &&
                         blocked[Cell{x + 1, y}] != 0 && blocked[Cell{x, y - 1}] != 0 &&
                         blocked[Cell{x, y + 1}] != 0;
      if (inner) continue;
      for (Cell o : offs) {
        const Cell c{x + o.x, y + o.y};
        if (c.x >= 0 && c.y >= 0 && c.x < w && c.y < h) out[c] = 1;
      }
    }
  return out;
}

}  // namespace

BinaryGrid inflate(const BinaryGrid& blocked, double radius_m) {
  if (std::isnan(radius_m) || radius_m < 0.0)
    throw Error("radius", 0, "expected a non-negative number of metres, got " +
                                 std::to_string(radius_m));
  if (radius_m == 0.0 || blocked.empty()) return blocked;
  const double r_cells = radius_m / blocked.resolution();
  const double r2 = r_cells * r_cells;
  if (r2 <= kDilateMaxR2) return dilate(blocked, r2);
  const DistanceField df = distance_transform(blocked);
  BinaryGrid out(blocked.geometry(), 0);
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = (blocked[i] != 0 || static_cast<double>(df.squared_distance[i]) < r2) ? 1 : 0;
  return out;
}

}  // namespace voronav::field
