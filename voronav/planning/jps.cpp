// Online JPS and JPS+ (jps.hpp): one A* over jump points; the two differ only in how a jump is
// made (bit scans of the map, or table look-ups).
#include "voronav/planning/jps.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

#include "voronav/core/error.hpp"
#include "voronav/planning/internal/jps_data.hpp"

namespace voronav::planning {
namespace {

using internal::JpsMapData;
using internal::kNoJump;
using internal::scan_straight;

constexpr double kSqrt2 = std::numbers::sqrt2;
constexpr std::size_t kMaxCachedMaps = 4;
constexpr unsigned kCancelCheckInterval = 256;

double cost(std::int32_t straight, std::int32_t diagonal) {
  return static_cast<double>(straight) + kSqrt2 * static_cast<double>(diagonal);
}

int sign(int v) {
  return (v > 0) - (v < 0);
}

struct Jump {
  int x = 0, y = 0, steps = 0;  ///< steps == 0: no jump point in that direction
};

/// Online jump (Harabor & Grastien 2011, algorithm 2, no-corner-cutting rules; straight parts
/// block-based, 2014): from free (x, y) in direction (dx, dy).
Jump jump_online(const JpsMapData& m, int x, int y, int dx, int dy, Cell goal) {
  if (dy == 0) {
    const int c = scan_straight(m.rows, y, x, dx, goal.y == y ? goal.x : kNoJump);
    return c == kNoJump ? Jump{} : Jump{c, y, std::abs(c - x)};
  }
  if (dx == 0) {
    const int c = scan_straight(m.cols, x, y, dy, goal.x == x ? goal.y : kNoJump);
    return c == kNoJump ? Jump{} : Jump{x, c, std::abs(c - y)};
  }
  // Diagonal: one cell at a time (no corner cutting: both side cells free); a cell is a jump point
  // when it is the goal or a straight jump from it along dx or dy finds one.
  for (int k = 1;; ++k) {
    if (!m.free(x + dx, y) || !m.free(x, y + dy) || !m.free(x + dx, y + dy)) return {};
    x += dx;
    y += dy;
    if ((x == goal.x && y == goal.y) ||
        scan_straight(m.rows, y, x, dx, goal.y == y ? goal.x : kNoJump) != kNoJump ||
        scan_straight(m.cols, x, y, dy, goal.x == x ? goal.y : kNoJump) != kNoJump)
      return {x, y, k};
  }
}

/// JPS+ jump: the table entry, cut short where the goal lies on the way (straight) or where the
/// diagonal crosses the goal's row or column (a "target" jump point, from which a straight jump
/// reaches the goal when nothing blocks it).
Jump jump_table(const JpsMapData& m, int x, int y, int dx, int dy, Cell goal) {
  const std::int32_t t =
      m.table[8 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(m.width) +
                   static_cast<std::size_t>(x)) +
              static_cast<std::size_t>(internal::dir_index(dx, dy))];
  const int reach = t > 0 ? t : -t;  // free steps available along the jump
  int to_goal = 0;
  if (dy == 0) {
    if (goal.y == y) to_goal = (goal.x - x) * dx;
  } else if (dx == 0) {
    if (goal.x == x) to_goal = (goal.y - y) * dy;
  } else {
    const int gx = (goal.x - x) * dx, gy = (goal.y - y) * dy;
    if (gx > 0 && gy > 0) to_goal = std::min(gx, gy);
  }
  if (to_goal > 0 && to_goal <= reach) return {x + dx * to_goal, y + dy * to_goal, to_goal};
  if (t > 0) return {x + dx * t, y + dy * t, t};
  return {};
}

}  // namespace

JpsPlanner::JpsPlanner(PlannerOptions options, bool with_tables)
    : GridPlanner(std::move(options)),
      tables_(with_tables),
      state_(std::make_unique<internal::JpsSearchState>()) {
  if (options_.connectivity != Connectivity::k8)
    throw Error("--connectivity", 0,
                std::string(with_tables ? "jps+" : "jps") +
                    " searches 8-connected grids only; got 4 (use astar or dijkstra)");
}

JpsPlanner::~JpsPlanner() = default;

void JpsPlanner::invalidate() {
  cache_.clear();
}

const JpsMapData& JpsPlanner::map_data(const BinaryGrid& grid, double* build_ms) {
  *build_ms = 0.0;
  const void* key = grid.data().data();
  for (std::size_t i = 0; i < cache_.size(); ++i) {
    const auto& c = *cache_[i];
    if (c.key == key && c.width == grid.width() && c.height == grid.height()) {
      if (i != 0)
        std::rotate(cache_.begin(), cache_.begin() + static_cast<std::ptrdiff_t>(i),
                    cache_.begin() + static_cast<std::ptrdiff_t>(i + 1));
      return *cache_.front();
    }
  }
  const auto t0 = std::chrono::steady_clock::now();
  auto m = std::make_unique<JpsMapData>();
  m->key = key;
  m->width = grid.width();
  m->height = grid.height();
  m->rows = internal::BitGrid(grid, false);
  m->cols = internal::BitGrid(grid, true);
  if (tables_) internal::build_jump_tables(*m);
  cache_.insert(cache_.begin(), std::move(m));
  if (cache_.size() > kMaxCachedMaps) cache_.pop_back();
  *build_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  total_build_ms_ += *build_ms;
  return *cache_.front();
}

double JpsPlanner::prepare(const BinaryGrid& grid) {
  double ms = 0.0;
  (void)map_data(grid, &ms);
  return ms;
}

PlanResult JpsPlanner::plan(const BinaryGrid& grid, Cell start, Cell goal) {
  PlanResult result;
  if (!grid.contains(start) || !grid.contains(goal)) {
    result.status = PlanStatus::kOutOfMap;
    return result;
  }
  if (grid[start] != 0) {
    result.status = PlanStatus::kStartOccupied;
    return result;
  }
  if (grid[goal] != 0) {
    result.status = PlanStatus::kGoalOccupied;
    return result;
  }
  const JpsMapData& m = map_data(grid, &result.preprocess_ms);
  const auto t0 = std::chrono::steady_clock::now();
  auto finish = [&](PlanStatus s) {
    result.status = s;
    result.time_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return result;
  };

  auto& st = *state_;
  const int w = grid.width();
  const std::size_t n = grid.size();
  if (st.stamp.size() < n) {
    st.gs.resize(n);
    st.gd.resize(n);
    st.parent.resize(n);
    st.heap_pos.assign(n, internal::IndexedMinHeap::kNotInHeap);
    st.stamp.assign(n, 0);
    st.closed.resize(n);
  }
  if (++st.search_id == 0) {
    std::fill(st.stamp.begin(), st.stamp.end(), 0);
    st.search_id = 1;
  }
  auto f_of = [&](int x, int y, std::int32_t s, std::int32_t d) {
    const int dx = std::abs(x - goal.x), dy = std::abs(y - goal.y);
    const int lo = std::min(dx, dy), hi = std::max(dx, dy);
    return cost(s + hi - lo, d + lo);
  };
  const std::int32_t start_i = start.y * w + start.x, goal_i = goal.y * w + goal.x;
  st.open.reset(&st.heap_pos);
  {
    const auto su = static_cast<std::size_t>(start_i);
    st.stamp[su] = st.search_id;
    st.gs[su] = st.gd[su] = 0;
    st.parent[su] = -1;
    st.closed[su] = 0;
    st.open.push_or_decrease(start_i, f_of(start.x, start.y, 0, 0), 0.0);
  }
  auto relax = [&](std::int32_t from, int nx, int ny, std::int32_t s, std::int32_t d) {
    const std::int32_t ni = ny * w + nx;
    const auto su = static_cast<std::size_t>(ni);
    const double ng = cost(s, d);
    if (st.stamp[su] != st.search_id) {
      st.stamp[su] = st.search_id;
      st.closed[su] = 0;
    } else if (st.closed[su] || ng >= cost(st.gs[su], st.gd[su])) {
      return;
    }
    st.gs[su] = s;
    st.gd[su] = d;
    st.parent[su] = from;
    st.open.push_or_decrease(ni, f_of(nx, ny, s, d), ng);
  };

  bool found = false;
  unsigned since_check = 0;
  int dirs[8][2];
  while (!st.open.empty()) {
    const std::int32_t cur = st.open.pop();
    const auto cu = static_cast<std::size_t>(cur);
    st.closed[cu] = 1;
    ++result.expanded;
    const int x = cur % w, y = cur / w;
    if (options_.record_expanded) result.expanded_cells.push_back({x, y});
    if (cur == goal_i) {
      found = true;
      break;
    }
    if (++since_check == kCancelCheckInterval) {
      since_check = 0;
      if ((options_.cancel && options_.cancel()) ||
          (options_.deadline && std::chrono::steady_clock::now() >= *options_.deadline)) {
        st.open.clear();
        return finish(PlanStatus::kCancelled);
      }
    }
    // Successor directions (pruning rules without corner cutting).
    int nd = 0;
    auto add = [&](int dx, int dy) {
      dirs[nd][0] = dx;
      dirs[nd][1] = dy;
      ++nd;
    };
    const std::int32_t p = st.parent[cu];
    if (p < 0) {
      for (int d = 0; d < 8; ++d)
        add(internal::kDirX[d], internal::kDirY[d]);
    } else {
      const int dx = sign(x - p % w), dy = sign(y - p / w);
      if (dx != 0 && dy != 0) {
        add(dx, 0);
        add(0, dy);
        add(dx, dy);
      } else if (dy == 0) {
        add(dx, 0);
        for (const int sy : {1, -1})
          if (m.free(x, y + sy) && !m.free(x - dx, y + sy)) {
            add(0, sy);
            add(dx, sy);
          }
      } else {
        add(0, dy);
        for (const int sx : {1, -1})
          if (m.free(x + sx, y) && !m.free(x + sx, y - dy)) {
            add(sx, 0);
            add(sx, dy);
          }
      }
    }
    const std::int32_t s0 = st.gs[cu], d0 = st.gd[cu];
    for (int i = 0; i < nd; ++i) {
      const int dx = dirs[i][0], dy = dirs[i][1];
      const Jump j =
          tables_ ? jump_table(m, x, y, dx, dy, goal) : jump_online(m, x, y, dx, dy, goal);
      if (j.steps == 0) continue;
      if (dx != 0 && dy != 0)
        relax(cur, j.x, j.y, s0, d0 + j.steps);
      else
        relax(cur, j.x, j.y, s0 + j.steps, d0);
    }
  }
  st.open.clear();
  if (!found) return finish(PlanStatus::kUnreachable);

  // Jump points from goal to start; each segment is straight or diagonal: fill in its cells.
  std::vector<Cell> jumps;
  for (std::int32_t i = goal_i; i != -1; i = st.parent[static_cast<std::size_t>(i)])
    jumps.push_back({i % w, i / w});
  std::reverse(jumps.begin(), jumps.end());
  result.path.push_back(jumps.front());
  for (std::size_t k = 1; k < jumps.size(); ++k) {
    Cell c = jumps[k - 1];
    const int dx = sign(jumps[k].x - c.x), dy = sign(jumps[k].y - c.y);
    while (c != jumps[k]) {
      c = {c.x + dx, c.y + dy};
      result.path.push_back(c);
    }
  }
  result.length_cells =
      cost(st.gs[static_cast<std::size_t>(goal_i)], st.gd[static_cast<std::size_t>(goal_i)]);
  return finish(PlanStatus::kOk);
}

}  // namespace voronav::planning
