// GridMap<T>: a row-major 2-D grid of T with a GridGeometry (resolution, origin). The shared
// container of every raster in voronav: occupancy, distance fields, labels, region ids.
#pragma once

#include <cassert>
#include <cstddef>
#include <span>
#include <vector>

#include "voronav/core/error.hpp"
#include "voronav/core/grid_geometry.hpp"

namespace voronav {

template <typename T>
class GridMap {
 public:
  using value_type = T;

  GridMap() = default;
  explicit GridMap(GridGeometry geometry, T fill = T{}) : geometry_(geometry) {
    if (geometry.width < 0 || geometry.height < 0)
      throw Error("GridMap: width and height must be >= 0");
    if (!(geometry.resolution > 0.0) || !std::isfinite(geometry.resolution))
      throw Error("GridMap: resolution must be a positive finite number");
    data_.assign(geometry_.size(), fill);
  }
  GridMap(int width, int height, T fill = T{}, double resolution = 1.0)
      : GridMap(GridGeometry{width, height, resolution, {}}, fill) {}

  [[nodiscard]] const GridGeometry& geometry() const { return geometry_; }
  [[nodiscard]] int width() const { return geometry_.width; }
  [[nodiscard]] int height() const { return geometry_.height; }
  [[nodiscard]] double resolution() const { return geometry_.resolution; }
  [[nodiscard]] std::size_t size() const { return data_.size(); }
  [[nodiscard]] bool empty() const { return data_.empty(); }
  [[nodiscard]] bool contains(Cell c) const { return geometry_.contains(c); }
  [[nodiscard]] std::size_t index(Cell c) const { return geometry_.index(c); }
  [[nodiscard]] Cell cell_at(std::size_t i) const { return geometry_.cell_at(i); }

  /// Unchecked access (asserts in debug builds).
  [[nodiscard]] T& operator[](Cell c) {
    assert(contains(c));
    return data_[index(c)];
  }
  [[nodiscard]] const T& operator[](Cell c) const {
    assert(contains(c));
    return data_[index(c)];
  }
  [[nodiscard]] T& operator[](std::size_t i) { return data_[i]; }
  [[nodiscard]] const T& operator[](std::size_t i) const { return data_[i]; }
  /// Checked access: throws voronav::Error for a cell outside the grid.
  [[nodiscard]] T& at(Cell c) {
    check(c);
    return data_[index(c)];
  }
  [[nodiscard]] const T& at(Cell c) const {
    check(c);
    return data_[index(c)];
  }

  [[nodiscard]] std::span<T> data() { return data_; }
  [[nodiscard]] std::span<const T> data() const { return data_; }
  [[nodiscard]] const std::vector<T>& values() const { return data_; }
  void fill(const T& v) { std::fill(data_.begin(), data_.end(), v); }

  friend bool operator==(const GridMap&, const GridMap&) = default;

 private:
  void check(Cell c) const {
    if (!contains(c))
      throw Error("GridMap: cell (" + std::to_string(c.x) + ", " + std::to_string(c.y) +
                  ") is outside the " + std::to_string(width()) + "x" + std::to_string(height()) +
                  " grid");
  }

  GridGeometry geometry_;
  std::vector<T> data_;
};

}  // namespace voronav
