// Tests of the team map caches of an exploration run (internal/map_cache.hpp): a value is made
// once per map version, kept (same object) while the version stays, and made afresh when it
// changes, including a version 0 that is asked first.
#include <gtest/gtest.h>

#include "voronav/exploration/internal/map_cache.hpp"

namespace voronav::exploration::internal {
namespace {

TEST(MapCache, MakesOncePerVersion) {
  MapCache<int> cache;
  int made = 0;
  const auto make = [&] { return ++made * 10; };
  const int& first = cache.get(0, make);  // version 0 first: made, not taken as cached
  EXPECT_EQ(first, 10);
  EXPECT_EQ(made, 1);
  EXPECT_EQ(&cache.get(0, make), &first);  // same version: the same object, not made again
  EXPECT_EQ(made, 1);
  EXPECT_EQ(cache.get(1, make), 20);  // the map changed: made afresh
  EXPECT_EQ(made, 2);
  EXPECT_EQ(cache.get(1, make), 20);
  EXPECT_EQ(made, 2);
  EXPECT_EQ(cache.get(0, make), 30);  // any other version, not only a larger one
  EXPECT_EQ(made, 3);
}

}  // namespace
}  // namespace voronav::exploration::internal
