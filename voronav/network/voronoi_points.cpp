#include "voronav/network/voronoi_points.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <optional>
#include <queue>
#include <tuple>
#include <unordered_map>

#include "voronav/core/error.hpp"
#include "voronav/field/distance_transform.hpp"

namespace voronav::network {

namespace {

/// Lower corner of the known free cells' bounding box grown by one cell (within the map), or
/// {-1, -1} when no cell is known free.
Cell free_box_origin(const OccupancyGrid& m) {
  const auto& g = m.geometry();
  int x0 = g.width, y0 = g.height;
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width; ++x)
      if (m[Cell{x, y}] == kFree) {
        x0 = std::min(x0, x);
        y0 = std::min(y0, y);
      }
  if (x0 == g.width) return {-1, -1};
  return {std::max(0, x0 - 1), std::max(0, y0 - 1)};
}

/// The map from `off` to one cell past its known free cells (within the map) as blocked (1) /
/// free (0), unknown = blocked.
BinaryGrid known_free_blocked(const OccupancyGrid& m, Cell off) {
  const auto& g = m.geometry();
  int x1 = off.x, y1 = off.y;
  for (int y = off.y; y < g.height; ++y)
    for (int x = off.x; x < g.width; ++x)
      if (m[Cell{x, y}] == kFree) {
        x1 = std::max(x1, x);
        y1 = std::max(y1, y);
      }
  x1 = std::min(g.width - 1, x1 + 1);
  y1 = std::min(g.height - 1, y1 + 1);
  BinaryGrid b(GridGeometry{x1 - off.x + 1, y1 - off.y + 1, g.resolution, {}}, 1);
  for (int y = off.y; y <= y1; ++y)
    for (int x = off.x; x <= x1; ++x)
      b[Cell{x - off.x, y - off.y}] = m[Cell{x, y}] == kFree ? 0 : 1;
  return b;
}

}  // namespace

VoronoiPoints make_voronoi_points(const OccupancyGrid& local_map,
                                  const VoronoiPointsOptions& options) {
  if (!(options.robot_radius_m >= 0.0) || !std::isfinite(options.robot_radius_m))
    throw Error("voronoi_points.robot_radius_m", 0, "expected a finite number >= 0");
  if (!(options.min_site_separation_cells >= 1.0) ||
      !std::isfinite(options.min_site_separation_cells))
    throw Error("voronoi_points.min_site_separation_cells", 0, "expected a finite number >= 1");
  if (!(options.close_point_spacing_m > 0.0) || !std::isfinite(options.close_point_spacing_m))
    throw Error("voronoi_points.close_point_spacing_m", 0, "expected a finite number > 0");
  VoronoiPoints out;
  if (local_map.empty()) return out;
  const auto& full = local_map.geometry();
  const double res = full.resolution;
  out.cells_processed = local_map.size() * 2;
  // The EDT runs on the known free cells' bounding box plus one cell (cropped to the map): a
  // free cell's nearest blocked cell is always in that ring or inside it (any cell beyond is
  // farther than its projection onto the ring, which is not free), and only free cells and
  // their neighbours are read below, so the result is that of the whole window. Most of a
  // robot's window is unknown margin (LocalMap grows by 16 cells), so this is 1.5-2x fewer cells.
  const Cell off = free_box_origin(local_map);
  if (off.x < 0) return out;  // nothing known free: no points
  const BinaryGrid blocked = known_free_blocked(local_map, off);
  const auto& g = blocked.geometry();
  const field::DistanceField df = field::distance_transform(
      blocked, field::DistanceTransformOptions{.border_is_blocked = true});
  const double sep2 = options.min_site_separation_cells * options.min_site_separation_cells;
  auto site_cell = [&](std::int32_t s) { return g.cell_at(static_cast<std::size_t>(s)); };
  auto clearance_of = [&](Cell c) {
    const double d = std::sqrt(static_cast<double>(df.squared_distance[c]));
    return std::max(0.0, (d - 0.5) * res);
  };
  struct Cand {
    Cell cell;
    double clearance;
  };
  std::vector<Cand> open_c, close_c;
  for (int y = 0; y < g.height; ++y) {
    for (int x = 0; x < g.width; ++x) {
      const Cell c{x, y};
      if (blocked[c]) continue;
      const std::int32_t sc = df.nearest[c];
      const Cell a = sc == field::kNoSite ? c : site_cell(sc);
      bool ridge = false;
      for (int k = 0; k < 4 && !ridge && sc != field::kNoSite; ++k) {
        const Cell n = c + kNeighbours8[k];
        // Sites beyond the border are not in the EDT's nearest map; the border acts only through
        // distances, so compare neighbours inside the grid.
        if (!g.contains(n) || blocked[n]) continue;
        const std::int32_t sn = df.nearest[n];
        if (sn == field::kNoSite || sn == sc) continue;
        const Cell b = site_cell(sn);
        const double dx = a.x - b.x, dy = a.y - b.y;
        if (dx * dx + dy * dy >= sep2 && df.squared_distance[c] >= df.squared_distance[n])
          ridge = true;
      }
      // A local maximum of the distance (e.g. the centre of a sensed disc whose nearest sites are
      // all border cells) is on the diagram too.
      if (!ridge) {
        bool is_max = true;
        for (Cell o : kNeighbours8) {
          const Cell n = c + o;
          if (g.contains(n) && df.squared_distance[n] > df.squared_distance[c]) {
            is_max = false;
            break;
          }
        }
        ridge = is_max;
      }
      if (!ridge) continue;
      const double cl = clearance_of(c);
      (cl > options.robot_radius_m + res ? open_c : close_c).push_back({c, cl});
    }
  }
  auto by_clearance = [](const Cand& a, const Cand& b) {
    if (a.clearance != b.clearance) return a.clearance > b.clearance;
    return a.cell < b.cell;
  };
  std::sort(open_c.begin(), open_c.end(), by_clearance);
  for (const auto& c : open_c) {
    const Vec2 p = full.cell_center(c.cell + off);
    bool covered = false;
    for (const auto& q : out.open) {
      // s is covered when it continues q with one cell to spare: the next skeleton cell then
      // still continues q or is selected itself, so the selected points stay chained.
      const double cover = (static_cast<double>(q.clearance) - options.robot_radius_m) +
                           (c.clearance - options.robot_radius_m) - res;
      if (cover > 0.0 && (q.position - p).squared_norm() <= cover * cover) {
        covered = true;
        break;
      }
    }
    if (!covered) out.open.push_back({p, static_cast<float>(c.clearance), 0.0f});
  }
  std::sort(close_c.begin(), close_c.end(), by_clearance);
  const double sp2 = options.close_point_spacing_m * options.close_point_spacing_m;
  for (const auto& c : close_c) {
    const Vec2 p = full.cell_center(c.cell + off);
    bool covered = false;
    for (Vec2 q : out.close)
      if ((q - p).squared_norm() < sp2) {
        covered = true;
        break;
      }
    if (!covered) out.close.push_back(p);
  }
  out.cells_processed += open_c.size() * (out.open.size() + 1) + close_c.size();
  return out;
}

double clearance_at(const OccupancyGrid& local_map, Vec2 world) {
  const auto cell = local_map.geometry().world_to_cell(world);
  if (!cell || !local_map.contains(*cell) || local_map[*cell] != kFree) return 0.0;
  // Nearest blocked-or-unknown cell by an expanding square search (maps are small).
  const auto& g = local_map.geometry();
  double best2 = std::numeric_limits<double>::infinity();
  const int maxr = std::max(g.width, g.height);
  for (int r = 1; r <= maxr; ++r) {
    if (static_cast<double>(r - 1) * (r - 1) > best2) break;
    for (int dy = -r; dy <= r; ++dy) {
      for (int dx = -r; dx <= r; ++dx) {
        if (std::max(std::abs(dx), std::abs(dy)) != r) continue;
        const Cell n{cell->x + dx, cell->y + dy};
        if (!g.contains(n) || local_map[n] != kFree)
          best2 = std::min(best2, static_cast<double>(dx * dx + dy * dy));
      }
    }
  }
  return std::max(0.0, (std::sqrt(best2) - 0.5) * g.resolution);
}

namespace {

// continues() itself, visible to the compiler here so the search loops inline it.
inline bool continues_inline(const VoronoiPoint& p, const VoronoiPoint& q, double r) {
  const double a = static_cast<double>(p.clearance) - r;
  const double b = static_cast<double>(q.clearance) - r;
  if (a <= 0.0 || b <= 0.0) return false;
  // Squared distances: this test runs for every pair of points of a search (the hot loop of
  // large runs); hypot was most of the time on 100 robots (docs/reproductions/networked.md).
  const double dx = p.position.x - q.position.x, dy = p.position.y - q.position.y;
  return dx * dx + dy * dy <= (a + b) * (a + b);
}

}  // namespace

bool continues(const VoronoiPoint& p, const VoronoiPoint& q, double r) {
  return continues_inline(p, q, r);
}

PointSearch search_points(std::span<const VoronoiPoint> points, std::span<const double> start_cost,
                          double robot_radius_m, const ExtraEdge& extra_edge) {
  if (start_cost.size() != points.size())
    throw Error("search_points", 0, "start_cost must have one entry per point");
  const std::size_t n = points.size();
  PointSearch s;
  s.cost.assign(n, std::numeric_limits<double>::infinity());
  s.parent.assign(n, -1);
  using Item = std::pair<double, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  for (std::size_t i = 0; i < n; ++i)
    if (std::isfinite(start_cost[i])) {
      s.cost[i] = start_cost[i];
      open.push({start_cost[i], i});
    }
  std::vector<std::uint8_t> done(n, 0);
  while (!open.empty()) {
    const auto [c, i] = open.top();
    open.pop();
    if (done[i]) continue;
    done[i] = 1;
    for (std::size_t j = 0; j < n; ++j) {
      ++s.work;
      ++s.candidates;
      if (done[j]) continue;
      if (!continues_inline(points[i], points[j], robot_radius_m) &&
          !(extra_edge && extra_edge(i, j)))
        continue;
      const double nc = c + distance(points[i].position, points[j].position);
      if (nc < s.cost[j]) {
        s.cost[j] = nc;
        s.parent[j] = static_cast<std::int32_t>(i);
        open.push({nc, j});
      }
    }
  }
  return s;
}

namespace {

constexpr double kHuge = 1e300;  // "no limit" for a reach in PointGrid::for_each_near

/// Points bucketed by position into square cells of side h (counting sort); settled points are
/// taken out, so the order within a cell changes (the search's result does not depend on it).
class PointGrid {
 public:
  PointGrid(std::span<const VoronoiPoint> points, double h, double robot_radius) {
    double x1 = -std::numeric_limits<double>::infinity(), y1 = x1;
    x0_ = std::numeric_limits<double>::infinity();
    y0_ = x0_;
    for (const auto& p : points) {
      x0_ = std::min(x0_, p.position.x);
      y0_ = std::min(y0_, p.position.y);
      x1 = std::max(x1, p.position.x);
      y1 = std::max(y1, p.position.y);
    }
    // At most ~4 cells per point (and at least 1024 allowed): a wide, sparse set gets wider cells
    // rather than a huge empty grid.
    const double cap = std::max(1024.0, 4.0 * static_cast<double>(points.size()));
    auto cells_for = [&](double side) {
      return (std::floor((x1 - x0_) / side) + 1.0) * (std::floor((y1 - y0_) / side) + 1.0);
    };
    while (cells_for(h) > cap)
      h *= std::sqrt(cells_for(h) / cap) + 0.01;
    h_ = h;
    nx_ = static_cast<int>(std::floor((x1 - x0_) / h_)) + 1;
    ny_ = static_cast<int>(std::floor((y1 - y0_) / h_)) + 1;
    begin_.assign(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_) + 1, 0);
    cell_.resize(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
      cell_[i] = index(cx(points[i].position.x), cy(points[i].position.y));
      ++begin_[cell_[i] + 1];
    }
    for (std::size_t c = 1; c < begin_.size(); ++c)
      begin_[c] += begin_[c - 1];
    order_.resize(points.size());
    end_.assign(begin_.begin(), begin_.end() - 1);
    for (std::size_t i = 0; i < points.size(); ++i)
      order_[end_[cell_[i]]++] = i;
    reach_.assign(begin_.size() - 1, -std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < points.size(); ++i)
      reach_[cell_[i]] =
          std::max(reach_[cell_[i]], static_cast<double>(points[i].clearance) - robot_radius);
  }
  /// Takes point i out of its cell (a settled point is never compared again).
  void remove(std::size_t i) {
    const std::size_t c = cell_[i];
    for (std::size_t k = begin_[c]; k < end_[c]; ++k)
      if (order_[k] == i) {
        order_[k] = order_[--end_[c]];
        return;
      }
  }
  /// Calls f(j) for every point j in the cells that overlap the square [p - R, p + R] and whose
  /// rectangle is within `reach` plus the cell's largest (c - r) of p, or within `always` of p
  /// (`margin` is added to both, for rounding).
  template <typename F>
  void for_each_near(Vec2 p, double radius, double reach, double always, double margin,
                     F&& f) const {
    const int xa = cx(p.x - radius), xb = cx(p.x + radius);
    const int ya = cy(p.y - radius), yb = cy(p.y + radius);
    for (int y = ya; y <= yb; ++y) {
      const double ylo = y0_ + h_ * y, dy = std::max({0.0, ylo - p.y, p.y - (ylo + h_)});
      for (int x = xa; x <= xb; ++x) {
        const std::size_t c = index(x, y);
        if (begin_[c] == end_[c]) continue;
        const double xlo = x0_ + h_ * x, dx = std::max({0.0, xlo - p.x, p.x - (xlo + h_)});
        const double d2 = dx * dx + dy * dy;
        const double lim = std::max(reach + reach_[c], always) + margin;
        if (lim < 0.0 || d2 > lim * lim) continue;
        for (std::size_t k = begin_[c]; k < end_[c]; ++k)
          f(order_[k]);
      }
    }
  }

 private:
  // Monotonic in x, so every point within R of p lies in the cells of [p.x - R, p.x + R].
  int cx(double x) const {
    return std::clamp(static_cast<int>(std::floor((x - x0_) / h_)), 0, nx_ - 1);
  }
  int cy(double y) const {
    return std::clamp(static_cast<int>(std::floor((y - y0_) / h_)), 0, ny_ - 1);
  }
  std::size_t index(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(nx_) +
           static_cast<std::size_t>(x);
  }
  double x0_, y0_, h_ = 1.0;
  int nx_ = 1, ny_ = 1;
  std::vector<std::size_t> begin_;  // first entry of each cell in order_ (row-major, + end)
  std::vector<std::size_t> end_;    // one past the last point still in each cell
  std::vector<std::size_t> cell_;   // cell of each point
  std::vector<std::size_t> order_;
  std::vector<double> reach_;  // per cell: the largest (c - r) of its points
};

}  // namespace

namespace {

/// Which of two points of equal cost the search settles first: the one with the lower key. For
/// the plain search the key is the point's index; for merged copies (see below) it is the index
/// of the copy that the search over all points would settle first.
struct TieKeys {
  std::span<const std::size_t> at_start;  ///< while a point keeps its start cost
  std::span<const std::size_t> reached;   ///< once a relaxation lowered it
};

/// The grid search itself (search_points_bucketed without the merging of duplicates); the
/// caller has checked the input.
PointSearch search_grid(std::span<const VoronoiPoint> points, std::span<const double> start_cost,
                        double robot_radius_m, const BoundedExtraEdges& extra,
                        const TieKeys& keys = {}, std::vector<std::int32_t>* tie_parent = nullptr) {
  const std::size_t n = points.size();
  const bool has_edge = static_cast<bool>(extra.edge);
  // The largest (c - r): a point i continues no point farther than (c_i - r) + amax.
  double amax = 0.0;
  for (const auto& p : points)
    amax = std::max(amax, static_cast<double>(p.clearance) - robot_radius_m);
  const double emax = has_edge ? std::max(0.0, extra.max_distance_m) : 0.0;
  // Cells of side amax: a point looks (c - r) + amax <= 2 amax around it for continuing points
  // (5 x 5 cells); a point in the edge range also emax around it.
  // (Cells no wider than 1 m: each cell's largest (c - r) then prunes well where narrow
  // corridors and wide rooms mix.)
  const double cell_side = amax > 0.0 ? std::min(amax, 1.0) : std::max(emax, 1.0);
  // Adjacency of the unbounded pairs (CSR).
  std::vector<std::size_t> adj_begin(n + 1, 0), adj;
  if (has_edge && !extra.unbounded_pairs.empty()) {
    for (const auto& [i, j] : extra.unbounded_pairs) {
      ++adj_begin[i + 1];
      ++adj_begin[j + 1];
    }
    for (std::size_t i = 1; i <= n; ++i)
      adj_begin[i] += adj_begin[i - 1];
    adj.resize(adj_begin[n]);
    std::vector<std::size_t> fill(adj_begin.begin(), adj_begin.end() - 1);
    for (const auto& [i, j] : extra.unbounded_pairs) {
      adj[fill[i]++] = j;
      adj[fill[j]++] = i;
    }
  }
  PointSearch s;
  s.cost.assign(n, std::numeric_limits<double>::infinity());
  s.parent.assign(n, -1);
  if (n == 0) return s;
  PointGrid grid(points, cell_side, robot_radius_m);
  const bool keyed = !keys.at_start.empty();
  using Item = std::tuple<double, std::size_t, std::size_t>;  // cost, tie key, point
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  for (std::size_t i = 0; i < n; ++i)
    if (std::isfinite(start_cost[i])) {
      s.cost[i] = start_cost[i];
      open.push({start_cost[i], keyed ? keys.at_start[i] : i, i});
    }
  if (tie_parent) tie_parent->assign(n, -1);
  std::vector<std::uint8_t> done(n, 0);
  std::vector<std::size_t> seen(n, n);  // the settled point that last compared j
  while (!open.empty()) {
    // Plain variables, not a structured binding: the lambda below captures them (C++20 allows
    // capturing bindings, clang before 16 does not).
    const double c = std::get<0>(open.top());
    const std::size_t i = std::get<2>(open.top());
    open.pop();
    if (done[i]) continue;
    done[i] = 1;
    grid.remove(i);
    s.work += n;  // what the all-pairs search examines for this settled point
    const VoronoiPoint& pi = points[i];
    const bool in_range = has_edge && i >= extra.range_begin && i < extra.range_end;
    // may_edge: edge() can join i and j (an unbounded pair, or both in the edge range).
    auto relax = [&](std::size_t j, bool may_edge) {
      if (seen[j] == i) return;
      seen[j] = i;
      ++s.candidates;
      if (done[j]) return;
      if (!continues_inline(pi, points[j], robot_radius_m)) {
        if (!may_edge) return;
        if (extra.on_asked) {
          extra.on_asked(i, j);
          // The answer matters only where the relaxation below would do something.
          const double nc = c + distance(pi.position, points[j].position);
          const bool matters = nc < s.cost[j] || (tie_parent && nc == s.cost[j] &&
                                                  s.parent[j] < 0 && (*tie_parent)[j] < 0);
          if (!matters) return;
        }
        if (!extra.edge(i, j)) return;
      }
      const double nc = c + distance(pi.position, points[j].position);
      if (nc < s.cost[j]) {
        s.cost[j] = nc;
        s.parent[j] = static_cast<std::int32_t>(i);
        open.push({nc, keyed ? keys.reached[j] : j, j});
      } else if (tie_parent && nc == s.cost[j] && s.parent[j] < 0 && (*tie_parent)[j] < 0) {
        // j keeps its start, but a copy that started higher is reached here at the same cost.
        (*tie_parent)[j] = static_cast<std::int32_t>(i);
        if (keyed) open.push({nc, keys.reached[j], j});
      }
    };
    // Unbounded pairs first: a pair the grid visits is not compared again (seen).
    for (std::size_t k = adj_begin[i]; k < adj_begin[i + 1]; ++k)
      relax(adj[k], true);
    const double ai = static_cast<double>(pi.clearance) - robot_radius_m;
    double radius = std::max(ai > 0.0 ? ai + amax : 0.0, in_range ? emax : 0.0);
    if (ai > 0.0 || in_range) {  // (an edge bound of 0 still joins points at one place)
      // A margin for rounding: the exact tests decide, the grid only has to include.
      const double margin =
          1e-6 * (1.0 + radius + std::abs(pi.position.x) + std::abs(pi.position.y));
      // A cell can hold a point that continues i only within (c_i - r) + its largest (c - r).
      grid.for_each_near(pi.position, radius + margin, ai > 0.0 ? ai : -kHuge,
                         in_range ? emax : -kHuge, margin, [&](std::size_t j) {
                           relax(j, in_range && j >= extra.range_begin && j < extra.range_end);
                         });
    }
  }
  return s;
}

/// Points that are exact copies of each other (a Search merged from re-forwards carries the same
/// point several times): same position and clearance, clearance > r (so each copy continues
/// the others at distance 0), outside the extra-edge range and in no unbounded pair (so the
/// caller's edge() cannot tell them apart). `group[i]` is the lowest index of i's copies.
std::vector<std::size_t> copy_groups(std::span<const VoronoiPoint> points, double robot_radius_m,
                                     const BoundedExtraEdges& extra, bool& any) {
  const std::size_t n = points.size();
  std::vector<std::uint8_t> fixed(n, 0);
  for (const auto& [i, j] : extra.unbounded_pairs) {
    fixed[i] = 1;
    fixed[j] = 1;
  }
  // Open addressing on (x, y, clearance), in index order: the first point of a key is the
  // lowest index of its copies.
  std::size_t cap = 16;
  while (cap < 2 * n)
    cap *= 2;
  std::vector<std::size_t> table(cap, n);  // n = empty slot
  auto bits = [](double d) {
    std::uint64_t u = 0;
    std::memcpy(&u, &d, sizeof u);
    return u;
  };
  std::vector<std::size_t> group(n);
  std::iota(group.begin(), group.end(), std::size_t{0});
  any = false;
  for (std::size_t i = 0; i < n; ++i) {
    const bool in_range = extra.edge && i >= extra.range_begin && i < extra.range_end;
    const auto& p = points[i];
    if (fixed[i] || in_range || !(static_cast<double>(p.clearance) - robot_radius_m > 0.0))
      continue;
    std::uint64_t h = bits(p.position.x) * 0x9e3779b97f4a7c15ull;
    h = (h ^ (h >> 29) ^ bits(p.position.y)) * 0xbf58476d1ce4e5b9ull;
    h = (h ^ (h >> 31) ^ bits(static_cast<double>(p.clearance))) * 0x94d049bb133111ebull;
    for (std::size_t k = (h ^ (h >> 32)) & (cap - 1);; k = (k + 1) & (cap - 1)) {
      if (table[k] == n) {
        table[k] = i;
        break;
      }
      const auto& q = points[table[k]];
      if (q.position.x == p.position.x && q.position.y == p.position.y &&
          q.clearance == p.clearance) {
        group[i] = table[k];
        any = true;
        break;
      }
    }
  }
  return group;
}

}  // namespace

PointSearch search_points_bucketed(std::span<const VoronoiPoint> points,
                                   std::span<const double> start_cost, double robot_radius_m,
                                   const BoundedExtraEdges& extra) {
  if (start_cost.size() != points.size())
    throw Error("search_points", 0, "start_cost must have one entry per point");
  const std::size_t n = points.size();
  const bool has_edge = static_cast<bool>(extra.edge);
  bool finite = true;
  for (const auto& p : points)
    finite = finite && std::isfinite(p.position.x) && std::isfinite(p.position.y);
  if (!finite || (has_edge && !(extra.max_distance_m < std::numeric_limits<double>::infinity()))) {
    if (has_edge && extra.on_asked) {
      const ExtraEdge counted = [&](std::size_t i, std::size_t j) {
        extra.on_asked(i, j);
        return extra.edge(i, j);
      };
      return search_points(points, start_cost, robot_radius_m, counted);
    }
    return search_points(points, start_cost, robot_radius_m, extra.edge);  // nothing to bound by
  }
  for (const auto& [i, j] : extra.unbounded_pairs)
    if (i >= n || j >= n) throw Error("search_points", 0, "an unbounded pair names no point");
  bool any_copy = false;
  const auto group = copy_groups(points, robot_radius_m, extra, any_copy);
  if (!any_copy) return search_grid(points, start_cost, robot_radius_m, extra);
  // Search one point per group of copies (its cheapest start), then give every copy the result
  // the search over all points gives it. In that search the copies of a group all receive the
  // same relaxations from other points (same position and clearance); the first copy settled,
  // F, relaxes the others at distance 0, and every later point reached through the group gets F
  // as its parent (the later copies offer the same cost, which is not lower). So:
  //  - a group reached below its cheapest start m (from point k): every copy has that cost and
  //    parent k; F is the lowest index;
  //  - otherwise F is the lowest index whose start is m; every copy costs m, the copies whose
  //    start is m keep parent -1, the others get parent F.
  // (Exact floating-point ties between a relaxation and m are the one case this does not cover.)
  std::vector<std::size_t> compact_of(n), full_of;                    // point <-> compact index
  std::vector<double> m(n, std::numeric_limits<double>::infinity());  // per group leader
  for (std::size_t i = 0; i < n; ++i)
    m[group[i]] = std::min(m[group[i]], start_cost[i]);
  std::vector<VoronoiPoint> cpoints;
  std::vector<double> cstart;
  for (std::size_t i = 0; i < n; ++i) {
    if (group[i] != i) {
      compact_of[i] = compact_of[group[i]];
      continue;
    }
    compact_of[i] = full_of.size();
    full_of.push_back(i);
    cpoints.push_back(points[i]);
    cstart.push_back(m[i]);
  }
  BoundedExtraEdges cextra;
  cextra.max_distance_m = extra.max_distance_m;
  if (has_edge) {
    // Points in the edge range are never merged, so the range stays contiguous.
    cextra.edge = [&](std::size_t a, std::size_t b) { return extra.edge(full_of[a], full_of[b]); };
    if (extra.on_asked)
      cextra.on_asked = [&](std::size_t a, std::size_t b) {
        extra.on_asked(full_of[a], full_of[b]);
      };
    cextra.range_begin = static_cast<std::size_t>(
        std::lower_bound(full_of.begin(), full_of.end(), extra.range_begin) - full_of.begin());
    cextra.range_end = static_cast<std::size_t>(
        std::lower_bound(full_of.begin(), full_of.end(), extra.range_end) - full_of.begin());
  }
  for (const auto& [i, j] : extra.unbounded_pairs)
    cextra.unbounded_pairs.emplace_back(compact_of[i], compact_of[j]);
  // F of every group while it keeps its start (the lowest index whose start is m) and once it
  // is reached below m (the lowest index): equal costs are settled in the order of these keys,
  // as the search over all points settles them in the order of their indices.
  std::vector<std::size_t> first_at_start(full_of.begin(), full_of.end());
  for (std::size_t i = n; i-- > 0;) {
    const std::size_t c = compact_of[i];
    if (start_cost[i] == cstart[c]) first_at_start[c] = i;  // ends at the lowest
  }
  std::vector<std::int32_t> tie;  // (see search_grid) the group's copies that started above m
  const PointSearch cs =
      search_grid(cpoints, cstart, robot_radius_m, cextra, TieKeys{first_at_start, full_of}, &tie);
  std::vector<std::size_t> first(full_of.size());
  for (std::size_t c = 0; c < full_of.size(); ++c)
    first[c] = cs.parent[c] < 0 && tie[c] < 0 ? first_at_start[c] : full_of[c];
  PointSearch s;
  s.cost.assign(n, std::numeric_limits<double>::infinity());
  s.parent.assign(n, -1);
  s.candidates = cs.candidates;
  std::size_t reached = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t c = compact_of[i];
    s.cost[i] = cs.cost[c];
    if (!std::isfinite(cs.cost[c])) continue;
    ++reached;
    if (cs.parent[c] >= 0) {
      s.parent[i] = static_cast<std::int32_t>(first[static_cast<std::size_t>(cs.parent[c])]);
    } else if (start_cost[i] != cstart[c]) {
      s.parent[i] = static_cast<std::int32_t>(tie[c] >= 0 ? first[static_cast<std::size_t>(tie[c])]
                                                          : first[c]);
    }
  }
  s.work = reached * n;  // the all-pairs search settles every reached point and examines n pairs
  return s;
}

struct CopyCheck::Index {
  std::vector<VoronoiPoint> points;
  std::vector<double> cost;
  double r = 0.0;
  double amax = 0.0;  // the largest (c - r) of the held points
  std::size_t target_begin = 0;
  std::optional<PointGrid> grid;
  bool brute = false;  // a held point is not finite: compare every pair
  // Exact points (position, clearance) -> the lowest cost held for them.
  struct Key {
    double x, y;
    float c;
    bool operator==(const Key&) const = default;
  };
  struct Hash {
    std::size_t operator()(const Key& k) const {
      std::uint64_t a = 0, b = 0;
      std::uint32_t c = 0;
      std::memcpy(&a, &k.x, sizeof a);
      std::memcpy(&b, &k.y, sizeof b);
      std::memcpy(&c, &k.c, sizeof c);
      std::uint64_t h = (a * 0x9e3779b97f4a7c15ull) ^ (b + 0xbf58476d1ce4e5b9ull + (a << 6));
      h = (h ^ (h >> 31) ^ c) * 0x94d049bb133111ebull;
      return static_cast<std::size_t>(h ^ (h >> 29));
    }
  };
  std::unordered_map<Key, double, Hash> exact;
};

CopyCheck::CopyCheck(std::span<const VoronoiPoint> points, const PointSearch& done,
                     double robot_radius_m, std::size_t target_begin) {
  if (done.cost.size() != points.size())
    throw Error("search_would_improve", 0, "expected one cost per point");
  auto ix = std::make_shared<Index>();
  ix->points.assign(points.begin(), points.end());
  ix->cost = done.cost;
  ix->r = robot_radius_m;
  ix->target_begin = target_begin;
  for (std::size_t i = 0; i < points.size(); ++i) {
    ix->amax = std::max(ix->amax, static_cast<double>(points[i].clearance) - robot_radius_m);
    if (!std::isfinite(done.cost[i])) continue;
    const Index::Key k{points[i].position.x, points[i].position.y, points[i].clearance};
    const auto [it, fresh] = ix->exact.emplace(k, done.cost[i]);
    if (!fresh) it->second = std::min(it->second, done.cost[i]);
  }
  bool finite = true;
  for (const auto& p : points)
    finite = finite && std::isfinite(p.position.x) && std::isfinite(p.position.y);
  ix->brute = !finite;
  if (finite && !points.empty() && ix->amax > 0.0)
    ix->grid.emplace(points, std::min(ix->amax, 1.0), robot_radius_m);
  index_ = std::move(ix);
}

ImprovementCheck CopyCheck::improves(std::span<const VoronoiPoint> added,
                                     std::span<const double> added_start, double tolerance) const {
  if (added_start.size() != added.size())
    throw Error("search_would_improve", 0, "expected one start cost per added point");
  const Index& ix = *index_;
  const std::size_t n = ix.points.size(), k = added.size();
  const double r = ix.r;
  ImprovementCheck out;
  // Costs the search over all points would lower: held points (sparse) and added points.
  std::unordered_map<std::size_t, double> lowered;
  std::vector<double> add_cost(k, std::numeric_limits<double>::infinity());
  auto cost_of = [&](std::size_t i) {
    if (i >= n) return add_cost[i - n];
    const auto it = lowered.find(i);
    return it == lowered.end() ? ix.cost[i] : it->second;
  };
  auto at = [&](std::size_t i) -> const VoronoiPoint& {
    return i < n ? ix.points[i] : added[i - n];
  };
  auto redundant = [&](const VoronoiPoint& p, double c) {
    const auto it = ix.exact.find(Index::Key{p.position.x, p.position.y, p.clearance});
    return it != ix.exact.end() && it->second <= c;
  };
  // Held points that may continue p (the grid's cells within (c_p - r) + their largest (c - r)).
  auto near_held = [&](const VoronoiPoint& p, auto&& f) {
    const double a = static_cast<double>(p.clearance) - r;
    if (a <= 0.0 || !std::isfinite(p.position.x) || !std::isfinite(p.position.y)) return;
    if (ix.brute) {
      for (std::size_t i = 0; i < n; ++i)
        f(i);
      return;
    }
    if (!ix.grid) return;
    const double margin =
        1e-6 * (1.0 + a + ix.amax + std::abs(p.position.x) + std::abs(p.position.y));
    ix.grid->for_each_near(p.position, a + ix.amax + margin, a, -kHuge, margin, f);
  };
  using Item = std::pair<double, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  // A target is lowered: the copy is new. Another point is lowered: it is expanded.
  auto lower = [&](std::size_t j, double c) {
    if (j < n && j >= ix.target_begin) {
      const double old = ix.cost[j];
      return c < old - tolerance || (!std::isfinite(old) && std::isfinite(c));
    }
    if (c < cost_of(j)) {
      if (j < n)
        lowered[j] = c;
      else
        add_cost[j - n] = c;
      open.push({c, j});
    }
    return false;
  };
  for (std::size_t a = 0; a < k; ++a) {
    const VoronoiPoint& p = added[a];
    ++out.work;  // looked up among the held points
    if (redundant(p, added_start[a])) continue;
    // Its cost through the held points (a copy can join two of them).
    double c = added_start[a];
    near_held(p, [&](std::size_t i) {
      ++out.work;
      if (std::isfinite(ix.cost[i]) && continues_inline(ix.points[i], p, r))
        c = std::min(c, ix.cost[i] + distance(ix.points[i].position, p.position));
    });
    if (std::isfinite(c) && !redundant(p, c)) {
      add_cost[a] = c;
      open.push({c, n + a});
    }
  }
  while (!open.empty()) {
    const double c = open.top().first;
    const std::size_t i = open.top().second;
    open.pop();
    if (c > cost_of(i)) continue;  // lowered again since
    const VoronoiPoint& pi = at(i);
    bool hit = false;
    auto relax = [&](std::size_t j) {
      ++out.work;
      if (hit || j == i || !continues_inline(pi, at(j), r)) return;
      hit = lower(j, c + distance(pi.position, at(j).position));
    };
    near_held(pi, relax);
    for (std::size_t a = 0; a < k && !hit; ++a)
      relax(n + a);
    if (hit) {
      out.improves = true;
      return out;
    }
  }
  return out;
}

ImprovementCheck search_would_improve(std::span<const VoronoiPoint> points, const PointSearch& done,
                                      std::span<const VoronoiPoint> added,
                                      std::span<const double> added_start, double robot_radius_m,
                                      std::size_t target_begin, double tolerance) {
  return CopyCheck(points, done, robot_radius_m, target_begin)
      .improves(added, added_start, tolerance);
}

std::vector<std::size_t> trace_points(const PointSearch& s, std::size_t last) {
  std::vector<std::size_t> chain;
  for (std::int32_t i = static_cast<std::int32_t>(last); i >= 0;
       i = s.parent[static_cast<std::size_t>(i)]) {
    chain.push_back(static_cast<std::size_t>(i));
    if (chain.size() > s.parent.size()) break;  // defensive: parents form a tree
  }
  std::reverse(chain.begin(), chain.end());
  return chain;
}

double route_length(std::span<const VoronoiPoint> route) {
  double len = 0.0;
  for (std::size_t i = 1; i < route.size(); ++i)
    len += distance(route[i - 1].position, route[i].position);
  return len;
}

}  // namespace voronav::network
