#include "voronav/topology/segmentation.hpp"

#include <algorithm>
#include <unordered_map>
#include <vector>

#include "voronav/core/error.hpp"

namespace voronav::topology {

GridMap<std::int32_t> free_components(const BinaryGrid& blocked, bool eight) {
  const GridGeometry& g = blocked.geometry();
  GridMap<std::int32_t> out(g, -1);
  std::int32_t n = 0;
  std::vector<Cell> stack;
  for (std::size_t i = 0; i < blocked.size(); ++i) {
    if (blocked[i] || out[i] >= 0) continue;
    out[i] = n;
    stack.push_back(g.cell_at(i));
    while (!stack.empty()) {
      const Cell c = stack.back();
      stack.pop_back();
      for (int k = 0; k < (eight ? 8 : 4); ++k) {
        const Cell q = c + kNeighbours8[k];
        if (!g.contains(q) || blocked[q] || out[q] >= 0) continue;
        out[q] = n;
        stack.push_back(q);
      }
    }
    ++n;
  }
  return out;
}

namespace {

using AreaMap = std::unordered_map<std::int32_t, std::size_t>;
using OverlapMap = std::unordered_map<std::uint64_t, std::size_t>;

std::uint64_t overlap_key(std::int32_t room, std::int32_t region) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(room)) << 32) |
         static_cast<std::uint32_t>(region);
}

// Recall: mean over rooms of (largest overlap with one region) / room area; precision: the same
// over regions. Both scores share this once the areas and overlaps are counted.
SegmentationScores scores_from_overlap(const AreaMap& room_area, const AreaMap& region_area,
                                       const OverlapMap& overlap) {
  AreaMap best_room, best_region;
  for (const auto& [k, n] : overlap) {
    const auto room = static_cast<std::int32_t>(k >> 32);
    const auto region = static_cast<std::int32_t>(k & 0xffffffffU);
    best_room[room] = std::max(best_room[room], n);
    best_region[region] = std::max(best_region[region], n);
  }
  SegmentationScores s;
  s.rooms = static_cast<int>(room_area.size());
  s.regions = static_cast<int>(region_area.size());
  for (const auto& [room, a] : room_area)
    s.recall += static_cast<double>(best_room[room]) / static_cast<double>(a);
  for (const auto& [region, a] : region_area)
    s.precision += static_cast<double>(best_region[region]) / static_cast<double>(a);
  if (s.rooms > 0) s.recall /= s.rooms;
  if (s.regions > 0) s.precision /= s.regions;
  return s;
}

}  // namespace

SegmentationScores segmentation_scores_ipa(const GridMap<std::int32_t>& regions,
                                           const BinaryGrid& ground_truth, std::size_t min_pixels) {
  if (regions.width() != ground_truth.width() || regions.height() != ground_truth.height())
    throw Error("segmentation_scores_ipa", 0,
                "the segmentation is " + std::to_string(regions.width()) + "x" +
                    std::to_string(regions.height()) + " but the ground truth is " +
                    std::to_string(ground_truth.width()) + "x" +
                    std::to_string(ground_truth.height()));
  const GridMap<std::int32_t> rooms = free_components(ground_truth, true);
  std::unordered_map<std::int32_t, std::size_t> room_area, region_area;
  std::unordered_map<std::uint64_t, std::size_t> overlap;
  for (std::size_t i = 0; i < rooms.size(); ++i) {
    if (rooms[i] >= 0) room_area[rooms[i]]++;
    if (regions[i] >= 0) region_area[regions[i]]++;
  }
  std::erase_if(room_area, [&](const auto& kv) { return kv.second <= min_pixels; });
  std::erase_if(region_area, [&](const auto& kv) { return kv.second <= min_pixels; });
  for (std::size_t i = 0; i < rooms.size(); ++i) {
    const std::int32_t room = rooms[i], region = regions[i];
    if (room < 0 || region < 0 || !room_area.contains(room) || !region_area.contains(region))
      continue;
    overlap[overlap_key(room, region)]++;
  }
  return scores_from_overlap(room_area, region_area, overlap);
}

BinaryGrid resample_nearest(const BinaryGrid& grid, int width, int height) {
  if (width <= 0 || height <= 0 || grid.width() <= 0 || grid.height() <= 0)
    throw Error("resample_nearest", 0, "empty grid or target size");
  BinaryGrid out(GridGeometry{width, height, grid.resolution() * grid.width() / width, {}}, 1);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const int sx = std::min(grid.width() - 1, static_cast<int>((x + 0.5) * grid.width() / width));
      const int sy =
          std::min(grid.height() - 1, static_cast<int>((y + 0.5) * grid.height() / height));
      out[Cell{x, y}] = grid[Cell{sx, sy}];
    }
  return out;
}

SegmentationScores segmentation_scores(const GridMap<std::int32_t>& regions,
                                       const GridMap<std::int32_t>& rooms,
                                       std::size_t min_room_cells) {
  if (regions.width() != rooms.width() || regions.height() != rooms.height())
    throw Error("segmentation_scores", 0,
                "the segmentation is " + std::to_string(regions.width()) + "x" +
                    std::to_string(regions.height()) + " but the ground truth is " +
                    std::to_string(rooms.width()) + "x" + std::to_string(rooms.height()));
  std::unordered_map<std::int32_t, std::size_t> room_size;
  for (std::size_t i = 0; i < rooms.size(); ++i)
    if (rooms[i] >= 0) room_size[rooms[i]]++;
  std::unordered_map<std::int32_t, std::size_t> room_area, region_area;
  std::unordered_map<std::uint64_t, std::size_t> overlap;
  for (std::size_t i = 0; i < rooms.size(); ++i) {
    const std::int32_t room = rooms[i], region = regions[i];
    if (room < 0 || region < 0 || room_size[room] < min_room_cells) continue;
    room_area[room]++;
    region_area[region]++;
    overlap[overlap_key(room, region)]++;
  }
  return scores_from_overlap(room_area, region_area, overlap);
}

}  // namespace voronav::topology
