// SegmentCache (segment_cache.hpp): answers are kept until the map version changes, and never
// more than max_entries of them; forgetting only costs asking again, never a different answer.
#include "voronav/sim/segment_cache.hpp"

#include <gtest/gtest.h>

namespace voronav::sim {
namespace {

TEST(SegmentCache, KeepsAnswersPerVersionAndStaysWithinItsBound) {
  SegmentCache cache(8);
  EXPECT_EQ(cache.max_entries(), 8u);
  int computed = 0;
  // "Free" when the move ends right of x = 50 (any pure function of the two ends).
  auto ask = [&](std::uint64_t version, int bx) {
    return cache.get(version, Vec2{0.0, 0.0}, Vec2{static_cast<double>(bx), 1.0}, [&] {
      ++computed;
      return bx > 50;
    });
  };
  EXPECT_FALSE(ask(1, -1));
  EXPECT_FALSE(ask(1, -1));
  EXPECT_EQ(computed, 1) << "the second question is answered from the cache";
  // 100 different moves in one map version: the cache never holds more than 8, and every
  // answer is the computed one.
  for (int i = 0; i < 100; ++i) {
    EXPECT_EQ(ask(1, i), i > 50) << i;
    EXPECT_LE(cache.size(), 8u) << i;
  }
  EXPECT_EQ(computed, 101);
  // The latest answers are still held; one forgotten at the bound is computed again, the same.
  EXPECT_TRUE(ask(1, 99));
  EXPECT_EQ(computed, 101);
  EXPECT_FALSE(ask(1, -1));
  EXPECT_EQ(computed, 102);
  // A new map version forgets every answer.
  EXPECT_TRUE(ask(2, 99));
  EXPECT_EQ(computed, 103);
  EXPECT_EQ(cache.size(), 1u);
}

}  // namespace
}  // namespace voronav::sim
