// RAS (seed 001) benchmark and the reproduction of its Tables 3 and 4.
//
//   ras_bench                 Google Benchmark: RAS, a plain BFS, A* and Dijkstra on the same
//   region
//                             grids of the Table 3/4 stand-in maps (same run, compare the rows).
//   ras_bench --write-maps D  Writes the stand-in maps as D/ras_table3.map and D/ras_table4.map.
//   ras_bench --tables        Markdown tables (bench/ras_tables.sh writes them to
//                             bench/results/ras.md): Table 3 and Table 4 on the stand-ins and on
//                             the real Moving AI maps, and RAS-with-density vs A*-with-robot-radius
//                             on the real ROS maps and floor plans (length [m], clearance [m],
//                             time).
//
// Times are medians of the thread CPU time of repeated runs of one query (>= 7 runs and >= 0.15 s
// per row; CPU time because the build machine is shared), measured in the same process; every row
// also gives its ratio to the plain BFS over the same region grid (a FIFO queue with parent
// pointers, stopping at the goal, same neighbour rule). RAS time = the numbering plus the
// count-rule path extraction; A*/Dijkstra/BFS times include their path reconstruction. Region-grid
// construction is reported separately (all share it). The RAS rows of one configuration (default,
// optimal, optimal per region) and its BFS baselines are timed interleaved, one run of each in
// turn. With density > 0 the baselines run twice: on the grid density-filtered beforehand
// ("precomputed", filtering not timed) and with the filtering inside the timed call ("online", as
// RAS tests density while it numbers).
//
// Real maps come from $VORONAV_DATA_DIR, else ../shared/data beside the repository, else data/.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "voronav/field/distance_transform.hpp"
#include "voronav/io/floorplan.hpp"
#include "voronav/io/movingai.hpp"
#include "voronav/io/ros_map.hpp"
#include "voronav/planning/astar.hpp"
#include "voronav/planning/ras.hpp"
#include "voronav/planning/ras_maps.hpp"

namespace fs = std::filesystem;
using namespace voronav;
using namespace voronav::planning;

namespace {

fs::path data_dir() {
  if (const char* env = std::getenv("VORONAV_DATA_DIR")) return env;
  for (const char* up : {"..", "../.."}) {  // main checkout or a worktree under wt/
    const fs::path shared = fs::path(VORONAV_SOURCE_DIR) / up / "shared" / "data";
    if (fs::exists(shared / "movingai")) return shared;
  }
  return fs::path(VORONAV_SOURCE_DIR) / "data";
}

// ---- The baseline: plain BFS over the region grid with parent pointers. ----------------------
class RegionBfs {
 public:
  /// Returns the number of regions on the path (0 when unreachable); `reached` counts visited.
  std::size_t run(const BinaryGrid& blocked, Cell s, Cell t, bool no_cut, std::size_t& reached) {
    const int w = blocked.width(), h = blocked.height();
    const auto pw = static_cast<std::ptrdiff_t>(w + 2);
    const std::size_t n = static_cast<std::size_t>(pw) * static_cast<std::size_t>(h + 2);
    parent_.assign(n, kBlocked);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        if (blocked[Cell{x, y}] == 0)
          parent_[static_cast<std::size_t>((y + 1) * pw + x + 1)] = kFree;
    queue_.clear();
    const std::ptrdiff_t off[8] = {1, pw + 1, pw, pw - 1, -1, -pw - 1, -pw, -pw + 1};
    const std::int32_t sp = static_cast<std::int32_t>((s.y + 1) * pw + s.x + 1);
    const std::int32_t tp = static_cast<std::int32_t>((t.y + 1) * pw + t.x + 1);
    parent_[static_cast<std::size_t>(sp)] = sp;
    queue_.push_back(sp);
    bool found = sp == tp;
    for (std::size_t head = 0; head < queue_.size() && !found; ++head) {
      const std::int32_t p = queue_[head];
      for (int k = 0; k < 8; ++k) {
        const std::int32_t q = p + static_cast<std::int32_t>(off[k]);
        if (parent_[static_cast<std::size_t>(q)] != kFree) continue;
        if (no_cut && (k & 1) != 0 &&
            (parent_[static_cast<std::size_t>(p + off[(k + 7) % 8])] == kBlocked ||
             parent_[static_cast<std::size_t>(p + off[(k + 1) % 8])] == kBlocked))
          continue;
        parent_[static_cast<std::size_t>(q)] = p;
        queue_.push_back(q);
        if (q == tp) {
          found = true;
          break;
        }
      }
    }
    reached = queue_.size();
    if (!found) return 0;
    std::size_t len = 1;
    for (std::int32_t p = tp; p != sp; p = parent_[static_cast<std::size_t>(p)])
      ++len;
    return len;
  }

 private:
  static constexpr std::int32_t kBlocked = -1, kFree = -2;
  std::vector<std::int32_t> parent_;
  std::vector<std::int32_t> queue_;
};

// Thread CPU time [s]: the machine is shared, so wall time would measure the neighbours too.
double cpu_s() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// Median CPU time [ms] of fn() over >= 7 runs and >= min_total_s.
double median_ms(const std::function<void()>& fn, double min_total_s = 0.15) {
  std::vector<double> t;
  double total = 0.0;
  while (t.size() < 7 || (total < min_total_s && t.size() < 2000)) {
    const double t0 = cpu_s();
    fn();
    const double s = cpu_s() - t0;
    t.push_back(s * 1e3);
    total += s;
  }
  std::nth_element(t.begin(), t.begin() + static_cast<std::ptrdiff_t>(t.size() / 2), t.end());
  return t[t.size() / 2];
}

// Medians like median_ms for several functions run in turn (one run of each per round), so a
// change of the machine's load hits them alike: their ratios are what these rows compare.
std::vector<double> interleaved_median_ms(const std::vector<std::function<void()>>& fns,
                                          double min_total_s = 0.15) {
  std::vector<std::vector<double>> t(fns.size());
  double total = 0.0;
  while (t[0].size() < 7 ||
         (total < min_total_s * static_cast<double>(fns.size()) && t[0].size() < 2000)) {
    for (std::size_t i = 0; i < fns.size(); ++i) {
      const double t0 = cpu_s();
      fns[i]();
      const double s = cpu_s() - t0;
      t[i].push_back(s * 1e3);
      total += s;
    }
  }
  std::vector<double> out;
  for (auto& v : t) {
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
    out.push_back(v[v.size() / 2]);
  }
  return out;
}

// Regions whose density is below D become blocked (the start region excepted): the graph RAS
// with density D searches, for A* and Dijkstra.
BinaryGrid density_filtered(const BinaryGrid& blocked, int D, Cell start) {
  BinaryGrid out = blocked;
  if (D == 0) return out;
  for (int y = 0; y < blocked.height(); ++y) {
    for (int x = 0; x < blocked.width(); ++x) {
      const Cell c{x, y};
      if (blocked[c] != 0 || c == start) continue;
      int d = 0;
      for (const Cell o : kNeighbours8)
        d += blocked.contains(c + o) && blocked[c + o] == 0;
      if (d < D) out[c] = 1;
    }
  }
  return out;
}

struct Row {
  std::string algorithm;
  int region_size = 0;
  std::string direction = "-";
  int density = 0;
  double ms = 0.0;
  long regions = 0;              // RAS: numbered regions; A*/Dijkstra: expanded; BFS: reached
  long path_regions = 0;         // 0 = no path
  std::string failure = "none";  // shown instead of the path regions when there is no path
  /// Baselines with density > 0: "precomputed" (the density-filtered grid built before timing)
  /// or "online" (the filtering timed with the search, as RAS tests density while it numbers).
  std::string filter = "-";
};

struct Query {
  Cell start, goal;
  std::string label;
};

std::string fmt(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

// Runs RAS (given options), and A*, Dijkstra and BFS on the same (density-filtered) region grid.
std::vector<Row> run_config(const RegionGrid& rg, const Query& q, int D, bool with_others,
                            const std::vector<RasDirection>& dirs) {
  std::vector<Row> rows;
  const Cell sr = rg.region_of(q.start), gr = rg.region_of(q.goal);
  const int r = rg.region_size();
  const BinaryGrid graph = density_filtered(rg.blocked(), D, sr);
  // The RAS directions and the BFS baselines are timed interleaved (their cost ratios are the
  // point of Table 4's rows). With density, each baseline runs twice: on the grid filtered
  // beforehand ("precomputed", the filtering not timed) and with the filtering inside the timed
  // call ("online").
  const std::size_t nd = dirs.size();
  std::vector<RasSearch> searches(nd);
  std::vector<RasStatus> st(nd, RasStatus::kUnreachable);
  std::vector<std::size_t> lens(nd, 0);
  std::vector<std::function<void()>> runs;
  for (std::size_t i = 0; i < nd; ++i)
    runs.push_back([&, i] {
      const RasOptions o{.region_size = r,
                         .density = D,
                         .direction = dirs[i],
                         .corner_rule = RasCornerRule::kNoCornerCutting};
      st[i] = searches[i].run(rg, sr, gr, o);
      const RasField& f = searches[i].field();
      lens[i] = st[i] == RasStatus::kOk ? f.path_to(f.id_at(gr)).size() : 0;
      benchmark::DoNotOptimize(lens[i]);
    });
  const std::vector<bool> filters =
      D > 0 ? std::vector<bool>{false, true} : std::vector<bool>{false};
  std::vector<RegionBfs> bfs(filters.size());
  std::vector<std::size_t> bfs_len(filters.size(), 0), bfs_reached(filters.size(), 0);
  for (std::size_t i = 0; i < filters.size(); ++i)
    runs.push_back([&, i] {
      if (filters[i]) {
        const BinaryGrid g = density_filtered(rg.blocked(), D, sr);
        bfs_len[i] = bfs[i].run(g, sr, gr, true, bfs_reached[i]);
      } else {
        bfs_len[i] = bfs[i].run(graph, sr, gr, true, bfs_reached[i]);
      }
    });
  const std::vector<double> ms = interleaved_median_ms(runs);
  for (std::size_t i = 0; i < nd; ++i) {
    const RasDirection dir = dirs[i];
    const char* name = dir == RasDirection::kOptimal            ? "optimal"
                       : dir == RasDirection::kOptimalPerRegion ? "optimal per region"
                                                                : "default";
    rows.push_back({"RAS", r, name, D, ms[i], searches[i].field().size(),
                    static_cast<long>(lens[i]), std::string(to_string(st[i]))});
  }
  for (const bool online : filters) {
    const std::string filter = D == 0 ? "-" : (online ? "online" : "precomputed");
    const std::size_t i = online ? 1 : 0;
    rows.push_back({"BFS", r, "-", D, ms[nd + i], static_cast<long>(bfs_reached[i]),
                    static_cast<long>(bfs_len[i]), "none", filter});
    if (with_others) {
      for (const bool astar : {true, false}) {
        AStarPlanner p({}, astar);
        PlanResult res;
        const double t_ms = median_ms([&] {
          if (online) {
            const BinaryGrid g = density_filtered(rg.blocked(), D, sr);
            res = p.plan(g, sr, gr);
          } else {
            res = p.plan(graph, sr, gr);
          }
        });
        rows.push_back({astar ? "A*" : "Dijkstra", r, "-", D, t_ms, static_cast<long>(res.expanded),
                        res.ok() ? static_cast<long>(res.path.size()) : 0, "none", filter});
      }
    }
  }
  return rows;
}

void print_rows(const std::vector<Row>& rows, bool numbered) {
  std::cout << "| " << (numbered ? "# | " : "")
            << "algorithm | region size | direction | density | density filter | time (ms) | "
               "x BFS | x BFS online | regions | path regions |\n|"
            << (numbered ? "---|" : "") << "---|---|---|---|---|---|---|---|---|---|\n";
  // BFS rows of the same (region size, density) for the ratios: the precomputed-filter BFS (the
  // only one at density 0) and, at density > 0, the BFS that filters online.
  int n = 0;
  for (const Row& row : rows) {
    double bfs_ms = 0.0, bfs_online_ms = 0.0;
    for (const Row& b : rows)
      if (b.algorithm == "BFS" && b.region_size == row.region_size && b.density == row.density) {
        if (b.filter == "online")
          bfs_online_ms = b.ms;
        else
          bfs_ms = b.ms;
      }
    std::cout << "| ";
    if (numbered) std::cout << (row.algorithm == "RAS" ? std::to_string(++n) : "") << " | ";
    std::cout << row.algorithm << " | " << row.region_size << " | " << row.direction << " | "
              << (row.algorithm == "RAS" || row.density > 0 ? std::to_string(row.density) : "0")
              << " | " << (row.algorithm == "RAS" && row.density > 0 ? "online" : row.filter)
              << " | " << fmt("%.3f", row.ms) << " | " << fmt("%.2f", row.ms / bfs_ms) << " | "
              << (bfs_online_ms > 0.0 ? fmt("%.2f", row.ms / bfs_online_ms) : std::string("-"))
              << " | " << row.regions << " | "
              << (row.path_regions > 0 ? std::to_string(row.path_regions) : row.failure) << " |\n";
  }
}

// The longest .scen query (by optimal length) for which `ok` holds.
std::optional<Query> pick_query(const fs::path& map_path, const BinaryGrid& grid,
                                const std::function<bool(Cell, Cell)>& ok) {
  const fs::path scen = map_path.string() + ".scen";
  if (!fs::exists(scen)) return std::nullopt;
  auto qs = io::load_movingai_scen(scen);
  std::sort(qs.begin(), qs.end(),
            [](const auto& a, const auto& b) { return a.optimal_length > b.optimal_length; });
  for (const auto& q : qs) {
    const Cell s = io::movingai_to_cell(q.start_x, q.start_y, grid.height());
    const Cell g = io::movingai_to_cell(q.goal_x, q.goal_y, grid.height());
    if (ok(s, g))
      return Query{s, g,
                   "scen line " + std::to_string(q.line) + ", (" + std::to_string(q.start_x) + "," +
                       std::to_string(q.start_y) + ") -> (" + std::to_string(q.goal_x) + "," +
                       std::to_string(q.goal_y) + ") in file coordinates, optimal " +
                       fmt("%.1f", q.optimal_length)};
  }
  return std::nullopt;
}

bool ras_ok(const BinaryGrid& g, Cell s, Cell t, int r, int D,
            RegionRule rule = RegionRule::kAnyBlocked) {
  RasPlanner p({.region_size = r,
                .region_rule = rule,
                .density = D,
                .corner_rule = RasCornerRule::kNoCornerCutting});
  return p.plan_ras(g, s, t).ok();
}

std::vector<fs::path> movingai_maps() {
  std::vector<fs::path> maps;
  const fs::path dir = data_dir() / "movingai";
  if (!fs::exists(dir)) return maps;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".map" && fs::exists(e.path().string() + ".scen"))
      maps.push_back(e.path());
  std::sort(maps.begin(), maps.end());
  return maps;
}

void table3() {
  std::cout << "## Table 3: A*, Dijkstra and RAS on the same region grid (density 0)\n\n";
  struct Case {
    std::string name;
    BinaryGrid grid;
    Query q;
    RegionRule rule = RegionRule::kAnyBlocked;
  };
  std::vector<Case> cases;
  {
    RasStandInMap m = ras_table3_map();
    cases.push_back({"stand-in 512x512 (ras_table3_map)",
                     std::move(m.grid),
                     {m.start, m.goal, "image (40,472) -> (472,40)"}});
  }
  // Real 512x512 maps: with 16-cell regions almost every region holds a wall cell, so these
  // use the majority rule (a region is blocked when most of its cells are).
  for (const char* name : {"32room_000", "random512-10-0"}) {
    const fs::path p = data_dir() / "movingai" / (std::string(name) + ".map");
    if (!fs::exists(p)) continue;
    BinaryGrid g = binarize(io::load_movingai_map(p));
    auto q = pick_query(p, g, [&](Cell s, Cell t) {
      return ras_ok(g, s, t, 16, 0, RegionRule::kMajorityBlocked) &&
             ras_ok(g, s, t, 8, 0, RegionRule::kMajorityBlocked);
    });
    if (q)
      cases.push_back({std::string(name) + " (Moving AI, majority rule)", std::move(g), *q,
                       RegionRule::kMajorityBlocked});
  }
  for (const Case& c : cases) {
    std::cout << "### " << c.name << "\n\nQuery: " << c.q.label << ".\n\n";
    std::vector<Row> rows;
    for (const int r : {16, 8}) {
      const RegionGrid rg(c.grid, {.region_size = r, .rule = c.rule});
      const double build = median_ms(
          [&] { benchmark::DoNotOptimize(RegionGrid(c.grid, {.region_size = r, .rule = c.rule})); },
          0.05);
      std::cout << "Region grid r = " << r << ": " << rg.width() << "x" << rg.height()
                << " regions, built in " << fmt("%.3f", build) << " ms.  \n";
      auto part = run_config(rg, c.q, 0, true, {RasDirection::kDefault});
      rows.insert(rows.end(), part.begin(), part.end());
    }
    std::cout << "\n";
    print_rows(rows, false);
    std::cout << "\n";
  }
}

void table4_on(const BinaryGrid& grid, const Query& q) {
  std::vector<Row> rows;
  for (const int r : {2, 8}) {
    const RegionGrid rg(grid, {.region_size = r});
    for (const int D : {0, 8}) {
      auto part = run_config(
          rg, q, D, true,
          {RasDirection::kDefault, RasDirection::kOptimal, RasDirection::kOptimalPerRegion});
      rows.insert(rows.end(), part.begin(), part.end());
    }
  }
  // Paper order: r, direction, density for the RAS rows; the other rows after each RAS pair.
  std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) {
    if (a.region_size != b.region_size) return a.region_size < b.region_size;
    const bool ra = a.algorithm == "RAS", rb = b.algorithm == "RAS";
    if (ra != rb) return ra;
    if (ra && a.direction != b.direction) return a.direction < b.direction;
    return a.density < b.density;
  });
  print_rows(rows, true);
  std::cout << "\n";
}

void table4() {
  std::cout << "## Table 4: RAS by region size, direction and density (robot size 8)\n\n"
            << "A*, Dijkstra and BFS run on the same region grid with the regions below the "
               "density threshold blocked.\n\n";
  {
    const RasStandInMap m = ras_table4_map();
    std::cout << "### stand-in 1000x1000 (ras_table4_map), start (100,250), goal (700,250)\n\n";
    table4_on(m.grid, {m.start, m.goal, ""});
  }
  for (const fs::path& p : movingai_maps()) {
    const BinaryGrid g = binarize(io::load_movingai_map(p));
    if (g.width() < 200) continue;  // too small for region size 8 to mean anything
    // The longest query RAS solves with 2-cell regions and no density; the other rows show
    // what larger regions and density 8 do to it (narrow passages close).
    auto q = pick_query(p, g, [&](Cell s, Cell t) { return ras_ok(g, s, t, 2, 0); });
    std::cout << "### " << p.stem().string() << " (" << g.width() << "x" << g.height()
              << ", Moving AI)\n\n";
    if (!q) {
      std::cout << "No .scen query has free start and goal regions at region size 2.\n\n";
      continue;
    }
    std::cout << "Query: " << q->label << ".\n\n";
    table4_on(g, *q);
  }
}

// ---- RAS with density vs A* with a robot radius, in metres. ---------------------------------
struct MetricMap {
  std::string name;
  OccupancyGrid grid;
};

std::vector<MetricMap> metric_maps() {
  std::vector<MetricMap> out;
  const fs::path d = data_dir();
  for (const auto& [name, rel] : std::vector<std::pair<std::string, std::string>>{
           {"turtlebot3_world", "ros_maps/turtlebot3_world/map.yaml"},
           {"depot", "ros_maps/depot/depot.yaml"},
           {"warehouse", "ros_maps/warehouse/warehouse.yaml"},
           {"willow", "ros_maps/willow/willow-full-0.05.yaml"}}) {
    if (fs::exists(d / rel)) out.push_back({name, io::load_ros_map(d / rel)});
  }
  for (const char* fp : {"office_a", "lab_intel", "NLB"}) {
    const fs::path p = d / "floorplans" / (std::string(fp) + ".png");
    if (fs::exists(p)) out.push_back({fp, io::load_floorplan(p)});
  }
  return out;
}

double min_clearance(const field::DistanceField& df, const std::vector<Cell>& cells, double res) {
  double m = std::numeric_limits<double>::infinity();
  for (const Cell c : cells)
    m = std::min(m, std::sqrt(static_cast<double>(df.squared_distance[c])));
  return m * res;
}

double polyline_m(const std::vector<Vec2>& pts) {
  double l = 0.0;
  for (std::size_t i = 1; i < pts.size(); ++i)
    l += (pts[i] - pts[i - 1]).norm();
  return l;
}

void comparison(double robot_size_m, int n_queries) {
  std::cout
      << "## RAS with density 8 vs A* with a robot radius (robot diameter "
      << fmt("%.2f", robot_size_m) << " m)\n\n"
      << "Per map: " << n_queries
      << " random start/goal pairs (seed 1) among free cells whose A* inflated cell is free "
         "and whose RAS regions are free and dense; the columns average over the queries "
         "both planners solve. RAS length = the polyline start, region centres, goal "
         "(figure 7); A* length = its octile cell path. Clearance = distance from path cell "
         "centres to the nearest blocked cell centre (exact EDT of the map), minimum along "
         "the path, then mean and worst over the queries. Time per query excludes the per-map "
         "preparation (inflation for A*, region grid for RAS), given separately.\n\n"
      << "| map | res (m) | r (cells) | queries | solved RAS / A* | length RAS (m) | length A* "
         "(m) | RAS / A* length | clearance RAS mean / worst (m) | clearance A* mean / worst "
         "(m) | time RAS (ms) | time A* (ms) | prep RAS / A* (ms) |\n"
      << "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const MetricMap& m : metric_maps()) {
    const double res = m.grid.resolution();
    const RasRobotParameters rp = ras_parameters_for_robot(robot_size_m, res, 8);
    const BinaryGrid raw = binarize(m.grid);
    const auto df = field::distance_transform(raw, {.border_is_blocked = true});
    const double radius = robot_size_m / 2.0;
    BinaryGrid inflated;
    const double prep_astar = median_ms([&] { inflated = make_planning_grid(raw, radius); }, 0.05);
    RegionGrid rg;
    const double prep_ras =
        median_ms([&] { rg = RegionGrid(raw, {.region_size = rp.region_size}); }, 0.05);
    RasPlanner ras({.region_size = rp.region_size, .density = 8});
    AStarPlanner astar;
    std::mt19937 rng(1);
    std::uniform_int_distribution<int> ux(0, raw.width() - 1), uy(0, raw.height() - 1);
    auto usable = [&](Cell c) {
      if (raw[c] != 0 || inflated[c] != 0) return false;
      const Cell r = rg.region_of(c);
      if (rg.is_blocked(r)) return false;
      for (const Cell o : kNeighbours8)
        if (!rg.contains(r + o) || rg.is_blocked(r + o)) return false;
      return true;
    };
    int queries = 0, solved_ras = 0, solved_astar = 0, both = 0;
    double len_ras = 0, len_astar = 0, cl_ras = 0, cl_astar = 0, t_ras = 0, t_astar = 0;
    double worst_ras = 1e9, worst_astar = 1e9;
    for (int attempt = 0; attempt < 200000 && queries < n_queries; ++attempt) {
      const Cell s{ux(rng), uy(rng)}, g{ux(rng), uy(rng)};
      if (!usable(s) || !usable(g) || s == g) continue;
      ++queries;
      RasResult a;
      PlanResult b;
      const double ta = median_ms([&] { a = ras.plan_regions(rg, s, g); }, 0.0);
      const double tb = median_ms([&] { b = astar.plan(inflated, s, g); }, 0.0);
      solved_ras += a.ok();
      solved_astar += b.ok();
      if (!a.ok() || !b.ok()) continue;
      ++both;
      len_ras += polyline_m(a.waypoints);
      len_astar += b.length_cells * res;
      const double ca = min_clearance(df, a.path_cells, res), cb = min_clearance(df, b.path, res);
      cl_ras += ca;
      cl_astar += cb;
      worst_ras = std::min(worst_ras, ca);
      worst_astar = std::min(worst_astar, cb);
      t_ras += ta;
      t_astar += tb;
    }
    if (both == 0) {
      std::cout << "| " << m.name << " | " << res << " | " << rp.region_size << " | " << queries
                << " | " << solved_ras << " / " << solved_astar
                << " | - | - | - | - | - | - | - | - |\n";
      continue;
    }
    const double nb = both;
    std::cout << "| " << m.name << " | " << fmt("%.3f", res) << " | " << rp.region_size << " | "
              << queries << " | " << solved_ras << " / " << solved_astar << " | "
              << fmt("%.2f", len_ras / nb) << " | " << fmt("%.2f", len_astar / nb) << " | "
              << fmt("%.3f", len_ras / len_astar) << " | " << fmt("%.3f", cl_ras / nb) << " / "
              << fmt("%.3f", worst_ras) << " | " << fmt("%.3f", cl_astar / nb) << " / "
              << fmt("%.3f", worst_astar) << " | " << fmt("%.3f", t_ras / nb) << " | "
              << fmt("%.3f", t_astar / nb) << " | " << fmt("%.2f", prep_ras) << " / "
              << fmt("%.2f", prep_astar) << " |\n";
  }
  std::cout << "\n";
}

// ---- Google Benchmark registrations. --------------------------------------------------------
struct BenchCase {
  RegionGrid rg;
  Cell sr, gr;
};

std::shared_ptr<BenchCase> bench_case(const RasStandInMap& m, int r) {
  auto c = std::make_shared<BenchCase>();
  c->rg = RegionGrid(m.grid, {.region_size = r});
  c->sr = c->rg.region_of(m.start);
  c->gr = c->rg.region_of(m.goal);
  return c;
}

void register_benchmarks() {
  const RasStandInMap t3 = ras_table3_map(), t4 = ras_table4_map();
  for (const auto& [m, r] :
       std::vector<std::pair<const RasStandInMap*, int>>{{&t3, 16}, {&t3, 8}, {&t4, 8}, {&t4, 2}}) {
    const auto c = bench_case(*m, r);
    const std::string tag = m->name + "/r" + std::to_string(r);
    for (const auto dir : {RasDirection::kDefault, RasDirection::kOptimal}) {
      benchmark::RegisterBenchmark(
          ("ras_" + std::string(dir == RasDirection::kDefault ? "default/" : "optimal/") + tag)
              .c_str(),
          [c, dir](benchmark::State& st) {
            RasSearch s;
            const RasOptions o{.region_size = c->rg.region_size(),
                               .direction = dir,
                               .corner_rule = RasCornerRule::kNoCornerCutting};
            for (auto _ : st) {
              s.run(c->rg, c->sr, c->gr, o);
              benchmark::DoNotOptimize(s.field().path_to(s.field().id_at(c->gr)).size());
            }
          })
          ->Unit(benchmark::kMicrosecond);
    }
    benchmark::RegisterBenchmark(("bfs/" + tag).c_str(), [c](benchmark::State& st) {
      RegionBfs bfs;
      std::size_t reached = 0;
      for (auto _ : st)
        benchmark::DoNotOptimize(bfs.run(c->rg.blocked(), c->sr, c->gr, true, reached));
    })->Unit(benchmark::kMicrosecond);
    for (const bool astar : {true, false}) {
      benchmark::RegisterBenchmark(
          ((astar ? "astar/" : "dijkstra/") + tag).c_str(),
          [c, astar](benchmark::State& st) {
            AStarPlanner p({}, astar);
            for (auto _ : st)
              benchmark::DoNotOptimize(p.plan(c->rg.blocked(), c->sr, c->gr).path.size());
          })
          ->Unit(benchmark::kMicrosecond);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 2 && std::strcmp(argv[1], "--write-maps") == 0) {
    // The stand-in maps as Moving AI .map files: their file frame (x right, y down) is the
    // paper's image frame, so `voronav plan --start 100,250 --goal 700,250` means what it says.
    for (const RasStandInMap& m : {ras_table3_map(), ras_table4_map()}) {
      OccupancyGrid occ(m.grid.geometry(), kFree);
      for (std::size_t i = 0; i < occ.size(); ++i)
        occ[i] = m.grid[i] != 0 ? kOccupied : kFree;
      const fs::path out = fs::path(argv[2]) / (m.name + ".map");
      io::save_movingai_map(occ, out);
      std::cout << out.string() << "\n";
    }
    return 0;
  }
  if (argc > 1 && std::strcmp(argv[1], "--tables") == 0) {
    std::cout << "# RAS (seed 001): Tables 3 and 4 and the comparison with A*\n\n"
              << "Generated by `bench/ras_tables.sh` (`ras_bench --tables`); data from "
              << fs::weakly_canonical(data_dir()).filename().string()
              << "/. Times are medians of the thread CPU time of repeated runs in one process, "
                 "with the ratio to a "
                 "plain BFS over the same region grid measured in the same run (`x BFS`). "
                 "All searches use 8 neighbours without corner cutting.\n\n";
    const std::string only = argc > 2 ? argv[2] : "";
    if (only.empty() || only == "3") table3();
    if (only.empty() || only == "4") table4();
    if (only.empty() || only == "compare") comparison(0.4, 40);
    return 0;
  }
  register_benchmarks();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
