// sense(): exact range-limited sensing into a robot's local map (seed 000, section 4.1). It walks
// a stencil of Bresenham lines traced once per range; these tests compare it with tracing every
// line on the spot, cell by cell, as the definition says.
#include "voronav/sim/world.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "voronav/core/cell_iterators.hpp"

namespace voronav::sim {
namespace {

// The definition: a disc cell is copied when no blocked cell lies on the line before it.
SenseResult sense_by_definition(const BinaryGrid& truth, Vec2 position, double range_m,
                                LocalMap& map) {
  SenseResult out;
  const auto& g = truth.geometry();
  const auto rc = g.world_to_cell(position);
  if (!rc || !truth.contains(*rc)) return out;
  const double rcells = range_m / g.resolution;
  const int r = static_cast<int>(std::ceil(rcells));
  map.ensure(*rc - Cell{r, r}, *rc + Cell{r, r});  // the window grows as in sense()
  for_each_disc_cell(*rc, rcells, [&](Cell c) {
    ++out.cells;
    if (!truth.contains(c)) return;
    bool visible = true;
    for_each_line_cell(*rc, c, [&](Cell l) {
      if (l == c) return false;
      ++out.cells;
      if (truth[l]) visible = false;
      return visible;
    });
    if (!visible) return;
    const std::int8_t v = truth[c] ? kOccupied : kFree;
    if (map.at(c) != v) {
      map.set(c, v);
      out.changed = true;
    }
  });
  return out;
}

TEST(World, SenseEqualsTracingEveryLine) {
  std::size_t visible_cells = 0;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double res = seed % 2 ? 0.05 : 0.2;
    BinaryGrid truth(
        GridGeometry{20 + static_cast<int>(rng() % 60), 20 + static_cast<int>(rng() % 60), res, {}},
        0);
    const double density = 0.3 * u(rng);
    for (std::size_t i = 0; i < truth.size(); ++i)
      truth[i] = u(rng) < density ? 1 : 0;
    LocalMap a(truth.geometry()), b(truth.geometry());
    // Ranges change from call to call (the stencil is rebuilt), positions reach the borders.
    for (int k = 0; k < 4; ++k) {
      const double range = k % 3 == 0 ? 3.0 : 0.5 + 2.5 * u(rng);
      const Vec2 p{u(rng) * truth.width() * res, u(rng) * truth.height() * res};
      const auto got = sense(truth, p, range, a);
      const auto want = sense_by_definition(truth, p, range, b);
      ASSERT_EQ(got.cells, want.cells) << "seed " << seed << " call " << k;
      ASSERT_EQ(got.changed, want.changed) << "seed " << seed << " call " << k;
      ASSERT_EQ(a.offset(), b.offset());
      ASSERT_EQ(a.grid().values(), b.grid().values()) << "seed " << seed << " call " << k;
      EXPECT_EQ(a.version() > 0, b.version() > 0);
    }
    visible_cells += a.known_cells();
  }
  EXPECT_GT(visible_cells, 2000u);  // the maps are not empty
}

TEST(World, LocalMapVersionChangesWithEverySet) {
  LocalMap m(GridGeometry{10, 10, 0.1, {}});
  const auto v0 = m.version();
  m.set(Cell{2, 3}, kFree);
  EXPECT_NE(m.version(), v0);
  const auto v1 = m.version();
  m.ensure(Cell{0, 0}, Cell{9, 9});  // growing the window changes no value
  EXPECT_EQ(m.version(), v1);
}

}  // namespace
}  // namespace voronav::sim
