// A robot's answers to "is the straight move a -> b known free in its own map?" (the own-edge
// check of the decentralized point search, RobotAgent::try_continue), kept until the map changes.
// A relay runs the point search again for every copy of a Search it hears, and between two
// copies its map and its own points usually stay the same, so the same moves are checked again
// and again (a quarter of the time of 100 robots on willow, docs/reproductions/networked.md,
// "Scale"). The answer depends only on the map and the two positions, so caching it changes no
// result; the work counter (eq. 8-9) still counts each check the search asks for. The cache is
// bounded: when it holds max_entries answers it forgets them all (a robot whose map stays
// unchanged for a long time would otherwise keep every answer); forgetting changes no result.
#pragma once

#include <cstdint>
#include <cstring>
#include <functional>
#include <unordered_map>

#include "voronav/core/vec2.hpp"

namespace voronav::sim {

class SegmentCache {
 public:
  /// At most this many answers are kept (~40 bytes each plus the table: ~4 MB at the default).
  static constexpr std::size_t kDefaultMaxEntries = std::size_t{1} << 16;
  explicit SegmentCache(std::size_t max_entries = kDefaultMaxEntries)
      : max_entries_(max_entries < 1 ? 1 : max_entries) {}

  /// The answer for a -> b in the map of `version` (LocalMap::version()): cached, or
  /// compute() stored. A new version, or a full cache, forgets every answer.
  template <typename F>
  bool get(std::uint64_t version, Vec2 a, Vec2 b, F&& compute) {
    if (version != version_) {
      answers_.clear();
      version_ = version;
    }
    const Key k{a.x, a.y, b.x, b.y};
    if (const auto it = answers_.find(k); it != answers_.end()) return it->second;
    const bool v = compute();
    if (answers_.size() >= max_entries_) answers_.clear();
    answers_.emplace(k, v);
    return v;
  }
  [[nodiscard]] std::size_t size() const { return answers_.size(); }
  [[nodiscard]] std::size_t max_entries() const { return max_entries_; }

 private:
  struct Key {
    double ax, ay, bx, by;
    bool operator==(const Key& o) const {
      return ax == o.ax && ay == o.ay && bx == o.bx && by == o.by;
    }
  };
  struct Hash {
    std::size_t operator()(const Key& k) const {
      std::size_t h = 0;
      for (double d : {k.ax, k.ay, k.bx, k.by}) {
        std::uint64_t u = 0;
        std::memcpy(&u, &d, sizeof u);
        h ^= std::hash<std::uint64_t>{}(u) + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
      }
      return h;
    }
  };
  std::size_t max_entries_;
  std::uint64_t version_ = ~std::uint64_t{0};
  std::unordered_map<Key, bool, Hash> answers_;
};

}  // namespace voronav::sim
