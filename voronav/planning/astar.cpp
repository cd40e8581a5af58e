#include "voronav/planning/astar.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

namespace voronav::planning {
namespace {

constexpr double kSqrt2 = std::numbers::sqrt2;
constexpr unsigned kCancelCheckInterval = 1024;

bool should_stop(const PlannerOptions& o) {
  if (o.cancel && o.cancel()) return true;
  return o.deadline && std::chrono::steady_clock::now() >= *o.deadline;
}

}  // namespace

double octile_distance(Cell a, Cell b) {
  const int dx = std::abs(a.x - b.x), dy = std::abs(a.y - b.y);
  return static_cast<double>(std::max(dx, dy) - std::min(dx, dy)) +
         kSqrt2 * static_cast<double>(std::min(dx, dy));
}

double path_length_cells(const std::vector<Cell>& path) {
  double len = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i)
    len += octile_distance(path[i - 1], path[i]);
  return len;
}

bool is_valid_path(const BinaryGrid& grid, const std::vector<Cell>& path,
                   Connectivity connectivity) {
  if (path.empty()) return false;
  auto free_cell = [&](Cell c) { return grid.contains(c) && grid[c] == 0; };
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (!free_cell(path[i])) return false;
    if (i == 0) continue;
    const Cell d = path[i] - path[i - 1];
    if (std::abs(d.x) > 1 || std::abs(d.y) > 1 || (d.x == 0 && d.y == 0)) return false;
    if (d.x != 0 && d.y != 0) {
      if (connectivity == Connectivity::k4) return false;
      if (!free_cell({path[i - 1].x + d.x, path[i - 1].y}) ||
          !free_cell({path[i - 1].x, path[i - 1].y + d.y}))
        return false;
    }
  }
  return true;
}

AStarPlanner::AStarPlanner(PlannerOptions options, bool use_heuristic)
    : GridPlanner(std::move(options)), use_heuristic_(use_heuristic) {}

PlanResult AStarPlanner::plan(const BinaryGrid& grid, Cell start, Cell goal) {
  const auto t0 = std::chrono::steady_clock::now();
  PlanResult result;
  auto finish = [&](PlanStatus s) {
    result.status = s;
    result.time_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return result;
  };
  if (!grid.contains(start) || !grid.contains(goal)) return finish(PlanStatus::kOutOfMap);
  if (grid[start] != 0) return finish(PlanStatus::kStartOccupied);
  if (grid[goal] != 0) return finish(PlanStatus::kGoalOccupied);

  const int w = grid.width(), h = grid.height();
  const std::size_t n = grid.size();
  if (stamp_.size() < n) {
    gs_.resize(n);
    gd_.resize(n);
    parent_.resize(n);
    heap_pos_.assign(n, internal::IndexedMinHeap::kNotInHeap);
    stamp_.assign(n, 0);
    closed_.resize(n);
  }
  if (++search_id_ == 0) {  // stamp wrapped: invalidate everything once
    std::fill(stamp_.begin(), stamp_.end(), 0);
    search_id_ = 1;
  }
  const bool eight = options_.connectivity == Connectivity::k8;
  const auto* cells = grid.data().data();
  const std::int32_t start_i = static_cast<std::int32_t>(grid.index(start));
  const std::int32_t goal_i = static_cast<std::int32_t>(grid.index(goal));
  // Exact cost a + b sqrt 2 from integer counts (see the header).
  auto cost = [](std::int32_t a, std::int32_t b) {
    return static_cast<double>(a) + kSqrt2 * static_cast<double>(b);
  };
  // f = cost(g counts + heuristic counts): the heuristic is octile (hi - lo straight, lo diagonal
  // steps) or Manhattan for 4-connectivity.
  auto f_of = [&](int x, int y, std::int32_t s, std::int32_t d) {
    if (!use_heuristic_) return cost(s, d);
    const int dx = std::abs(x - goal.x), dy = std::abs(y - goal.y);
    if (!eight) return cost(s + dx + dy, d);
    const int lo = std::min(dx, dy), hi = std::max(dx, dy);
    return cost(s + hi - lo, d + lo);
  };

  open_.reset(&heap_pos_);
  stamp_[static_cast<std::size_t>(start_i)] = search_id_;
  gs_[static_cast<std::size_t>(start_i)] = 0;
  gd_[static_cast<std::size_t>(start_i)] = 0;
  parent_[static_cast<std::size_t>(start_i)] = -1;
  closed_[static_cast<std::size_t>(start_i)] = 0;
  open_.push_or_decrease(start_i, f_of(start.x, start.y, 0, 0), 0.0);

  // (s, d): the step counts of g at `from` plus this step (1, 0) or (0, 1).
  auto relax = [&](std::int32_t from, std::int32_t s, std::int32_t d, int nx, int ny) {
    const std::int32_t ni = ny * w + nx;
    const auto su = static_cast<std::size_t>(ni);
    const double ng = cost(s, d);
    if (stamp_[su] != search_id_) {
      stamp_[su] = search_id_;
      closed_[su] = 0;
    } else if (closed_[su] || ng >= cost(gs_[su], gd_[su])) {
      return;
    }
    gs_[su] = s;
    gd_[su] = d;
    parent_[su] = from;
    open_.push_or_decrease(ni, f_of(nx, ny, s, d), ng);
  };

  bool found = false;
  unsigned since_check = 0;
  while (!open_.empty()) {
    const std::int32_t cur = open_.pop();
    const auto cu = static_cast<std::size_t>(cur);
    closed_[cu] = 1;
    ++result.expanded;
    if (options_.record_expanded) result.expanded_cells.push_back(grid.cell_at(cu));
    if (cur == goal_i) {
      found = true;
      break;
    }
    if (++since_check == kCancelCheckInterval) {
      since_check = 0;
      if (should_stop(options_)) {
        open_.clear();
        return finish(PlanStatus::kCancelled);
      }
    }
    const int x = cur % w, y = cur / w;
    const std::int32_t s1 = gs_[cu] + 1, d0 = gd_[cu], s0 = gs_[cu], d1 = gd_[cu] + 1;
    const bool e = x + 1 < w && cells[cu + 1] == 0;
    const bool wst = x > 0 && cells[cu - 1] == 0;
    const bool nth = y + 1 < h && cells[cu + static_cast<std::size_t>(w)] == 0;
    const bool sth = y > 0 && cells[cu - static_cast<std::size_t>(w)] == 0;
    if (e) relax(cur, s1, d0, x + 1, y);
    if (nth) relax(cur, s1, d0, x, y + 1);
    if (wst) relax(cur, s1, d0, x - 1, y);
    if (sth) relax(cur, s1, d0, x, y - 1);
    if (eight) {
      const auto uw = static_cast<std::size_t>(w);
      if (e && nth && cells[cu + uw + 1] == 0) relax(cur, s0, d1, x + 1, y + 1);
      if (wst && nth && cells[cu + uw - 1] == 0) relax(cur, s0, d1, x - 1, y + 1);
      if (wst && sth && cells[cu - uw - 1] == 0) relax(cur, s0, d1, x - 1, y - 1);
      if (e && sth && cells[cu - uw + 1] == 0) relax(cur, s0, d1, x + 1, y - 1);
    }
  }
  // Leave heap positions clean for the next query.
  open_.clear();
  if (!found) return finish(PlanStatus::kUnreachable);

  for (std::int32_t i = goal_i; i != -1; i = parent_[static_cast<std::size_t>(i)])
    result.path.push_back(grid.cell_at(static_cast<std::size_t>(i)));
  std::reverse(result.path.begin(), result.path.end());
  result.length_cells =
      cost(gs_[static_cast<std::size_t>(goal_i)], gd_[static_cast<std::size_t>(goal_i)]);
  return finish(PlanStatus::kOk);
}

}  // namespace voronav::planning
