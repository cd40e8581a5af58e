#include "voronav/planning/ras.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <numbers>
#include <string>

#include "voronav/core/error.hpp"
#include "voronav/planning/astar.hpp"

namespace voronav::planning {
namespace {

// Directions in counter-clockwise order from east; index k is the angle 45 k degrees.
constexpr std::array<Cell, 8> kDirs = {Cell{1, 0},  Cell{1, 1},   Cell{0, 1},  Cell{-1, 1},
                                       Cell{-1, 0}, Cell{-1, -1}, Cell{0, -1}, Cell{1, -1}};
constexpr unsigned kCancelCheckInterval = 1024;

using Order = std::array<std::uint8_t, 8>;

// Neighbour order starting at direction k, then alternating sides (side +1 = counter-clockwise
// first), then the opposite direction. step = 1 for 8 neighbours, 2 for 4 neighbours.
Order make_order(int k, int side, int step) {
  Order o{};
  int n = 0;
  o[n++] = static_cast<std::uint8_t>(k);
  const int count = 8 / step;
  for (int i = 1; n < count - 1; ++i) {
    o[n++] = static_cast<std::uint8_t>((k + 8 + side * i * step) % 8);
    o[n++] = static_cast<std::uint8_t>((k + 8 - side * i * step) % 8);
  }
  o[n++] = static_cast<std::uint8_t>((k + 4) % 8);
  return o;
}

// Index into the optimal-order table for the goal offset (dx, dy) != (0, 0): 2 k + (cw first),
// k = the direction closest to the goal (on an exact tie between two, the one counter-clockwise
// of the goal), then the side nearer the goal first (counter-clockwise on a tie).
std::size_t goal_order_index(int dx, int dy, bool eight) {
  const double ax = std::abs(dx), ay = std::abs(dy);
  int k = 0;
  if (eight) {
    constexpr double kTan22 = 0.41421356237309503;  // tan(22.5 deg); never hit exactly by integers
    if (ay < ax * kTan22) {
      k = dx > 0 ? 0 : 4;
    } else if (ax < ay * kTan22) {
      k = dy > 0 ? 2 : 6;
    } else {
      k = dx > 0 ? (dy > 0 ? 1 : 7) : (dy > 0 ? 3 : 5);
    }
  } else if (ax > ay) {
    k = dx > 0 ? 0 : 4;
  } else if (ay > ax) {
    k = dy > 0 ? 2 : 6;
  } else {  // exactly diagonal: the straight direction counter-clockwise of the goal
    k = dx > 0 ? (dy > 0 ? 2 : 0) : (dy > 0 ? 4 : 6);
  }
  const Cell u = kDirs[static_cast<std::size_t>(k)];
  const int cross = u.x * dy - u.y * dx;  // > 0: the goal lies counter-clockwise of u
  return static_cast<std::size_t>(2 * k + (cross >= 0 ? 0 : 1));
}

bool should_stop(const CancelFn& cancel,
                 const std::optional<std::chrono::steady_clock::time_point>& deadline) {
  if (cancel && cancel()) return true;
  return deadline && std::chrono::steady_clock::now() >= *deadline;
}

// Appends the cells from a (excluded) to b (included): diagonal steps first, then straight ones
// (4-connected: x first, then y). The walk stays inside the bounding box of a and b.
void walk(std::vector<Cell>& out, Cell a, Cell b, bool eight) {
  Cell c = a;
  while (c != b) {
    const int sx = (b.x > c.x) - (b.x < c.x), sy = (b.y > c.y) - (b.y < c.y);
    if (eight && sx != 0 && sy != 0) {
      c = {c.x + sx, c.y + sy};
    } else if (sx != 0) {
      c.x += sx;
    } else {
      c.y += sy;
    }
    out.push_back(c);
  }
}

}  // namespace

void validate(const RasOptions& o) {
  if (o.region_size < 1 || o.region_size > kMaxRegionSize)
    throw Error("region_size", 0,
                "expected a region size in 1.." + std::to_string(kMaxRegionSize) + " cells, got " +
                    std::to_string(o.region_size));
  if (o.density < 0 || o.density > 8)
    throw Error("density", 0, "expected a density in [0, 8], got " + std::to_string(o.density));
  if (o.connectivity != Connectivity::k4 && o.connectivity != Connectivity::k8)
    throw Error("connectivity", 0, "expected 4 or 8 neighbours");
}

std::string_view to_string(RasStatus s) {
  switch (s) {
    case RasStatus::kOk:
      return "ok";
    case RasStatus::kOutOfMap:
      return "out_of_map";
    case RasStatus::kStartBlocked:
      return "start_blocked";
    case RasStatus::kGoalBlocked:
      return "goal_blocked";
    case RasStatus::kStartBelowDensity:
      return "start_below_density";
    case RasStatus::kGoalBelowDensity:
      return "goal_below_density";
    case RasStatus::kUnreachable:
      return "unreachable";
    case RasStatus::kCancelled:
      return "cancelled";
  }
  return "unknown";
}

PlanStatus to_plan_status(RasStatus s) {
  switch (s) {
    case RasStatus::kOk:
      return PlanStatus::kOk;
    case RasStatus::kOutOfMap:
      return PlanStatus::kOutOfMap;
    case RasStatus::kStartBlocked:
    case RasStatus::kStartBelowDensity:
      return PlanStatus::kStartOccupied;
    case RasStatus::kGoalBlocked:
      return PlanStatus::kGoalOccupied;
    case RasStatus::kGoalBelowDensity:
    case RasStatus::kUnreachable:
      return PlanStatus::kUnreachable;
    case RasStatus::kCancelled:
      return PlanStatus::kCancelled;
  }
  return PlanStatus::kUnreachable;
}

// ---------------------------------------------------------------------------------------------
// RasField

std::int32_t RasField::id_at(Cell region) const {
  if (region.x < 0 || region.y < 0 || region.x >= w_ || region.y >= h_) return kObstacle;
  return label_[padded(region)];
}

Cell RasField::region_of(std::int32_t k) const {
  if (k < 0 || k >= size()) throw Error("RasField::region_of", 0, "no region " + std::to_string(k));
  const auto p = static_cast<std::size_t>(cell_of_[static_cast<std::size_t>(k)]);  // k < n_
  const auto pw = static_cast<std::size_t>(w_ + 2);
  return {static_cast<int>(p % pw) - 1, static_cast<int>(p / pw) - 1};
}

std::int32_t RasField::count(std::int32_t k) const {
  if (k < 0 || k >= size()) throw Error("RasField::count", 0, "no region " + std::to_string(k));
  const auto K = static_cast<std::size_t>(k);
  if (K >= cum_.size()) return 0;
  return cum_[K] - (K == 0 ? 0 : cum_[K - 1]);
}

int RasField::density_at(Cell region) const {
  if (region.x < 0 || region.y < 0 || region.x >= w_ || region.y >= h_) return 0;
  const std::size_t p = padded(region);
  const auto pw = static_cast<std::ptrdiff_t>(w_ + 2);
  int d = 0;
  for (const Cell c : kDirs)
    d += label_[static_cast<std::size_t>(static_cast<std::ptrdiff_t>(p) + c.y * pw + c.x)] !=
         kObstacle;
  return d;
}

int RasField::step(std::int32_t k) const {
  if (k < 0 || k >= size()) throw Error("RasField::step", 0, "no region " + std::to_string(k));
  return static_cast<int>(std::upper_bound(step_first_.begin(), step_first_.end(), k) -
                          step_first_.begin()) -
         1;
}

RasRegion RasField::region(std::int32_t k, const RegionGrid& regions) const {
  RasRegion f;
  f.k = k;
  f.region = region_of(k);
  f.p = regions.center_world(f.region);
  f.N = count(k);
  f.d = density_at(f.region);
  const auto K = static_cast<std::size_t>(k);
  f.first_child = K < cum_.size() ? (K == 0 ? 0 : cum_[K - 1]) + 1 : size();
  f.step = step(k);
  return f;
}

std::int32_t RasField::parent(std::int32_t R) const {
  if (R < 0 || R >= size()) throw Error("RasField::parent", 0, "no region " + std::to_string(R));
  if (R == 0) return -1;
  // Table 1: the smallest K with R <= sum_{i<=K} N_i; cum_ is non-decreasing.
  const auto it = std::lower_bound(cum_.begin(), cum_.end(), R);
  return static_cast<std::int32_t>(it - cum_.begin());
}

std::vector<std::int32_t> RasField::path_to(std::int32_t k) const {
  std::vector<std::int32_t> ids;
  for (std::int32_t R = k; R >= 0; R = parent(R))
    ids.push_back(R);
  std::reverse(ids.begin(), ids.end());
  return ids;
}

// ---------------------------------------------------------------------------------------------
// RasSearch: eq. 6-7, the numbering wave.

RasStatus RasSearch::run(const RegionGrid& regions, Cell start_region,
                         std::optional<Cell> goal_region, const RasOptions& options,
                         const CancelFn& cancel,
                         std::optional<std::chrono::steady_clock::time_point> deadline) {
  validate(options);
  RasField& f = field_;
  const int w = regions.width(), h = regions.height();
  f.w_ = w;
  f.h_ = h;
  f.density_threshold_ = options.density;
  f.n_ = 0;
  f.cum_.clear();
  f.step_first_.clear();
  const auto pw = static_cast<std::size_t>(w + 2);
  f.label_.assign(pw * static_cast<std::size_t>(h + 2), RasField::kObstacle);
  const std::uint8_t* blocked = regions.blocked().data().data();
  std::size_t free_regions = 0;
  for (int y = 0; y < h; ++y) {
    std::int32_t* row = f.label_.data() + static_cast<std::size_t>(y + 1) * pw + 1;
    const std::uint8_t* src = blocked + static_cast<std::size_t>(y) * static_cast<std::size_t>(w);
    for (int x = 0; x < w; ++x) {
      row[x] = src[x] != 0 ? RasField::kObstacle : RasField::kUnnumbered;
      free_regions += src[x] == 0 ? 1 : 0;
    }
  }
  if (!regions.contains(start_region) || (goal_region && !regions.contains(*goal_region)))
    return RasStatus::kOutOfMap;
  if (regions.is_blocked(start_region)) return RasStatus::kStartBlocked;
  if (goal_region && regions.is_blocked(*goal_region)) return RasStatus::kGoalBlocked;
  const int D = options.density;
  if (D > 0 && options.start_density == RasStartDensity::kEnforced &&
      f.density_at(start_region) < D)
    return RasStatus::kStartBelowDensity;
  if (goal_region && D > 0 && *goal_region != start_region && f.density_at(*goal_region) < D)
    return RasStatus::kGoalBelowDensity;

  std::int32_t* label = f.label_.data();
  const auto ipw = static_cast<std::ptrdiff_t>(pw);
  std::array<std::ptrdiff_t, 8> off{};
  for (std::size_t k = 0; k < 8; ++k)
    off[k] = kDirs[k].y * ipw + kDirs[k].x;
  const bool eight = options.connectivity == Connectivity::k8;
  const int dir_step = eight ? 1 : 2;
  const int ndirs = eight ? 8 : 4;
  const bool no_cut = options.corner_rule == RasCornerRule::kNoCornerCutting;
  const bool per_region =
      options.direction == RasDirection::kOptimalPerRegion && goal_region.has_value();
  // Default: counter-clockwise from east (E, NE, N, ... or E, N, W, S).
  Order default_order{};
  for (int i = 0; i < 8 / dir_step; ++i)
    default_order[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(i * dir_step);
  // Optimal orders: nearest direction k and side s (+1 ccw first) -> order table [2 k + (s < 0)].
  std::array<Order, 16> goal_orders{};
  for (int k = 0; k < 8; ++k) {
    goal_orders[static_cast<std::size_t>(2 * k)] = make_order(k, 1, dir_step);
    goal_orders[static_cast<std::size_t>(2 * k + 1)] = make_order(k, -1, dir_step);
  }
  const bool until_goal = options.extent == RasExtent::kUntilGoal && goal_region.has_value();
  // The order of kDefault and kOptimal (chosen here, once, from the start->goal direction).
  // Per position i of the order: the neighbour's offset, and for a diagonal the offsets of its
  // two flanking straight neighbours (0 for a straight step: no corner test).
  std::array<std::ptrdiff_t, 8> step_off{}, flank_a{}, flank_b{};
  {
    const Order* o = &default_order;
    if (options.direction == RasDirection::kOptimal && goal_region && *goal_region != start_region)
      o = &goal_orders[goal_order_index(goal_region->x - start_region.x,
                                        goal_region->y - start_region.y, eight)];
    for (std::size_t i = 0; i < 8; ++i) {
      const int k = (*o)[i];
      step_off[i] = off[static_cast<std::size_t>(k)];
      const bool corner = no_cut && (k & 1) != 0;
      flank_a[i] = corner ? off[static_cast<std::size_t>(k - 1)] : 0;
      flank_b[i] = corner ? off[static_cast<std::size_t>((k + 1) & 7)] : 0;
    }
  }
  const std::ptrdiff_t goal_p =
      goal_region ? static_cast<std::ptrdiff_t>(f.padded(*goal_region)) : -1;
  const int gx = goal_region ? goal_region->x + 1 : 0, gy = goal_region ? goal_region->y + 1 : 0;

  auto density = [&](std::ptrdiff_t q) {
    int d = 0;
    for (std::size_t k = 0; k < 8; ++k)
      d += label[q + off[k]] != RasField::kObstacle;
    return d;
  };

  std::int32_t* queue = nullptr;
  std::int32_t next = 1;
  // Table 1's count rule for an unnumbered free neighbour q: a region below the density
  // threshold is marked and skipped, any other gets the next number. True when q is the goal.
  auto number = [&](std::ptrdiff_t q) {
    if (D > 0 && density(q) < D) {
      label[q] = RasField::kBelowDensity;
      return false;
    }
    label[q] = next;
    queue[next++] = static_cast<std::int32_t>(q);
    return until_goal && q == goal_p;
  };

  const auto start_p = static_cast<std::int32_t>(f.padded(start_region));
  label[start_p] = 0;
  f.step_first_.push_back(0);
  // The queue: ids in numbering order, at most one per free region (grown, never shrunk, so
  // a warmed-up search allocates and clears nothing here).
  if (f.cell_of_.size() < free_regions + 1) f.cell_of_.resize(free_regions + 1);
  f.cell_of_[0] = start_p;
  f.n_ = 1;
  if (until_goal && start_p == goal_p) {
    f.cum_.push_back(0);
    return RasStatus::kOk;
  }
  queue = f.cell_of_.data();
  queue[0] = start_p;
  std::int32_t step_end = 0;  // last id of the step being expanded
  unsigned since_check = 0;
  RasStatus status = until_goal ? RasStatus::kUnreachable : RasStatus::kOk;
  for (std::int32_t K = 0; K < next; ++K) {
    if (K > step_end) {  // the previous step is done: K opens the next one
      step_end = next - 1;
      f.step_first_.push_back(K);
    }
    if (++since_check == kCancelCheckInterval) {
      since_check = 0;
      if (should_stop(cancel, deadline)) {
        status = RasStatus::kCancelled;
        break;
      }
    }
    const std::ptrdiff_t p = queue[static_cast<std::size_t>(K)];
    bool found = false;
    if (!per_region) {
      // One order for the whole search (default, or toward the goal from the start). Branches
      // per neighbour follow the regular pattern of the wave front and predict well (as in a
      // plain BFS).
      for (int i = 0; i < ndirs; ++i) {
        const auto ui = static_cast<std::size_t>(i);
        const std::ptrdiff_t q = p + step_off[ui];
        if (label[q] != RasField::kUnnumbered) continue;
        if (flank_a[ui] != 0 && (label[p + flank_a[ui]] == RasField::kObstacle ||
                                 label[p + flank_b[ui]] == RasField::kObstacle))
          continue;
        if (number(q)) {
          found = true;
          break;
        }
      }
    } else {
      // Order per region: it changes from region to region, so per-neighbour branches would not
      // predict. Neighbour states become bit masks over the directions (bit k = direction k)
      // from one load each, the mask is permuted into this region's order, and only its set bits
      // are visited.
      unsigned unnumbered = 0, obstacle = 0;
      for (int k = 0; k < 8; k += dir_step) {
        const std::int32_t v = label[p + off[static_cast<std::size_t>(k)]];
        unnumbered |= static_cast<unsigned>(v == RasField::kUnnumbered) << k;
        obstacle |= static_cast<unsigned>(v == RasField::kObstacle) << k;
      }
      if (no_cut && eight) {  // a diagonal needs both flanking straight neighbours free
        const unsigned flank =
            (obstacle << 1) | (obstacle >> 7) | (obstacle >> 1) | (obstacle << 7);
        unnumbered &= ~(flank & 0xAAU);
      }
      const Order* order = &default_order;
      const auto px = static_cast<int>(p % ipw), py = static_cast<int>(p / ipw);
      const int dx = gx - px, dy = gy - py;
      if (dx != 0 || dy != 0) order = &goal_orders[goal_order_index(dx, dy, eight)];
      unsigned mask = 0;  // bit i = the i-th direction of the order can be numbered
      for (int i = 0; i < ndirs; ++i)
        mask |= ((unnumbered >> (*order)[static_cast<std::size_t>(i)]) & 1U) << i;
      while (mask != 0) {
        const int i = std::countr_zero(mask);
        mask &= mask - 1;
        const std::ptrdiff_t q = p + off[(*order)[static_cast<std::size_t>(i)]];
        if (number(q)) {
          found = true;
          break;
        }
      }
    }
    f.cum_.push_back(next - 1);
    if (found) {
      status = RasStatus::kOk;
      break;
    }
  }
  f.n_ = next;
  if (next - 1 > step_end) f.step_first_.push_back(step_end + 1);
  return status;
}

// ---------------------------------------------------------------------------------------------
// RasPlanner

RasPlanner::RasPlanner(RasOptions ras, PlannerOptions options)
    : GridPlanner(std::move(options)), ras_(ras) {
  ras_.connectivity = options_.connectivity;
  validate(ras_);
}

RasResult RasPlanner::plan_regions(const RegionGrid& regions, Cell start, Cell goal) {
  const auto t0 = std::chrono::steady_clock::now();
  RasResult res;
  auto finish = [&](RasStatus s) {
    res.status = s;
    res.regions = search_.field().size();
    res.time_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return res;
  };
  const GridGeometry& cg = regions.cell_geometry();
  if (!cg.contains(start) || !cg.contains(goal)) return finish(RasStatus::kOutOfMap);
  const Cell sr = regions.region_of(start), gr = regions.region_of(goal);
  const RasStatus s = search_.run(regions, sr, gr, ras_, options_.cancel, options_.deadline);
  if (s != RasStatus::kOk) return finish(s);
  const RasField& f = search_.field();
  res.path_ids = f.path_to(f.id_at(gr));
  res.path_regions.reserve(res.path_ids.size());
  res.waypoints.reserve(res.path_ids.size() + 2);
  res.waypoints.push_back(cg.cell_center(start));
  for (const std::int32_t k : res.path_ids) {
    res.path_regions.push_back(f.region_of(k));
    res.waypoints.push_back(regions.center_world(res.path_regions.back()));
  }
  res.waypoints.push_back(cg.cell_center(goal));
  const bool eight = ras_.connectivity == Connectivity::k8;
  res.path_cells.push_back(start);
  for (const Cell r : res.path_regions)
    walk(res.path_cells, res.path_cells.back(), regions.center_cell(r), eight);
  walk(res.path_cells, res.path_cells.back(), goal, eight);
  return finish(RasStatus::kOk);
}

RasResult RasPlanner::plan_ras(const BinaryGrid& grid, Cell start, Cell goal) {
  const auto t0 = std::chrono::steady_clock::now();
  if (grid.contains(start) && grid[start] != 0) {
    RasResult r;
    r.status = RasStatus::kStartBlocked;
    return r;
  }
  if (grid.contains(goal) && grid[goal] != 0) {
    RasResult r;
    r.status = RasStatus::kGoalBlocked;
    return r;
  }
  regions_ = RegionGrid(grid, {ras_.region_size, ras_.region_rule});
  RasResult r = plan_regions(regions_, start, goal);
  r.time_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

PlanResult RasPlanner::plan(const BinaryGrid& grid, Cell start, Cell goal) {
  last_ = plan_ras(grid, start, goal);
  const RasResult& r = last_;
  PlanResult out;
  out.status = to_plan_status(r.status);
  out.expanded = static_cast<std::size_t>(std::max(0, r.regions));
  out.time_ms = r.time_ms;
  if (r.ok()) {
    out.path = r.path_cells;
    out.length_cells = path_length_cells(out.path);
  }
  return out;
}

RasRobotParameters ras_parameters_for_robot(double robot_size_m, double resolution_m, int density) {
  if (!(robot_size_m > 0.0) || !std::isfinite(robot_size_m))
    throw Error("robot_size", 0,
                "expected a positive robot size [m], got " + std::to_string(robot_size_m));
  if (!(resolution_m > 0.0) || !std::isfinite(resolution_m))
    throw Error("resolution", 0,
                "expected a positive resolution [m/cell], got " + std::to_string(resolution_m));
  if (density != 0 && density != 8)
    throw Error("density", 0, "expected density 0 or 8, got " + std::to_string(density));
  const double half = robot_size_m / (2.0 * resolution_m) + 0.5;
  if (half > 1e6) throw Error("robot_size", 0, "robot size too large for this resolution");
  const int r = static_cast<int>(std::ceil(half));
  return {density == 8 ? r : 2 * r, density};
}

}  // namespace voronav::planning
