#include "voronav/bag/run_bag.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <nlohmann/json.hpp>

#include "voronav/bag/ros_bag.hpp"
#include "voronav/core/error.hpp"

namespace voronav::bag {
namespace {

using ros::Marker;

ros::Header header(double t) {
  return {ros::Time::from_seconds(t), "map"};
}

ros::Point point(Vec2 p, double z = 0.0) {
  return {p.x, p.y, z};
}

ros::PathMsg path_msg(const report::PathRecord& p) {
  ros::PathMsg m;
  m.header = header(p.t_start);
  double yaw = 0.0;
  for (std::size_t i = 0; i < p.points.size(); ++i) {
    if (i + 1 < p.points.size()) {
      const Vec2 d = p.points[i + 1] - p.points[i];
      if (d.norm() > 1e-12) yaw = std::atan2(d.y, d.x);
    }
    m.poses.push_back({header(p.t_start), ros::Pose::from({p.points[i], yaw})});
  }
  return m;
}

// A distinct colour per label value (golden-angle hues).
ros::ColorRGBA label_color(int v) {
  const double h = std::fmod(v * 0.618033988749895, 1.0) * 6.0;
  const double x = 1.0 - std::abs(std::fmod(h, 2.0) - 1.0);
  double r = 0, g = 0, b = 0;
  switch (static_cast<int>(h)) {
    case 0:
      r = 1, g = x;
      break;
    case 1:
      r = x, g = 1;
      break;
    case 2:
      g = 1, b = x;
      break;
    case 3:
      g = x, b = 1;
      break;
    case 4:
      r = x, b = 1;
      break;
    default:
      r = 1, b = x;
      break;
  }
  return {static_cast<float>(0.3 + 0.6 * r), static_cast<float>(0.3 + 0.6 * g),
          static_cast<float>(0.3 + 0.6 * b), 0.5F};
}

Marker raster_marker(const report::RasterLayer& layer, double t, int id) {
  Marker m;
  m.header = header(t);
  m.ns = layer.name;
  m.id = id;
  m.type = Marker::kCubeList;
  const double res = layer.cells.resolution();
  m.scale = {res, res, 0.01};
  m.color = ros::color_from_css(layer.color, 0.8F);
  for (std::size_t i = 0; i < layer.cells.size(); ++i) {
    const int v = layer.cells[i];
    if (v == 0) continue;
    m.points.push_back(point(layer.cells.geometry().cell_center(layer.cells.cell_at(i))));
    if (layer.style == report::RasterStyle::kLabels) m.colors.push_back(label_color(v));
  }
  return m;
}

void add_graph_markers(const report::GraphLayer& g, double t, int& id, std::vector<Marker>& out) {
  std::map<int, Vec2> pos;
  for (const auto& n : g.nodes)
    pos[n.id] = n.position;
  const ros::ColorRGBA color = ros::color_from_css(g.color);
  Marker edges;
  edges.header = header(t);
  edges.ns = g.name + " edges";
  edges.id = id++;
  edges.type = Marker::kLineList;
  edges.scale = {0.05, 0, 0};
  edges.color = color;
  for (const auto& e : g.edges) {
    edges.points.push_back(point(pos[e.from]));
    edges.points.push_back(point(pos[e.to]));
  }
  Marker nodes = edges;
  nodes.ns = g.name + " nodes";
  nodes.id = id++;
  nodes.type = Marker::kSphereList;
  nodes.scale = {0.2, 0.2, 0.2};
  nodes.points.clear();
  for (const auto& n : g.nodes)
    nodes.points.push_back(point(n.position));
  out.push_back(std::move(edges));
  out.push_back(std::move(nodes));
  for (const auto& n : g.nodes) {
    if (n.label.empty()) continue;
    Marker text;
    text.header = header(t);
    text.ns = g.name + " labels";
    text.id = id++;
    text.type = Marker::kTextViewFacing;
    text.pose = ros::Pose::from({n.position + Vec2{0.0, 0.25}, 0.0});
    text.scale = {0, 0, 0.3};
    text.color = color;
    text.text = n.label;
    out.push_back(std::move(text));
  }
}

bool is_voronoi(const std::string& name) {
  std::string lower = name;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return lower.find("voronoi") != std::string::npos;
}

std::string event_json(double t, const std::string& event, nlohmann::json fields) {
  fields["t"] = t;
  fields["event"] = event;
  return fields.dump();
}

}  // namespace

std::string base_link(int robot_id) {
  return "robot_" + std::to_string(robot_id) + "/base_link";
}

std::vector<std::pair<double, OccupancyGrid>> known_map_series(
    const OccupancyGrid& final_map, const std::vector<float>& reveal_time, double end_s,
    double period_s, std::size_t max_snapshots) {
  if (reveal_time.size() != final_map.size())
    throw Error("known_map_series", 0,
                "reveal times for " + std::to_string(reveal_time.size()) + " cells, the map has " +
                    std::to_string(final_map.size()));
  if (!(period_s > 0.0) || !std::isfinite(period_s))
    throw Error("--known-map-period", 0, "expected a period > 0 s");
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < reveal_time.size(); ++i)
    if (reveal_time[i] >= 0.0F && reveal_time[i] <= end_s) order.push_back(i);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return reveal_time[a] < reveal_time[b]; });
  std::vector<std::pair<double, OccupancyGrid>> out;
  if (order.empty()) return out;
  const double first = reveal_time[order.front()];
  if (max_snapshots >= 2 && (end_s - first) / period_s > static_cast<double>(max_snapshots - 1))
    period_s = (end_s - first) / static_cast<double>(max_snapshots - 1);
  OccupancyGrid map(final_map.geometry(), kUnknown);
  std::size_t k = 0;
  for (double t = first;; t += period_s) {
    const bool last = t >= end_s - 1e-9;
    if (last) t = end_s;
    const std::size_t before = k;
    for (; k < order.size() && reveal_time[order[k]] <= t + 1e-9; ++k) {
      const Cell c = final_map.cell_at(order[k]);
      map[c] = final_map[c];
    }
    if (k > before || (last && out.empty())) out.emplace_back(t, map);
    if (last) break;
  }
  return out;
}

std::map<std::string, std::size_t> write_run_bag(const report::Recording& rec,
                                                 const std::filesystem::path& file,
                                                 const BagExtras& extras,
                                                 const McapOptions& options) {
  RosBagWriter bag(file, options);
  const double t0 = rec.start_time();
  // The recording's own events (route, change, repair, kill, arrival) when it has them; else
  // events derived from its paths and obstacle changes.
  const bool derive_events = rec.events.empty();
  for (const auto& e : rec.events)
    bag.write("/events", e.t,
              ros::StringMsg{event_json(e.t, e.kind, {{"detail", e.text}, {"robot", e.robot}})});

  // /map: the static map, then the map after each obstacle change.
  if (!rec.map.empty()) {
    bag.write("/map", t0, ros::OccupancyGridMsg::from(rec.map, ros::Time::from_seconds(t0)));
    std::vector<report::ObstacleChange> changes = rec.obstacle_changes;
    std::stable_sort(changes.begin(), changes.end(),
                     [](const auto& a, const auto& b) { return a.t < b.t; });
    OccupancyGrid map = rec.map;
    for (const auto& c : changes) {
      for (const Cell cell : c.cells)
        if (map.contains(cell)) map[cell] = c.value;
      bag.write("/map", c.t, ros::OccupancyGridMsg::from(map, ros::Time::from_seconds(c.t)));
      if (derive_events)
        bag.write("/events", c.t,
                  ros::StringMsg{event_json(c.t, "obstacle_change",
                                            {{"cells", c.cells.size()}, {"value", c.value}})});
    }
  }
  for (const auto& [t, m] : extras.known_maps)
    bag.write("/known_map", t, ros::OccupancyGridMsg::from(m, ros::Time::from_seconds(t)));

  // Paths.
  for (const auto& p : rec.paths) {
    if (p.points.empty()) continue;
    const ros::PathMsg m = path_msg(p);
    bag.write("/robot_" + std::to_string(p.robot) + "/plan", p.t_start, m);
    if (rec.robots.size() <= 1 || p.label == "route") bag.write("/plan", p.t_start, m);
    if (derive_events)
      bag.write("/events", p.t_start,
                ros::StringMsg{event_json(
                    p.t_start, p.label == "route" ? "route_found" : "path",
                    {{"robot", p.robot}, {"label", p.label}, {"points", p.points.size()}})});
  }

  // /tf and /robots at every track sample time (thinned evenly).
  std::vector<double> times;
  for (const auto& r : rec.robots)
    for (const auto& p : r.poses)
      times.push_back(p.t);
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  if (times.size() > extras.max_tf_samples && extras.max_tf_samples >= 2) {
    std::vector<double> thin;
    const double step =
        static_cast<double>(times.size() - 1) / static_cast<double>(extras.max_tf_samples - 1);
    for (std::size_t k = 0; k < extras.max_tf_samples; ++k)
      thin.push_back(times[static_cast<std::size_t>(std::llround(static_cast<double>(k) * step))]);
    thin.erase(std::unique(thin.begin(), thin.end()), thin.end());
    times = std::move(thin);
  }
  for (const double t : times) {
    ros::TFMessage tf;
    ros::PoseArrayMsg robots;
    robots.header = header(t);
    for (const auto& r : rec.robots) {
      if (r.poses.empty()) continue;
      const Pose2 p = report::pose_at(r, t);
      tf.transforms.push_back(
          {header(t), base_link(r.id), point(p.position), ros::Quaternion::from_yaw(p.yaw)});
      robots.poses.push_back(ros::Pose::from(p));
    }
    bag.write("/tf", t, tf);
    bag.write("/robots", t, robots);
  }

  // Layers: published once, at the start.
  ros::MarkerArrayMsg voronoi, topology;
  int id = 0;
  for (const auto& r : rec.rasters)
    (is_voronoi(r.name) ? voronoi : topology).markers.push_back(raster_marker(r, t0, id++));
  for (const auto& g : rec.graphs)
    add_graph_markers(g, t0, id, is_voronoi(g.name) ? voronoi.markers : topology.markers);
  if (!voronoi.markers.empty()) bag.write("/voronoi", t0, voronoi);
  if (!topology.markers.empty()) bag.write("/topology", t0, topology);
  if (!extras.collision_boxes.empty())
    bag.write("/collision_boxes", t0, ros::MarkerArrayMsg{extras.collision_boxes});

  // /messages: one MarkerArray per instant, an arrow per message, shown for message_display_s.
  std::map<int, const report::RobotTrack*> tracks;
  for (const auto& r : rec.robots)
    if (!r.poses.empty()) tracks[r.id] = &r;
  std::map<double, ros::MarkerArrayMsg> by_time;
  int msg_id = 0;
  for (const auto& m : rec.messages) {
    const auto from = tracks.find(m.from), to = tracks.find(m.to);
    if (from == tracks.end() || to == tracks.end()) continue;
    Marker a;
    a.header = header(m.t);
    a.ns = m.type;
    a.id = msg_id++;
    a.type = Marker::kArrow;
    a.scale = {0.05, 0.15, 0.15};
    a.color = label_color(static_cast<int>(std::hash<std::string>{}(m.type) % 97U));
    a.color.a = 1.0F;
    a.lifetime = ros::Time::from_seconds(rec.message_display_s);
    a.points = {point(report::pose_at(*from->second, m.t).position, 0.1),
                point(report::pose_at(*to->second, m.t).position, 0.1)};
    by_time[m.t].markers.push_back(std::move(a));
  }
  for (const auto& [t, arr] : by_time)
    bag.write("/messages", t, arr);

  for (const auto& e : extras.events)
    bag.write("/events", e.t, ros::StringMsg{event_json(e.t, e.event, {{"detail", e.detail}})});

  bag.close();
  return bag.counts();
}

}  // namespace voronav::bag
