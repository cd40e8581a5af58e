// RAS, the Random Access Sequence planner with distribution density (seed 001: Kwak & Lim,
// "Minimum path planning for mobile robot using distribution density", 2006).
//
// Free space is cut into square regions (RegionGrid, eq. 5). Regions are numbered outward from the
// start region in expansion steps (eq. 6-7): step 1 numbers the free neighbours of the start
// (id 0); every later step takes the regions of the previous step in increasing id order and
// numbers their not-yet-numbered free neighbours, continuing the count; a region is never
// renumbered. Each numbered region k records F = (k, p, N, d, n) (eq. 1): its centre p, the number
// N of regions it numbered, its density d and the ids n it numbered -- which are consecutive, so n
// is (first id, N). The path is read backwards from the goal by the count rule of Table 1 /
// eq. 10-11: the parent of region R is the K with sum_{i<K} N_i < R <= sum_{i<=K} N_i, found from
// the counts alone (no parent pointers). The numbering is a breadth-first wave, so the path has the
// minimum number of regions and one is found whenever the region graph connects start and goal.
//
// Density (eq. 2, section 2.2): d = number of free regions among the 8 around a region (map
// border = blocked). With a threshold D > 0 a region is numbered only when d >= D, so paths keep a
// ring of free regions between the robot and walls and skip gaps narrower than the robot.
//
// Decisions where the paper is vague (docs/reproductions/ras.md):
//  - default direction: neighbours in counter-clockwise order starting east (E, NE, N, NW, W, SW,
//    S, SE), which reproduces steps 0-2 of the paper's figure 2 id for id;
//  - optimal direction: neighbours sorted by the angle between the step and the direction from the
//    start to the goal (closest first, then alternating sides), one order chosen once per search,
//    so a search costs what the default order costs, as the paper's Table 4 times suggest; the
//    goal-ward regions of a step get the lower ids and are expanded first, so the wave reaches
//    the goal after numbering fewer regions (Table 4 rows 5 vs 7). kOptimalPerRegion re-sorts the
//    order toward the goal at every region (the stricter reading, at 2-3x the default's cost).
//    Either way the path keeps the minimum number of regions;
//  - diagonal steps may pass a blocked corner, as in figure 2 (RasCornerRule; kNoCornerCutting
//    gives the graph of this library's A*, used for the comparisons);
//  - density is counted over the 8 surrounding regions, also with 4-neighbour expansion; the start
//    region is exempt from the density rule by default (the robot already stands there).
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "voronav/core/cell.hpp"
#include "voronav/core/vec2.hpp"
#include "voronav/planning/grid_planner.hpp"
#include "voronav/planning/region_grid.hpp"

namespace voronav::planning {

/// Order in which a region numbers its neighbours (seed 001, Table 4 "search direction").
enum class RasDirection {
  kDefault,  ///< counter-clockwise from east: E, NE, N, NW, W, SW, S, SE
  kOptimal,  ///< by angle to the start->goal direction, closest first; chosen once per search
  kOptimalPerRegion,  ///< by angle from each region to the goal, re-sorted at every region
};
/// Whether the numbering stops when the goal is numbered or covers every reachable region (T_M,
/// eq. 8: one numbering then answers any goal by the count rule).
enum class RasExtent { kUntilGoal, kWholeMap };
enum class RasStartDensity {
  kExempt,    ///< the start region is numbered whatever its density
  kEnforced,  ///< the start region must reach the density threshold too
};
enum class RasCornerRule {
  kNoCornerCutting,     ///< a diagonal step needs both flanking regions free (as A*)
  kAllowCornerCutting,  ///< any free diagonal neighbour is numbered
};

struct RasOptions {
  /// Side of a square region S_p = r [cells], >= 1.
  int region_size = 1;
  RegionRule region_rule = RegionRule::kAnyBlocked;
  /// Density threshold D in [0, 8]: a region is numbered only if d >= D. 0 disables the rule.
  int density = 0;
  RasDirection direction = RasDirection::kDefault;
  /// 4- or 8-neighbour expansion (the paper uses 8).
  Connectivity connectivity = Connectivity::k8;
  RasExtent extent = RasExtent::kUntilGoal;
  RasStartDensity start_density = RasStartDensity::kExempt;
  /// The paper's figure 2 numbers diagonal neighbours past a blocked corner, so that is the
  /// default; kNoCornerCutting gives the graph of this library's A* (used in the comparisons).
  RasCornerRule corner_rule = RasCornerRule::kAllowCornerCutting;
};

/// Throws voronav::Error naming the bad field (region_size < 1, density outside [0, 8]).
void validate(const RasOptions& options);

enum class RasStatus {
  kOk,
  kOutOfMap,           ///< start or goal outside the map
  kStartBlocked,       ///< start cell or start region blocked
  kGoalBlocked,        ///< goal cell or goal region blocked
  kStartBelowDensity,  ///< RasStartDensity::kEnforced and the start region's d < D
  kGoalBelowDensity,   ///< the goal region's d < D: too close to walls for this robot
  kUnreachable,        ///< the wave ended without numbering the goal
  kCancelled,
};
[[nodiscard]] std::string_view to_string(RasStatus s);
/// The GridPlanner status for a RAS status (below-density goal -> kUnreachable).
[[nodiscard]] PlanStatus to_plan_status(RasStatus s);

/// F = (k, p, N, d, n) of one numbered region (seed 001, eq. 1).
struct RasRegion {
  std::int32_t k = -1;           ///< id
  Cell region;                   ///< region coordinates in the RegionGrid
  Vec2 p;                        ///< centre [m, world]
  std::int32_t N = 0;            ///< number of regions it numbered
  int d = 0;                     ///< density: free regions among its 8 neighbours
  std::int32_t first_child = 0;  ///< n = (first_child, ..., first_child + N - 1)
  int step = 0;                  ///< expansion step (0 for the start)
};

/// The numbered region space T_M (eq. 8) of one RAS run: a user can inspect and render it.
class RasField {
 public:
  static constexpr std::int32_t kObstacle = -1;      ///< blocked region (s = 0)
  static constexpr std::int32_t kBelowDensity = -2;  ///< free but rejected by the density rule
  static constexpr std::int32_t kUnnumbered = -3;    ///< free, not reached (or search stopped)

  /// Number of numbered regions (the paper's "region num").
  [[nodiscard]] std::int32_t size() const { return n_; }
  [[nodiscard]] int width() const { return w_; }
  [[nodiscard]] int height() const { return h_; }
  [[nodiscard]] int density_threshold() const { return density_threshold_; }
  /// Id of a region (>= 0) or kObstacle / kBelowDensity / kUnnumbered; kObstacle outside the grid.
  [[nodiscard]] std::int32_t id_at(Cell region) const;
  /// Region coordinates of id k (0 <= k < size()).
  [[nodiscard]] Cell region_of(std::int32_t k) const;
  /// N_k: regions numbered by k (0 for regions not expanded before the search stopped).
  [[nodiscard]] std::int32_t count(std::int32_t k) const;
  /// Density of any region (free regions among its 8 neighbours; border counts as blocked).
  [[nodiscard]] int density_at(Cell region) const;
  /// Expansion step of id k, and the number of steps (including step 0).
  [[nodiscard]] int step(std::int32_t k) const;
  [[nodiscard]] int steps() const { return static_cast<int>(step_first_.size()); }
  /// F_k, with p from `regions` (the RegionGrid the field was numbered on).
  [[nodiscard]] RasRegion region(std::int32_t k, const RegionGrid& regions) const;
  /// The count rule of Table 1: the K with sum_{i<K} N_i < R <= sum_{i<=K} N_i; -1 for R = 0.
  [[nodiscard]] std::int32_t parent(std::int32_t R) const;
  /// Ids from 0 (start) to k by repeated count-rule parents.
  [[nodiscard]] std::vector<std::int32_t> path_to(std::int32_t k) const;

 private:
  friend class RasSearch;
  [[nodiscard]] std::size_t padded(Cell c) const {
    return static_cast<std::size_t>(c.y + 1) * static_cast<std::size_t>(w_ + 2) +
           static_cast<std::size_t>(c.x + 1);
  }
  int w_ = 0, h_ = 0;
  int density_threshold_ = 0;
  std::int32_t n_ = 0;                    ///< numbered regions
  std::vector<std::int32_t> label_;       ///< padded (w+2)x(h+2): id or a negative state
  std::vector<std::int32_t> cell_of_;     ///< id -> padded index (the numbering is the queue)
  std::vector<std::int32_t> cum_;         ///< cum_[K] = sum_{i<=K} N_i for expanded K
  std::vector<std::int32_t> step_first_;  ///< first id of every step (h_j + 1, eq. 7)
};

/// The numbering itself, reusing its buffers between runs (no allocation once warmed up).
class RasSearch {
 public:
  /// Numbers `regions` from start_region; with RasExtent::kUntilGoal stops once goal_region is
  /// numbered. cancel/deadline as in PlannerOptions (checked every 1024 expansions).
  RasStatus run(const RegionGrid& regions, Cell start_region, std::optional<Cell> goal_region,
                const RasOptions& options, const CancelFn& cancel = {},
                std::optional<std::chrono::steady_clock::time_point> deadline = {});
  [[nodiscard]] const RasField& field() const { return field_; }

 private:
  RasField field_;
};

struct RasResult {
  RasStatus status = RasStatus::kUnreachable;
  std::int32_t regions = 0;            ///< numbered regions ("region num")
  std::vector<std::int32_t> path_ids;  ///< ids from start region to goal region
  std::vector<Cell> path_regions;      ///< the same as region coordinates ("route num" = size)
  std::vector<Vec2> waypoints;         ///< start, region centres, goal [m, world]
  std::vector<Cell> path_cells;        ///< dense 8- (or 4-) connected cells start..goal
  double time_ms = 0.0;                ///< region grid + numbering + path extraction
  [[nodiscard]] bool ok() const { return status == RasStatus::kOk; }
};

/// RAS as a GridPlanner. PlannerOptions::connectivity overrides RasOptions::connectivity; the
/// robot radius is not applied (RAS keeps off walls by region size and density instead; inflate
/// with make_planning_grid first if both are wanted).
class RasPlanner : public GridPlanner {
 public:
  explicit RasPlanner(RasOptions ras = {}, PlannerOptions options = {});
  [[nodiscard]] std::string_view name() const override { return "ras"; }
  /// GridPlanner interface: path = RasResult::path_cells, length = its octile length,
  /// expanded = numbered regions.
  PlanResult plan(const BinaryGrid& grid, Cell start, Cell goal) override;
  /// Full RAS answer on a map of cells: builds the region grid, numbers, extracts the path.
  RasResult plan_ras(const BinaryGrid& grid, Cell start, Cell goal);
  /// The paper's search only, on a prebuilt region grid (start/goal given as map cells).
  RasResult plan_regions(const RegionGrid& regions, Cell start, Cell goal);
  [[nodiscard]] const RasOptions& ras_options() const { return ras_; }
  /// The field of the last query (for inspection and pictures).
  [[nodiscard]] const RasField& field() const { return search_.field(); }
  /// The region grid of the last plan()/plan_ras() call.
  [[nodiscard]] const RegionGrid& region_grid() const { return regions_; }
  /// The full RAS answer of the last plan() call (ids, regions, waypoints).
  [[nodiscard]] const RasResult& last_result() const { return last_; }

 private:
  RasOptions ras_;
  RasSearch search_;
  RegionGrid regions_;
  RasResult last_;
};

/// Region size and density for a robot of diameter robot_size [m] on a map of `resolution`
/// [m/cell] (seed 001, section 2.2: S_R, S_p, d). With density 8 every path region has a ring of
/// free regions around it, so every path cell outside the start region is at least r cells (centre
/// to centre) from the nearest blocked cell (tested); a disc of radius S_R/2 on a cell centre stays
/// off blocked cells when that clearance is >= S_R/2 + half a cell: r = ceil(S_R / (2 res) + 0.5).
/// Without density (d = 0) only the region itself is guaranteed free around a centre-to-centre
/// segment (clearance >= r/2): r = 2 ceil(S_R / (2 res) + 0.5). Throws voronav::Error for a
/// non-positive or non-finite size or resolution, or a density other than 0 or 8.
struct RasRobotParameters {
  int region_size = 1;
  int density = 8;
};
[[nodiscard]] RasRobotParameters ras_parameters_for_robot(double robot_size_m, double resolution_m,
                                                          int density = 8);

}  // namespace voronav::planning
