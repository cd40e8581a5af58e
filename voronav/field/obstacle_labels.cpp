#include "voronav/field/obstacle_labels.hpp"

#include <vector>

namespace voronav::field {

ObstacleLabels label_obstacles(const BinaryGrid& blocked) {
  ObstacleLabels out{GridMap<std::int32_t>(blocked.geometry(), kNoLabel), 0};
  const GridGeometry& g = blocked.geometry();
  std::vector<Cell> stack;
  for (std::size_t i = 0; i < blocked.size(); ++i) {
    if (blocked[i] == 0 || out.label[i] != kNoLabel) continue;
    const std::int32_t id = out.count++;
    out.label[i] = id;
    stack.push_back(g.cell_at(i));
    while (!stack.empty()) {
      const Cell c = stack.back();
      stack.pop_back();
      for (const Cell d : kNeighbours8) {
        const Cell n = c + d;
        if (!g.contains(n)) continue;
        const std::size_t j = g.index(n);
        if (blocked[j] == 0 || out.label[j] != kNoLabel) continue;
        out.label[j] = id;
        stack.push_back(n);
      }
    }
  }
  return out;
}

}  // namespace voronav::field
