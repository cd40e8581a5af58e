// A value derived from the team map (a grid, a distance field), kept until the map changes
// (run_exploration; not installed). The team map changes only when the robots sense
// (TeamRun::sense() bumps its version), so the grids every mechanism plans on are built once per
// map version instead of once per caller, and no caller has to pass them down to the next.
#pragma once

#include <cstdint>
#include <optional>
#include <utility>

namespace voronav::exploration::internal {

template <class T>
class MapCache {
 public:
  /// The value for map version `version`: make() when there is none yet or it is of another
  /// version. The reference stays valid until get() is called with another version.
  template <class Make>
  [[nodiscard]] const T& get(std::uint64_t version, Make&& make) {
    if (!value_ || version != version_) {
      value_ = std::forward<Make>(make)();
      version_ = version;
    }
    return *value_;
  }

 private:
  std::optional<T> value_;
  std::uint64_t version_ = 0;
};

}  // namespace voronav::exploration::internal
