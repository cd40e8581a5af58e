#include "voronav/voronoi/labeled_voronoi.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "voronav/core/error.hpp"
#include "voronav/field/distance_transform.hpp"
#include "voronav/field/obstacle_labels.hpp"
#include "voronav/voronoi/gvd.hpp"

namespace voronav::voronoi {
namespace {

constexpr std::uint8_t kFreeCell = 0, kBlockedCell = 1, kOutside = 2;

struct Padded {
  int w = 0, h = 0;
  std::vector<std::uint8_t> state;
  [[nodiscard]] std::size_t idx(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x);
  }
};

Padded pad(const BinaryGrid& blocked, bool border_is_blocked) {
  Padded p{blocked.width() + 2, blocked.height() + 2, {}};
  p.state.assign(static_cast<std::size_t>(p.w) * static_cast<std::size_t>(p.h),
                 border_is_blocked ? kBlockedCell : kOutside);
  for (int y = 0; y < blocked.height(); ++y)
    for (int x = 0; x < blocked.width(); ++x)
      p.state[p.idx(x + 1, y + 1)] = blocked[Cell{x, y}] ? kBlockedCell : kFreeCell;
  return p;
}

std::uint8_t code_of(const Padded& p, int x, int y) {
  if (p.state[p.idx(x, y)] != kBlockedCell) return 1;
  auto free_at = [&](int xx, int yy) {
    return xx >= 0 && yy >= 0 && xx < p.w && yy < p.h && p.state[p.idx(xx, yy)] == kFreeCell;
  };
  const bool e = free_at(x + 1, y), n = free_at(x, y + 1), w = free_at(x - 1, y),
             s = free_at(x, y - 1);
  const int count = e + n + w + s;
  if (count == 0) return 2;
  if (count >= 3) return 4;
  if (count == 1) return static_cast<std::uint8_t>(e ? 5 : n ? 6 : w ? 7 : 8);
  if ((e && w) || (n && s)) return 3;
  if (n && e) return 9;
  if (n && w) return 10;
  if (s && w) return 11;
  return 12;  // s && e
}

}  // namespace

GridMap<std::uint8_t> edge_codes(const BinaryGrid& blocked, bool border_is_blocked) {
  const Padded p = pad(blocked, border_is_blocked);
  GridMap<std::uint8_t> out(blocked.geometry(), 1);
  for (int y = 0; y < blocked.height(); ++y)
    for (int x = 0; x < blocked.width(); ++x)
      out[Cell{x, y}] = code_of(p, x + 1, y + 1);
  return out;
}

LabeledVoronoi build_labeled_voronoi(const BinaryGrid& blocked, const CaVoronoiOptions& o) {
  if (!(o.site_separation >= 0.0) || !(o.site_separation_ratio >= 0.0))
    throw Error("CaVoronoiOptions", 0, "site_separation and its ratio must be >= 0");
  const GridGeometry& g = blocked.geometry();
  LabeledVoronoi out{edge_codes(blocked, o.border_is_blocked),
                     GridMap<std::int32_t>(g, -1),
                     GridMap<std::int32_t>(g, -1),
                     BinaryGrid(g, 0),
                     BinaryGrid(g, 0),
                     0};
  if (blocked.empty()) return out;
  const Padded p = pad(blocked, o.border_is_blocked);
  const std::size_t n = p.state.size();
  // Component labels over the padded grid (the border ring is an obstacle like any other).
  BinaryGrid padded_blocked(p.w, p.h, 0);
  for (std::size_t i = 0; i < n; ++i)
    padded_blocked[i] = p.state[i] == kBlockedCell;
  const field::ObstacleLabels comps = field::label_obstacles(padded_blocked);

  std::vector<std::int32_t> label(n, -1), source(n, -1), time(n, -1);
  std::vector<std::uint8_t> flag(n, 0), vor(n, 0);
  std::vector<std::size_t> frontier;
  for (int y = 0; y < p.h; ++y)
    for (int x = 0; x < p.w; ++x) {
      const std::uint8_t code = code_of(p, x, y);
      const bool source_cell = code >= 5 || (o.noise_cells_are_sources && (code == 3 || code == 4));
      if (!source_cell) continue;
      const std::size_t i = p.idx(x, y);
      flag[i] = 1;
      label[i] = o.labels == CaLabels::kEdgeCode ? code : comps.label[i];
      source[i] = static_cast<std::int32_t>(i);
      time[i] = 0;
      frontier.push_back(i);
    }
  const auto pw = static_cast<std::ptrdiff_t>(p.w);
  const std::ptrdiff_t offs[4] = {1, pw, -1, -pw};
  auto sq_dist = [&](std::size_t a, std::size_t b) {
    const double dx = static_cast<double>(a % static_cast<std::size_t>(p.w)) -
                      static_cast<double>(b % static_cast<std::size_t>(p.w));
    const double dy = static_cast<double>(a / static_cast<std::size_t>(p.w)) -
                      static_cast<double>(b / static_cast<std::size_t>(p.w));
    return dx * dx + dy * dy;
  };
  // Whether the fronts from cells a and b come from different obstacles at step t.
  auto different = [&](std::size_t a, std::size_t b, int t) {
    if (label[a] != label[b]) return true;
    const double sep = std::max(o.site_separation, o.site_separation_ratio * t);
    return sq_dist(static_cast<std::size_t>(source[a]), static_cast<std::size_t>(source[b])) >
           sep * sep;
  };
  std::vector<std::size_t> candidates, flagged_now;
  std::vector<std::int32_t> stamp(n, -1);
  for (int t = 1;; ++t) {
    candidates.clear();
    for (const std::size_t f : frontier)
      for (const std::ptrdiff_t off : offs) {
        const auto q = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(f) + off);
        if (q >= n || p.state[q] != kFreeCell || flag[q] || vor[q] || stamp[q] == t) continue;
        stamp[q] = t;
        candidates.push_back(q);
      }
    flagged_now.clear();
    bool any_vor = false;
    std::vector<std::pair<std::size_t, std::size_t>> takes;  // cell, neighbour it copies
    for (const std::size_t c : candidates) {
      std::size_t best = n;
      double best_d = HUGE_VAL;
      std::size_t nbrs[4];
      int k = 0;
      for (const std::ptrdiff_t off : offs) {
        const auto q = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(c) + off);
        if (q >= n || !flag[q] || time[q] >= t) continue;
        nbrs[k++] = q;
        const double d = sq_dist(c, static_cast<std::size_t>(source[q]));
        if (d < best_d || (d == best_d && source[q] < source[best])) {
          best_d = d;
          best = q;
        }
      }
      bool meet = false;
      for (int j = 0; j < k && !meet; ++j)
        meet = different(best, nbrs[j], t);
      if (meet) {
        vor[c] = 1;
        time[c] = t;
        any_vor = true;
      } else {
        takes.emplace_back(c, best);
      }
    }
    for (const auto& [c, from] : takes) {
      flag[c] = 1;
      label[c] = label[from];
      source[c] = source[from];
      time[c] = t;
      flagged_now.push_back(c);
    }
    // Fronts of different obstacles that meet between two cells flagged in the same step.
    for (const std::size_t c : flagged_now)
      for (const std::ptrdiff_t off : offs) {
        const auto q = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(c) + off);
        if (q >= n || !flag[q] || time[q] != t || q < c) continue;
        if (!different(c, q, t)) continue;
        const double dc = sq_dist(c, static_cast<std::size_t>(source[c]));
        const double dq = sq_dist(q, static_cast<std::size_t>(source[q]));
        vor[(dc > dq || (dc == dq && c < q)) ? c : q] = 1;
      }
    if (flagged_now.empty()) {
      out.steps = any_vor ? t : t - 1;
      break;
    }
    frontier.swap(flagged_now);
  }
  GridMap<float> clearance(g, 0.0F);
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width; ++x) {
      const std::size_t i = p.idx(x + 1, y + 1);
      const Cell c{x, y};
      out.label[c] = label[i];
      out.time[c] = time[i];
      out.vor[c] = vor[i];
      clearance[c] = static_cast<float>(
          source[i] >= 0 ? std::sqrt(sq_dist(i, static_cast<std::size_t>(source[i]))) : time[i]);
    }
  out.diagram = out.vor;
  if (o.thin) thin_diagram(out.diagram, clearance);
  return out;
}

DiagramAgreement compare_diagrams(const BinaryGrid& a, const BinaryGrid& b, double tolerance) {
  if (a.width() != b.width() || a.height() != b.height())
    throw Error("compare_diagrams", 0, "the diagrams differ in size");
  if (!(tolerance >= 0.0)) throw Error("compare_diagrams", 0, "tolerance must be >= 0");
  DiagramAgreement out;
  const double t2 = tolerance * tolerance;
  auto fraction = [&](const BinaryGrid& from, const BinaryGrid& to, std::size_t* count) {
    const field::DistanceField df = field::distance_transform(to);
    std::size_t in = 0;
    *count = 0;
    for (std::size_t i = 0; i < from.size(); ++i) {
      if (!from[i]) continue;
      ++*count;
      if (static_cast<double>(df.squared_distance[i]) <= t2) ++in;
    }
    return *count == 0 ? 0.0 : static_cast<double>(in) / static_cast<double>(*count);
  };
  out.a_in_b = fraction(a, b, &out.a_cells);
  out.b_in_a = fraction(b, a, &out.b_cells);
  return out;
}

}  // namespace voronav::voronoi
