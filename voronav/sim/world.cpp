#include "voronav/sim/world.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <string>

#include "voronav/core/cell_iterators.hpp"
#include "voronav/core/error.hpp"
#include "voronav/field/distance_transform.hpp"

namespace voronav::sim {

std::int8_t LocalMap::at(Cell w) const {
  const Cell c = w - offset_;
  return grid_.contains(c) ? grid_[c] : kUnknown;
}

void LocalMap::ensure(Cell lo, Cell hi) {
  const Cell glo = offset_, ghi = offset_ + Cell{grid_.width() - 1, grid_.height() - 1};
  if (!grid_.empty() && lo.x >= glo.x && lo.y >= glo.y && hi.x <= ghi.x && hi.y <= ghi.y) return;
  constexpr int kMargin = 16;
  Cell nlo{lo.x - kMargin, lo.y - kMargin}, nhi{hi.x + kMargin, hi.y + kMargin};
  if (!grid_.empty()) {
    nlo = {std::min(nlo.x, glo.x), std::min(nlo.y, glo.y)};
    nhi = {std::max(nhi.x, ghi.x), std::max(nhi.y, ghi.y)};
  }
  GridGeometry g;
  g.width = nhi.x - nlo.x + 1;
  g.height = nhi.y - nlo.y + 1;
  g.resolution = world_.resolution;
  g.origin = world_.origin;
  g.origin.position =
      world_.grid_to_world({static_cast<double>(nlo.x), static_cast<double>(nlo.y)});
  OccupancyGrid n(g, kUnknown);
  for (int y = 0; y < grid_.height(); ++y)
    for (int x = 0; x < grid_.width(); ++x)
      n[Cell{x, y} + offset_ - nlo] = grid_[Cell{x, y}];
  grid_ = std::move(n);
  offset_ = nlo;
}

void LocalMap::set(Cell w, std::int8_t v) {
  ensure(w, w);
  grid_[w - offset_] = v;
  ++version_;
}

std::size_t LocalMap::known_cells() const {
  return static_cast<std::size_t>(std::count_if(grid_.values().begin(), grid_.values().end(),
                                                [](std::int8_t v) { return v != kUnknown; }));
}

namespace {

/// The cells sense() visits around a robot, relative to its cell: the disc of `rcells` cells and,
/// for each disc cell, the Bresenham line toward it without its last cell (lines are translation
/// invariant). Every robot senses every step, so the lines are traced once per range, not per
/// step (same cells in the same order, so the same answer and work count).
struct SenseStencil {
  double rcells = -1.0;
  std::vector<Cell> disc;
  std::vector<std::size_t> line_begin;  // per disc cell; one extra entry at the end
  std::vector<Cell> line;
};

const SenseStencil& sense_stencil(double rcells) {
  thread_local SenseStencil st;
  if (st.rcells == rcells) return st;
  st = SenseStencil{};
  st.rcells = rcells;
  for_each_disc_cell(Cell{0, 0}, rcells, [&](Cell c) {
    st.disc.push_back(c);
    st.line_begin.push_back(st.line.size());
    for_each_line_cell(Cell{0, 0}, c, [&](Cell l) {
      if (l == c) return false;
      st.line.push_back(l);
      return true;
    });
  });
  st.line_begin.push_back(st.line.size());
  return st;
}

}  // namespace

SenseResult sense(const BinaryGrid& truth, Vec2 position, double range_m, LocalMap& map) {
  SenseResult out;
  const auto& g = truth.geometry();
  const auto rc = g.world_to_cell(position);
  if (!rc || !truth.contains(*rc)) return out;
  const double rcells = range_m / g.resolution;
  const int r = static_cast<int>(std::ceil(rcells));
  map.ensure(*rc - Cell{r, r}, *rc + Cell{r, r});
  const SenseStencil& st = sense_stencil(rcells);
  for (std::size_t k = 0; k < st.disc.size(); ++k) {
    ++out.cells;
    const Cell c = *rc + st.disc[k];
    if (!truth.contains(c)) continue;
    // The line from the robot's cell to c stays in the box of both, so inside the grid.
    bool visible = true;
    for (std::size_t i = st.line_begin[k]; i < st.line_begin[k + 1]; ++i) {
      ++out.cells;
      if (truth[*rc + st.line[i]]) {
        visible = false;
        break;
      }
    }
    if (!visible) continue;
    const std::int8_t v = truth[c] ? kOccupied : kFree;
    if (map.at(c) != v) {
      map.set(c, v);
      out.changed = true;
    }
  }
  return out;
}

void OfficeWorldOptions::validate() const {
  auto pos = [](double v, const char* n) {
    if (!(v > 0.0) || !std::isfinite(v))
      throw Error(std::string("office.") + n, 0,
                  "expected a positive finite number, got " + std::to_string(v));
  };
  pos(width_m, "width_m");
  pos(height_m, "height_m");
  pos(resolution, "resolution");
  pos(room_size_m, "room_size_m");
  pos(wall_m, "wall_m");
  pos(door_m, "door_m");
  if (!(extra_door_prob >= 0.0 && extra_door_prob <= 1.0))
    throw Error("office.extra_door_prob", 0, "expected a probability in [0, 1]");
  if (furniture_per_room < 0) throw Error("office.furniture_per_room", 0, "expected >= 0");
  if (width_m / resolution > 20000 || height_m / resolution > 20000)
    throw Error("office", 0, "world too large (more than 20000 cells per side)");
  if (door_m + 2 * wall_m >= room_size_m) throw Error("office.door_m", 0, "door wider than a room");
}

OfficeWorld make_office_world(const OfficeWorldOptions& o) {
  o.validate();
  const int w = static_cast<int>(std::lround(o.width_m / o.resolution));
  const int h = static_cast<int>(std::lround(o.height_m / o.resolution));
  OfficeWorld out;
  out.grid = OccupancyGrid(GridGeometry{w, h, o.resolution, {}}, kFree);
  auto& m = out.grid;
  const int wall = std::max(1, static_cast<int>(std::lround(o.wall_m / o.resolution)));
  const int door = std::max(2, static_cast<int>(std::lround(o.door_m / o.resolution)));
  const int pitch =
      std::max(door + 2 * wall + 4, static_cast<int>(std::lround(o.room_size_m / o.resolution)));
  const int nx = std::max(1, (w - wall) / pitch), ny = std::max(1, (h - wall) / pitch);
  auto block = [&](int x0, int y0, int x1, int y1) {
    for (int y = std::max(0, y0); y <= std::min(h - 1, y1); ++y)
      for (int x = std::max(0, x0); x <= std::min(w - 1, x1); ++x)
        m[Cell{x, y}] = kOccupied;
  };
  // Outer walls.
  block(0, 0, w - 1, wall - 1);
  block(0, h - wall, w - 1, h - 1);
  block(0, 0, wall - 1, h - 1);
  block(w - wall, 0, w - 1, h - 1);
  std::mt19937_64 rng(o.seed);
  auto corridor_row = [&](int j) { return ny >= 3 && j % 3 == 1; };
  // Room x-boundaries at i*pitch (i = 1..nx-1), y-boundaries at j*pitch; the last room takes the
  // rest.
  auto xb = [&](int i) { return i >= nx ? w - wall : i * pitch; };
  auto yb = [&](int j) { return j >= ny ? h - wall : j * pitch; };
  // Union-find over rooms for a spanning tree of doors.
  std::vector<int> parent(static_cast<std::size_t>(nx * ny));
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int a) {
    while (parent[static_cast<std::size_t>(a)] != a)
      a = parent[static_cast<std::size_t>(a)] =
          parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(a)])];
    return a;
  };
  struct Wall {
    int a, b;  // rooms
    bool vertical;
    int i, j;
  };
  std::vector<Wall> walls;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      if (i + 1 < nx && !corridor_row(j))
        walls.push_back({j * nx + i, j * nx + i + 1, true, i + 1, j});
      if (j + 1 < ny) walls.push_back({j * nx + i, (j + 1) * nx + i, false, i, j + 1});
    }
  // Corridor rows are one open space: merge their rooms.
  for (int j = 0; j < ny; ++j)
    if (corridor_row(j))
      for (int i = 0; i + 1 < nx; ++i)
        parent[static_cast<std::size_t>(find(j * nx + i + 1))] = find(j * nx + i);
  std::shuffle(walls.begin(), walls.end(), rng);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const auto& wl : walls) {
    bool has_door = false;
    const int ra = find(wl.a), rb = find(wl.b);
    if (ra != rb) {
      parent[static_cast<std::size_t>(ra)] = rb;
      has_door = true;
    } else {
      has_door = u(rng) < o.extra_door_prob;
    }
    Door d;
    if (wl.vertical) {
      const int x = xb(wl.i);
      const int y0 = yb(wl.j) + wall, y1 = yb(wl.j + 1) - 1;
      block(x, y0 - wall, x + wall - 1, y1 + wall);
      if (has_door && y1 - y0 + 1 > door + 2) {
        std::uniform_int_distribution<int> pos(y0 + 1, y1 - door - 1);
        const int dy = pos(rng);
        for (int y = dy; y < dy + door; ++y)
          for (int xx = x; xx < x + wall; ++xx) {
            m[Cell{xx, y}] = kFree;
            d.cells.push_back({xx, y});
          }
      }
    } else {
      const int y = yb(wl.j);
      const int x0 = xb(wl.i) + wall, x1 = xb(wl.i + 1) - 1;
      block(x0 - wall, y, x1 + wall, y + wall - 1);
      if (has_door && x1 - x0 + 1 > door + 2) {
        std::uniform_int_distribution<int> pos(x0 + 1, x1 - door - 1);
        const int dx = pos(rng);
        for (int x = dx; x < dx + door; ++x)
          for (int yy = y; yy < y + wall; ++yy) {
            m[Cell{x, yy}] = kFree;
            d.cells.push_back({x, yy});
          }
      }
    }
    if (!d.cells.empty()) {
      Vec2 c{};
      for (Cell k : d.cells)
        c += m.geometry().cell_center(k);
      d.centre = c / static_cast<double>(d.cells.size());
      out.doors.push_back(std::move(d));
    }
  }
  // Re-open doors possibly overwritten by a later wall block at a junction.
  for (const auto& d : out.doors)
    for (Cell c : d.cells)
      m[c] = kFree;
  // Furniture: small blocks away from the walls, never on a door approach.
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      if (corridor_row(j)) continue;
      const int x0 = xb(i) + wall, x1 = xb(i + 1) - 1, y0 = yb(j) + wall, y1 = yb(j + 1) - 1;
      const int fw = std::max(2, pitch / 5);
      if (x1 - x0 < 3 * fw || y1 - y0 < 3 * fw) continue;
      std::uniform_int_distribution<int> px(x0 + fw, x1 - 2 * fw), py(y0 + fw, y1 - 2 * fw);
      for (int f = 0; f < o.furniture_per_room; ++f) {
        const int fx = px(rng), fy = py(rng);
        block(fx, fy, fx + fw - 1, fy + fw / 2);
      }
    }
  return out;
}

std::vector<Cell> voronoi_cells(const BinaryGrid& blocked, double min_clearance_m) {
  const auto df = field::distance_transform(blocked, {.border_is_blocked = true});
  const auto& g = blocked.geometry();
  const double min_d = min_clearance_m / g.resolution;
  std::vector<Cell> out;
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width; ++x) {
      const Cell c{x, y};
      if (blocked[c] || df.squared_distance[c] < min_d * min_d) continue;
      const std::int32_t sc = df.nearest[c];
      if (sc == field::kNoSite) continue;
      const Cell a = g.cell_at(static_cast<std::size_t>(sc));
      for (int k = 0; k < 2; ++k) {
        const Cell n = c + kNeighbours8[k];
        if (!g.contains(n) || blocked[n]) continue;
        const std::int32_t sn = df.nearest[n];
        if (sn == field::kNoSite) continue;
        const Cell b = g.cell_at(static_cast<std::size_t>(sn));
        if ((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) >= 9) {
          out.push_back(c);
          break;
        }
      }
    }
  return out;
}

}  // namespace voronav::sim
