// IndexedMinHeap: a binary min-heap over node ids 0..n-1 with decrease-key, keyed by (f, -g) so
// that among equal f the node with the larger g (nearer the goal) comes first. Positions live in a
// caller-owned array so a search reuses all memory between queries (no per-node allocation).
#pragma once

#include <cstdint>
#include <vector>

namespace voronav::planning::internal {

class IndexedMinHeap {
 public:
  static constexpr std::int32_t kNotInHeap = -1;

  /// Clears the heap; `position` must have one slot per node, all kNotInHeap for nodes not in it.
  void reset(std::vector<std::int32_t>* position) {
    pos_ = position;
    items_.clear();
  }
  /// Empties the heap and marks its remaining nodes as not in it (O(size)).
  void clear() {
    for (const Item& it : items_) (*pos_)[static_cast<std::size_t>(it.node)] = kNotInHeap;
    items_.clear();
  }
  [[nodiscard]] bool empty() const { return items_.empty(); }
  [[nodiscard]] std::size_t size() const { return items_.size(); }

  void push_or_decrease(std::int32_t node, double f, double g) {
    std::int32_t p = (*pos_)[static_cast<std::size_t>(node)];
    if (p == kNotInHeap) {
      items_.push_back({f, g, node});
      p = static_cast<std::int32_t>(items_.size() - 1);
      (*pos_)[static_cast<std::size_t>(node)] = p;
    } else {
      items_[static_cast<std::size_t>(p)].f = f;
      items_[static_cast<std::size_t>(p)].g = g;
    }
    sift_up(static_cast<std::size_t>(p));
  }

  /// Removes and returns the node with the smallest key.
  std::int32_t pop() {
    const std::int32_t top = items_.front().node;
    (*pos_)[static_cast<std::size_t>(top)] = kNotInHeap;
    const Item last = items_.back();
    items_.pop_back();
    if (!items_.empty()) {
      items_[0] = last;
      (*pos_)[static_cast<std::size_t>(last.node)] = 0;
      sift_down(0);
    }
    return top;
  }

 private:
  struct Item {
    double f;
    double g;
    std::int32_t node;
  };
  static bool less(const Item& a, const Item& b) { return a.f < b.f || (a.f == b.f && a.g > b.g); }

  void place(std::size_t i, const Item& it) {
    items_[i] = it;
    (*pos_)[static_cast<std::size_t>(it.node)] = static_cast<std::int32_t>(i);
  }
  void sift_up(std::size_t i) {
    const Item it = items_[i];
    while (i > 0) {
      const std::size_t parent = (i - 1) / 2;
      if (!less(it, items_[parent])) break;
      place(i, items_[parent]);
      i = parent;
    }
    place(i, it);
  }
  void sift_down(std::size_t i) {
    const Item it = items_[i];
    const std::size_t n = items_.size();
    while (true) {
      std::size_t c = 2 * i + 1;
      if (c >= n) break;
      if (c + 1 < n && less(items_[c + 1], items_[c])) ++c;
      if (!less(items_[c], it)) break;
      place(i, items_[c]);
      i = c;
    }
    place(i, it);
  }

  std::vector<Item> items_;
  std::vector<std::int32_t>* pos_ = nullptr;
};

}  // namespace voronav::planning::internal
