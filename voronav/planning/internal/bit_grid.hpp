// BitGrid: a BinaryGrid packed one bit per cell (1 = free), row by row, with a blocked border of
// one row above and below and kPad blocked bits left of column 0 (plus a spare word per row), so
// 64-bit windows can be read at any column without bounds checks. It is the map representation of
// block-based jump point search (Harabor & Grastien, "Improving Jump Point Search", ICAPS 2014,
// section 3): a jump scans 63 cells per step with a few shifts and one count-zeros. Built
// transposed as well, so vertical jumps are horizontal scans of the transpose.
#pragma once

#include <bit>
#include <cstdint>
#include <vector>

#include "voronav/core/occupancy.hpp"

namespace voronav::planning::internal {

class BitGrid {
 public:
  static constexpr int kPad = 64;

  BitGrid() = default;
  /// Packs `grid` (0 = free); transposed: bit row r holds grid column r.
  BitGrid(const BinaryGrid& grid, bool transposed) {
    rows_ = (transposed ? grid.width() : grid.height()) + 2;
    cols_ = transposed ? grid.height() : grid.width();
    words_ = static_cast<std::size_t>((kPad + cols_ + 1 + 63) / 64 + 1);
    bits_.assign(words_ * static_cast<std::size_t>(rows_), 0);
    for (int y = 0; y < grid.height(); ++y)
      for (int x = 0; x < grid.width(); ++x)
        if (grid[Cell{x, y}] == 0) {
          if (transposed)
            set(x, y);
          else
            set(y, x);
        }
  }

  /// Bit of cell `col` in row `row` (both unpadded; row -1 and col -1 read as blocked).
  [[nodiscard]] bool free(int row, int col) const {
    const std::size_t b = static_cast<std::size_t>(col + kPad);
    return (word(row, b >> 6) >> (b & 63)) & 1U;
  }

  /// Bits of cells col .. col+63 of `row` (bit 0 = col).
  [[nodiscard]] std::uint64_t forward(int row, int col) const {
    const std::size_t b = static_cast<std::size_t>(col + kPad);
    const std::size_t i = b >> 6, off = b & 63;
    std::uint64_t v = word(row, i) >> off;
    if (off != 0) v |= word(row, i + 1) << (64 - off);
    return v;
  }
  /// Bits of cells col-63 .. col of `row` (bit 63 = col).
  [[nodiscard]] std::uint64_t backward(int row, int col) const { return forward(row, col - 63); }

 private:
  [[nodiscard]] std::uint64_t word(int row, std::size_t i) const {
    return bits_[static_cast<std::size_t>(row + 1) * words_ + i];
  }
  void set(int row, int col) {
    const std::size_t b = static_cast<std::size_t>(col + kPad);
    bits_[static_cast<std::size_t>(row + 1) * words_ + (b >> 6)] |= std::uint64_t{1} << (b & 63);
  }

  int rows_ = 0, cols_ = 0;
  std::size_t words_ = 0;
  std::vector<std::uint64_t> bits_;
};

/// Block-based straight jump (Harabor & Grastien 2014, algorithm "jump east" on bit words) along
/// `row` of `g` from column `col` (free) in direction `dir` (+1 or -1), for 8-connected grids
/// without corner cutting: stops at the first column c where a neighbour row turns from blocked
/// (at c - dir) to free (at c) — a forced neighbour — or at `target` (the goal's column when the
/// goal lies on this row, else INT_MIN). Returns that column, or kNoJump when a wall comes first.
inline constexpr int kNoJump = -0x7fffffff;

inline int scan_straight(const BitGrid& g, int row, int col, int dir, int target) {
  if (dir > 0) {
    for (int c = col;; c += 63) {
      const std::uint64_t cur = g.forward(row, c);
      const std::uint64_t up = g.forward(row + 1, c), dn = g.forward(row - 1, c);
      const std::uint64_t stop = ((up & ~(up << 1)) | (dn & ~(dn << 1)) | ~cur) & ~std::uint64_t{1};
      if (stop != 0) {
        const int s = c + std::countr_zero(stop);
        if (target > col && target <= s && (target < s || ((cur >> (s - c)) & 1U))) return target;
        return ((cur >> (s - c)) & 1U) ? s : kNoJump;
      }
      if (target > c && target <= c + 63) return target;
    }
  }
  for (int c = col;; c -= 63) {
    const std::uint64_t cur = g.backward(row, c);
    const std::uint64_t up = g.backward(row + 1, c), dn = g.backward(row - 1, c);
    const std::uint64_t top = std::uint64_t{1} << 63;
    const std::uint64_t stop = ((up & ~(up >> 1)) | (dn & ~(dn >> 1)) | ~cur) & ~top;
    if (stop != 0) {
      const int s = c - std::countl_zero(stop);
      const bool s_free = (cur >> (63 - (c - s))) & 1U;
      if (target < col && target != kNoJump && target >= s && (target > s || s_free)) return target;
      return s_free ? s : kNoJump;
    }
    if (target != kNoJump && target < c && target >= c - 63) return target;
  }
}

}  // namespace voronav::planning::internal
