#include "voronav/report/example_recording.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "voronav/core/cell_iterators.hpp"
#include "voronav/core/error.hpp"

namespace voronav::report {

namespace {

constexpr double kRes = 0.1;  // [m/cell]
constexpr int kWidth = 320;
constexpr int kHeight = 200;
constexpr double kChangeTime = 6.0;  // [s] when the box appears

struct Rect {
  double x0, y0, x1, y1;  // [m]
};

int to_cell(double m) {
  return static_cast<int>(std::lround(m / kRes));
}

template <typename T>
void fill(GridMap<T>& g, const Rect& r, T v) {
  for (int y = std::max(0, to_cell(r.y0)); y < std::min(g.height(), to_cell(r.y1)); ++y)
    for (int x = std::max(0, to_cell(r.x0)); x < std::min(g.width(), to_cell(r.x1)); ++x)
      g[Cell{x, y}] = v;
}

const Rect kBox{12.0, 9.6, 13.5, 11.9};

// Rooms and the corridor: free rectangles between the walls. Index + 1 is the region label.
const std::vector<std::pair<const char*, Rect>>& regions() {
  static const std::vector<std::pair<const char*, Rect>> r = {
      {"corridor", {0.2, 8.1, 31.8, 11.9}}, {"room A", {0.2, 12.1, 10.4, 19.8}},
      {"room B", {10.6, 12.1, 20.9, 19.8}}, {"room C", {21.1, 12.1, 31.8, 19.8}},
      {"room D", {0.2, 0.2, 15.9, 7.9}},    {"room E", {16.1, 0.2, 31.8, 7.9}}};
  return r;
}

struct Door {
  double x;  // centre [m]
  double y;  // wall centre [m]
  int room;  // region index of the room behind it
};
const std::vector<Door>& doors() {
  static const std::vector<Door> d = {
      {5.0, 12.0, 1}, {16.0, 12.0, 2}, {27.0, 12.0, 3}, {8.0, 8.0, 4}, {24.0, 8.0, 5}};
  return d;
}

OccupancyGrid build_map() {
  OccupancyGrid g(GridGeometry{kWidth, kHeight, kRes, {}}, kOccupied);
  for (const auto& [name, r] : regions())
    fill(g, r, kFree);
  for (const auto& d : doors())
    fill(g, Rect{d.x - 0.6, d.y - 0.2, d.x + 0.6, d.y + 0.2}, kFree);
  // Furniture.
  for (const Rect& r :
       {Rect{3.0, 15.5, 7.0, 16.5}, Rect{12.0, 17.8, 14.0, 19.8}, Rect{17.0, 13.5, 19.0, 15.5},
        Rect{25.0, 15.0, 29.0, 16.0}, Rect{3.0, 2.0, 5.0, 4.0}, Rect{10.0, 3.0, 12.0, 5.0},
        Rect{20.0, 2.0, 22.0, 5.0}, Rect{27.0, 4.0, 29.0, 6.0}})
    fill(g, r, kOccupied);
  return g;
}

// Medial axis of an axis-aligned rectangle: the centre segment along the long side and the four
// segments from its ends to the corners.
void draw_medial_axis(GridMap<std::int32_t>& g, const Rect& r) {
  const double w = r.x1 - r.x0, h = r.y1 - r.y0;
  Vec2 a, b;
  if (w >= h) {
    a = {r.x0 + h / 2, (r.y0 + r.y1) / 2};
    b = {r.x1 - h / 2, a.y};
  } else {
    a = {(r.x0 + r.x1) / 2, r.y0 + w / 2};
    b = {a.x, r.y1 - w / 2};
  }
  auto seg = [&](Vec2 p, Vec2 q) {
    for_each_line_cell(Cell{to_cell(p.x), to_cell(p.y)}, Cell{to_cell(q.x), to_cell(q.y)},
                       [&](Cell c) {
                         if (g.contains(c)) g[c] = 1;
                       });
  };
  seg(a, b);
  const Vec2 lo{r.x0, r.y0}, hi{r.x1, r.y1};
  seg(a, {lo.x, lo.y});
  seg(w >= h ? a : b, {lo.x, hi.y});
  seg(w >= h ? b : a, {hi.x, lo.y});
  seg(b, {hi.x, hi.y});
}

struct Route {
  int id;
  const char* name;
  const char* color;
  double speed;  // [m/s]
  std::vector<Vec2> waypoints;
};

std::vector<Route> routes() {
  return {
      {0,
       "robot 0",
       "#e6550d",
       0.7,
       {{1.5, 10.8},
        {5.0, 10.8},
        {5.0, 14.0},
        {2.0, 14.0},
        {2.0, 18.5},
        {9.0, 18.5},
        {9.0, 14.0},
        {6.0, 13.8}}},
      {1,
       "robot 1",
       "#3182bd",
       0.8,
       {{1.5, 10.0},
        {10.5, 10.0},
        {11.5, 9.0},
        {14.0, 9.0},
        {15.0, 10.0},
        {27.0, 10.0},
        {27.0, 13.5},
        {30.5, 13.5},
        {30.5, 18.5},
        {22.5, 18.5},
        {22.5, 13.5}}},
      {2,
       "robot 2",
       "#31a354",
       1.0,
       {{3.5, 8.9},
        {24.0, 8.9},
        {24.0, 6.5},
        {18.0, 6.5},
        {18.0, 1.2},
        {30.5, 1.2},
        {30.5, 7.0},
        {26.0, 7.0}}},
  };
}

// The route robot 1 planned at t = 0, before the box appeared (straight along the corridor).
std::vector<Vec2> robot1_initial_plan() {
  return {{1.5, 10.0},  {27.0, 10.0}, {27.0, 13.5}, {30.5, 13.5},
          {30.5, 18.5}, {22.5, 18.5}, {22.5, 13.5}};
}

std::vector<TimedPose> drive(const Route& r, double dt) {
  std::vector<TimedPose> out;
  double t = 0.0;
  const auto& w = r.waypoints;
  double yaw = std::atan2(w[1].y - w[0].y, w[1].x - w[0].x);
  out.push_back({0.0, {w[0], yaw}});
  double carry = 0.0;  // distance already travelled into the current sample step
  for (std::size_t i = 0; i + 1 < w.size(); ++i) {
    const Vec2 d = w[i + 1] - w[i];
    const double len = d.norm();
    yaw = std::atan2(d.y, d.x);
    const double step = r.speed * dt;
    double s = step - carry;
    while (s <= len + 1e-12) {
      t += dt;
      out.push_back({t, {w[i] + d * (s / len), yaw}});
      s += step;
    }
    carry = len - (s - step);
  }
  if (carry > 1e-9) out.push_back({t + carry / r.speed, {w.back(), yaw}});
  return out;
}

}  // namespace

Recording make_example_recording(const ExampleOptions& o) {
  if (!(o.sample_period_s > 0.0) || !(o.sensor_range_m > 0.0) || !(o.coverage_period_s > 0.0) ||
      !(o.radio_range_m >= 0.0) ||
      !std::isfinite(o.sample_period_s + o.sensor_range_m + o.coverage_period_s + o.radio_range_m))
    throw Error("ExampleOptions", 0, "periods and ranges must be positive finite numbers");
  Recording rec;
  rec.title = "voronav replay example: three robots in an office";
  rec.description =
      "Synthetic recording (voronav replay --example): three robots leave the corridor to "
      "explore rooms A, C and E. At t = 6 s a box appears in the corridor and robot 1 re-plans "
      "around it. Lines between robots are messages; the plots show the explored area and "
      "the radio traffic.";
  rec.map = build_map();
  const GridGeometry geo = rec.map.geometry();

  // Layers.
  RasterLayer region_layer{"Regions", RasterStyle::kLabels, "#000000", false,
                           GridMap<std::int32_t>(geo, 0)};
  RasterLayer voronoi{"Voronoi (medial axis)", RasterStyle::kMask, "#d62728", true,
                      GridMap<std::int32_t>(geo, 0)};
  for (std::size_t i = 0; i < regions().size(); ++i) {
    const Rect& r = regions()[i].second;
    GridMap<std::int32_t> tmp(geo, 0);
    fill(tmp, r, 1);
    for (std::size_t k = 0; k < tmp.size(); ++k)
      if (tmp[k] != 0 && rec.map[k] == kFree)
        region_layer.cells[k] = static_cast<std::int32_t>(i + 1);
    draw_medial_axis(voronoi.cells, r);
  }
  for (std::size_t k = 0; k < voronoi.cells.size(); ++k)
    if (rec.map[k] != kFree) voronoi.cells[k] = 0;
  rec.rasters.push_back(std::move(region_layer));
  rec.rasters.push_back(std::move(voronoi));

  GraphLayer graph{"Topological graph", "#1f3b99", true, {}, {}};
  for (std::size_t i = 0; i < regions().size(); ++i) {
    const Rect& r = regions()[i].second;
    if (i == 0) continue;  // the corridor is represented by its junctions
    graph.nodes.push_back(
        {static_cast<int>(i), {(r.x0 + r.x1) / 2, (r.y0 + r.y1) / 2}, regions()[i].first});
  }
  std::vector<std::pair<double, int>> junctions;
  for (std::size_t k = 0; k < doors().size(); ++k) {
    const Door& d = doors()[k];
    const int door_id = 100 + static_cast<int>(k);
    const int junction_id = 200 + static_cast<int>(k);
    graph.nodes.push_back({door_id, {d.x, d.y}, ""});
    graph.nodes.push_back({junction_id, {d.x, 10.0}, ""});
    graph.edges.push_back({d.room, door_id});
    graph.edges.push_back({door_id, junction_id});
    junctions.emplace_back(d.x, junction_id);
  }
  std::sort(junctions.begin(), junctions.end());
  for (std::size_t k = 0; k + 1 < junctions.size(); ++k)
    graph.edges.push_back({junctions[k].second, junctions[k + 1].second});
  rec.graphs.push_back(std::move(graph));

  // Robots and their paths.
  const auto rs = routes();
  for (const Route& r : rs) {
    RobotTrack t;
    t.id = r.id;
    t.name = r.name;
    t.radius = 0.3;
    t.color = r.color;
    t.poses = drive(r, o.sample_period_s);
    rec.robots.push_back(std::move(t));
    if (r.id == 1) {
      rec.paths.push_back({1, 0.0, "A*", robot1_initial_plan()});
      // The repair path starts where robot 1 is when the box appears.
      // Keep the remaining waypoints in route order from the first one ahead of the robot.
      std::vector<Vec2> repair{pose_at(rec.robots.back(), kChangeTime).position};
      bool ahead = false;
      for (const Vec2& p : r.waypoints) {
        ahead = ahead || p.x > repair.front().x;
        if (ahead) repair.push_back(p);
      }
      rec.paths.push_back({1, kChangeTime, "repair", repair});
    } else {
      rec.paths.push_back({r.id, 0.0, "A*", r.waypoints});
    }
  }

  ObstacleChange change;
  change.t = kChangeTime;
  change.value = kOccupied;
  for (int y = to_cell(kBox.y0); y < to_cell(kBox.y1); ++y)
    for (int x = to_cell(kBox.x0); x < to_cell(kBox.x1); ++x)
      change.cells.push_back({x, y});
  rec.obstacle_changes.push_back(change);

  // Where each robot is going, and what happens when.
  for (const Route& r : rs)
    rec.markers.push_back({"goal", r.waypoints.back(), r.id, std::string("goal of ") + r.name});
  rec.events.push_back({kChangeTime, "change", "a box appears in the corridor", -1});
  rec.events.push_back({kChangeTime + 0.15, "repair", "robot 1 re-plans around the box", 1});
  for (const auto& t : rec.robots)
    rec.events.push_back({t.poses.back().t, "arrival", t.name + " reaches its goal", t.id});

  // Messages: a Search from everyone at the start, a Path update every second to robots in radio
  // range, and robot 1's Repair right after the change.
  const double end = rec.end_time();
  std::map<std::pair<int, std::string>, std::int64_t> bytes_by;
  auto send = [&](double t, int from, const std::string& type, std::int64_t bytes) {
    const Vec2 p = pose_at(rec.robots[static_cast<std::size_t>(from)], t).position;
    for (const auto& other : rec.robots) {
      if (other.id == from) continue;
      if (distance(p, pose_at(other, t).position) > o.radio_range_m) continue;
      rec.messages.push_back({t, from, other.id, type, bytes});
      bytes_by[{from, type}] += bytes;
    }
  };
  for (const auto& r : rs)
    send(0.0 + 0.05 * r.id, r.id, "Search", 32);
  for (double t = 1.0; t <= end; t += 1.0)
    for (const auto& r : rs)
      send(t + 0.1 * r.id, r.id, "Path", 16 + 8 * static_cast<std::int64_t>(r.waypoints.size()));
  send(kChangeTime + 0.15, 1, "Repair", 96);
  std::sort(rec.messages.begin(), rec.messages.end(),
            [](const MessageRecord& a, const MessageRecord& b) { return a.t < b.t; });

  // Coverage: free cells within sensor range and line of sight of a robot, over time.
  OccupancyGrid world = rec.map;
  std::size_t free_total = 0;
  for (std::size_t k = 0; k < world.size(); ++k)
    free_total += world[k] == kFree ? 1 : 0;
  std::vector<std::vector<char>> seen(rs.size() + 1, std::vector<char>(world.size(), 0));
  std::vector<std::size_t> count(rs.size() + 1, 0);
  Plot coverage{
      "Explored area", "time [s]", "explored free area [%]", PlotKind::kLine, true, {}, {}};
  for (const auto& r : rs)
    coverage.series.push_back({r.name, r.color, {}, {}});
  coverage.series.push_back({"team", "#444444", {}, {}});
  const double range_cells = o.sensor_range_m / kRes;
  bool changed = false;
  for (double t = 0.0; t <= end + 1e-9; t += o.coverage_period_s) {
    if (!changed && t >= kChangeTime) {
      for (const Cell& c : change.cells)
        world[c] = change.value;
      changed = true;
    }
    for (std::size_t i = 0; i < rs.size(); ++i) {
      const auto cell = geo.world_to_cell(pose_at(rec.robots[i], t).position);
      if (!cell || !geo.contains(*cell)) continue;
      for_each_disc_cell(*cell, range_cells, [&](Cell target) {
        const double d = std::hypot(target.x - cell->x, target.y - cell->y);
        if (d < range_cells - 1.0) return;  // cast rays to the rim only
        for_each_line_cell(*cell, target, [&](Cell c) {
          if (!geo.contains(c) || world[c] == kOccupied) return false;
          const std::size_t k = geo.index(c);
          for (std::size_t s : {i, rs.size()})
            if (!seen[s][k]) {
              seen[s][k] = 1;
              ++count[s];
            }
          return true;
        });
      });
    }
    for (std::size_t s = 0; s <= rs.size(); ++s) {
      coverage.series[s].x.push_back(t);
      coverage.series[s].y.push_back(100.0 * static_cast<double>(count[s]) /
                                     static_cast<double>(free_total));
    }
  }
  rec.plots.push_back(std::move(coverage));

  Plot traffic{"Radio traffic per robot",
               "message type",
               "bytes sent [B]",
               PlotKind::kBar,
               false,
               {"Search", "Path", "Repair"},
               {}};
  for (const auto& r : rs) {
    Series s{r.name, r.color, {}, {}};
    for (const auto& type : traffic.categories)
      s.y.push_back(static_cast<double>(bytes_by[{r.id, type}]));
    traffic.series.push_back(std::move(s));
  }
  rec.plots.push_back(std::move(traffic));
  return rec;
}

}  // namespace voronav::report
