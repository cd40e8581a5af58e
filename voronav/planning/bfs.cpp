#include "voronav/planning/bfs.hpp"

#include <algorithm>

namespace voronav::planning {

std::size_t BfsFlood::flood(const BinaryGrid& grid, Cell start, Connectivity connectivity) {
  const std::size_t n = grid.size();
  dist_.assign(n, -1);
  queue_.resize(n);
  reached_ = 0;
  if (!grid.contains(start) || grid[start] != 0) return 0;
  const int w = grid.width(), h = grid.height();
  const auto* cells = grid.data().data();
  const bool eight = connectivity == Connectivity::k8;
  std::size_t head = 0, tail = 0;
  const auto s = static_cast<std::int32_t>(grid.index(start));
  dist_[static_cast<std::size_t>(s)] = 0;
  queue_[tail++] = s;
  auto visit = [&](std::size_t ni, std::int32_t d) {
    if (dist_[ni] < 0) {
      dist_[ni] = d;
      queue_[tail++] = static_cast<std::int32_t>(ni);
    }
  };
  const auto uw = static_cast<std::size_t>(w);
  while (head < tail) {
    const auto cu = static_cast<std::size_t>(queue_[head++]);
    const int x = static_cast<int>(cu % uw), y = static_cast<int>(cu / uw);
    const std::int32_t d = dist_[cu] + 1;
    const bool e = x + 1 < w && cells[cu + 1] == 0;
    const bool wst = x > 0 && cells[cu - 1] == 0;
    const bool nth = y + 1 < h && cells[cu + uw] == 0;
    const bool sth = y > 0 && cells[cu - uw] == 0;
    if (e) visit(cu + 1, d);
    if (nth) visit(cu + uw, d);
    if (wst) visit(cu - 1, d);
    if (sth) visit(cu - uw, d);
    if (eight) {
      if (e && nth && cells[cu + uw + 1] == 0) visit(cu + uw + 1, d);
      if (wst && nth && cells[cu + uw - 1] == 0) visit(cu + uw - 1, d);
      if (wst && sth && cells[cu - uw - 1] == 0) visit(cu - uw - 1, d);
      if (e && sth && cells[cu - uw + 1] == 0) visit(cu - uw + 1, d);
    }
  }
  reached_ = tail;
  return tail;
}

std::int32_t BfsFlood::steps(const BinaryGrid& grid, Cell c) const {
  if (!grid.contains(c) || dist_.size() != grid.size()) return -1;
  return dist_[grid.index(c)];
}

}  // namespace voronav::planning
