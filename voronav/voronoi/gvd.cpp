#include "voronav/voronoi/gvd.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "voronav/core/error.hpp"
#include "voronav/voronoi/internal/skeleton.hpp"

namespace voronav::voronoi {
namespace {

constexpr std::uint8_t kFreeCell = 0;
constexpr std::uint8_t kBlockedCell = 1;
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
// the argmin column.
class Envelope {
 public:
  void run(const std::int64_t* f, int n, std::int64_t* d, std::int32_t* arg) {
    v_.resize(static_cast<std::size_t>(n));
    z_.resize(static_cast<std::size_t>(n) + 1);
    int k = -1;
    for (int q = 0; q < n; ++q) {
      if (f[q] < 0) continue;
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
      std::fill(d, d + n, kNone);
      std::fill(arg, arg + n, -1);
      return;
    }
    int j = 0;
    for (int q = 0; q < n; ++q) {
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
  const std::size_t n = static_cast<std::size_t>(pw_) * static_cast<std::size_t>(ph_);
  state_.assign(n, options.border_is_blocked ? kBlockedCell : kOutside);
  for (int y = 0; y < geometry_.height; ++y)
    for (int x = 0; x < geometry_.width; ++x)
      state_[pidx(x + 1, y + 1)] = blocked[Cell{x, y}] ? kBlockedCell : kFreeCell;
  col_d_.assign(n, kNone);
  col_arg_.assign(n, -1);
  d2_.assign(n, kNone);
  site_.assign(n, -1);
  label_.assign(n, -1);
  raw_.assign(n, 0);
  skel_.assign(n, 0);
  for (int x = 0; x < pw_; ++x)
    column_pass(x, nullptr);
  for (int y = 0; y < ph_; ++y)
    row_pass(y, nullptr);
  full_labels();
  for (std::size_t i = 0; i < n; ++i)
    raw_[i] = raw_mark(i) ? 1 : 0;
  thin_and_prune();
}

void DynamicGvd::column_pass(int x, std::vector<int>* changed_rows) {
  // 1-D nearest site along the column: forward then backward scan (ties: the lower row).
  std::int32_t last = -1;
  std::vector<std::int32_t> below(static_cast<std::size_t>(ph_));
  for (int y = 0; y < ph_; ++y) {
    if (state_[pidx(x, y)] == kBlockedCell) last = y;
    below[static_cast<std::size_t>(y)] = last;
  }
  std::int32_t above = -1;
  for (int y = ph_ - 1; y >= 0; --y) {
    if (state_[pidx(x, y)] == kBlockedCell) above = y;
    const std::int32_t b = below[static_cast<std::size_t>(y)];
    std::int32_t best = -1;
    if (b >= 0 && (above < 0 || y - b <= above - y))
      best = b;
    else if (above >= 0)
      best = above;
    const std::int64_t d = best < 0 ? kNone : std::int64_t{y - best} * (y - best);
    const std::size_t i = pidx(x, y);
    if (changed_rows && (col_d_[i] != d || col_arg_[i] != best)) changed_rows->push_back(y);
    col_d_[i] = d;
    col_arg_[i] = best;
  }
}

void DynamicGvd::row_pass(int y, std::vector<std::size_t>* changed) {
  static thread_local Envelope env;
  static thread_local std::vector<std::int64_t> d;
  static thread_local std::vector<std::int32_t> arg;
  d.resize(static_cast<std::size_t>(pw_));
  arg.resize(static_cast<std::size_t>(pw_));
  env.run(&col_d_[pidx(0, y)], pw_, d.data(), arg.data());
  for (int x = 0; x < pw_; ++x) {
    const std::size_t i = pidx(x, y);
    const std::int32_t ax = arg[static_cast<std::size_t>(x)];
    const std::int32_t s = ax < 0 ? -1 : static_cast<std::int32_t>(pidx(ax, col_arg_[pidx(ax, y)]));
    const std::int64_t dd = d[static_cast<std::size_t>(x)];
    if (changed && (d2_[i] != dd || site_[i] != s)) changed->push_back(i);
    d2_[i] = dd;
    site_[i] = s;
  }
}

int DynamicGvd::relabel_from(std::size_t seed, std::int32_t id) {
  std::vector<std::int32_t> seen;
  auto note = [&](std::int32_t old) {
    if (old >= 0 && std::find(seen.begin(), seen.end(), old) == seen.end()) seen.push_back(old);
  };
  std::vector<std::size_t> stack{seed};
  note(label_[seed]);
  label_[seed] = id;
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
      stack.push_back(j);
    }
  }
  return static_cast<int>(seen.size());
}

void DynamicGvd::full_labels() {
  std::fill(label_.begin(), label_.end(), -1);
  for (std::size_t i = 0; i < state_.size(); ++i)
    if (state_[i] == kBlockedCell && label_[i] < 0) relabel_from(i, next_label_++);
}

bool DynamicGvd::raw_mark(std::size_t i) const {
  if (state_[i] != kFreeCell || site_[i] < 0) return false;
  const auto s = static_cast<std::size_t>(site_[i]);
  const int sx = static_cast<int>(s % static_cast<std::size_t>(pw_));
  const int sy = static_cast<int>(s / static_cast<std::size_t>(pw_));
  const double sep = std::max(options_.site_separation, options_.site_separation_ratio *
                                                            std::sqrt(static_cast<double>(d2_[i])));
  const double sep2 = sep * sep;
  const std::ptrdiff_t offs[4] = {1, -1, pw_, -pw_};
  for (const std::ptrdiff_t off : offs) {
    const auto j = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(i) + off);
    // A blocked neighbour is its own site: this catches one-cell-wide gaps between two
    // obstacles, where every free neighbour may name the same side by tie-breaking.
    if (state_[j] == kBlockedCell) {
      if (label_[s] != label_[j]) return true;  // d_i = 1 = distance to j: exactly equidistant
      continue;
    }
    if (state_[j] != kFreeCell || site_[j] < 0 || site_[j] == site_[i]) continue;
    const auto t = static_cast<std::size_t>(site_[j]);
    bool different = label_[s] != label_[t];
    if (!different) {
      const int tx = static_cast<int>(t % static_cast<std::size_t>(pw_));
      const int ty = static_cast<int>(t / static_cast<std::size_t>(pw_));
      const double dx = sx - tx, dy = sy - ty;
      different = dx * dx + dy * dy > sep2;
    }
    if (!different) continue;
    if (d2_[i] > d2_[j] || (d2_[i] == d2_[j] && i < j)) return true;
  }
  return false;
}

void DynamicGvd::thin_and_prune() {
  skel_ = raw_;
  if (!options_.thin) return;
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < raw_.size(); ++i)
    if (raw_[i]) order.push_back(i);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return d2_[a] != d2_[b] ? d2_[a] < d2_[b] : a < b;
  });
  const internal::PaddedRaster r{pw_, ph_};
  internal::thin(skel_, r, order);
  if (options_.spur_min_length <= 0.0 && options_.spur_clearance_ratio <= 0.0) return;
  const double min_cells = options_.spur_min_length / geometry_.resolution;
  for (int round = 0; round < options_.prune_rounds; ++round) {
    const std::size_t removed = internal::prune_spurs(skel_, r, [&](std::size_t j) {
      return std::max(min_cells,
                      options_.spur_clearance_ratio * std::sqrt(static_cast<double>(d2_[j])));
    });
    if (removed == 0) break;
    internal::thin(skel_, r, order);
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
  stats.changed_cells = added.size() + removed.size();
  if (stats.changed_cells == 0) return stats;

  // Distance field: recompute the touched columns, then the rows whose column data changed.
  std::sort(columns.begin(), columns.end());
  columns.erase(std::unique(columns.begin(), columns.end()), columns.end());
  std::vector<int> rows;
  for (const int x : columns)
    column_pass(x, &rows);
  std::sort(rows.begin(), rows.end());
  rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
  std::vector<std::size_t> changed;
  for (const int y : rows)
    row_pass(y, &changed);
  stats.recomputed_rows = rows.size();
  stats.changed_distances = changed.size();

  // Obstacle labels: re-flood the components that lost or gained cells.
  bool repartitioned = false;
  const internal::PaddedRaster r{pw_, ph_};
  const std::int32_t batch_start = next_label_;
  std::vector<std::pair<std::int32_t, int>> floods;  // old label -> pieces found
  for (const std::size_t i : removed) {
    const std::int32_t old = label_[i];
    label_[i] = -1;
    if (old < 0 || old >= batch_start) continue;
    for (int k = 0; k < 8; ++k) {
      const auto j = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(i) + r.offset(k));
      if (state_[j] != kBlockedCell || label_[j] != old) continue;
      relabel_from(j, next_label_++);
      auto it = std::find_if(floods.begin(), floods.end(), [&](auto& f) { return f.first == old; });
      if (it == floods.end())
        floods.emplace_back(old, 1);
      else if (++it->second > 1)
        repartitioned = true;  // the component split
    }
  }
  for (const std::size_t i : added) {
    if (label_[i] >= batch_start) continue;  // already flooded from another added cell
    // The flood counts the components it joins (a merge when more than one).
    if (relabel_from(i, next_label_++) > 1) repartitioned = true;
  }
  stats.labels_repartitioned = repartitioned;

  // Raw diagram: a mark depends on the cell and its 4 neighbours.
  if (repartitioned) {
    for (std::size_t i = 0; i < raw_.size(); ++i)
      raw_[i] = raw_mark(i) ? 1 : 0;
  } else {
    const std::ptrdiff_t offs[5] = {0, 1, -1, pw_, -pw_};
    for (const std::size_t c : changed)
      for (const std::ptrdiff_t off : offs) {
        const std::ptrdiff_t j = static_cast<std::ptrdiff_t>(c) + off;
        if (j < 0 || j >= static_cast<std::ptrdiff_t>(raw_.size())) continue;
        raw_[static_cast<std::size_t>(j)] = raw_mark(static_cast<std::size_t>(j)) ? 1 : 0;
      }
  }
  thin_and_prune();
  return stats;
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
  return skel_[pidx(c.x + 1, c.y + 1)] != 0;
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
      if (site_[i] >= 0) {
        const auto s = static_cast<std::size_t>(site_[i]);
        g.nearest_site[c] = Cell{static_cast<int>(s % static_cast<std::size_t>(pw_)) - 1,
                                 static_cast<int>(s / static_cast<std::size_t>(pw_)) - 1};
      }
      g.obstacle_label[c] = label_[i];
      g.raw[c] = raw_[i];
      g.diagram[c] = skel_[i];
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
