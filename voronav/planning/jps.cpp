// Online JPS and JPS+ (jps.hpp): one A* over jump points; the two differ only in how a jump is
// made (bit scans of the map, or table look-ups). Both prune intermediate jump points on
// diagonals (Harabor & Grastien 2014, section 5, "jps2"/"jps2+"): a diagonal jump does not stop
// at the first cell from which a straight jump finds a jump point; it walks on to the wall and
// generates those straight jump points directly, as successors of the node being expanded. A
// successor's incoming direction is read from the offset to its parent (diagonal when |dx| = |dy|,
// else along the longer axis, the direction of the last straight leg).
#include "voronav/planning/jps.hpp"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <numbers>

#include "voronav/core/error.hpp"
#include "voronav/planning/internal/jps_data.hpp"

namespace voronav::planning {
namespace {

using internal::JpsMapData;
using internal::JpsNode;
using internal::JpsOpenItem;
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

/// Online jumps (Harabor & Grastien 2011, algorithm 2, no-corner-cutting rules; straight jumps
/// block-based, 2014).
struct OnlineJumps {
  const JpsMapData& m;

  static void prefetch(std::int32_t /*cell*/) {}

  /// Straight jump from free (x, y) along (dx, dy) (one of them 0); stops at the goal too.
  [[nodiscard]] Jump straight(int x, int y, int dx, int dy, Cell goal) const {
    if (dy == 0) {
      const int c = scan_straight(m.rows, y, x, dx, goal.y == y ? goal.x : kNoJump);
      return c == kNoJump ? Jump{} : Jump{c, y, std::abs(c - x)};
    }
    const int c = scan_straight(m.cols, x, y, dy, goal.x == x ? goal.y : kNoJump);
    return c == kNoJump ? Jump{} : Jump{x, c, std::abs(c - y)};
  }

  /// Diagonal walk from (x, y) along (dx, dy) one cell at a time (no corner cutting: both side
  /// cells free) to the wall; at each cell the two straight jumps along dx and dy; emit(x, y,
  /// straight steps, diagonal steps) for each jump point found, and for the goal on the diagonal.
  template <class Emit>
  void diagonal(int x, int y, int dx, int dy, Cell goal, Emit&& emit) const {
    for (int k = 1;; ++k) {
      if (!m.free(x + dx, y + dy) || !m.free(x + dx, y) || !m.free(x, y + dy)) return;
      x += dx;
      y += dy;
      if (x == goal.x && y == goal.y) {
        emit(x, y, 0, k);
        return;
      }
      const int cx = scan_straight(m.rows, y, x, dx, goal.y == y ? goal.x : kNoJump);
      if (cx != kNoJump) emit(cx, y, std::abs(cx - x), k);
      const int cy = scan_straight(m.cols, x, y, dy, goal.x == x ? goal.y : kNoJump);
      if (cy != kNoJump) emit(x, cy, std::abs(cy - y), k);
    }
  }
};

/// JPS+ jumps by table look-up.
struct TableJumps {
  const JpsMapData& m;
  const std::int8_t* table;

  /// Loads the table entries of a cell about to be expanded.
  void prefetch(std::int32_t cell) const { __builtin_prefetch(table + 8 * cell); }

  [[nodiscard]] const std::int8_t* at(int x, int y) const {
    return table + 8 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(m.width) +
                        static_cast<std::size_t>(x));
  }

  /// Straight jump from (x, y) along (dx, dy) with table entry t, cut short at the goal when it
  /// lies on the way.
  [[nodiscard]] static Jump straight_from(int t, int x, int y, int dx, int dy, Cell goal) {
    int to_goal = 0;
    if (dy == 0) {
      if (goal.y == y) to_goal = (goal.x - x) * dx;
    } else if (goal.x == x) {
      to_goal = (goal.y - y) * dy;
    }
    if (to_goal > 0 && to_goal <= (t > 0 ? t : -t))
      return {x + dx * to_goal, y + dy * to_goal, to_goal};
    if (t > 0) return {x + dx * t, y + dy * t, t};
    return {};
  }

  /// The full entry of (x, y) in direction d = (dx, dy), following kFarJump entries.
  [[nodiscard]] int entry(int t, int x, int y, int d, int dx, int dy) const {
    if (t != internal::kFarJump) [[likely]]
      return t;
    int base = 0;
    do {
      base += internal::kFarSteps;
      t = at(x + dx * base, y + dy * base)[d];
    } while (t == internal::kFarJump);
    return t > 0 ? t + base : t - base;
  }

  [[nodiscard]] Jump straight(int x, int y, int dx, int dy, Cell goal) const {
    const int d = internal::dir_index(dx, dy);
    return straight_from(entry(at(x, y)[d], x, y, d, dx, dy), x, y, dx, dy, goal);
  }

  /// Diagonal walk by table hops: to the next cell with a straight jump point, or to the cell
  /// where the diagonal crosses the goal's row or column (a "target": the goal may be a straight
  /// jump from it), until the wall; emits like OnlineJumps::diagonal.
  template <class Emit>
  void diagonal(int x, int y, int dx, int dy, Cell goal, Emit&& emit) const {
    const int d = internal::dir_index(dx, dy);
    const int dh = internal::dir_index(dx, 0), dv = internal::dir_index(0, dy);
    const int gx = (goal.x - x) * dx, gy = (goal.y - y) * dy;
    const int target = gx > 0 && gy > 0 ? std::min(gx, gy) : 0;  // steps to the crossing
    for (int k = 0;;) {
      const int t = entry(at(x, y)[d], x, y, d, dx, dy);
      const int to_target = target - k;
      int step;
      if (to_target > 0 && to_target <= (t > 0 ? t : -t))
        step = to_target;
      else if (t > 0)
        step = t;
      else
        return;
      x += dx * step;
      y += dy * step;
      k += step;
      if (x == goal.x && y == goal.y) {
        emit(x, y, 0, k);
        return;
      }
      const std::int8_t* e = at(x, y);
      const Jump h = straight_from(entry(e[dh], x, y, dh, dx, 0), x, y, dx, 0, goal);
      if (h.steps != 0) emit(h.x, h.y, h.steps, k);
      const Jump v = straight_from(entry(e[dv], x, y, dv, 0, dy), x, y, 0, dy, goal);
      if (v.steps != 0) emit(v.x, v.y, v.steps, k);
    }
  }
};

/// The open list: a 4-ary min-heap (half the depth of a binary heap, children in one cache line)
/// ordered by (f, larger g first, node), compared as one 128-bit key without branches: f >= 0, so
/// its IEEE bits order like its value; g is a float only for the tie-break. Lazy: a node improved
/// while open is pushed again, the stale entry skipped when popped.
class OpenList {
 public:
  explicit OpenList(std::vector<JpsOpenItem>& items) : a_(items) { a_.clear(); }
  [[nodiscard]] bool empty() const { return a_.empty(); }
  /// The node that pops next (the open list must not be empty).
  [[nodiscard]] std::int32_t top() const {
    return static_cast<std::int32_t>(static_cast<std::uint32_t>(a_.front()));
  }
  static JpsOpenItem item(double f, float g, std::int32_t node) {
    const std::uint64_t g_desc = ~std::uint64_t{std::bit_cast<std::uint32_t>(g)} << 32;
    return (JpsOpenItem{std::bit_cast<std::uint64_t>(f)} << 64) | g_desc |
           static_cast<std::uint32_t>(node);
  }
  void push(const JpsOpenItem& it) {
    std::size_t i = a_.size();
    a_.push_back(it);
    JpsOpenItem* a = a_.data();
    while (i > 0) {
      const std::size_t p = (i - 1) / 4;
      if (!before(it, a[p])) break;
      a[i] = a[p];
      i = p;
    }
    a[i] = it;
  }
  std::int32_t pop() {
    JpsOpenItem* a = a_.data();
    const auto top = static_cast<std::int32_t>(static_cast<std::uint32_t>(a[0]));
    const JpsOpenItem last = a_.back();
    a_.pop_back();
    const std::size_t n = a_.size();
    if (n == 0) return top;
    std::size_t i = 0;
    while (true) {
      const std::size_t c0 = 4 * i + 1;
      if (c0 >= n) break;
      std::size_t c = c0;
      if (c0 + 3 < n) {  // all four children: branch-free minimum
        const std::size_t c01 = before(a[c0 + 1], a[c0]) ? c0 + 1 : c0;
        const std::size_t c23 = before(a[c0 + 3], a[c0 + 2]) ? c0 + 3 : c0 + 2;
        c = before(a[c23], a[c01]) ? c23 : c01;
      } else {
        for (std::size_t k = c0 + 1; k < n; ++k)
          if (before(a[k], a[c])) c = k;
      }
      if (!before(a[c], last)) break;
      a[i] = a[c];
      i = c;
    }
    a[i] = last;
    return top;
  }

 private:
  static bool before(JpsOpenItem a, JpsOpenItem b) { return a < b; }
  std::vector<JpsOpenItem>& a_;
};

/// A* over jump points; fills result.path, length_cells and expanded. Returns the status.
template <class Jumps>
PlanStatus search(const Jumps& jumps, const JpsMapData& m, internal::JpsSearchState& st,
                  const PlannerOptions& options, Cell start, Cell goal, PlanResult& result) {
  const int w = m.width;
  const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(m.height);
  if (st.nodes.size() < n) st.nodes.resize(n, JpsNode{0, -1, 0, 0});
  if (st.search_id >= 0xfffffff0U) {
    for (JpsNode& node : st.nodes)
      node.stamp = 0;
    st.search_id = 0;
  }
  st.search_id += 2;
  const std::uint32_t open_id = st.search_id, closed_id = st.search_id + 1;
  JpsNode* nodes = st.nodes.data();
  OpenList open(st.open);

  auto f_of = [&](int x, int y, std::int32_t s, std::int32_t d) {
    const int dx = std::abs(x - goal.x), dy = std::abs(y - goal.y);
    const int lo = std::min(dx, dy), hi = std::max(dx, dy);
    return cost(s + hi - lo, d + lo);
  };
  const std::int32_t start_i = start.y * w + start.x, goal_i = goal.y * w + goal.x;
  nodes[start_i] = {open_id, -1, 0, 0};
  open.push(OpenList::item(f_of(start.x, start.y, 0, 0), 0.0F, start_i));

  bool found = false;
  unsigned since_check = 0;
  int dirs[8][2];
  while (!open.empty()) {
    const std::int32_t cur = open.pop();
    JpsNode& cn = nodes[cur];
    if (cn.stamp != open_id) continue;  // a stale entry of a node since closed
    cn.stamp = closed_id;
    ++result.expanded;
    const int x = cur % w, y = cur / w;
    if (options.record_expanded) result.expanded_cells.push_back({x, y});
    if (cur == goal_i) {
      found = true;
      break;
    }
    if (++since_check == kCancelCheckInterval) {
      since_check = 0;
      if ((options.cancel && options.cancel()) ||
          (options.deadline && std::chrono::steady_clock::now() >= *options.deadline))
        return PlanStatus::kCancelled;
    }
    // Successor directions (pruning rules without corner cutting) from the incoming direction.
    int nd = 0;
    auto add = [&](int dx, int dy) {
      dirs[nd][0] = dx;
      dirs[nd][1] = dy;
      ++nd;
    };
    const std::int32_t p = cn.parent;
    if (p < 0) {
      for (int d = 0; d < 8; ++d)
        add(internal::kDirX[d], internal::kDirY[d]);
    } else {
      const int ox = x - p % w, oy = y - p / w;
      const int ax = std::abs(ox), ay = std::abs(oy);
      const int dx = ax >= ay ? sign(ox) : 0, dy = ay >= ax ? sign(oy) : 0;
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
    // Successors are gathered first, their node states prefetched, then relaxed: the misses on
    // the node array overlap instead of stalling one after another.
    auto& succ = st.successors;
    succ.clear();
    auto emit = [&](int nx, int ny, std::int32_t ds, std::int32_t dd) {
      const std::int32_t ni = ny * w + nx;
      __builtin_prefetch(&nodes[ni]);
      succ.push_back({ni, nx, ny, ds, dd});
    };
    for (int i = 0; i < nd; ++i) {
      const int dx = dirs[i][0], dy = dirs[i][1];
      if (dx != 0 && dy != 0) {
        jumps.diagonal(x, y, dx, dy, goal, emit);
      } else {
        const Jump j = jumps.straight(x, y, dx, dy, goal);
        if (j.steps != 0) emit(j.x, j.y, j.steps, 0);
      }
    }
    const std::int32_t s0 = cn.gs, d0 = cn.gd;
    for (const internal::JpsSuccessor& sc : succ) {
      JpsNode& nn = nodes[sc.node];
      const std::int32_t s = s0 + sc.ds, d = d0 + sc.dd;
      const double ng = cost(s, d);
      if (nn.stamp == closed_id || (nn.stamp == open_id && ng >= cost(nn.gs, nn.gd))) continue;
      nn = {open_id, cur, s, d};
      open.push(OpenList::item(f_of(sc.x, sc.y, s, d), static_cast<float>(ng), sc.node));
    }
    // The next node to expand is known now: start loading its state and jump entries.
    if (!open.empty()) {
      __builtin_prefetch(&nodes[open.top()]);
      jumps.prefetch(open.top());
    }
  }
  if (!found) return PlanStatus::kUnreachable;

  // Jump points from goal to start; each segment is diagonal, then straight: fill in its cells.
  const JpsNode& gn = nodes[goal_i];
  std::vector<std::int32_t>& chain = st.chain;
  chain.clear();
  for (std::int32_t i = goal_i; i != -1; i = nodes[i].parent)
    chain.push_back(i);
  result.path.reserve(static_cast<std::size_t>(gn.gs + gn.gd) + 1);
  Cell c{start.x, start.y};
  result.path.push_back(c);
  for (std::size_t k = chain.size() - 1; k-- > 0;) {
    const Cell to{chain[k] % w, chain[k] / w};
    const int ox = to.x - c.x, oy = to.y - c.y, sx = sign(ox), sy = sign(oy);
    const int diagonal = std::min(std::abs(ox), std::abs(oy));
    for (int i = 0; i < diagonal; ++i) {
      c.x += sx;
      c.y += sy;
      result.path.push_back(c);
    }
    const int ex = std::abs(ox) > diagonal ? sx : 0, ey = std::abs(oy) > diagonal ? sy : 0;
    for (int i = std::max(std::abs(ox), std::abs(oy)) - diagonal; i > 0; --i) {
      c.x += ex;
      c.y += ey;
      result.path.push_back(c);
    }
  }
  result.length_cells = cost(gn.gs, gn.gd);
  return PlanStatus::kOk;
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
  auto& st = *state_;
  if (!tables_)
    result.status = search(OnlineJumps{m}, m, st, options_, start, goal, result);
  else
    result.status = search(TableJumps{m, m.table.data()}, m, st, options_, start, goal, result);
  result.time_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

}  // namespace voronav::planning
