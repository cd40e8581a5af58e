// The cells a robot's disc sweeps along a straight move: the union of for_each_disc_cell(c, r)
// over the Bresenham cells c of the move (what RobotAgent::segment_known_free checks). Visiting
// the whole disc at every line cell looks up each swept cell about 2r + 1 times; consecutive line
// cells differ by one of 8 steps, and the disc moved by a step only adds the cells of a thin
// crescent, so after the first disc only those are visited (precomputed per step). The union is
// the same (disc(c_i) is in disc(c_i-1) plus its crescent), so a check over it (all free? any
// occupied?) gives the same answer; a cell may still be visited twice, which such checks allow.
// Hot spot of the decentralized search (own-edge checks) on scenario 4 and at scale
// (docs/reproductions/networked.md, "Issue #13, stop 17").
#pragma once

#include <algorithm>
#include <array>
#include <cstdlib>
#include <vector>

#include "voronav/core/cell.hpp"
#include "voronav/core/cell_iterators.hpp"

namespace voronav::sim {

class DiscSweep {
 public:
  /// radius in cells, as for_each_disc_cell (negative or NaN: the disc has no cells).
  explicit DiscSweep(double radius_cells) {
    for_each_disc_cell(Cell{0, 0}, radius_cells, [&](Cell o) { disc_.push_back(o); });
    for (Cell o : disc_) {
      reach_.x = std::max(reach_.x, std::abs(o.x));
      reach_.y = std::max(reach_.y, std::abs(o.y));
    }
    auto in_disc = [&](Cell o) {
      for (Cell d : disc_)
        if (d == o) return true;
      return false;
    };
    for (int sy = -1; sy <= 1; ++sy)
      for (int sx = -1; sx <= 1; ++sx) {
        auto& added = added_[step_index(sx, sy)];
        // disc(c + s) \ disc(c), as offsets from c + s: o with o + s outside the disc.
        for (Cell o : disc_)
          if (!in_disc(Cell{o.x + sx, o.y + sy})) added.push_back(o);
      }
  }

  /// Cells of the disc (offsets from its centre).
  [[nodiscard]] const std::vector<Cell>& disc() const { return disc_; }
  /// The largest |dx| and the largest |dy| of a disc cell ({0, 0} for an empty disc).
  [[nodiscard]] Cell reach() const { return reach_; }
  /// Offsets a step (sx, sy) in {-1, 0, 1}^2 adds (from the new centre).
  [[nodiscard]] const std::vector<Cell>& added(int sx, int sy) const {
    return added_[step_index(sx, sy)];
  }

  /// Visits every cell of the union of the discs centred on the Bresenham cells from a to b
  /// (some cells twice); stops when visit returns false. Returns false when it stopped.
  template <typename F>
  bool visit(Cell a, Cell b, F&& visit_cell) const {
    if (disc_.empty()) return true;
    Cell prev = a;
    bool first = true;
    return for_each_line_cell(a, b, [&](Cell c) {
      const auto& offs = first ? disc_ : added_[step_index(c.x - prev.x, c.y - prev.y)];
      first = false;
      prev = c;
      for (Cell o : offs)
        if (!visit_cell(Cell{c.x + o.x, c.y + o.y})) return false;
      return true;
    });
  }

 private:
  static std::size_t step_index(int sx, int sy) {
    return static_cast<std::size_t>((sy + 1) * 3 + (sx + 1));
  }
  std::vector<Cell> disc_;
  Cell reach_{0, 0};
  std::array<std::vector<Cell>, 9> added_;
};

}  // namespace voronav::sim
