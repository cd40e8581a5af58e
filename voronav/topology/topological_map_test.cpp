#include "voronav/topology/topological_map.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <set>

#include "voronav/core/error.hpp"
#include "voronav/topology/topo_planner.hpp"
#include "voronav/voronoi/test_maps.hpp"

namespace voronav::topology {
namespace {

using voronoi::testing::fill_rect;
using voronoi::testing::random_room;
using voronoi::testing::two_rooms;

// n rooms in a row (each room_w x h inside), one door of `door` cells between neighbours.
BinaryGrid rooms_in_a_row(int n, int room_w = 24, int h = 20, int door = 4) {
  const int w = n * (room_w + 1) + 1;
  BinaryGrid g(GridGeometry{w, h + 2, 0.1, {}}, 0);
  fill_rect(g, 0, 0, w - 1, 0);
  fill_rect(g, 0, h + 1, w - 1, h + 1);
  for (int k = 0; k <= n; ++k)
    fill_rect(g, k * (room_w + 1), 0, k * (room_w + 1), h + 1);
  const int y0 = (h + 2 - door) / 2;
  for (int k = 1; k < n; ++k)
    fill_rect(g, k * (room_w + 1), y0, k * (room_w + 1), y0 + door - 1, 0);
  return g;
}

TEST(TopologicalMap, TwoRoomsOneDoorGiveTwoRegionsAndOneCriticalPoint) {
  for (const DiagramMethod method : {DiagramMethod::kEdt, DiagramMethod::kCellularAutomaton}) {
    const BinaryGrid g = two_rooms(30, 24, 4);  // dividing wall x = 31, door y = 11..14
    TopologyOptions o;
    o.method = method;
    const TopologicalMap m = build_topological_map(g, o);
    ASSERT_EQ(m.regions.size(), 2U) << static_cast<int>(method);
    int separating = 0;
    for (const auto& cp : m.critical_points) {
      if (!cp.separates) continue;
      ++separating;
      EXPECT_NEAR(cp.cell.x, 31, 1) << cp.cell;
      EXPECT_GE(cp.cell.y, 11);
      EXPECT_LE(cp.cell.y, 14);
      // The basis points are the two jambs of the door.
      std::set<Cell> basis{cp.basis[0], cp.basis[1]};
      EXPECT_EQ(cp.basis[0].x, 31);
      EXPECT_EQ(cp.basis[1].x, 31);
      EXPECT_TRUE(basis.count(Cell{31, 10}) && basis.count(Cell{31, 15}))
          << cp.basis[0] << " " << cp.basis[1];
      EXPECT_NEAR(cp.clearance_m, 0.2, 0.11);
    }
    EXPECT_EQ(separating, 1) << static_cast<int>(method);
    EXPECT_EQ(m.critical_points.size(), 1U) << static_cast<int>(method);
    ASSERT_EQ(m.edges.size(), 1U);
    EXPECT_EQ(m.edges[0].a, 0);
    EXPECT_EQ(m.edges[0].b, 1);
    // Rooms are on either side of the wall.
    EXPECT_NE(m.region_of({10, 10}), m.region_of({50, 10}));
    EXPECT_EQ(m.region_of({31, 0}), -1);
    // Region areas: 30 x 24 cells each plus the door cells.
    EXPECT_NEAR(m.regions[0].area_m2 + m.regions[1].area_m2, (2 * 30 * 24 + 4) * 0.01, 1e-9);
  }
}

TEST(TopologicalMap, RoomsInARowAndThePlanThroughTheDoors) {
  const BinaryGrid g = rooms_in_a_row(4);
  const TopologicalMap m = build_topological_map(g);
  ASSERT_EQ(m.regions.size(), 4U);
  EXPECT_EQ(m.edges.size(), 3U);
  const TopoPlan p = plan_on_graph(m, {3, 3}, {4 * 25 - 3, 18});
  ASSERT_TRUE(p.ok());
  EXPECT_EQ(p.regions.size(), 4U);
  EXPECT_EQ(p.edges.size(), 3U);
  ASSERT_EQ(p.waypoints.size(), 5U);
  for (int k = 1; k <= 3; ++k) {
    EXPECT_EQ(p.waypoints[static_cast<std::size_t>(k)].x, 25 * k);  // in the door
    EXPECT_GE(p.waypoints[static_cast<std::size_t>(k)].y, 9);
    EXPECT_LE(p.waypoints[static_cast<std::size_t>(k)].y, 12);
  }
  // Same region: a direct segment.
  const TopoPlan q = plan_on_graph(m, {3, 3}, {20, 15});
  ASSERT_TRUE(q.ok());
  EXPECT_EQ(q.waypoints.size(), 2U);
  EXPECT_EQ(plan_on_graph(m, {0, 0}, {3, 3}).status, TopoPlanStatus::kStartBlocked);
  EXPECT_EQ(plan_on_graph(m, {3, 3}, {25, 1}).status, TopoPlanStatus::kGoalBlocked);
  EXPECT_EQ(plan_on_graph(m, {3, 3}, {-5, 3}).status, TopoPlanStatus::kGoalBlocked);
}

TEST(TopologicalMap, ClosedDoorMakesTheGoalUnreachable) {
  BinaryGrid g = rooms_in_a_row(2);
  fill_rect(g, 25, 0, 25, 21);  // close the door
  const TopologicalMap m = build_topological_map(g);
  EXPECT_EQ(m.regions.size(), 2U);
  EXPECT_TRUE(m.edges.empty());
  EXPECT_EQ(plan_on_graph(m, {3, 3}, {40, 10}).status, TopoPlanStatus::kUnreachable);
}

// Brute force over all simple door sequences: the graph A* must find the shortest waypoint path.
double brute_force(const TopologicalMap& m, Cell start, Cell goal) {
  const GridGeometry& geo = m.geometry;
  double best = HUGE_VAL;
  std::vector<char> used(m.edges.size(), 0);
  std::function<void(int, Vec2, double)> dfs = [&](int region, Vec2 at, double len) {
    if (region == m.region_of(goal))
      best = std::min(best, len + distance(at, geo.cell_center(goal)));
    for (std::size_t k = 0; k < m.edges.size(); ++k) {
      const TopoEdge& e = m.edges[k];
      if (used[k] || (e.a != region && e.b != region)) continue;
      const Vec2 mid =
          geo.cell_center(m.critical_points[static_cast<std::size_t>(e.critical_point)].midpoint);
      used[k] = 1;
      dfs(e.a == region ? e.b : e.a, mid, len + distance(at, mid));
      used[k] = 0;
    }
  };
  dfs(m.region_of(start), geo.cell_center(start), 0.0);
  return best;
}

TEST(TopologicalMap, GraphPlanIsOptimalOverDoorSequences) {
  // A 2 x 2 block of rooms with doors between all neighbours: two routes between opposite rooms.
  BinaryGrid g(GridGeometry{51, 41, 0.1, {}}, 0);
  fill_rect(g, 0, 0, 50, 0);
  fill_rect(g, 0, 40, 50, 40);
  fill_rect(g, 0, 0, 0, 40);
  fill_rect(g, 50, 0, 50, 40);
  fill_rect(g, 25, 0, 25, 40);
  fill_rect(g, 0, 20, 50, 20);
  fill_rect(g, 25, 5, 25, 8, 0);    // bottom rooms, door near the bottom
  fill_rect(g, 25, 33, 25, 36, 0);  // top rooms, door near the top
  fill_rect(g, 5, 20, 8, 20, 0);    // left rooms, door on the left
  fill_rect(g, 42, 20, 45, 20, 0);  // right rooms, door on the right
  const TopologicalMap m = build_topological_map(g);
  ASSERT_EQ(m.regions.size(), 4U);
  ASSERT_EQ(m.edges.size(), 4U);
  int checked = 0;
  for (const Cell s : {Cell{3, 3}, Cell{20, 17}, Cell{10, 30}})
    for (const Cell t : {Cell{47, 37}, Cell{30, 23}, Cell{45, 10}, Cell{4, 38}}) {
      const TopoPlan p = plan_on_graph(m, s, t);
      ASSERT_TRUE(p.ok());
      EXPECT_NEAR(p.waypoint_length_m, brute_force(m, s, t), 1e-9) << s << " -> " << t;
      ++checked;
    }
  EXPECT_EQ(checked, 12);
}

TEST(TopologicalMap, InvariantsOnRandomRooms) {
  for (std::uint32_t seed = 0; seed < 25; ++seed) {
    const BinaryGrid g = random_room(seed, 60, 44, 6);
    const TopologicalMap m = build_topological_map(g);
    const double min_area = TopologyOptions{}.min_region_area;
    std::vector<std::size_t> count(m.regions.size(), 0), absorbed(m.regions.size(), 0);
    for (std::size_t i = 0; i < g.size(); ++i) {
      if (g[i]) {
        // An obstacle cell has no region unless its piece joined one (regions_absorb_obstacles);
        // region_of, for planning, never gives one.
        EXPECT_EQ(m.region_of(g.geometry().cell_at(i)), -1);
        if (m.region[i] >= 0) {
          ASSERT_LT(m.region[i], static_cast<int>(m.regions.size()));
          count[static_cast<std::size_t>(m.region[i])]++;
          absorbed[static_cast<std::size_t>(m.region[i])]++;
        }
        continue;
      }
      ASSERT_GE(m.region[i], 0) << "seed " << seed;
      ASSERT_LT(m.region[i], static_cast<int>(m.regions.size()));
      count[static_cast<std::size_t>(m.region[i])]++;
    }
    for (std::size_t r = 0; r < m.regions.size(); ++r) {
      EXPECT_EQ(count[r], m.regions[r].cells);
      EXPECT_EQ(absorbed[r], m.regions[r].absorbed_cells);
      EXPECT_EQ(m.region_of(m.regions[r].centre), static_cast<int>(r));
      // Small regions survive only when they touch no critical line (isolated pockets).
      if (m.regions[r].area_m2 < min_area) {
        for (const auto& e : m.edges)
          EXPECT_TRUE(e.a != static_cast<int>(r) && e.b != static_cast<int>(r));
      }
    }
    for (const auto& e : m.edges) {
      EXPECT_LT(e.a, e.b);
      EXPECT_GT(e.length_m, 0.0);
      EXPECT_TRUE(m.critical_points[static_cast<std::size_t>(e.critical_point)].separates);
    }
  }
}

TEST(TopologicalPlanner, PlansThroughTheGraphOnTheGrid) {
  const BinaryGrid g = rooms_in_a_row(3);
  TopologicalPlanner planner;
  const planning::PlanResult r = planner.plan(g, {3, 3}, {70, 18});
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.path.front(), (Cell{3, 3}));
  EXPECT_EQ(r.path.back(), (Cell{70, 18}));
  for (std::size_t k = 1; k < r.path.size(); ++k) {
    EXPECT_FALSE(g[r.path[k]]);
    EXPECT_LE(std::abs(r.path[k].x - r.path[k - 1].x), 1);
    EXPECT_LE(std::abs(r.path[k].y - r.path[k - 1].y), 1);
  }
  ASSERT_TRUE(planner.map().has_value());
  EXPECT_EQ(planner.map()->regions.size(), 3U);
  // Never shorter than the optimal grid path, and not much longer on this map.
  planning::AStarPlanner astar;
  const double opt = astar.plan(g, {3, 3}, {70, 18}).length_cells;
  EXPECT_GE(r.length_cells, opt - 1e-9);
  EXPECT_LT(r.length_cells, 1.15 * opt);
  EXPECT_EQ(planner.plan(g, {0, 0}, {70, 18}).status, planning::PlanStatus::kStartOccupied);
  EXPECT_EQ(planner.plan(g, {3, 3}, {25, 0}).status, planning::PlanStatus::kGoalOccupied);
  EXPECT_EQ(planner.plan(g, {3, 3}, {500, 0}).status, planning::PlanStatus::kOutOfMap);
}

// Depot-like hall with closed boxes (enclosed free pockets, like depot's shelves whose grey
// interior is free under its yaml thresholds) and boxes with an opening: the regions of one
// connected free area are connected in the graph; an enclosed pocket has no edge.
TEST(TopologicalMap, RegionsAreConnectedExactlyWhereTheFreeSpaceIs) {
  for (int open_boxes = 0; open_boxes <= 3; ++open_boxes) {
    BinaryGrid g(GridGeometry{120, 60, 0.1, {}}, 0);
    for (int k = 0; k < 3; ++k) {  // 3 boxes 20x20 with a one-cell wall, 14 cells apart
      const int x0 = 10 + 36 * k, y0 = 25;
      fill_rect(g, x0, y0, x0 + 19, y0 + 19);
      fill_rect(g, x0 + 1, y0 + 1, x0 + 18, y0 + 18, 0);
      if (k < open_boxes) fill_rect(g, x0 + 8, y0, x0 + 11, y0, 0);  // a 4-cell door
    }
    const TopologicalMap m = build_topological_map(g);
    // Free components (4-connected) and graph components (union-find on the edges).
    std::vector<int> comp(g.size(), -1);
    int ncomp = 0;
    for (std::size_t i = 0; i < g.size(); ++i) {
      if (g[i] || comp[i] >= 0) continue;
      std::vector<Cell> stack{g.cell_at(i)};
      comp[i] = ncomp;
      while (!stack.empty()) {
        const Cell c = stack.back();
        stack.pop_back();
        for (const Cell q : {c + Cell{1, 0}, c + Cell{-1, 0}, c + Cell{0, 1}, c + Cell{0, -1}}) {
          if (!g.contains(q) || g[q] || comp[g.index(q)] >= 0) continue;
          comp[g.index(q)] = ncomp;
          stack.push_back(q);
        }
      }
      ++ncomp;
    }
    EXPECT_EQ(ncomp, 1 + 3 - open_boxes);
    std::vector<int> parent(m.regions.size());
    for (std::size_t r = 0; r < parent.size(); ++r)
      parent[r] = static_cast<int>(r);
    std::function<int(int)> find = [&](int x) {
      return parent[static_cast<std::size_t>(x)] == x ? x
                                                      : find(parent[static_cast<std::size_t>(x)]);
    };
    for (const TopoEdge& e : m.edges)
      parent[static_cast<std::size_t>(find(e.a))] = find(e.b);
    std::map<int, std::set<int>> pieces;  // free component -> graph components of its regions
    for (std::size_t i = 0; i < g.size(); ++i)
      if (m.region[i] >= 0) pieces[comp[i]].insert(find(m.region[i]));
    EXPECT_EQ(static_cast<int>(pieces.size()), ncomp) << open_boxes;
    for (const auto& [c, roots] : pieces)
      EXPECT_EQ(roots.size(), 1U) << "free component " << c << ", " << open_boxes << " open";
    // A pocket's region has no edge; an opened box is linked to the hall.
    std::set<int> linked;
    for (const TopoEdge& e : m.edges)
      linked.insert(e.a), linked.insert(e.b);
    for (int k = 0; k < 3; ++k) {
      const int r = m.region[(Cell{20 + 36 * k, 35})];
      ASSERT_GE(r, 0);
      EXPECT_EQ(linked.contains(r), k < open_boxes) << k << " " << open_boxes;
    }
  }
}

TEST(TopologicalMap, RejectsBadInput) {
  TopologyOptions o;
  o.min_region_area = -1.0;
  EXPECT_THROW((void)build_topological_map(two_rooms(), o), Error);
  o = {};
  o.rise_ratio = std::nan("");
  EXPECT_THROW((void)build_topological_map(two_rooms(), o), Error);
  EXPECT_THROW((void)build_topological_map(two_rooms(), BinaryGrid(3, 3, 0)), Error);
  const TopologicalMap empty = build_topological_map(BinaryGrid{});
  EXPECT_TRUE(empty.regions.empty());
  const TopologicalMap full = build_topological_map(BinaryGrid(5, 5, 1));
  EXPECT_TRUE(full.regions.empty());
}

// A hall 10 m x 3 m (0.05 m cells) with a 1 m door at its east end into a second room, and two
// benches against its long walls in the middle that narrow it by `bench` cells each side.
BinaryGrid hall_with_benches(int bench) {
  const int w = 200, h = 60, room = 60;
  BinaryGrid g(GridGeometry{w + room + 3, h + 2, 0.05, {}}, 0);
  fill_rect(g, 0, 0, w + room + 2, 0);
  fill_rect(g, 0, h + 1, w + room + 2, h + 1);
  fill_rect(g, 0, 0, 0, h + 1);
  fill_rect(g, w + room + 2, 0, w + room + 2, h + 1);
  fill_rect(g, w + 1, 0, w + 1, h + 1);                  // the wall between hall and room
  fill_rect(g, w + 1, h / 2 - 9, w + 1, h / 2 + 10, 0);  // its 1 m door
  if (bench > 0) {
    fill_rect(g, 90, 1, 110, bench);
    fill_rect(g, 90, h + 1 - bench, 110, h);
  }
  return g;
}

int narrowings(const TopologicalMap& m) {
  int n = 0;
  for (const auto& cp : m.critical_points)
    n += cp.separates && !cp.wall_gap && !cp.passage_junction;
  return n;
}

TEST(TopologicalMap, BenchesThatNarrowAHallByAFifthDoNotCutItButTheDoorDoes) {
  // Half-width 30 cells; 6-cell benches leave 24, a rise back to 1.25x (the old 0.25 just
  // fires), under the default 0.3; 9-cell benches leave 21, a rise to 1.43x.
  TopologyOptions o;
  o.passage_length = 0.0;  // the classic rule alone
  o.validate_sides = false;
  const TopologicalMap plain = build_topological_map(hall_with_benches(0), o);
  EXPECT_EQ(plain.regions.size(), 2U);
  EXPECT_EQ(narrowings(plain), 1);  // the door
  const TopologicalMap benches = build_topological_map(hall_with_benches(6), o);
  EXPECT_EQ(benches.regions.size(), 2U);
  EXPECT_EQ(narrowings(benches), 1);
  TopologyOptions old = o;
  old.rise_ratio = 0.25;  // the default until stop 27
  EXPECT_EQ(narrowings(build_topological_map(hall_with_benches(6), old)), 2);
  const TopologicalMap deep = build_topological_map(hall_with_benches(9), o);
  EXPECT_EQ(narrowings(deep), 2);
  EXPECT_EQ(deep.regions.size(), 3U);
}

TEST(TopologicalMap, DiagramMethodNamesRoundTripAndABadNameIsNamed) {
  for (const DiagramMethod m : {DiagramMethod::kEdt, DiagramMethod::kCellularAutomaton})
    EXPECT_EQ(parse_diagram_method(diagram_method_name(m), "--method"), m);
  EXPECT_EQ(diagram_method_name(TopologyOptions{}.method), "edt");
  try {
    (void)parse_diagram_method("voronoi", "--method");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("--method"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("'voronoi'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace voronav::topology

namespace voronav::topology {
namespace {

// A room (50 x 50 cells at 0.05 m) with a 12-cell-wide, 60-cell-long room opening into it over
// its full width (an open-fronted room or a corridor end): no door jambs, so the clearance along
// the diagram falls from the big room into the long one and never rises again on its far side.
// With `far_room`, a second big room closes the long one's far end (a corridor between rooms).
BinaryGrid room_with_open_passage(bool far_room) {
  BinaryGrid g(GridGeometry{far_room ? 164 : 113, 52, 0.05, {}}, 1);
  fill_rect(g, 1, 1, 50, 50, 0);     // room A
  fill_rect(g, 51, 20, 110, 31, 0);  // the passage, open over its whole width
  if (far_room) fill_rect(g, 111, 1, 162, 50, 0);
  return g;
}

TEST(TopologicalMap, PassageOpeningIntoARoomIsCutAtItsMouth) {
  const BinaryGrid g = room_with_open_passage(false);
  // The classic rule (a rise on both sides) finds no critical point: one region. (The room's
  // wall line continues across the passage's mouth: the wall-opening rule, off here, cuts it.)
  TopologyOptions classic_options;
  classic_options.wall_openings.max_width = 0.0;
  classic_options.passage_length = 0.0;
  classic_options.validate_sides = false;
  const TopologicalMap classic = build_topological_map(g, classic_options);
  EXPECT_EQ(classic.regions.size(), 1U);
  TopologyOptions o = classic_options;
  o.passage_length = 1.0;  // 20 cells; the passage is 60 long
  const TopologicalMap m = build_topological_map(g, o);
  ASSERT_EQ(m.regions.size(), 2U);
  int separating = 0;
  for (const auto& cp : m.critical_points) {
    if (!cp.separates) continue;
    ++separating;
    EXPECT_NEAR(cp.cell.x, 51, 3) << cp.cell;  // at the mouth, not inside the passage
    EXPECT_NEAR(cp.clearance_m, 0.3, 0.06);
  }
  EXPECT_EQ(separating, 1);
  // Every passage cell a few cells past the mouth is in one region, every room cell in the other.
  const int passage = m.region_of(Cell{80, 25}), room = m.region_of(Cell{25, 25});
  EXPECT_NE(passage, room);
  for (int y = 20; y <= 31; ++y)
    for (int x = 56; x <= 110; ++x)
      EXPECT_EQ(m.region_of(Cell{x, y}), passage) << Cell{x, y};
  for (int y = 1; y <= 50; ++y)
    for (int x = 1; x <= 48; ++x)
      EXPECT_EQ(m.region_of(Cell{x, y}), room) << Cell{x, y};
}

TEST(TopologicalMap, CorridorBetweenTwoRoomsIsItsOwnRegion) {
  const BinaryGrid g = room_with_open_passage(true);
  // Classic: one cut in the middle of the corridor, each half joins a room.
  TopologyOptions classic_options;
  classic_options.passage_length = 0.0;
  classic_options.validate_sides = false;
  const TopologicalMap classic = build_topological_map(g, classic_options);
  EXPECT_EQ(classic.regions.size(), 2U);
  TopologyOptions o = classic_options;
  o.passage_length = 1.0;
  const TopologicalMap m = build_topological_map(g, o);
  ASSERT_EQ(m.regions.size(), 3U);
  const int a = m.region_of(Cell{25, 25}), c = m.region_of(Cell{80, 25}),
            b = m.region_of(Cell{136, 25});
  EXPECT_EQ(std::set<int>({a, b, c}).size(), 3U);
  const auto corridor = m.regions[static_cast<std::size_t>(c)].cells;
  EXPECT_GE(corridor, 50U * 12U);  // the corridor, cut within a few cells of both mouths
  EXPECT_LE(corridor, 66U * 12U);
  // The room test keeps both cuts: each separates the narrow corridor from a wide room.
  o.validate_sides = true;
  EXPECT_EQ(build_topological_map(g, o).regions.size(), 3U);
}

TEST(TopologicalMap, RoomTestMergesPiecesOfOnePassage) {
  // Two passages of one width, 12 cells, joined at a right angle, each opening into a big room at
  // its other end. With a low rise ratio the bend's small widening makes critical points inside
  // the L; the room test drops a line whose two sides are both no wider than the passage.
  BinaryGrid g(GridGeometry{170, 170, 0.05, {}}, 1);
  fill_rect(g, 1, 1, 50, 50, 0);        // room A
  fill_rect(g, 51, 20, 130, 31, 0);     // passage east from A
  fill_rect(g, 119, 32, 130, 110, 0);   // passage north
  fill_rect(g, 100, 111, 160, 165, 0);  // room B
  TopologyOptions o;
  o.passage_length = 1.0;
  o.rise_ratio = 0.05;
  o.min_rise = 0.05;
  o.passage_bulges = false;  // (the bulge rule alone also keeps the L whole: next test)
  o.validate_sides = true;
  const TopologicalMap m = build_topological_map(g, o);
  const int a = m.region_of(Cell{25, 25}), b = m.region_of(Cell{130, 140});
  const int east = m.region_of(Cell{90, 25}), north = m.region_of(Cell{125, 70});
  EXPECT_NE(a, east);
  EXPECT_NE(b, north);
  EXPECT_EQ(east, north);  // one passage, one region
  o.validate_sides = false;
  const TopologicalMap split = build_topological_map(g, o);
  EXPECT_GT(split.regions.size(), m.regions.size());
}

TEST(TopologicalMap, DeadEndPassageIsCutWhereItOpensNotAtItsBend) {
  // A 12-cell-wide passage opening into room A, bending north at a right angle and ending blind
  // (issue #15, lab_intel: a narrow room whose L bend comes before its door). Along the diagram
  // from the dead end the clearance stays at the passage's 6 cells, bulges at the bend (the
  // corner square) and narrows back to 6 cells before room A opens. Without the bulge rule the
  // passage's first rise, the bend, is taken for its opening and the L is cut in two there.
  BinaryGrid g(GridGeometry{140, 120, 0.05, {}}, 1);
  fill_rect(g, 1, 1, 50, 50, 0);       // room A
  fill_rect(g, 51, 20, 130, 31, 0);    // passage east from A
  fill_rect(g, 119, 32, 130, 110, 0);  // passage north, a dead end
  TopologyOptions o;
  o.wall_openings.max_width = 0.0;
  o.validate_sides = false;  // the room test would mend the cut afterwards: the rule alone here
  o.passage_bulges = true;
  const TopologicalMap m = build_topological_map(g, o);
  const int a = m.region_of(Cell{25, 25});
  const int east = m.region_of(Cell{90, 25}), north = m.region_of(Cell{125, 100});
  EXPECT_EQ(m.regions.size(), 2U);
  EXPECT_NE(a, east);
  EXPECT_EQ(east, north);
  for (const auto& cp : m.critical_points) {
    if (!cp.separates) continue;
    EXPECT_NEAR(cp.cell.x, 51, 4) << cp.cell;  // at room A's mouth
  }
  o.passage_bulges = false;
  const TopologicalMap cut = build_topological_map(g, o);
  EXPECT_NE(cut.region_of(Cell{90, 25}), cut.region_of(Cell{125, 100}));
}

TEST(TopologicalMap, ObstaclesEnclosedByOneRegionJoinIt) {
  // Two 3 x 3 m rooms (0.05 m cells) joined by two 0.6 m doors; room A holds a 0.5 x 1 m table
  // (200 cells, 0.5 m^2) and a 1.5 x 1 m block (600 cells, 1.5 m^2); room B a table touching
  // its wall (part of the wall piece). Only A's table is an obstacle piece enclosed by one region
  // and under the area: it joins A. The wall piece between the rooms borders both (never joins),
  // the block is over the area, the wall-side table is part of the outer wall.
  BinaryGrid g(GridGeometry{125, 63, 0.05, {}}, 1);
  fill_rect(g, 1, 1, 60, 60, 0);     // room A
  fill_rect(g, 62, 1, 122, 60, 0);   // room B
  fill_rect(g, 61, 1, 61, 12, 0);    // two doors: the wall between the rooms is a free-
  fill_rect(g, 61, 49, 61, 60, 0);   // standing piece (36 cells) bordering both rooms
  fill_rect(g, 10, 10, 19, 29, 1);   // A's table: 10 x 20 cells
  fill_rect(g, 25, 35, 54, 54, 1);   // A's block: 30 x 20 cells, 1.5 m^2
  fill_rect(g, 100, 1, 110, 10, 1);  // B's table against the wall
  TopologyOptions o;
  o.min_wall_area = 3.0;  // no critical lines from the table and the block to the walls
  o.regions_absorb_obstacles = 0.0;
  const TopologicalMap off = build_topological_map(g, o);
  ASSERT_EQ(off.regions.size(), 2U);
  EXPECT_EQ(off.absorbed_obstacles, 0U);
  o.regions_absorb_obstacles = 1.0;  // the table (0.5 m^2) joins, the block (1.5 m^2) not
  const TopologicalMap on = build_topological_map(g, o);
  ASSERT_EQ(on.regions.size(), 2U);
  EXPECT_EQ(on.absorbed_obstacles, 1U);
  const int a = on.region_of(Cell{5, 5});
  ASSERT_GE(a, 0);
  for (int y = 10; y <= 29; ++y)
    for (int x = 10; x <= 19; ++x) {
      EXPECT_EQ(on.region[Cell({x, y})], a) << Cell{x, y};
      EXPECT_EQ(on.region_of(Cell{x, y}), -1);  // still an obstacle for planning
    }
  EXPECT_EQ(on.region[Cell({30, 40})], -1);  // the block: over the area
  EXPECT_EQ(on.region[Cell({61, 30})], -1);  // the wall between the rooms
  EXPECT_EQ(on.region[Cell({105, 5})], -1);  // B's table: part of the outer wall
  const auto& ra = on.regions[static_cast<std::size_t>(a)];
  const auto& ra_off = off.regions[static_cast<std::size_t>(off.region_of(Cell{5, 5}))];
  EXPECT_EQ(ra.absorbed_cells, 200U);
  EXPECT_EQ(ra.cells, ra_off.cells + 200U);
  EXPECT_NEAR(ra.area_m2, ra_off.area_m2 + 0.5, 1e-9);
  EXPECT_FALSE(g[ra.centre]);  // the centre stays a free cell
  EXPECT_EQ(on.edges.size(), off.edges.size());
  o.regions_absorb_obstacles = 2.0;  // now the block too
  EXPECT_EQ(build_topological_map(g, o).absorbed_obstacles, 2U);
  o.regions_absorb_obstacles = -1.0;
  EXPECT_THROW((void)build_topological_map(g, o), Error);
}

TEST(TopologicalMap, RoomTestKeepsTwoRoomsBehindAWideOpening) {
  // Two 3 x 3 m rooms side by side, joined by a 2.2 m opening in the wall between them (like
  // Freiburg52's two bottom-left rooms): the opening is a critical line (clearance 22 cells, the
  // rooms' 30), and neither room is wider than the room test's rise (x 1.5), so without the
  // shape rule the test joins them. Both are room-shaped (elongation ~1), not passage pieces.
  BinaryGrid g(GridGeometry{125, 63, 0.05, {}}, 1);
  fill_rect(g, 1, 1, 60, 60, 0);    // room A
  fill_rect(g, 63, 1, 122, 60, 0);  // room B
  fill_rect(g, 61, 9, 62, 52, 0);   // the opening in the wall between them
  TopologyOptions o;
  o.validate_sides = true;
  o.passage_rise_ratio = 0.5;
  const TopologicalMap m = build_topological_map(g, o);
  EXPECT_EQ(m.regions.size(), 2U);
  EXPECT_NE(m.region_of(Cell{30, 30}), m.region_of(Cell{92, 30}));
  o.room_test_elongation = 0.0;  // the earlier room test: any shape joins
  const TopologicalMap joined = build_topological_map(g, o);
  EXPECT_EQ(joined.regions.size(), 1U);
  o.room_test_elongation = -1.0;
  EXPECT_THROW((void)build_topological_map(g, o), Error);
}

TEST(TopologicalMap, NewCriticalPointOptionsAreChecked) {
  const BinaryGrid g = room_with_open_passage(false);
  for (const char* which : {"max_rise_walk", "passage_length", "passage_rise_ratio"}) {
    TopologyOptions o;
    const std::string w = which;
    (w == "max_rise_walk"    ? o.max_rise_walk
     : w == "passage_length" ? o.passage_length
                             : o.passage_rise_ratio) = -1.0;
    EXPECT_THROW((void)build_topological_map(g, o), Error) << which;
  }
}

TEST(TopologicalMap, BasisAcrossGivesANotchedMouthALineThatCrossesIt) {
  // Room A, a 32-cell-wide passage (1.6 m at 0.05 m) east to room B, and a 4-cell notch in the
  // passage's south wall at A's mouth (issue #15, lab_ipa: a gap in a jagged wall where the link
  // opens into the hall). The passage's mouth point lies above the notch: its nearest site and
  // its neighbourhood's farthest site are the notch's two jambs, so the paper's line is 5 cells
  // long on the south wall and cuts nothing; A and the passage stay one region. With
  // basis_across the second basis point is the north wall across the point.
  BinaryGrid g(GridGeometry{200, 120, 0.05, {}}, 1);
  fill_rect(g, 1, 1, 70, 110, 0);     // room A
  fill_rect(g, 71, 40, 150, 71, 0);   // passage, walls at y = 39 and y = 72
  fill_rect(g, 151, 1, 198, 110, 0);  // room B
  fill_rect(g, 73, 39, 76, 39, 0);    // the notch
  TopologyOptions o;
  o.basis_across = false;
  const TopologicalMap off = build_topological_map(g, o);
  EXPECT_EQ(off.basis_across, 0U);
  EXPECT_EQ(off.region_of(Cell{30, 50}), off.region_of(Cell{110, 55}));  // A + passage
  EXPECT_NE(off.region_of(Cell{110, 55}), off.region_of(Cell{175, 50}));
  o.basis_across = true;
  const TopologicalMap on = build_topological_map(g, o);
  EXPECT_EQ(on.basis_across, 1U);
  EXPECT_EQ(on.regions.size(), 3U);
  const int a = on.region_of(Cell{30, 50}), p = on.region_of(Cell{110, 55}),
            b = on.region_of(Cell{175, 50});
  EXPECT_NE(a, p);
  EXPECT_NE(p, b);
  EXPECT_NE(a, b);
  int across = 0;
  for (const auto& cp : on.critical_points) {
    if (cp.wall_gap || cp.cell.x > 100) continue;
    ++across;
    EXPECT_TRUE(cp.separates);
    // From the notch's jamb on the south wall to the north wall, at the mouth.
    EXPECT_EQ(cp.basis[0].y, 39);
    EXPECT_EQ(cp.basis[1].y, 72) << cp.basis[1];
    EXPECT_NEAR(cp.cell.x, 74, 3);
  }
  EXPECT_EQ(across, 1);
  // Without the notch the paper's basis points already span the passage: nothing changes.
  fill_rect(g, 73, 39, 76, 39, 1);
  const TopologicalMap plain = build_topological_map(g, o);
  EXPECT_EQ(plain.basis_across, 0U);
}

TEST(TopologicalMap, ChairBesideADoorDoesNotHideTheDoorsWallOpening) {
  // Two rooms (0.05 m cells) divided by a wall at x = 50..51 with a 1.2 m door (y = 21..44), and
  // a chair (an 8-cell ring, 0.04 m^2 of obstacle) in the east room beside the door's north jamb
  // (issue #15, lab_ipa_furnitures: the bins beside the lab's door). The chair makes the
  // diagram branch right behind the door, so the door gives no narrowing; the narrowing between
  // the wall and the chair gives a 4-cell line next to the jamb, which hid the door's wall-line
  // opening (the two were taken for lines across the same opening): the rooms were one region.
  // With furniture_line_area the chair's line hides nothing and the door's wall line splits them.
  BinaryGrid g(GridGeometry{120, 64, 0.05, {}}, 0);
  fill_rect(g, 0, 0, 119, 0);
  fill_rect(g, 0, 63, 119, 63);
  fill_rect(g, 0, 0, 0, 63);
  fill_rect(g, 119, 0, 119, 63);
  fill_rect(g, 50, 0, 51, 20);
  fill_rect(g, 50, 45, 51, 63);
  fill_rect(g, 55, 46, 62, 53);  // the chair: a ring
  fill_rect(g, 56, 47, 61, 52, 0);
  TopologyOptions o;
  o.furniture_line_area = 0.0;
  const TopologicalMap off = build_topological_map(g, o);
  EXPECT_EQ(off.regions.size(), 1U);
  EXPECT_EQ(off.openings_past_furniture, 0U);
  EXPECT_EQ(off.region_of(Cell{20, 30}), off.region_of(Cell{90, 30}));
  o.furniture_line_area = 0.25;
  const TopologicalMap on = build_topological_map(g, o);
  EXPECT_EQ(on.openings_past_furniture, 1U);
  ASSERT_EQ(on.regions.size(), 2U);
  EXPECT_NE(on.region_of(Cell{20, 30}), on.region_of(Cell{90, 30}));
  int doors = 0;
  for (const auto& cp : on.critical_points) {
    if (!cp.wall_gap) continue;
    ++doors;
    EXPECT_TRUE(cp.separates);
    for (const Cell c : cp.line) {  // across the door, on the wall's line
      EXPECT_GE(c.x, 50);
      EXPECT_LE(c.x, 51);
    }
  }
  EXPECT_EQ(doors, 1);
  // A chair of more than the area is not furniture: its line hides the opening again.
  o.furniture_line_area = 0.02;
  EXPECT_EQ(build_topological_map(g, o).regions.size(), 1U);
}

TEST(TopologicalMap, PassageIntoAJunctionOfNarrowerBranchesIsCutAtItsMouth) {
  // A 2 m corridor C (0.05 m cells, x = 111..150) runs from room A (north) down into a 1.6 m
  // link L (y = 30..61) that leads west into hall H and east through a 0.9 m door into room B
  // (issue #15, lab_ipa: the diagonal corridor's foot on the link between the hall and the lab).
  // The corridor opens into A (a critical line there), but at its foot the clearance only rises
  // a little into the T junction, whose other branches (the link, the door) are narrower: no
  // narrowing, so C and L were one region. With passage_junctions C is cut at its mouth, on
  // the line of the link's north wall.
  BinaryGrid g(GridGeometry{240, 230, 0.05, {}}, 1);
  fill_rect(g, 5, 5, 95, 80, 0);       // hall H
  fill_rect(g, 96, 30, 150, 61, 0);    // link L
  fill_rect(g, 111, 62, 150, 140, 0);  // corridor C
  fill_rect(g, 156, 5, 235, 100, 0);   // room B
  fill_rect(g, 151, 44, 155, 61, 0);   // door L -> B
  fill_rect(g, 90, 141, 200, 225, 0);  // room A
  const Cell h{30, 40}, l{130, 45}, c{130, 100}, a{150, 180}, b{200, 50};
  TopologyOptions o;
  o.passage_junctions = false;
  const TopologicalMap off = build_topological_map(g, o);
  EXPECT_EQ(off.regions.size(), 4U);
  EXPECT_EQ(off.region_of(l), off.region_of(c));
  o.passage_junctions = true;
  const TopologicalMap on = build_topological_map(g, o);
  ASSERT_EQ(on.regions.size(), 5U);
  const std::set<int> ids{on.region_of(h), on.region_of(l), on.region_of(c), on.region_of(a),
                          on.region_of(b)};
  EXPECT_EQ(ids.size(), 5U);
  int mouths = 0;
  for (const auto& cp : on.critical_points) {
    if (!cp.passage_junction) continue;
    ++mouths;
    EXPECT_TRUE(cp.separates);
    // From the corridor's west corner to its east wall's end, on the link's north wall line.
    for (const Cell q : cp.basis)
      EXPECT_EQ(q.y, 62) << q;
    EXPECT_EQ(std::min(cp.basis[0].x, cp.basis[1].x), 110);
    EXPECT_EQ(std::max(cp.basis[0].x, cp.basis[1].x), 151);
  }
  EXPECT_EQ(mouths, 1);
}

}  // namespace
}  // namespace voronav::topology
