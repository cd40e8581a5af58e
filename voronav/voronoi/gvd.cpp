#include "voronav/voronoi/gvd.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <tuple>
#include <unordered_map>

#include "voronav/core/error.hpp"
#include "voronav/voronoi/internal/skeleton.hpp"

namespace voronav::voronoi {
namespace {

// Blocked is 0: the state array starts zeroed (CellVector), all blocked, and only the box of the
// non-blocked cells is written.
constexpr std::uint8_t kBlockedCell = 0;
constexpr std::uint8_t kFreeCell = 1;
constexpr std::uint8_t kOutside = 2;
constexpr std::int64_t kNone = -1;

void check_options(const GvdOptions& o) {
  if (!(o.site_separation >= 0.0) || !std::isfinite(o.site_separation))
    throw Error("GvdOptions.site_separation", 0,
                "expected >= 0 [cells], got " + std::to_string(o.site_separation));
  if (!(o.site_separation_ratio >= 0.0) || !std::isfinite(o.site_separation_ratio))
    throw Error("GvdOptions.site_separation_ratio", 0,
                "expected >= 0, got " + std::to_string(o.site_separation_ratio));
  if (!(o.spur_min_length >= 0.0) || !std::isfinite(o.spur_min_length))
    throw Error("GvdOptions.spur_min_length", 0,
                "expected >= 0 [m], got " + std::to_string(o.spur_min_length));
  if (!(o.spur_clearance_ratio >= 0.0) || !std::isfinite(o.spur_clearance_ratio))
    throw Error("GvdOptions.spur_clearance_ratio", 0,
                "expected >= 0, got " + std::to_string(o.spur_clearance_ratio));
  if (o.prune_rounds < 0)
    throw Error("GvdOptions.prune_rounds", 0,
                "expected >= 0, got " + std::to_string(o.prune_rounds));
}

// Lower envelope of parabolas (Felzenszwalb & Huttenlocher 2012, Algorithm 1) over integer
// inputs; f[q] < 0 means "no site in this column". Writes the squared distance (or kNone) and
// the argmin column for the outputs [lo, hi] (default all n). Columns whose value at the nearest
// output, f[q] + dist(q, [lo, hi])^2, exceeds `limit` are left out: the caller knows that every
// output's minimum is at most `limit`, so they are never the argmin (not even in a tie).
class Envelope {
 public:
  void run(const std::int64_t* f, int n, std::int64_t* d, std::int32_t* arg) {
    run(f, n, d, arg, 0, n - 1, std::numeric_limits<std::int64_t>::max());
  }
  void run(const std::int64_t* f, int n, std::int64_t* d, std::int32_t* arg, int lo, int hi,
           std::int64_t limit) {
    v_.resize(static_cast<std::size_t>(n));
    z_.resize(static_cast<std::size_t>(n) + 1);
    int k = -1;
    for (int q = 0; q < n; ++q) {
      if (f[q] < 0) continue;
      const std::int64_t dq = q < lo ? lo - q : (q > hi ? q - hi : 0);
      if (f[q] > limit - dq * dq) continue;
      if (k < 0) {
        k = 0;
        v_[0] = q;
        z_[0] = -HUGE_VAL;
        z_[1] = HUGE_VAL;
        continue;
      }
      double s = 0.0;
      while (true) {
        const int p = v_[static_cast<std::size_t>(k)];
        s = (static_cast<double>(f[q] + std::int64_t{q} * q) -
             static_cast<double>(f[p] + std::int64_t{p} * p)) /
            (2.0 * (q - p));
        if (s <= z_[static_cast<std::size_t>(k)] && k > 0) {
          --k;
          continue;
        }
        break;
      }
      if (s <= z_[static_cast<std::size_t>(k)]) {  // k == 0 and q dominates everything
        v_[0] = q;
        z_[0] = -HUGE_VAL;
        z_[1] = HUGE_VAL;
        continue;
      }
      ++k;
      v_[static_cast<std::size_t>(k)] = q;
      z_[static_cast<std::size_t>(k)] = s;
      z_[static_cast<std::size_t>(k) + 1] = HUGE_VAL;
    }
    if (k < 0) {
      std::fill(d + lo, d + hi + 1, kNone);
      std::fill(arg + lo, arg + hi + 1, -1);
      return;
    }
    int j = 0;
    for (int q = lo; q <= hi; ++q) {
      while (z_[static_cast<std::size_t>(j) + 1] < q)
        ++j;
      const int p = v_[static_cast<std::size_t>(j)];
      d[q] = std::int64_t{q - p} * (q - p) + f[p];
      arg[q] = p;
    }
  }

 private:
  std::vector<int> v_;
  std::vector<double> z_;
};

}  // namespace

std::vector<Cell> GeneralizedVoronoi::cells() const {
  std::vector<Cell> out;
  for (std::size_t i = 0; i < diagram.size(); ++i)
    if (diagram[i]) out.push_back(diagram.cell_at(i));
  return out;
}

DynamicGvd::DynamicGvd(const BinaryGrid& blocked, const GvdOptions& options)
    : options_(options), geometry_(blocked.geometry()) {
  check_options(options);
  pw_ = geometry_.width + 2;
  ph_ = geometry_.height + 2;
  inv_pw_ = 1.0 / static_cast<double>(pw_);
  const std::size_t n = static_cast<std::size_t>(pw_) * static_cast<std::size_t>(ph_);
  // Every per-cell array starts zeroed without a write (CellVector): 0 is a blocked cell that is
  // its own site at distance 0 (col_arg_ and site_ are stored relative to the cell), not in the
  // raw diagram, of obstacle label 0 (the obstacles around the box, see full_labels). So the
  // build writes, and the system maps, only the pages of the box below.
  state_ = internal::CellVector<std::uint8_t>(n);
  col_d_ = internal::CellVector<std::int64_t>(n);
  col_arg_ = internal::CellVector<std::int32_t>(n);
  d2_ = internal::CellVector<std::int64_t>(n);
  site_ = internal::CellVector<std::int32_t>(n);
  label_ = internal::CellVector<std::int32_t>(n);
  raw_ = internal::CellVector<std::uint8_t>(n);
  // Sparse build: every cell outside the bounding box of the non-blocked cells is an obstacle
  // whose own distance is 0, and the obstacles just outside the box shield it from the rest, so
  // the EDT, the labels and the raw diagram are computed inside the box (plus its one-cell frame)
  // only; on a map that is mostly unknown (= blocked) the cost follows the known free area.
  // (The box never touches the padding ring when the border is blocked; otherwise the ring is
  // outside-not-obstacle and the box is the whole raster.)
  int bx0 = pw_, by0 = ph_, bx1 = -1, by1 = -1;
  const auto src = blocked.data();
  if (!options.border_is_blocked) {
    bx0 = 0, by0 = 0, bx1 = pw_ - 1, by1 = ph_ - 1;
    for (int x = 0; x < pw_; ++x)
      state_[pidx(x, 0)] = kOutside, state_[pidx(x, ph_ - 1)] = kOutside;
    for (int y = 0; y < ph_; ++y)
      state_[pidx(0, y)] = kOutside, state_[pidx(pw_ - 1, y)] = kOutside;
  } else {
    for (int y = 0; y < geometry_.height; ++y) {
      const std::uint8_t* in =
          &src[static_cast<std::size_t>(y) * static_cast<std::size_t>(geometry_.width)];
      int first = -1, lastx = -1;
      for (int x = 0; x < geometry_.width; ++x)
        if (!in[x]) {
          if (first < 0) first = x;
          lastx = x;
        }
      if (first < 0) continue;
      bx0 = std::min(bx0, first + 1), bx1 = std::max(bx1, lastx + 1);
      by0 = std::min(by0, y + 1), by1 = y + 1;
    }
  }
  if (bx1 >= 0) {
    const int x0 = std::max(bx0, 1), x1 = std::min(bx1, pw_ - 2);
    for (int y = std::max(by0, 1); y <= std::min(by1, ph_ - 2); ++y) {
      const std::uint8_t* in =
          &src[static_cast<std::size_t>(y - 1) * static_cast<std::size_t>(geometry_.width) +
               static_cast<std::size_t>(x0 - 1)];
      std::uint8_t* out = &state_[pidx(x0, y)];
      for (int x = 0; x <= x1 - x0; ++x)
        out[x] = in[x] ? kBlockedCell : kFreeCell;
    }
  }
  max_d2_ = 0;
  if (bx1 >= 0) {
    for (int x = bx0; x <= bx1; ++x)
      column_pass(x, nullptr, by0 == 0 && by1 == ph_ - 1 ? std::pair{-1, -1} : std::pair{by0, by1});
    for (int y = by0; y <= by1; ++y)
      row_pass(y, std::max(0, bx0 - 1), std::min(pw_ - 1, bx1 + 1));
    for (int y = by0; y <= by1; ++y)
      for (int x = bx0; x <= bx1; ++x)
        max_d2_ = std::max(max_d2_, d2_[pidx(x, y)]);
  }
  full_labels(bx0, by0, bx1, by1);
  if (bx1 >= 0)
    for (int y = by0; y <= by1; ++y)
      for (int x = bx0; x <= bx1; ++x) {
        const std::size_t i = pidx(x, y);
        raw_[i] = raw_mark(i) ? 1 : 0;
      }
  // The raw diagram lies in the box: the skeleton builds scan only its index range.
  build_skeleton(bx1 >= 0 ? std::pair{pidx(bx0, by0), pidx(bx1, by1) + 1}
                          : std::pair<std::size_t, std::size_t>{0, 0});
}

void DynamicGvd::grow_span(std::unordered_map<int, std::pair<int, int>>& spans,
                           std::size_t i) const {
  const int x = static_cast<int>(i % static_cast<std::size_t>(pw_));
  const int y = static_cast<int>(i / static_cast<std::size_t>(pw_));
  auto [it, fresh] = spans.try_emplace(x, y, y);
  if (!fresh) {
    it->second.first = std::min(it->second.first, y);
    it->second.second = std::max(it->second.second, y);
  }
}

void DynamicGvd::column_pass(int x, std::vector<ChangedRow>* changed_rows,
                             std::pair<int, int> span) {
  // 1-D nearest site along the column: forward then backward scan (ties: the lower row). Only
  // the rows between the nearest obstacles outside the changed span can change: those obstacles
  // shield the rest of the column.
  int y0 = 0, y1 = ph_ - 1;
  if (span.first >= 0) {
    y0 = span.first;
    while (y0 > 0 && state_[pidx(x, y0 - 1)] != kBlockedCell)
      --y0;
    y0 = std::max(0, y0 - 1);
    y1 = span.second;
    while (y1 < ph_ - 1 && state_[pidx(x, y1 + 1)] != kBlockedCell)
      ++y1;
    y1 = std::min(ph_ - 1, y1 + 1);
  }
  std::int32_t last = -1;
  static thread_local std::vector<std::int32_t> below;
  below.resize(static_cast<std::size_t>(ph_));
  for (int y = y0; y <= y1; ++y) {
    if (state_[pidx(x, y)] == kBlockedCell) last = y;
    below[static_cast<std::size_t>(y)] = last;
  }
  std::int32_t above = -1;
  for (int y = y1; y >= y0; --y) {
    if (state_[pidx(x, y)] == kBlockedCell) above = y;
    const std::int32_t b = below[static_cast<std::size_t>(y)];
    std::int32_t best = -1;
    if (b >= 0 && (above < 0 || y - b <= above - y))
      best = b;
    else if (above >= 0)
      best = above;
    const std::int64_t d = best < 0 ? kNone : std::int64_t{y - best} * (y - best);
    const std::size_t i = pidx(x, y);
    const std::int32_t old_arg = col_arg_of(i, y);
    if (changed_rows && (col_d_[i] != d || old_arg != best)) {
      // Lowered: the new (distance, row) is lexicographically smaller and exists.
      const bool lowered =
          d >= 0 && (col_d_[i] < 0 || d < col_d_[i] || (d == col_d_[i] && best < old_arg));
      changed_rows->push_back(
          {y, !lowered, old_arg < 0 ? -1 : static_cast<std::int32_t>(pidx(x, old_arg))});
    }
    col_d_[i] = d;
    set_col_arg(i, y, best);
  }
}

void DynamicGvd::row_pass(int y, int x0, int x1) {
  // Columns [x0, x1] only: the cells outside are obstacles (distance 0) that hide everything
  // beyond them from the cells inside, so the envelope over the window is exact there.
  static thread_local Envelope env;
  static thread_local std::vector<std::int64_t> d;
  static thread_local std::vector<std::int32_t> arg;
  const int n = x1 - x0 + 1;
  d.resize(static_cast<std::size_t>(n));
  arg.resize(static_cast<std::size_t>(n));
  env.run(&col_d_[pidx(x0, y)], n, d.data(), arg.data());
  for (int x = x0; x <= x1; ++x) {
    const std::size_t i = pidx(x, y);
    const auto k = static_cast<std::size_t>(x - x0);
    const std::int32_t ax = arg[k] < 0 ? -1 : arg[k] + x0;
    d2_[i] = d[k];
    set_site(i, ax < 0 ? -1 : static_cast<std::int32_t>(pidx(ax, col_arg_of(pidx(ax, y), y))));
  }
}

void DynamicGvd::row_segment(int y, int xa, int xb, std::vector<std::size_t>* changed) {
  static thread_local Envelope env;
  static thread_local std::vector<std::int64_t> d;
  static thread_local std::vector<std::int32_t> arg;
  // The new distance of a cell of [xa, xb] is at most the distance of an unchanged neighbour
  // outside the segment plus the way to it (1-Lipschitz), so its nearest column is within W.
  auto dist = [&](int u) {
    if (u < 0 || u >= pw_) return HUGE_VAL;
    const std::int64_t v = d2_[pidx(u, y)];
    return v < 0 ? HUGE_VAL : std::sqrt(static_cast<double>(v));
  };
  // D(x) <= min(a + (x - xa + 1), b + (xb + 1 - x)) =: B(x) for the cells x of the segment, so
  // the nearest column of x lies in [x - B(x), x + B(x)] and no minimum exceeds max B^2.
  const double a = dist(xa - 1), b = dist(xb + 1);
  const double len = static_cast<double>(xb - xa);
  int c0 = 0, c1 = pw_ - 1;
  std::int64_t limit = std::numeric_limits<std::int64_t>::max();
  if (a < HUGE_VAL || b < HUGE_VAL) {
    const double reach_l = std::min(a + 1.0, b + len + 1.0);
    const double reach_r = std::min(b + 1.0, a + len + 1.0);
    double bmax = std::min(a, b) + len + 1.0;
    if (a < HUGE_VAL && b < HUGE_VAL) bmax = std::min(bmax, 0.5 * (a + b + len + 2.0));
    c0 = std::max(0, xa - static_cast<int>(std::ceil(reach_l)) - 1);
    c1 = std::min(pw_ - 1, xb + static_cast<int>(std::ceil(reach_r)) + 1);
    limit = static_cast<std::int64_t>(std::ceil((bmax + 0.01) * (bmax + 0.01)));
  }
  const int n = c1 - c0 + 1;
  d.resize(static_cast<std::size_t>(n));
  arg.resize(static_cast<std::size_t>(n));
  env.run(&col_d_[pidx(c0, y)], n, d.data(), arg.data(), xa - c0, xb - c0, limit);
  for (int x = xa; x <= xb; ++x) {
    const std::size_t i = pidx(x, y);
    const auto k = static_cast<std::size_t>(x - c0);
    const std::int32_t ax = arg[k] < 0 ? -1 : arg[k] + c0;
    const std::int32_t s =
        ax < 0 ? -1 : static_cast<std::int32_t>(pidx(ax, col_arg_of(pidx(ax, y), y)));
    if (d2_[i] == d[k] && site_of(i) == s) continue;
    changed->push_back(i);
    if (d2_[i] != d[k]) d2_changed_[i] = 1, old_d2_[i] = d2_[i];
    d2_[i] = d[k];
    set_site(i, s);
  }
}

void DynamicGvd::row_lower(int y, int xa, int xb, const std::vector<int>& cols,
                           std::vector<std::size_t>* changed) {
  // Only lowered columns changed in this row: their old sites still exist, so the new nearest
  // site of a cell is the lexicographic minimum of its old one and the changed columns' sites.
  std::vector<LowerCol>& cs = lower_cols_;
  cs.clear();
  for (const int xc : cols) {
    const std::size_t ci = pidx(xc, y);
    if (col_d_[ci] < 0) continue;
    const std::int32_t sy = col_arg_of(ci, y);
    cs.push_back({col_d_[ci], xc, sy, static_cast<std::int32_t>(pidx(xc, sy))});
  }
  for (int x = xa; x <= xb; ++x) {
    const std::size_t i = pidx(x, y);
    std::int64_t bd = d2_[i];
    const std::int32_t old_site = site_of(i);
    std::int32_t bs = old_site;
    for (const LowerCol& c : cs) {
      const std::int64_t dd = std::int64_t{x - c.x} * (x - c.x) + c.d;
      bool better = bd < 0 || dd < bd;
      if (!better && dd == bd && c.s != bs) {  // ties: the lower column, then the lower row
        const auto [bx, by] = xy(static_cast<std::size_t>(bs));
        better = c.x != bx ? c.x < bx : c.sy < by;
      }
      if (better) bd = dd, bs = c.s;
    }
    if (bd == d2_[i] && bs == old_site) continue;
    changed->push_back(i);
    if (bd != d2_[i]) d2_changed_[i] = 1, old_d2_[i] = d2_[i];
    d2_[i] = bd;
    set_site(i, bs);
  }
}

void DynamicGvd::lowered_ranges(int y, int c0, int c1,
                                std::vector<std::pair<int, int>>* ranges) const {
  // Cell x of row y can change only when the new site s = (c, sy) of a run column c beats its
  // old distance: f_c(x) = |p_x - s|^2 - d^2(x) <= 0. With t the old site of x (|p_x - t|^2 =
  // d^2(x)), g(x') = |p_x' - s|^2 - |p_x' - t|^2 is linear along the row, g(x) = f_c(x), slope
  // 2 (t_x - c); and d^2(x') <= |p_x' - t|^2 (t was an obstacle), so f_c(x') >= g(x'). Where
  // f_c(x) > 0 the cells up to where g reaches 0 are skipped (all of them when g grows away
  // from the run), and where x cannot see c (|x - c|^2 > d^2(x)) no cell beyond can (the
  // distance is 1-Lipschitz). The cells kept are appended as ranges.
  std::pair<int, std::int64_t> sites[kMaxHalfPlaneRun];  // (column, squared height of its site)
  int ns = 0;
  for (int c = c0; c <= c1; ++c) {
    const std::size_t ci = pidx(c, y);
    if (col_d_[ci] >= 0) sites[ns++] = {c, col_d_[ci]};
  }
  const std::int64_t* drow = &d2_[pidx(0, y)];
  const std::size_t row0 = pidx(0, y);
  constexpr int kAll = std::numeric_limits<int>::max();
  // Cells from x on (dir = +1 right, -1 left) that no run column can change: 0 when x may
  // change, kAll when no cell from x on can.
  auto safe = [&](int x, int dir) {
    const std::int64_t v = drow[x];
    if (v < 0) return 0;
    const int tx = xy(static_cast<std::size_t>(site_of(row0 + static_cast<std::size_t>(x)))).first;
    int skip = kAll;
    for (int k = 0; k < ns; ++k) {
      const auto [c, h2] = sites[k];
      const std::int64_t dx2 = std::int64_t{x - c} * (x - c);
      if (dx2 > v) continue;  // x cannot see c, nor can the cells beyond
      const std::int64_t f = dx2 + h2 - v;
      if (f <= 0) return 0;
      const std::int64_t rate = 2 * std::int64_t{dir > 0 ? c - tx : tx - c};  // fall of g per cell
      if (rate <= 0) continue;
      skip = static_cast<int>(std::min<std::int64_t>(skip, (f + rate - 1) / rate));
    }
    return skip;
  };
  for (int dir = -1; dir <= 1; dir += 2) {
    const int from = dir > 0 ? c1 : c0;
    int a = from, b = from;  // the piece being grown (from the run's end outwards)
    if (dir > 0) a = c0;
    int x = from + dir;
    while (x >= 0 && x < pw_) {
      const std::int64_t v = drow[x];
      if (v >= 0 && std::int64_t{x - from} * (x - from) > v) break;
      const int k = safe(x, dir);
      if (k == kAll) break;
      if (k > 0) {
        x += dir * k;
        continue;
      }
      if (x != b + dir) {
        ranges->emplace_back(std::min(a, b), std::max(a, b));
        a = x;
      }
      b = x;
      x += dir;
    }
    ranges->emplace_back(std::min(a, b), std::max(a, b));
  }
}

int DynamicGvd::relabel_from(std::size_t seed, std::int32_t id, std::vector<std::size_t>* cells) {
  std::vector<std::int32_t> seen;
  auto note = [&](std::int32_t old) {
    if (old >= 0 && std::find(seen.begin(), seen.end(), old) == seen.end()) seen.push_back(old);
  };
  std::vector<std::size_t> stack{seed};
  note(label_[seed]);
  label_[seed] = id;
  if (cells) cells->push_back(seed);
  const internal::PaddedRaster r{pw_, ph_};
  while (!stack.empty()) {
    const std::size_t c = stack.back();
    stack.pop_back();
    const int cx = static_cast<int>(c % static_cast<std::size_t>(pw_));
    const int cy = static_cast<int>(c / static_cast<std::size_t>(pw_));
    for (int k = 0; k < 8; ++k) {
      const std::ptrdiff_t off = r.offset(k);
      const int nx = cx + (k == 0 || k == 1 || k == 7 ? 1 : (k >= 3 && k <= 5 ? -1 : 0));
      const int ny = cy + (k >= 1 && k <= 3 ? 1 : (k >= 5 ? -1 : 0));
      if (nx < 0 || ny < 0 || nx >= pw_ || ny >= ph_) continue;
      const auto j = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(c) + off);
      if (state_[j] != kBlockedCell || label_[j] == id) continue;
      note(label_[j]);
      label_[j] = id;
      if (cells) cells->push_back(j);
      stack.push_back(j);
    }
  }
  return static_cast<int>(seen.size());
}

void DynamicGvd::full_labels(int bx0, int by0, int bx1, int by1) {
  label_size_.clear();
  next_label_ = 0;
  std::vector<std::size_t> cells;
  // Sparse: the obstacle cells outside the box grown by one form one component (the padding
  // ring is blocked around the box): label 0, which every cell has from the start (label_ is
  // zeroed); the box and its frame are cleared, then flooded from the frame into the box.
  const int fx0 = bx0 - 1, fy0 = by0 - 1, fx1 = bx1 + 1, fy1 = by1 + 1;
  if (bx1 >= 0 && fx0 >= 0 && fy0 >= 0 && fx1 < pw_ && fy1 < ph_) {
    const std::int32_t id = next_label_++;  // 0
    for (int y = fy0; y <= fy1; ++y)
      std::fill_n(&label_[pidx(fx0, y)], fx1 - fx0 + 1, -1);
    relabel_from(pidx(fx0, fy0), id, &cells);
    const std::int64_t frame = std::int64_t{fx1 - fx0 + 1} * (fy1 - fy0 + 1);
    label_size_.push_back(std::int64_t{pw_} * ph_ - frame +
                          static_cast<std::int64_t>(cells.size()));
  } else {
    std::fill(label_.begin(), label_.end(), -1);
    bx0 = 0, by0 = 0, bx1 = pw_ - 1, by1 = ph_ - 1;
  }
  for (int y = std::max(0, by0 - 1); y <= std::min(ph_ - 1, by1 + 1); ++y)
    for (int x = std::max(0, bx0 - 1); x <= std::min(pw_ - 1, bx1 + 1); ++x) {
      const std::size_t i = pidx(x, y);
      if (state_[i] != kBlockedCell || label_[i] >= 0) continue;
      cells.clear();
      relabel_from(i, next_label_++, &cells);
      label_size_.push_back(static_cast<std::int64_t>(cells.size()));
    }
}

namespace {

// The 8 neighbours of padded cell c that lie inside the padded raster.
template <class F>
void for_neighbours8(std::size_t c, int pw, int ph, F&& f) {
  const int cx = static_cast<int>(c % static_cast<std::size_t>(pw));
  const int cy = static_cast<int>(c / static_cast<std::size_t>(pw));
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      if ((dx == 0 && dy == 0) || cx + dx < 0 || cy + dy < 0 || cx + dx >= pw || cy + dy >= ph)
        continue;
      f(static_cast<std::size_t>(cy + dy) * static_cast<std::size_t>(pw) +
        static_cast<std::size_t>(cx + dx));
    }
}

}  // namespace

bool DynamicGvd::update_labels(const std::vector<std::size_t>& added,
                               const std::vector<std::size_t>& removed,
                               std::vector<std::size_t>* relabeled) {
  bool repartitioned = false;
  // Removals: a component that lost cells may have split. Its remaining cells next to the
  // removed ones ("seeds") are flooded in turn; floods that meet are joined, and the search stops
  // when at most one flood is unfinished: every finished flood is then a whole component.
  std::vector<std::pair<std::int32_t, std::size_t>> lost;  // (old label, removed cell)
  for (const std::size_t i : removed) {
    const std::int32_t l = label_[i];
    label_[i] = -1;
    if (l < 0) continue;
    --label_size_[static_cast<std::size_t>(l)];
    lost.emplace_back(l, i);
  }
  std::sort(lost.begin(), lost.end());
  for (std::size_t a = 0; a < lost.size();) {
    const std::int32_t l = lost[a].first;
    std::size_t b = a;
    std::vector<std::size_t> seeds;
    int x0 = pw_, y0 = ph_, x1 = -1, y1 = -1;
    for (; b < lost.size() && lost[b].first == l; ++b) {
      const std::size_t i = lost[b].second;
      const int x = static_cast<int>(i % static_cast<std::size_t>(pw_));
      const int y = static_cast<int>(i / static_cast<std::size_t>(pw_));
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
      for_neighbours8(i, pw_, ph_, [&](std::size_t j) {
        if (state_[j] == kBlockedCell && label_[j] == l) seeds.push_back(j);
      });
    }
    a = b;
    std::sort(seeds.begin(), seeds.end());
    seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
    if (seeds.size() <= 1) continue;
    std::vector<std::size_t> visited;
    // Fast path: the seeds are connected near the removed cells.
    {
      const int m = 3;
      std::vector<std::size_t> stack{seeds[0]};
      visit_[seeds[0]] = 0;
      visited.push_back(seeds[0]);
      while (!stack.empty()) {
        const std::size_t c = stack.back();
        stack.pop_back();
        for_neighbours8(c, pw_, ph_, [&](std::size_t j) {
          if (state_[j] != kBlockedCell || label_[j] != l || visit_[j] >= 0) return;
          const int x = static_cast<int>(j % static_cast<std::size_t>(pw_));
          const int y = static_cast<int>(j / static_cast<std::size_t>(pw_));
          if (x < x0 - m || x > x1 + m || y < y0 - m || y > y1 + m) return;
          visit_[j] = 0;
          visited.push_back(j);
          stack.push_back(j);
        });
      }
      const bool local =
          std::all_of(seeds.begin(), seeds.end(), [&](std::size_t s) { return visit_[s] >= 0; });
      for (const std::size_t c : visited)
        visit_[c] = -1;
      visited.clear();
      if (local) continue;
    }
    const std::size_t k = seeds.size();
    std::vector<std::size_t> parent(k);
    for (std::size_t s = 0; s < k; ++s)
      parent[s] = s;
    auto find = [&](std::size_t s) {
      while (parent[s] != s)
        s = parent[s] = parent[parent[s]];
      return s;
    };
    std::vector<std::vector<std::size_t>> queue(k), cells(k);
    std::vector<std::size_t> head(k, 0);
    for (std::size_t s = 0; s < k; ++s) {
      visit_[seeds[s]] = static_cast<std::int32_t>(s);
      queue[s].push_back(seeds[s]);
      cells[s].push_back(seeds[s]);
      visited.push_back(seeds[s]);
    }
    while (true) {
      std::size_t roots = 0, open_roots = 0;
      std::vector<std::uint8_t> open(k, 0), is_root(k, 0);
      for (std::size_t s = 0; s < k; ++s) {
        const std::size_t rt = find(s);
        if (!is_root[rt]) is_root[rt] = 1, ++roots;
        if (head[s] < queue[s].size() && !open[rt]) open[rt] = 1, ++open_roots;
      }
      if (roots <= 1 || open_roots <= 1) break;
      for (std::size_t s = 0; s < k; ++s) {
        if (head[s] >= queue[s].size()) continue;
        const std::size_t c = queue[s][head[s]++];
        for_neighbours8(c, pw_, ph_, [&](std::size_t j) {
          if (state_[j] != kBlockedCell || label_[j] != l) return;
          if (visit_[j] < 0) {
            visit_[j] = static_cast<std::int32_t>(s);
            queue[s].push_back(j);
            cells[s].push_back(j);
            visited.push_back(j);
          } else {
            const std::size_t ra = find(static_cast<std::size_t>(visit_[j])), rb = find(s);
            if (ra != rb) parent[ra] = rb;
          }
        });
      }
    }
    for (const std::size_t c : visited)
      visit_[c] = -1;
    // Group the floods by root; the unfinished one (or the largest) keeps label l.
    std::vector<std::size_t> roots;
    std::vector<std::int64_t> size(k, 0);
    std::vector<std::uint8_t> open(k, 0);
    for (std::size_t s = 0; s < k; ++s) {
      const std::size_t rt = find(s);
      size[rt] += static_cast<std::int64_t>(cells[s].size());
      if (head[s] < queue[s].size()) open[rt] = 1;
      if (std::find(roots.begin(), roots.end(), rt) == roots.end()) roots.push_back(rt);
    }
    if (roots.size() <= 1) continue;
    repartitioned = true;
    std::size_t keep = roots[0];
    for (const std::size_t rt : roots)
      if (open[rt] || (!open[keep] && size[rt] > size[keep])) keep = rt;
    for (const std::size_t rt : roots) {
      if (rt == keep) continue;
      const std::int32_t id = next_label_++;
      label_size_.push_back(size[rt]);
      label_size_[static_cast<std::size_t>(l)] -= size[rt];
      for (std::size_t s = 0; s < k; ++s) {
        if (find(s) != rt) continue;
        for (const std::size_t c : cells[s]) {
          label_[c] = id;
          relabeled->push_back(c);
        }
      }
    }
  }
  // Additions: a group of added cells takes the label it touches; when it touches several, the
  // smaller components take the label of the largest.
  for (const std::size_t i : added) {
    if (label_[i] >= 0) continue;
    std::vector<std::size_t> group{i};
    label_[i] = -2;                                              // in the group
    std::vector<std::pair<std::int32_t, std::size_t>> touching;  // (label, a cell of it)
    for (std::size_t g = 0; g < group.size(); ++g)
      for_neighbours8(group[g], pw_, ph_, [&](std::size_t j) {
        if (state_[j] != kBlockedCell) return;
        if (label_[j] == -1) {
          label_[j] = -2;
          group.push_back(j);
        } else if (label_[j] >= 0 &&
                   std::none_of(touching.begin(), touching.end(),
                                [&](const auto& t) { return t.first == label_[j]; })) {
          touching.emplace_back(label_[j], j);
        }
      });
    std::int32_t id = -1;
    if (touching.empty()) {
      id = next_label_++;
      label_size_.push_back(0);
    } else {
      id = touching[0].first;
      for (const auto& t : touching)
        if (label_size_[static_cast<std::size_t>(t.first)] >
            label_size_[static_cast<std::size_t>(id)])
          id = t.first;
    }
    for (const std::size_t c : group)
      label_[c] = id;
    label_size_[static_cast<std::size_t>(id)] += static_cast<std::int64_t>(group.size());
    for (const auto& t : touching) {
      if (t.first == id || label_[t.second] == id) continue;
      repartitioned = true;
      const std::size_t before = relabeled->size();
      relabel_from(t.second, id, relabeled);
      const auto moved = static_cast<std::int64_t>(relabeled->size() - before);
      label_size_[static_cast<std::size_t>(t.first)] = 0;
      label_size_[static_cast<std::size_t>(id)] += moved;
    }
    if (touching.size() > 1) repartitioned = true;
  }
  return repartitioned;
}

bool DynamicGvd::raw_mark(std::size_t i) const {
  const std::int32_t si = site_of(i);
  if (state_[i] != kFreeCell || si < 0) return false;
  const auto s = static_cast<std::size_t>(si);
  double sep2 = -1.0;  // computed when first needed
  const std::ptrdiff_t offs[4] = {1, -1, pw_, -pw_};
  for (const std::ptrdiff_t off : offs) {
    const auto j = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(i) + off);
    // A blocked neighbour is its own site: this catches one-cell-wide gaps between two
    // obstacles, where every free neighbour may name the same side by tie-breaking.
    if (state_[j] == kBlockedCell) {
      if (label_[s] != label_[j]) return true;  // d_i = 1 = distance to j: exactly equidistant
      continue;
    }
    if (state_[j] != kFreeCell) continue;
    const std::int32_t sj = site_of(j);
    if (sj < 0 || sj == si) continue;
    if (!(d2_[i] > d2_[j] || (d2_[i] == d2_[j] && i < j))) continue;  // the other one is marked
    const auto t = static_cast<std::size_t>(sj);
    if (label_[s] != label_[t]) return true;
    if (sep2 < 0.0) {
      const double sep =
          std::max(options_.site_separation,
                   options_.site_separation_ratio * std::sqrt(static_cast<double>(d2_[i])));
      sep2 = sep * sep;
    }
    const auto [sx, sy] = xy(s);
    const auto [tx, ty] = xy(t);
    const double dx = sx - tx, dy = sy - ty;
    if (dx * dx + dy * dy > sep2) return true;
  }
  return false;
}

double DynamicGvd::max_spur() const {
  const double min_cells = options_.spur_min_length / geometry_.resolution;
  return std::max(min_cells,
                  options_.spur_clearance_ratio * std::sqrt(static_cast<double>(max_d2_))) +
         1.0;
}

const internal::CellVector<std::uint8_t>& DynamicGvd::skel() const {
  return thins_.empty() ? raw_ : thins_.back().out();
}

void DynamicGvd::build_skeleton(std::pair<std::size_t, std::size_t> span) {
  thins_.clear();
  prunes_.clear();
  if (!options_.thin) return;
  const internal::PaddedRaster r{pw_, ph_};
  thins_.emplace_back(r);
  thins_.back().build(raw_, d2_, span);
  if (options_.spur_min_length <= 0.0 && options_.spur_clearance_ratio <= 0.0) return;
  const double min_cells = options_.spur_min_length / geometry_.resolution;
  for (int round = 0; round < options_.prune_rounds; ++round) {
    prunes_.emplace_back(r, min_cells, options_.spur_clearance_ratio);
    prunes_.back().build(thins_.back().out(), d2_, max_spur(), span);
    thins_.emplace_back(r);
    thins_.back().build(prunes_.back().out(), d2_, span);
  }
}

GvdUpdateStats DynamicGvd::update(std::span<const CellChange> changes) {
  for (const CellChange& c : changes)
    if (!geometry_.contains(c.cell))
      throw Error("DynamicGvd::update", 0,
                  "cell (" + std::to_string(c.cell.x) + ", " + std::to_string(c.cell.y) +
                      ") is outside the " + std::to_string(geometry_.width) + "x" +
                      std::to_string(geometry_.height) + " grid");
  GvdUpdateStats stats;
  std::vector<std::size_t> added, removed;
  std::vector<int> columns;
  for (const CellChange& c : changes) {
    const std::size_t i = pidx(c.cell.x + 1, c.cell.y + 1);
    const std::uint8_t want = c.blocked ? kBlockedCell : kFreeCell;
    if (state_[i] == want) continue;
    state_[i] = want;
    (c.blocked ? added : removed).push_back(i);
    columns.push_back(c.cell.x + 1);
  }
  // A cell changed twice in one batch may be back to its old state: keep the net changes.
  auto net = [&](std::vector<std::size_t>& v, std::uint8_t want) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    std::erase_if(v, [&](std::size_t i) { return state_[i] != want; });
  };
  net(added, kBlockedCell);
  net(removed, kFreeCell);
  // A cell that was both added and removed but ended as it began is in neither list; its label
  // must stay as it was (a removed-then-added cell keeps a valid label below).
  stats.changed_cells = added.size() + removed.size();
  if (stats.changed_cells == 0) return stats;
  if (mark_.empty()) {  // scratch of the updates, allocated on the first one
    visit_.assign(state_.size(), -1);
    mark_ = internal::CellVector<std::uint8_t>(state_.size());
    d2_changed_ = internal::CellVector<std::uint8_t>(state_.size());
    old_d2_ = internal::CellVector<std::int64_t>(state_.size());
  }

  // Distance field: recompute the touched columns between the nearest obstacles above and below
  // the changed cells, then in each row whose column data changed the segments that can see a
  // changed column.
  std::sort(columns.begin(), columns.end());
  columns.erase(std::unique(columns.begin(), columns.end()), columns.end());
  std::unordered_map<int, std::pair<int, int>> column_rows;  // column -> changed row span
  for (const std::size_t i : added)
    grow_span(column_rows, i);
  for (const std::size_t i : removed)
    grow_span(column_rows, i);
  // (row, column, raised, old site of the column in that row) that changed
  std::vector<std::tuple<int, int, bool, std::int32_t>> row_cols;
  std::vector<ChangedRow> rows;
  for (const int x : columns) {
    rows.clear();
    column_pass(x, &rows, column_rows[x]);
    for (const ChangedRow& r : rows)
      row_cols.emplace_back(r.y, x, r.raised, r.old_site);
  }
  std::sort(row_cols.begin(), row_cols.end());
  std::vector<std::size_t> changed;
  std::vector<std::pair<int, int>> ranges;
  std::vector<int> lowered_cols;
  std::vector<std::int32_t> old_sites;
  for (std::size_t a = 0; a < row_cols.size();) {
    const int y = std::get<0>(row_cols[a]);
    ranges.clear();
    lowered_cols.clear();
    old_sites.clear();
    bool raised = false, lowered = false;
    for (; a < row_cols.size() && std::get<0>(row_cols[a]) == y; ++a) {
      raised |= std::get<2>(row_cols[a]);
      lowered |= !std::get<2>(row_cols[a]);
      lowered_cols.push_back(std::get<1>(row_cols[a]));  // sorted, distinct
      if (std::get<3>(row_cols[a]) >= 0) old_sites.push_back(std::get<3>(row_cols[a]));
    }
    // The rows are far apart in memory and the scans below start with reads of the row's
    // distances and sites around its changed columns: fetch the next row's while this one runs.
    if (a < row_cols.size()) {
      const int ny = std::get<0>(row_cols[a]), nx = std::get<1>(row_cols[a]);
      const std::size_t lo = pidx(std::max(0, nx - 32), ny),
                        hi = pidx(std::min(pw_ - 1, nx + 32), ny);
      for (std::size_t i = lo; i <= hi; i += 8)
        __builtin_prefetch(&d2_[i]);
      for (std::size_t i = lo; i <= hi; i += 16)
        __builtin_prefetch(&site_[i]);
    }
    // The cells that can see column xc (|x - xc|^2 <= d^2) form an interval around it (the
    // distance is 1-Lipschitz). For a run of adjacent columns c0..c1 the union of the intervals
    // is [left end seen from c0, right end seen from c1]: a cell outside the run seen from any
    // column of the run is seen from the nearer run end too.
    const std::int64_t* drow = &d2_[pidx(0, y)];
    for (std::size_t k = 0; k < lowered_cols.size();) {
      std::size_t e = k;
      while (e + 1 < lowered_cols.size() && lowered_cols[e + 1] == lowered_cols[e] + 1)
        ++e;
      const int c0 = lowered_cols[k], c1 = lowered_cols[e];
      auto sees = [&](int x, int xc) {
        const std::int64_t v = drow[x];
        return v < 0 || std::int64_t{x - xc} * (x - xc) <= v;
      };
      if (!raised && c1 - c0 < kMaxHalfPlaneRun) {
        lowered_ranges(y, c0, c1, &ranges);
        k = e + 1;
        continue;
      }
      int l = c0, r = c1;
      while (l > 0 && sees(l - 1, c0))
        --l;
      while (r + 1 < pw_ && sees(r + 1, c1))
        ++r;
      ranges.emplace_back(l, r);
      k = e + 1;
    }
    std::sort(ranges.begin(), ranges.end());
    std::size_t m = 0;
    for (std::size_t k = 1; k < ranges.size(); ++k) {
      if (ranges[k].first <= ranges[m].second + 1)
        ranges[m].second = std::max(ranges[m].second, ranges[k].second);
      else
        ranges[++m] = ranges[k];
    }
    ranges.resize(m + 1);
    constexpr std::uint8_t kOldSiteBit = 4;  // marks old_sites in mark_ during the row
    if (raised && !lowered)
      for (const std::int32_t st : old_sites)
        mark_[static_cast<std::size_t>(st)] |= kOldSiteBit;
    for (const auto& [l, r] : ranges) {
      if (raised && !lowered) {
        // Only raised columns: every other column's candidate is unchanged or worse, so a cell
        // changes only when its nearest site was in a changed column (one of old_sites; the
        // site of a cell is the site of its column in its row). Those runs are recomputed,
        // bounded by the unchanged cells around them.
        auto hit = [&](int x) {
          const std::int32_t st = site_of(pidx(x, y));
          return st >= 0 && (mark_[static_cast<std::size_t>(st)] & kOldSiteBit) != 0;
        };
        for (int x = l; x <= r;) {
          if (!hit(x)) {
            ++x;
            continue;
          }
          int e = x;
          while (e + 1 <= r && hit(e + 1))
            ++e;
          row_segment(y, x, e, &changed);
          stats.row_cells += static_cast<std::size_t>(e - x + 1);
          x = e + 1;
        }
      } else if (raised) {
        row_segment(y, l, r, &changed);
        stats.row_cells += static_cast<std::size_t>(r - l + 1);
      } else {
        row_lower(y, l, r, lowered_cols, &changed);
        stats.row_cells += static_cast<std::size_t>(r - l + 1);
      }
    }
    if (raised && !lowered)
      for (const std::int32_t st : old_sites)
        mark_[static_cast<std::size_t>(st)] &= static_cast<std::uint8_t>(~kOldSiteBit);
    ++stats.recomputed_rows;
  }
  stats.changed_distances = changed.size();
  for (const std::size_t c : changed)
    max_d2_ = std::max(max_d2_, d2_[c]);

  // Obstacle labels.
  std::vector<std::size_t> relabeled;
  stats.labels_repartitioned = update_labels(added, removed, &relabeled);

  // Raw diagram: a mark depends on the cell, its 4 neighbours, their sites and site labels.
  std::vector<std::size_t> redo;
  const std::ptrdiff_t offs[5] = {0, 1, -1, pw_, -pw_};
  auto redo_around = [&](std::size_t c) {  // deduplicated with the mark bit 2
    for (const std::ptrdiff_t off : offs) {
      const std::ptrdiff_t j = static_cast<std::ptrdiff_t>(c) + off;
      if (j < 0 || j >= static_cast<std::ptrdiff_t>(raw_.size())) continue;
      const auto ju = static_cast<std::size_t>(j);
      if (mark_[ju] & 2U) continue;
      mark_[ju] |= 2U;
      redo.push_back(ju);
    }
  };
  for (const std::size_t c : changed)
    redo_around(c);
  if (!relabeled.empty()) {
    // Cells whose site lies in a relabeled component are within the largest distance of it.
    int x0 = pw_, y0 = ph_, x1 = -1, y1 = -1;
    for (const std::size_t c : relabeled) {
      mark_[c] |= 1U;
      redo_around(c);
      const int x = static_cast<int>(c % static_cast<std::size_t>(pw_));
      const int y = static_cast<int>(c / static_cast<std::size_t>(pw_));
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
    const int m = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(max_d2_)))) + 1;
    for (int y = std::max(0, y0 - m); y <= std::min(ph_ - 1, y1 + m); ++y)
      for (int x = std::max(0, x0 - m); x <= std::min(pw_ - 1, x1 + m); ++x) {
        const std::size_t i = pidx(x, y);
        const std::int32_t si = site_of(i);
        if (si >= 0 && (mark_[static_cast<std::size_t>(si)] & 1U)) redo_around(i);
      }
    for (const std::size_t c : relabeled)
      mark_[c] &= static_cast<std::uint8_t>(~1U);
  }
  std::vector<internal::Delta> deltas;
  for (const std::size_t c : redo) {
    mark_[c] = 0;
    const std::uint8_t now = raw_mark(c) ? 1 : 0;
    if (now == raw_[c]) continue;
    deltas.push_back({c, raw_[c]});
    raw_[c] = now;
  }
  stats.changed_raw = deltas.size();

  // Thinning and pruning, replayed where their input or the clearance changed. Every stage's
  // input is a subset of the raw diagram. The pruning reads the clearance of junctions (keys);
  // the thinning compares the keys of 8-neighbours only, so a key change matters to it only
  // where the order of the cell and a raw 8-neighbour flipped (thin_keys): in an open hall most
  // clearances on the diagram change by about the same amount and keep their order.
  std::vector<std::size_t> keys, thin_keys;
  for (const std::size_t c : changed)
    if (d2_changed_[c] && raw_[c]) {
      keys.push_back(c);
      if (key_order_flipped(c)) thin_keys.push_back(c);
    }
  for (const std::size_t c : changed)
    d2_changed_[c] = 0;
  stats.key_changes = keys.size();
  stats.thin_key_changes = thin_keys.size();
  if (!thins_.empty()) {
    deltas = thins_[0].update(raw_, deltas, d2_, thin_keys, &stats.skeleton_work);
    for (std::size_t k = 0; k < prunes_.size(); ++k) {
      deltas =
          prunes_[k].update(thins_[k].out(), deltas, d2_, keys, max_spur(), &stats.skeleton_work);
      // The pruned input is a subset of thins_[k]'s output, a fixed point of the thinning: only
      // the changes near pruned or removed cells are replayed.
      deltas = thins_[k + 1].update(prunes_[k].out(), deltas, d2_, thin_keys, &stats.skeleton_work,
                                    &thins_[k].out());
      stats.rethin_dormant += thins_[k + 1].last_dormant();
      stats.rethin_woken += thins_[k + 1].last_woken();
    }
  }
  stats.changed_diagram = deltas.size();
  for (const auto& t : thins_)
    stats.thinning_steps = std::max(stats.thinning_steps, t.steps());
  return stats;
}

bool DynamicGvd::key_order_flipped(std::size_t c) const {
  // Keys are (d2, index); the old key of a cell is old_d2_ where d2_changed_ is set.
  const auto old_key = [&](std::size_t i) { return d2_changed_[i] ? old_d2_[i] : d2_[i]; };
  const std::int64_t oc = old_key(c), nc = d2_[c];
  const internal::PaddedRaster r{pw_, ph_};
  for (int k = 0; k < 8; ++k) {
    const auto n = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(c) + r.offset(k));
    if (!raw_[n]) continue;
    const std::int64_t on = old_key(n), nn = d2_[n];
    const bool was_less = oc != on ? oc < on : c < n;
    const bool is_less = nc != nn ? nc < nn : c < n;
    if (was_less != is_less) return true;
  }
  return false;
}

std::int64_t DynamicGvd::squared_clearance(Cell c) const {
  if (!geometry_.contains(c)) throw Error("DynamicGvd", 0, "cell outside the grid");
  return d2_[pidx(c.x + 1, c.y + 1)];
}

bool DynamicGvd::is_blocked(Cell c) const {
  if (!geometry_.contains(c)) throw Error("DynamicGvd", 0, "cell outside the grid");
  return state_[pidx(c.x + 1, c.y + 1)] == kBlockedCell;
}

bool DynamicGvd::is_voronoi(Cell c) const {
  if (!geometry_.contains(c)) throw Error("DynamicGvd", 0, "cell outside the grid");
  return skel()[pidx(c.x + 1, c.y + 1)] != 0;
}

GeneralizedVoronoi DynamicGvd::snapshot() const {
  GeneralizedVoronoi g{geometry_,
                       BinaryGrid(geometry_, 0),
                       GridMap<float>(geometry_, std::numeric_limits<float>::infinity()),
                       GridMap<Cell>(geometry_, kNoSiteCell),
                       GridMap<std::int32_t>(geometry_, -1),
                       BinaryGrid(geometry_, 0),
                       BinaryGrid(geometry_, 0)};
  for (int y = 0; y < geometry_.height; ++y)
    for (int x = 0; x < geometry_.width; ++x) {
      const Cell c{x, y};
      const std::size_t i = pidx(x + 1, y + 1);
      g.blocked[c] = state_[i] == kBlockedCell ? 1 : 0;
      if (d2_[i] >= 0) g.clearance[c] = static_cast<float>(std::sqrt(static_cast<double>(d2_[i])));
      if (site_of(i) >= 0) {
        const auto s = static_cast<std::size_t>(site_of(i));
        g.nearest_site[c] = Cell{static_cast<int>(s % static_cast<std::size_t>(pw_)) - 1,
                                 static_cast<int>(s / static_cast<std::size_t>(pw_)) - 1};
      }
      g.obstacle_label[c] = label_[i];
      g.raw[c] = raw_[i];
      g.diagram[c] = skel()[i];
    }
  return g;
}

GeneralizedVoronoi build_gvd(const BinaryGrid& blocked, const GvdOptions& options) {
  return DynamicGvd(blocked, options).snapshot();
}

void thin_diagram(BinaryGrid& diagram, const GridMap<float>& clearance) {
  GvdOptions o;
  o.spur_min_length = 0.0;
  o.spur_clearance_ratio = 0.0;
  prune_diagram(diagram, clearance, o);
}

void prune_diagram(BinaryGrid& diagram, const GridMap<float>& clearance,
                   const GvdOptions& options) {
  check_options(options);
  if (diagram.width() != clearance.width() || diagram.height() != clearance.height())
    throw Error("prune_diagram", 0, "the diagram and the clearance differ in size");
  const int pw = diagram.width() + 2, ph = diagram.height() + 2;
  std::vector<std::uint8_t> skel(static_cast<std::size_t>(pw) * static_cast<std::size_t>(ph), 0);
  std::vector<std::size_t> order;
  std::vector<float> key(skel.size(), 0.0F);
  auto at = [&](int x, int y) {
    return static_cast<std::size_t>(y + 1) * static_cast<std::size_t>(pw) +
           static_cast<std::size_t>(x + 1);
  };
  for (int y = 0; y < diagram.height(); ++y)
    for (int x = 0; x < diagram.width(); ++x) {
      if (!diagram[Cell{x, y}]) continue;
      const std::size_t i = at(x, y);
      skel[i] = 1;
      key[i] = clearance[Cell{x, y}];
      order.push_back(i);
    }
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return key[a] != key[b] ? key[a] < key[b] : a < b;
  });
  const internal::PaddedRaster r{pw, ph};
  internal::thin(skel, r, order);
  if (options.spur_min_length > 0.0 || options.spur_clearance_ratio > 0.0) {
    const double min_cells = options.spur_min_length / diagram.resolution();
    for (int round = 0; round < options.prune_rounds; ++round) {
      const std::size_t removed = internal::prune_spurs(skel, r, [&](std::size_t j) {
        const double c = static_cast<double>(key[j]);
        return std::max(min_cells, options.spur_clearance_ratio * (std::isfinite(c) ? c : 0.0));
      });
      if (removed == 0) break;
      internal::thin(skel, r, order);
    }
  }
  for (int y = 0; y < diagram.height(); ++y)
    for (int x = 0; x < diagram.width(); ++x)
      diagram[Cell{x, y}] = skel[at(x, y)];
}

}  // namespace voronav::voronoi
