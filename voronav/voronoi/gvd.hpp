// EDT-based generalized Voronoi diagram (GVD) of a binary grid, with incremental updates.
//
// The diagram of seed 003 (section III) is the set of free cells equidistant to two obstacles. Here
// it is computed from the exact Euclidean distance transform (Felzenszwalb-Huttenlocher, with
// the nearest obstacle cell, the "site", of every cell) in three steps:
//  1. raw diagram: a free cell p is a Voronoi cell when a 4-neighbour q has a nearest site that is
//     "another obstacle": of a different 8-connected obstacle component, or of the same component
//     but far from p's site (|s_p - s_q| > max(site_separation, site_separation_ratio * d_p), so
//     that rooms bounded by one connected wall still get a diagram). Of the two cells p, q only
//     the one farther from the obstacles is marked (ties: the lower row-major index), which makes
//     every Voronoi cell equidistant to two different obstacles within one cell;
//  2. thinning to a one-cell-wide 8-connected skeleton: simple cells (Yokoi 8-connectivity
//     number 1) that are not end points are removed by a subfield-parallel automaton that peels
//     the low-clearance side of every band, so the skeleton keeps the ridge of the distance
//     field and its topology (internal/local_skeleton.hpp; order-independent, unlike a sequential
//     removal in clearance order, so that it can be updated locally);
//  3. pruning of spurs: every branch from an end point to a junction shorter than
//     max(spur_min_length, spur_clearance_ratio * clearance at the junction) is removed, all ends
//     of a round at once, then the diagram is thinned again (prune_rounds rounds).
//
// The full build works inside the bounding box of the non-blocked cells only (the cells outside
// are obstacles at distance 0 shielded by the box's frame; their labels are one component), so on
// a mostly unknown map its cost follows the known free area, not the grid: the per-cell arrays
// start zeroed without a write (zero encodes "blocked, its own site at distance 0"), so only the
// pages of the box's rows are written, and freed arrays are kept for the next build
// (internal::zeroed_alloc).
//
// DynamicGvd keeps the state so that changed cells (a door closes, an obstacle moves) update
// everything locally, in the spirit of the dynamic brushfire of Lau, Sprunk and Burgard (2013):
//  - distance: the columns holding changed cells are recomputed, then in every row whose column
//    data changed only the segment that can see a changed column (|x - x'|^2 <= old d^2, found by
//    scanning out from the changed columns; the distance is 1-Lipschitz so the scan stops at the
//    first cell that fails) is recomputed, by the parabola envelope over the columns within the
//    largest possible new distance (bounded by the unchanged cells just outside the segment, which
//    also bounds the columns worth entering the envelope); in a row where every changed column
//    was raised (obstacles removed) only the runs of cells whose site was in a changed column are
//    recomputed (every other candidate got no better); in a row where every changed column was
//    lowered (obstacles added) only the cells a new site can beat are: where it does not beat a
//    cell, |p - s|^2 - |p - t|^2 (t the cell's old site) is linear along the row, so the scan
//    skips ahead to where it could reach 0 and stops where it only grows. The nearest site is the
//    lexicographic minimum of (squared distance, column, row) in both builds;
//  - obstacle labels: added cells take the label they touch; a merge relabels the smaller
//    components, a split is found by flooding from the remaining neighbours of the removed cells
//    in turn until at most one flood is unfinished (only the pieces that split off are relabeled);
//  - raw marks: recomputed on the cells whose distance or site changed, their 4-neighbours, and
//    the cells whose site lies in a relabeled component;
//  - thinning and pruning: order-independent versions (internal/local_skeleton.hpp: a
//    subfield-parallel thinning automaton whose whole run is stored, and spur pruning of all ends
//    at once), replayed only where their input or the clearance changed (for the thinning, which
//    compares the clearances of 8-neighbours only: where the order of two raw neighbours flipped).
//    The re-thinning after a pruning round starts from the output of a thinning, a fixed point
//    in which no cell is removable, so it replays only the changes within 2 cells of a pruned
//    or removed cell (the others stay dormant unless a removal comes near them).
// The result is identical to a full rebuild (tested on random change sequences with merges and
// splits), and the cost follows the size of the change, not of the map.
#pragma once

#include <cstdint>
#include <limits>
#include <span>
#include <unordered_map>
#include <utility>
#include <vector>

#include "voronav/core/grid_map.hpp"
#include "voronav/core/occupancy.hpp"
#include "voronav/voronoi/internal/local_skeleton.hpp"

namespace voronav::voronoi {

struct GvdOptions {
  /// Whether the outside of the grid is an obstacle (a wall around the map).
  bool border_is_blocked = true;
  /// Sites of the same obstacle component count as different obstacles when farther apart than
  /// this [cells] (and than site_separation_ratio * clearance).
  double site_separation = 2.5;
  /// ... and farther apart than this fraction of the clearance of the cell (dimensionless).
  /// 0 by default: any positive ratio loses the parabolic arcs between a wall and a convex
  /// corner of the same component far from both, which can disconnect the diagram; the spurs
  /// that a small separation lets through on rough walls are pruned instead.
  double site_separation_ratio = 0.0;
  /// Thin the raw diagram to one cell wide.
  bool thin = true;
  /// Spurs shorter than max(spur_min_length, spur_clearance_ratio * junction clearance) are
  /// pruned; spur_min_length in [m], spur_clearance_ratio dimensionless; both 0 = no pruning.
  double spur_min_length = 0.0;
  double spur_clearance_ratio = 1.5;
  /// Rounds of pruning (each round may expose new spurs) (>= 0).
  int prune_rounds = 2;
};

/// A site position that means "no obstacle anywhere".
inline constexpr Cell kNoSiteCell{-2147483647, -2147483647};

struct GeneralizedVoronoi {
  GridGeometry geometry;
  /// The input, 1 = blocked.
  BinaryGrid blocked;
  /// Distance [cells] from each cell centre to the nearest obstacle cell centre (0 on obstacles,
  /// +inf when there is none).
  GridMap<float> clearance;
  /// The nearest obstacle cell of every cell (outside the grid for the border wall, kNoSiteCell
  /// when there is none).
  GridMap<Cell> nearest_site;
  /// Obstacle component id of every blocked cell (-1 on free cells). Ids are arbitrary but equal
  /// exactly for the cells of one component.
  GridMap<std::int32_t> obstacle_label;
  /// Raw diagram (before thinning), 1 = Voronoi cell.
  BinaryGrid raw;
  /// The final diagram: thinned and pruned, 1 = Voronoi cell.
  BinaryGrid diagram;

  /// Clearance [m] of a cell.
  [[nodiscard]] double clearance_m(Cell c) const {
    return static_cast<double>(clearance.at(c)) * geometry.resolution;
  }
  /// The cells of the final diagram in row-major order.
  [[nodiscard]] std::vector<Cell> cells() const;
};

/// A change of one cell for DynamicGvd::update.
struct CellChange {
  Cell cell;
  bool blocked = true;
};

/// What an incremental update touched (for benchmarks and tests).
struct GvdUpdateStats {
  std::size_t changed_cells = 0;      ///< cells whose blocked state actually changed
  std::size_t recomputed_rows = 0;    ///< rows of the second EDT pass that were recomputed
  std::size_t changed_distances = 0;  ///< cells whose distance or nearest site changed
  bool labels_repartitioned = false;  ///< a merge or split of obstacle components happened
  std::size_t row_cells = 0;          ///< cells of the row segments recomputed by the envelope
  std::size_t changed_raw = 0;        ///< cells whose raw Voronoi mark changed
  std::size_t key_changes = 0;        ///< raw cells whose clearance changed (read by the pruning)
  std::size_t thin_key_changes = 0;   ///< ... of which flip the order of two raw neighbours
  std::size_t skeleton_work = 0;      ///< cells the local re-thinning and re-pruning examined
  /// Changes and key changes that the re-thinnings after the pruning rounds left dormant (too
  /// far from every pruned or removed cell to change a decision), and those of them woken up
  /// again because the replay removed a cell nearby.
  std::size_t rethin_dormant = 0;
  std::size_t rethin_woken = 0;
  std::size_t changed_diagram = 0;  ///< cells of the final diagram that changed
  int thinning_steps = 0;           ///< steps of the longest stored thinning run
};

class DynamicGvd {
 public:
  /// Full build. Throws voronav::Error for invalid options.
  explicit DynamicGvd(const BinaryGrid& blocked, const GvdOptions& options = {});

  /// Applies cell changes and updates the diagram locally. Throws voronav::Error for a cell
  /// outside the grid (nothing is changed then).
  GvdUpdateStats update(std::span<const CellChange> changes);

  [[nodiscard]] const GridGeometry& geometry() const { return geometry_; }
  [[nodiscard]] const GvdOptions& options() const { return options_; }
  /// Squared distance [cells^2] to the nearest obstacle (checked access), -1 when none.
  [[nodiscard]] std::int64_t squared_clearance(Cell c) const;
  [[nodiscard]] bool is_blocked(Cell c) const;
  [[nodiscard]] bool is_voronoi(Cell c) const;
  /// A full copy of the current state as a GeneralizedVoronoi (O(cells)).
  [[nodiscard]] GeneralizedVoronoi snapshot() const;

 private:
  // (x, y) of padded index i without an integer division (the quotient from a floating
  // reciprocal, corrected by one).
  [[nodiscard]] std::pair<int, int> xy(std::size_t i) const {
    auto y = static_cast<std::int64_t>(static_cast<double>(i) * inv_pw_);
    std::int64_t r = static_cast<std::int64_t>(i) - y * pw_;
    if (r < 0) {
      --y, r += pw_;
    } else if (r >= pw_) {
      ++y, r -= pw_;
    }
    return {static_cast<int>(r), static_cast<int>(y)};
  }
  [[nodiscard]] std::size_t pidx(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(pw_) +
           static_cast<std::size_t>(x);
  }
  // Column x from scratch (span {-1, -1}) or around the changed rows span (the rows between
  // the nearest obstacles outside it); appends the rows whose column data changed.
  // (row, raised) pairs: raised when the new column value is not lexicographically smaller.
  struct ChangedRow {
    int y;
    bool raised;
    std::int32_t old_site;  // padded index of the column's old site in row y (-1 none)
  };
  void column_pass(int x, std::vector<ChangedRow>* changed_rows, std::pair<int, int> span);
  // Row y where only the columns `cols` changed and all were lowered: min of the old site and
  // the changed columns' sites for the cells [xa, xb].
  void row_lower(int y, int xa, int xb, const std::vector<int>& cols,
                 std::vector<std::size_t>* changed);
  // Row y where the run of columns [c0, c1] was lowered (obstacles added, nothing raised in
  // the row): appends the ranges of cells that a new site of the run can change.
  static constexpr int kMaxHalfPlaneRun = 8;
  void lowered_ranges(int y, int c0, int c1, std::vector<std::pair<int, int>>* ranges) const;
  void grow_span(std::unordered_map<int, std::pair<int, int>>& spans, std::size_t i) const;
  void row_pass(int y, int x0, int x1);
  // Recomputes the cells [xa, xb] of row y exactly from the column data (window of columns
  // bounded by the unchanged cells xa-1 and xb+1); appends the cells that changed.
  void row_segment(int y, int xa, int xb, std::vector<std::size_t>* changed);
  // Floods the blocked component of seed with id; returns how many distinct old labels it met.
  // The flooded cells are appended to `cells` when given.
  int relabel_from(std::size_t seed, std::int32_t id, std::vector<std::size_t>* cells = nullptr);
  // Labels of all obstacle cells; the cells outside the box [bx0, bx1] x [by0, by1] of the
  // non-blocked cells are all blocked (bx1 < 0: no box).
  void full_labels(int bx0, int by0, int bx1, int by1);
  // Labels after a batch; appends the blocked cells whose label changed to `relabeled`.
  bool update_labels(const std::vector<std::size_t>& added, const std::vector<std::size_t>& removed,
                     std::vector<std::size_t>* relabeled);
  [[nodiscard]] bool raw_mark(std::size_t i) const;
  // During update(): whether the key (d2, index) order of raw cell c and one of its raw
  // 8-neighbours differs from before the update.
  [[nodiscard]] bool key_order_flipped(std::size_t c) const;
  // span: an index range holding every raw cell.
  void build_skeleton(std::pair<std::size_t, std::size_t> span);
  [[nodiscard]] double max_spur() const;
  [[nodiscard]] const internal::CellVector<std::uint8_t>& skel() const;
  // site_ and col_arg_ hold the site (padded index) and the column's site row relative to the
  // cell (0: the cell itself, the value of a zeroed array) or kNoRel (none).
  static constexpr std::int32_t kNoRel = std::numeric_limits<std::int32_t>::min();
  [[nodiscard]] std::int32_t site_of(std::size_t i) const {
    const std::int32_t s = site_[i];
    return s == kNoRel ? -1 : static_cast<std::int32_t>(i) + s;
  }
  void set_site(std::size_t i, std::int32_t s) {
    site_[i] = s < 0 ? kNoRel : s - static_cast<std::int32_t>(i);
  }
  [[nodiscard]] std::int32_t col_arg_of(std::size_t i, int y) const {
    const std::int32_t a = col_arg_[i];
    return a == kNoRel ? -1 : y + a;
  }
  void set_col_arg(std::size_t i, int y, std::int32_t a) { col_arg_[i] = a < 0 ? kNoRel : a - y; }

  GvdOptions options_;
  GridGeometry geometry_;
  int pw_ = 0, ph_ = 0;  // padded size (one cell on each side)
  double inv_pw_ = 0.0;  // 1 / pw_
  // Per padded cell, all zeroed at the start (CellVector, see the constructor): blocked, free,
  // or outside and not an obstacle (border not blocked).
  internal::CellVector<std::uint8_t> state_;
  internal::CellVector<std::int64_t>
      col_d_;  // squared vertical distance to the nearest site in the column
  internal::CellVector<std::int32_t> col_arg_;  // row of that site (relative, col_arg_of)
  internal::CellVector<std::int64_t> d2_;       // squared distance (-1 none)
  internal::CellVector<std::int32_t> site_;  // padded index of the nearest site (relative, site_of)
  internal::CellVector<std::int32_t> label_;  // obstacle component id (-1 free)
  std::int32_t next_label_ = 0;
  std::vector<std::int64_t> label_size_;           // cells per label id
  std::int64_t max_d2_ = 0;                        // >= every finite squared distance
  std::vector<std::int32_t> visit_;                // scratch of the split search (-1)
  internal::CellVector<std::uint8_t> mark_;        // scratch marks (0)
  internal::CellVector<std::uint8_t> d2_changed_;  // scratch of update(): the distance changed (0)
  internal::CellVector<std::int64_t> old_d2_;      // scratch of update(): d2 before it changed
  struct LowerCol {   // scratch of row_lower(): a changed column's site
    std::int64_t d;   // squared vertical distance of the site
    int x;            // column
    std::int32_t sy;  // row of the site
    std::int32_t s;   // padded index of the site
  };
  std::vector<LowerCol> lower_cols_;
  internal::CellVector<std::uint8_t> raw_;
  std::vector<internal::ParallelThinning> thins_;  // thin, then (prune, thin) per round
  std::vector<internal::ParallelPruning> prunes_;
};

/// Full build of the generalized Voronoi diagram (see the file comment).
[[nodiscard]] GeneralizedVoronoi build_gvd(const BinaryGrid& blocked,
                                           const GvdOptions& options = {});

/// Thins a diagram in place to one cell wide, removing simple non-end cells in order of
/// increasing `clearance` (any field of the same size; larger = kept longer), sequentially. Used
/// by the cellular-automaton diagram; DynamicGvd uses the order-independent thinning of
/// internal/local_skeleton.hpp instead, which it can update locally.
void thin_diagram(BinaryGrid& diagram, const GridMap<float>& clearance);

/// Thins (as thin_diagram) and then prunes spurs of a diagram in place with the pruning options
/// of `options` (spur_min_length, spur_clearance_ratio, prune_rounds); clearance in [cells].
void prune_diagram(BinaryGrid& diagram, const GridMap<float>& clearance, const GvdOptions& options);

}  // namespace voronav::voronoi
