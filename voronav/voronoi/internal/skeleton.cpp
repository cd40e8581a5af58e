#include "voronav/voronoi/internal/skeleton.hpp"

#include <algorithm>
#include <cmath>

namespace voronav::voronoi::internal {

int skeleton_degree(const std::vector<std::uint8_t>& skel, const PaddedRaster& r, std::size_t i) {
  int n = 0;
  for (int k = 0; k < 8; ++k)
    n += skel[static_cast<std::size_t>(static_cast<std::ptrdiff_t>(i) + r.offset(k))] != 0;
  return n;
}

int yokoi8(const std::vector<std::uint8_t>& skel, const PaddedRaster& r, std::size_t i) {
  int xb[9];  // complement of the neighbours, x9 = x1
  for (int k = 0; k < 8; ++k)
    xb[k] = skel[static_cast<std::size_t>(static_cast<std::ptrdiff_t>(i) + r.offset(k))] ? 0 : 1;
  xb[8] = xb[0];
  int n = 0;
  for (int k = 0; k < 8; k += 2)
    n += xb[k] - xb[k] * xb[k + 1] * xb[(k + 2) % 8];
  return n;
}

void thin(std::vector<std::uint8_t>& skel, const PaddedRaster& r,
          const std::vector<std::size_t>& order) {
  bool changed = true;
  while (changed) {
    changed = false;
    for (const std::size_t i : order) {
      if (!skel[i]) continue;
      if (skeleton_degree(skel, r, i) <= 1) continue;  // end points stay
      if (yokoi8(skel, r, i) != 1) continue;
      skel[i] = 0;
      changed = true;
    }
  }
}

std::size_t prune_spurs(std::vector<std::uint8_t>& skel, const PaddedRaster& r,
                        const std::function<double(std::size_t)>& threshold) {
  std::vector<std::size_t> ends;
  for (std::size_t i = 0; i < skel.size(); ++i)
    if (skel[i] && skeleton_degree(skel, r, i) == 1) ends.push_back(i);
  std::size_t removed = 0;
  std::vector<std::size_t> path;
  for (const std::size_t e : ends) {
    if (!skel[e] || skeleton_degree(skel, r, e) != 1) continue;
    path.assign(1, e);
    std::size_t prev = e, cur = e;
    double length = 0.0;
    bool junction = false;
    while (true) {
      if (cur != e && skeleton_degree(skel, r, cur) >= 3) {
        junction = true;
        break;
      }
      // Next cell: a skeleton neighbour not yet on the path, straight neighbours first.
      std::size_t next = cur;
      double step = 0.0;
      for (int pass = 0; pass < 2 && next == cur; ++pass) {
        for (int k = pass; k < 8; k += 2) {
          const auto j = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(cur) + r.offset(k));
          if (!skel[j] || j == prev) continue;
          if (std::find(path.end() -
                            std::min<std::ptrdiff_t>(3, static_cast<std::ptrdiff_t>(path.size())),
                        path.end(), j) != path.end())
            continue;
          next = j;
          step = pass == 0 ? 1.0 : std::sqrt(2.0);
          break;
        }
      }
      if (next == cur) break;  // the other end of an isolated branch: never pruned
      length += step;
      prev = cur;
      cur = next;
      path.push_back(cur);
    }
    if (!junction || length >= threshold(cur)) continue;
    for (std::size_t k = 0; k + 1 < path.size(); ++k) {
      skel[path[k]] = 0;
      ++removed;
    }
  }
  return removed;
}

}  // namespace voronav::voronoi::internal
