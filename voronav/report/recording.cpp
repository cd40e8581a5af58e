#include "voronav/report/recording.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <set>
#include <sstream>

#include "voronav/core/error.hpp"

namespace voronav::report {

namespace {

using nlohmann::json;

// ---------------------------------------------------------------- validation helpers

[[noreturn]] void fail(const std::string& source, const std::string& field,
                       const std::string& reason) {
  throw Error(source, 0, field + ": " + reason);
}

void check_finite(double v, const std::string& source, const std::string& field) {
  if (!std::isfinite(v)) fail(source, field, "expected a finite number");
}

bool is_hex_color(const std::string& c) {
  if (c.size() != 7 || c[0] != '#') return false;
  return std::all_of(c.begin() + 1, c.end(),
                     [](char ch) { return std::isxdigit(static_cast<unsigned char>(ch)) != 0; });
}

void check_color(const std::string& c, bool allow_empty, const std::string& source,
                 const std::string& field) {
  if (c.empty() && allow_empty) return;
  if (!is_hex_color(c)) fail(source, field, "expected a colour '#rrggbb', got '" + c + "'");
}

std::string at_index(const std::string& base, std::size_t i) {
  return base + "[" + std::to_string(i) + "]";
}

// ---------------------------------------------------------------- run-length encoding

template <typename T>
json rle_encode(const std::vector<T>& values) {
  json out = json::array();
  std::size_t i = 0;
  while (i < values.size()) {
    std::size_t j = i + 1;
    while (j < values.size() && values[j] == values[i])
      ++j;
    out.push_back(static_cast<std::int64_t>(values[i]));
    out.push_back(static_cast<std::int64_t>(j - i));
    i = j;
  }
  return out;
}

// ---------------------------------------------------------------- JSON reading helpers

// Reads typed fields of a JSON object and names the field path in every error.
class Reader {
 public:
  explicit Reader(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail_at(const std::string& path, const std::string& reason) const {
    fail(source_, path, reason);
  }
  const json& require(const json& obj, const std::string& key, const std::string& path) const {
    if (!obj.is_object()) fail_at(path, "expected an object");
    auto it = obj.find(key);
    if (it == obj.end()) fail_at(join(path, key), "missing");
    return *it;
  }
  const json* optional(const json& obj, const std::string& key, const std::string& path) const {
    if (!obj.is_object()) fail_at(path, "expected an object");
    auto it = obj.find(key);
    return it == obj.end() || it->is_null() ? nullptr : &*it;
  }
  double number(const json& v, const std::string& path) const {
    if (!v.is_number()) fail_at(path, "expected a number, got " + brief(v));
    const double d = v.get<double>();
    if (!std::isfinite(d)) fail_at(path, "expected a finite number");
    return d;
  }
  std::int64_t integer(const json& v, const std::string& path, std::int64_t lo,
                       std::int64_t hi) const {
    if (!v.is_number_integer()) fail_at(path, "expected an integer, got " + brief(v));
    const auto out_of_range = [&] {
      fail_at(path, "expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                        "], got " + v.dump());
    };
    std::int64_t i = 0;
    if (v.is_number_unsigned()) {
      const auto u = v.get<std::uint64_t>();
      if (u > static_cast<std::uint64_t>(hi)) out_of_range();
      i = static_cast<std::int64_t>(u);
    } else {
      i = v.get<std::int64_t>();
    }
    if (i < lo || i > hi) out_of_range();
    return i;
  }
  int int32(const json& v, const std::string& path) const {
    return static_cast<int>(
        integer(v, path, std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
  }
  std::string string(const json& v, const std::string& path) const {
    if (!v.is_string()) fail_at(path, "expected a string, got " + brief(v));
    return v.get<std::string>();
  }
  bool boolean(const json& v, const std::string& path) const {
    if (!v.is_boolean()) fail_at(path, "expected true or false, got " + brief(v));
    return v.get<bool>();
  }
  const json& array(const json& v, const std::string& path) const {
    if (!v.is_array()) fail_at(path, "expected an array, got " + brief(v));
    return v;
  }
  std::string opt_string(const json& obj, const std::string& key, const std::string& path,
                         std::string def = {}) const {
    const json* v = optional(obj, key, path);
    return v ? string(*v, join(path, key)) : def;
  }
  bool opt_bool(const json& obj, const std::string& key, const std::string& path, bool def) const {
    const json* v = optional(obj, key, path);
    return v ? boolean(*v, join(path, key)) : def;
  }
  Vec2 point(const json& v, const std::string& path) const {
    array(v, path);
    if (v.size() != 2) fail_at(path, "expected [x, y]");
    return {number(v[0], path + "[0]"), number(v[1], path + "[1]")};
  }
  std::vector<double> numbers(const json& v, const std::string& path) const {
    array(v, path);
    std::vector<double> out;
    out.reserve(v.size());
    for (std::size_t i = 0; i < v.size(); ++i)
      out.push_back(number(v[i], at_index(path, i)));
    return out;
  }
  // Decodes [value, count, value, count, ...] into exactly `size` values in [lo, hi].
  template <typename T>
  std::vector<T> rle(const json& v, const std::string& path, std::size_t size, std::int64_t lo,
                     std::int64_t hi) const {
    array(v, path);
    if (v.size() % 2 != 0) fail_at(path, "run-length data must hold [value, count] pairs");
    std::vector<T> out;
    out.reserve(size);
    for (std::size_t i = 0; i < v.size(); i += 2) {
      const auto value = integer(v[i], at_index(path, i), lo, hi);
      const auto count =
          integer(v[i + 1], at_index(path, i + 1), 1, std::numeric_limits<std::int64_t>::max());
      if (static_cast<std::uint64_t>(count) > size - out.size())
        fail_at(path, "run-length data holds more than the " + std::to_string(size) +
                          " cells of the map");
      out.insert(out.end(), static_cast<std::size_t>(count), static_cast<T>(value));
    }
    if (out.size() != size)
      fail_at(path, "run-length data holds " + std::to_string(out.size()) + " cells, expected " +
                        std::to_string(size));
    return out;
  }

  static std::string join(const std::string& path, const std::string& key) {
    return path.empty() ? key : path + "." + key;
  }

 private:
  static std::string brief(const json& v) {
    std::string s = v.dump();
    if (s.size() > 40) s = s.substr(0, 37) + "...";
    return s;
  }
  std::string source_;
};

int line_of_byte(std::string_view text, std::size_t byte) {
  byte = std::min(byte, text.size());
  return 1 +
         static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(byte), '\n'));
}

std::string style_name(RasterStyle s) {
  return s == RasterStyle::kLabels ? "labels" : "mask";
}
std::string kind_name(PlotKind k) {
  return k == PlotKind::kBar ? "bar" : "line";
}

}  // namespace

// ---------------------------------------------------------------- Recording

double Recording::start_time() const {
  double lo = std::numeric_limits<double>::infinity();
  for (const auto& r : robots)
    if (!r.poses.empty()) lo = std::min(lo, r.poses.front().t);
  for (const auto& m : messages)
    lo = std::min(lo, m.t);
  for (const auto& c : obstacle_changes)
    lo = std::min(lo, c.t);
  for (const auto& e : events)
    lo = std::min(lo, e.t);
  return std::isfinite(lo) ? lo : 0.0;
}

double Recording::end_time() const {
  double hi = -std::numeric_limits<double>::infinity();
  for (const auto& r : robots)
    if (!r.poses.empty()) hi = std::max(hi, r.poses.back().t);
  for (const auto& m : messages)
    hi = std::max(hi, m.t);
  for (const auto& c : obstacle_changes)
    hi = std::max(hi, c.t);
  for (const auto& e : events)
    hi = std::max(hi, e.t);
  return std::isfinite(hi) ? hi : 0.0;
}

Pose2 pose_at(const RobotTrack& track, double t) {
  const auto& p = track.poses;
  if (p.empty())
    throw Error("pose_at: the track of robot " + std::to_string(track.id) + " is empty");
  if (!(t > p.front().t)) return p.front().pose;
  if (t >= p.back().t) return p.back().pose;
  auto hi =
      std::upper_bound(p.begin(), p.end(), t, [](double v, const TimedPose& s) { return v < s.t; });
  auto lo = hi - 1;
  const double span = hi->t - lo->t;
  const double a = span > 0.0 ? (t - lo->t) / span : 1.0;
  Pose2 out;
  out.position = lo->pose.position + (hi->pose.position - lo->pose.position) * a;
  out.yaw = wrap_angle(lo->pose.yaw + wrap_angle(hi->pose.yaw - lo->pose.yaw) * a);
  return out;
}

void validate(const Recording& rec, const std::string& source) {
  const auto& g = rec.map.geometry();
  if (rec.map.empty() || g.width <= 0 || g.height <= 0) fail(source, "map", "the map is empty");
  if (!(g.resolution > 0.0) || !std::isfinite(g.resolution))
    fail(source, "map.resolution", "expected a positive finite number");
  if (!g.origin.is_finite()) fail(source, "map.origin", "expected finite numbers");
  for (std::size_t i = 0; i < rec.map.size(); ++i) {
    const int v = rec.map[i];
    if (v < -1 || v > 100)
      fail(source, "map.occupancy",
           "value " + std::to_string(v) + " at cell index " + std::to_string(i) +
               " is outside [-1, 100]");
  }
  if (!(rec.message_display_s > 0.0) || !std::isfinite(rec.message_display_s))
    fail(source, "message_display_s", "expected a positive finite number");

  for (std::size_t i = 0; i < rec.rasters.size(); ++i) {
    const auto& r = rec.rasters[i];
    const std::string f = at_index("rasters", i);
    if (r.name.empty()) fail(source, f + ".name", "must not be empty");
    if (r.cells.width() != g.width || r.cells.height() != g.height)
      fail(source, f + ".cells",
           "size " + std::to_string(r.cells.width()) + "x" + std::to_string(r.cells.height()) +
               " differs from the map's " + std::to_string(g.width) + "x" +
               std::to_string(g.height));
    check_color(r.color, false, source, f + ".color");
  }
  for (std::size_t i = 0; i < rec.graphs.size(); ++i) {
    const auto& gr = rec.graphs[i];
    const std::string f = at_index("graphs", i);
    if (gr.name.empty()) fail(source, f + ".name", "must not be empty");
    check_color(gr.color, false, source, f + ".color");
    std::set<int> ids;
    for (std::size_t k = 0; k < gr.nodes.size(); ++k) {
      const auto& n = gr.nodes[k];
      if (!n.position.is_finite()) fail(source, at_index(f + ".nodes", k), "non-finite position");
      if (!ids.insert(n.id).second)
        fail(source, at_index(f + ".nodes", k), "duplicate node id " + std::to_string(n.id));
    }
    for (std::size_t k = 0; k < gr.edges.size(); ++k) {
      const auto& e = gr.edges[k];
      if (!ids.contains(e.from) || !ids.contains(e.to))
        fail(source, at_index(f + ".edges", k),
             "edge (" + std::to_string(e.from) + ", " + std::to_string(e.to) +
                 ") names a node that does not exist");
    }
  }
  std::set<int> robot_ids;
  for (std::size_t i = 0; i < rec.robots.size(); ++i) {
    const auto& r = rec.robots[i];
    const std::string f = at_index("robots", i);
    if (!robot_ids.insert(r.id).second)
      fail(source, f + ".id", "duplicate robot id " + std::to_string(r.id));
    if (!(r.radius > 0.0) || !std::isfinite(r.radius))
      fail(source, f + ".radius", "expected a positive finite radius [m]");
    check_color(r.color, true, source, f + ".color");
    if (r.poses.empty()) fail(source, f + ".poses", "a robot needs at least one pose");
    for (std::size_t k = 0; k < r.poses.size(); ++k) {
      const std::string pf = at_index(f + ".poses", k);
      check_finite(r.poses[k].t, source, pf + ".t");
      if (!r.poses[k].pose.is_finite()) fail(source, pf, "non-finite pose");
      if (k > 0 && r.poses[k].t < r.poses[k - 1].t)
        fail(source, pf + ".t", "times must be non-decreasing");
    }
  }
  for (std::size_t i = 0; i < rec.paths.size(); ++i) {
    const auto& p = rec.paths[i];
    const std::string f = at_index("paths", i);
    if (!robot_ids.contains(p.robot))
      fail(source, f + ".robot", "unknown robot id " + std::to_string(p.robot));
    check_finite(p.t_start, source, f + ".t_start");
    for (std::size_t k = 0; k < p.points.size(); ++k)
      if (!p.points[k].is_finite()) fail(source, at_index(f + ".points", k), "non-finite point");
  }
  for (std::size_t i = 0; i < rec.messages.size(); ++i) {
    const auto& m = rec.messages[i];
    const std::string f = at_index("messages", i);
    check_finite(m.t, source, f + ".t");
    if (!robot_ids.contains(m.from))
      fail(source, f + ".from", "unknown robot id " + std::to_string(m.from));
    if (!robot_ids.contains(m.to))
      fail(source, f + ".to", "unknown robot id " + std::to_string(m.to));
    if (m.bytes < 0) fail(source, f + ".bytes", "must be >= 0");
  }
  for (std::size_t i = 0; i < rec.obstacle_changes.size(); ++i) {
    const auto& c = rec.obstacle_changes[i];
    const std::string f = at_index("obstacle_changes", i);
    check_finite(c.t, source, f + ".t");
    if (c.value < -1 || c.value > 100) fail(source, f + ".value", "expected -1..100");
    for (std::size_t k = 0; k < c.cells.size(); ++k)
      if (!g.contains(c.cells[k]))
        fail(source, at_index(f + ".cells", k),
             "cell (" + std::to_string(c.cells[k].x) + ", " + std::to_string(c.cells[k].y) +
                 ") is outside the map");
  }
  for (std::size_t i = 0; i < rec.graph_appearances.size(); ++i) {
    const auto& a = rec.graph_appearances[i];
    if (a.graph >= rec.graphs.size())
      fail(source, at_index("graph_appearances", i),
           "names graph " + std::to_string(a.graph) + " but there are " +
               std::to_string(rec.graphs.size()));
    check_finite(a.t, source, at_index("graphs", a.graph) + ".shown_from");
  }
  if (!rec.reveal.empty()) {
    if (rec.reveal.width() != g.width || rec.reveal.height() != g.height)
      fail(source, "reveal.cells",
           "size " + std::to_string(rec.reveal.width()) + "x" +
               std::to_string(rec.reveal.height()) + " differs from the map's " +
               std::to_string(g.width) + "x" + std::to_string(g.height));
    for (std::size_t i = 0; i < rec.reveal.size(); ++i)
      if (rec.reveal[i] < -1)
        fail(source, "reveal.cells",
             "value " + std::to_string(rec.reveal[i]) + " at cell index " + std::to_string(i) +
                 " is below -1");
    if (!(rec.reveal_period_s > 0.0) || !std::isfinite(rec.reveal_period_s))
      fail(source, "reveal.period_s", "expected a positive finite number");
  }
  for (std::size_t i = 0; i < rec.markers.size(); ++i) {
    const auto& m = rec.markers[i];
    const std::string f = at_index("markers", i);
    if (m.kind != "goal" && m.kind != "start" && m.kind != "destination")
      fail(source, f + ".kind",
           "expected \"goal\", \"start\" or \"destination\", got \"" + m.kind + "\"");
    if (!m.position.is_finite()) fail(source, f + ".p", "non-finite position");
    if (m.robot != -1 && !robot_ids.contains(m.robot))
      fail(source, f + ".robot", "unknown robot id " + std::to_string(m.robot));
  }
  for (std::size_t i = 0; i < rec.events.size(); ++i) {
    const auto& e = rec.events[i];
    const std::string f = at_index("events", i);
    check_finite(e.t, source, f + ".t");
    if (e.kind.empty()) fail(source, f + ".kind", "must not be empty");
    if (e.robot != -1 && !robot_ids.contains(e.robot))
      fail(source, f + ".robot", "unknown robot id " + std::to_string(e.robot));
  }
  for (std::size_t i = 0; i < rec.plots.size(); ++i) {
    const auto& p = rec.plots[i];
    const std::string f = at_index("plots", i);
    if (p.kind == PlotKind::kBar && p.time_axis)
      fail(source, f + ".time_axis", "a bar plot has no time axis");
    for (std::size_t k = 0; k < p.series.size(); ++k) {
      const auto& s = p.series[k];
      const std::string sf = at_index(f + ".series", k);
      check_color(s.color, true, source, sf + ".color");
      for (std::size_t j = 0; j < s.x.size(); ++j)
        check_finite(s.x[j], source, at_index(sf + ".x", j));
      for (std::size_t j = 0; j < s.y.size(); ++j)
        check_finite(s.y[j], source, at_index(sf + ".y", j));
      if (p.kind == PlotKind::kLine && s.x.size() != s.y.size())
        fail(source, sf,
             "x has " + std::to_string(s.x.size()) + " values but y has " +
                 std::to_string(s.y.size()));
      if (p.kind == PlotKind::kBar && s.y.size() != p.categories.size())
        fail(source, sf + ".y",
             "a bar series needs one value per category (" + std::to_string(p.categories.size()) +
                 "), got " + std::to_string(s.y.size()));
    }
  }
}

// ---------------------------------------------------------------- JSON

std::string to_json(const Recording& rec) {
  validate(rec);
  const auto& g = rec.map.geometry();
  json j;
  j["format"] = kRecordingFormat;
  j["version"] = kRecordingVersion;
  j["title"] = rec.title;
  j["description"] = rec.description;
  j["message_display_s"] = rec.message_display_s;
  j["map"] = {{"width", g.width},
              {"height", g.height},
              {"resolution", g.resolution},
              {"origin", {g.origin.position.x, g.origin.position.y, g.origin.yaw}},
              {"occupancy", rle_encode(rec.map.values())}};
  j["rasters"] = json::array();
  for (const auto& r : rec.rasters)
    j["rasters"].push_back({{"name", r.name},
                            {"style", style_name(r.style)},
                            {"color", r.color},
                            {"visible", r.visible},
                            {"cells", rle_encode(r.cells.values())}});
  j["graphs"] = json::array();
  for (std::size_t gi = 0; gi < rec.graphs.size(); ++gi) {
    const auto& gr = rec.graphs[gi];
    json nodes = json::array();
    for (const auto& n : gr.nodes) {
      json node = {{"id", n.id}, {"p", {n.position.x, n.position.y}}};
      if (!n.label.empty()) node["label"] = n.label;
      nodes.push_back(std::move(node));
    }
    json edges = json::array();
    for (const auto& e : gr.edges)
      edges.push_back({e.from, e.to});
    json layer = {{"name", gr.name},
                  {"color", gr.color},
                  {"visible", gr.visible},
                  {"nodes", std::move(nodes)},
                  {"edges", std::move(edges)}};
    for (const auto& a : rec.graph_appearances)
      if (a.graph == gi) layer["shown_from"] = a.t;
    j["graphs"].push_back(std::move(layer));
  }
  j["robots"] = json::array();
  for (const auto& r : rec.robots) {
    json poses = json::array();
    for (const auto& p : r.poses)
      poses.push_back({p.t, p.pose.position.x, p.pose.position.y, p.pose.yaw});
    json robot = {{"id", r.id},
                  {"name", r.name},
                  {"radius", r.radius},
                  {"color", r.color},
                  {"poses", std::move(poses)}};
    j["robots"].push_back(std::move(robot));
  }
  j["paths"] = json::array();
  for (const auto& p : rec.paths) {
    json pts = json::array();
    for (const auto& q : p.points)
      pts.push_back({q.x, q.y});
    j["paths"].push_back({{"robot", p.robot},
                          {"t_start", p.t_start},
                          {"label", p.label},
                          {"points", std::move(pts)}});
  }
  j["messages"] = json::array();
  for (const auto& m : rec.messages)
    j["messages"].push_back(
        {{"t", m.t}, {"from", m.from}, {"to", m.to}, {"type", m.type}, {"bytes", m.bytes}});
  j["obstacle_changes"] = json::array();
  for (const auto& c : rec.obstacle_changes) {
    json cells = json::array();
    for (const auto& cell : c.cells)
      cells.push_back({cell.x, cell.y});
    j["obstacle_changes"].push_back(
        {{"t", c.t}, {"value", static_cast<int>(c.value)}, {"cells", std::move(cells)}});
  }
  if (!rec.reveal.empty())
    j["reveal"] = {{"period_s", rec.reveal_period_s}, {"cells", rle_encode(rec.reveal.values())}};
  j["markers"] = json::array();
  for (const auto& m : rec.markers) {
    json marker = {{"kind", m.kind}, {"p", {m.position.x, m.position.y}}, {"label", m.label}};
    if (m.robot != -1) marker["robot"] = m.robot;
    j["markers"].push_back(std::move(marker));
  }
  j["events"] = json::array();
  for (const auto& e : rec.events) {
    json event = {{"t", e.t}, {"kind", e.kind}, {"text", e.text}};
    if (e.robot != -1) event["robot"] = e.robot;
    j["events"].push_back(std::move(event));
  }
  j["plots"] = json::array();
  for (const auto& p : rec.plots) {
    json series = json::array();
    for (const auto& s : p.series)
      series.push_back({{"name", s.name}, {"color", s.color}, {"x", s.x}, {"y", s.y}});
    j["plots"].push_back({{"title", p.title},
                          {"x_label", p.x_label},
                          {"y_label", p.y_label},
                          {"kind", kind_name(p.kind)},
                          {"time_axis", p.time_axis},
                          {"categories", p.categories},
                          {"series", std::move(series)}});
  }
  return j.dump();
}

Recording from_json(std::string_view text, const std::string& source) {
  json j;
  try {
    j = json::parse(text.begin(), text.end());
  } catch (const json::parse_error& e) {
    std::string what = e.what();
    if (auto pos = what.find("parse error"); pos != std::string::npos) what = what.substr(pos);
    throw Error(source, line_of_byte(text, e.byte > 0 ? e.byte - 1 : 0), "invalid JSON: " + what);
  }
  const Reader rd(source);
  if (!j.is_object()) rd.fail_at("(top level)", "expected a JSON object");
  if (rd.string(rd.require(j, "format", ""), "format") != kRecordingFormat)
    rd.fail_at("format", "expected \"" + std::string(kRecordingFormat) + "\"");
  const auto version = rd.integer(rd.require(j, "version", ""), "version", 1, 1000000);
  if (version != kRecordingVersion)
    rd.fail_at("version", "unsupported version " + std::to_string(version) + " (this build reads " +
                              std::to_string(kRecordingVersion) + ")");
  Recording rec;
  rec.title = rd.opt_string(j, "title", "");
  rec.description = rd.opt_string(j, "description", "");
  if (const json* v = rd.optional(j, "message_display_s", ""))
    rec.message_display_s = rd.number(*v, "message_display_s");

  const json& m = rd.require(j, "map", "");
  GridGeometry g;
  g.width = rd.int32(rd.require(m, "width", "map"), "map.width");
  g.height = rd.int32(rd.require(m, "height", "map"), "map.height");
  if (g.width <= 0 || g.height <= 0) rd.fail_at("map", "width and height must be positive");
  if (static_cast<std::int64_t>(g.width) * g.height > 100'000'000)
    rd.fail_at("map", "more than 10^8 cells");
  g.resolution = rd.number(rd.require(m, "resolution", "map"), "map.resolution");
  if (!(g.resolution > 0.0)) rd.fail_at("map.resolution", "expected a positive number");
  if (const json* o = rd.optional(m, "origin", "map")) {
    rd.array(*o, "map.origin");
    if (o->size() != 3) rd.fail_at("map.origin", "expected [x, y, yaw]");
    g.origin = {{rd.number((*o)[0], "map.origin[0]"), rd.number((*o)[1], "map.origin[1]")},
                rd.number((*o)[2], "map.origin[2]")};
  }
  rec.map = OccupancyGrid(g);
  {
    auto cells =
        rd.rle<std::int8_t>(rd.require(m, "occupancy", "map"), "map.occupancy", g.size(), -1, 100);
    std::copy(cells.begin(), cells.end(), rec.map.data().begin());
  }

  if (const json* rs = rd.optional(j, "rasters", "")) {
    rd.array(*rs, "rasters");
    for (std::size_t i = 0; i < rs->size(); ++i) {
      const json& r = (*rs)[i];
      const std::string f = at_index("rasters", i);
      RasterLayer layer;
      layer.name = rd.string(rd.require(r, "name", f), f + ".name");
      const std::string style = rd.opt_string(r, "style", f, "mask");
      if (style == "mask") {
        layer.style = RasterStyle::kMask;
      } else if (style == "labels") {
        layer.style = RasterStyle::kLabels;
      } else {
        rd.fail_at(f + ".style", "expected \"mask\" or \"labels\", got \"" + style + "\"");
      }
      layer.color = rd.opt_string(r, "color", f, layer.color);
      layer.visible = rd.opt_bool(r, "visible", f, true);
      layer.cells = GridMap<std::int32_t>(g);
      auto cells = rd.rle<std::int32_t>(rd.require(r, "cells", f), f + ".cells", g.size(),
                                        std::numeric_limits<std::int32_t>::min(),
                                        std::numeric_limits<std::int32_t>::max());
      std::copy(cells.begin(), cells.end(), layer.cells.data().begin());
      rec.rasters.push_back(std::move(layer));
    }
  }
  if (const json* gs = rd.optional(j, "graphs", "")) {
    rd.array(*gs, "graphs");
    for (std::size_t i = 0; i < gs->size(); ++i) {
      const json& gj = (*gs)[i];
      const std::string f = at_index("graphs", i);
      GraphLayer layer;
      layer.name = rd.string(rd.require(gj, "name", f), f + ".name");
      layer.color = rd.opt_string(gj, "color", f, layer.color);
      layer.visible = rd.opt_bool(gj, "visible", f, true);
      if (const json* v = rd.optional(gj, "shown_from", f))
        rec.graph_appearances.push_back({rec.graphs.size(), rd.number(*v, f + ".shown_from")});
      const json& nodes = rd.array(rd.require(gj, "nodes", f), f + ".nodes");
      for (std::size_t k = 0; k < nodes.size(); ++k) {
        const std::string nf = at_index(f + ".nodes", k);
        GraphNode n;
        n.id = rd.int32(rd.require(nodes[k], "id", nf), nf + ".id");
        n.position = rd.point(rd.require(nodes[k], "p", nf), nf + ".p");
        n.label = rd.opt_string(nodes[k], "label", nf);
        layer.nodes.push_back(std::move(n));
      }
      const json& edges = rd.array(rd.require(gj, "edges", f), f + ".edges");
      for (std::size_t k = 0; k < edges.size(); ++k) {
        const std::string ef = at_index(f + ".edges", k);
        rd.array(edges[k], ef);
        if (edges[k].size() != 2) rd.fail_at(ef, "expected [from, to]");
        layer.edges.push_back(
            {rd.int32(edges[k][0], ef + "[0]"), rd.int32(edges[k][1], ef + "[1]")});
      }
      rec.graphs.push_back(std::move(layer));
    }
  }
  if (const json* rs = rd.optional(j, "robots", "")) {
    rd.array(*rs, "robots");
    for (std::size_t i = 0; i < rs->size(); ++i) {
      const json& r = (*rs)[i];
      const std::string f = at_index("robots", i);
      RobotTrack t;
      t.id = rd.int32(rd.require(r, "id", f), f + ".id");
      t.name = rd.opt_string(r, "name", f);
      if (const json* v = rd.optional(r, "radius", f)) t.radius = rd.number(*v, f + ".radius");
      t.color = rd.opt_string(r, "color", f);
      const json& poses = rd.array(rd.require(r, "poses", f), f + ".poses");
      for (std::size_t k = 0; k < poses.size(); ++k) {
        const std::string pf = at_index(f + ".poses", k);
        rd.array(poses[k], pf);
        if (poses[k].size() != 4) rd.fail_at(pf, "expected [t, x, y, yaw]");
        t.poses.push_back(
            {rd.number(poses[k][0], pf + "[0]"),
             {{rd.number(poses[k][1], pf + "[1]"), rd.number(poses[k][2], pf + "[2]")},
              rd.number(poses[k][3], pf + "[3]")}});
      }
      rec.robots.push_back(std::move(t));
    }
  }
  if (const json* ps = rd.optional(j, "paths", "")) {
    rd.array(*ps, "paths");
    for (std::size_t i = 0; i < ps->size(); ++i) {
      const json& p = (*ps)[i];
      const std::string f = at_index("paths", i);
      PathRecord path;
      path.robot = rd.int32(rd.require(p, "robot", f), f + ".robot");
      if (const json* v = rd.optional(p, "t_start", f))
        path.t_start = rd.number(*v, f + ".t_start");
      path.label = rd.opt_string(p, "label", f);
      const json& pts = rd.array(rd.require(p, "points", f), f + ".points");
      for (std::size_t k = 0; k < pts.size(); ++k)
        path.points.push_back(rd.point(pts[k], at_index(f + ".points", k)));
      rec.paths.push_back(std::move(path));
    }
  }
  if (const json* ms = rd.optional(j, "messages", "")) {
    rd.array(*ms, "messages");
    for (std::size_t i = 0; i < ms->size(); ++i) {
      const json& mj = (*ms)[i];
      const std::string f = at_index("messages", i);
      MessageRecord msg;
      msg.t = rd.number(rd.require(mj, "t", f), f + ".t");
      msg.from = rd.int32(rd.require(mj, "from", f), f + ".from");
      msg.to = rd.int32(rd.require(mj, "to", f), f + ".to");
      msg.type = rd.opt_string(mj, "type", f);
      if (const json* v = rd.optional(mj, "bytes", f))
        msg.bytes = rd.integer(*v, f + ".bytes", 0, std::numeric_limits<std::int64_t>::max());
      rec.messages.push_back(std::move(msg));
    }
  }
  if (const json* cs = rd.optional(j, "obstacle_changes", "")) {
    rd.array(*cs, "obstacle_changes");
    for (std::size_t i = 0; i < cs->size(); ++i) {
      const json& cj = (*cs)[i];
      const std::string f = at_index("obstacle_changes", i);
      ObstacleChange c;
      c.t = rd.number(rd.require(cj, "t", f), f + ".t");
      if (const json* v = rd.optional(cj, "value", f))
        c.value = static_cast<std::int8_t>(rd.integer(*v, f + ".value", -1, 100));
      const json& cells = rd.array(rd.require(cj, "cells", f), f + ".cells");
      for (std::size_t k = 0; k < cells.size(); ++k) {
        const std::string cf = at_index(f + ".cells", k);
        rd.array(cells[k], cf);
        if (cells[k].size() != 2) rd.fail_at(cf, "expected [x, y]");
        c.cells.push_back({rd.int32(cells[k][0], cf + "[0]"), rd.int32(cells[k][1], cf + "[1]")});
      }
      rec.obstacle_changes.push_back(std::move(c));
    }
  }
  if (const json* rv = rd.optional(j, "reveal", "")) {
    if (const json* v = rd.optional(*rv, "period_s", "reveal"))
      rec.reveal_period_s = rd.number(*v, "reveal.period_s");
    rec.reveal = GridMap<std::int32_t>(g);
    auto cells = rd.rle<std::int32_t>(rd.require(*rv, "cells", "reveal"), "reveal.cells", g.size(),
                                      -1, std::numeric_limits<std::int32_t>::max());
    std::copy(cells.begin(), cells.end(), rec.reveal.data().begin());
  }
  if (const json* ms = rd.optional(j, "markers", "")) {
    rd.array(*ms, "markers");
    for (std::size_t i = 0; i < ms->size(); ++i) {
      const json& mj = (*ms)[i];
      const std::string f = at_index("markers", i);
      MarkerRecord mk;
      mk.kind = rd.opt_string(mj, "kind", f, mk.kind);
      mk.position = rd.point(rd.require(mj, "p", f), f + ".p");
      if (const json* v = rd.optional(mj, "robot", f)) mk.robot = rd.int32(*v, f + ".robot");
      mk.label = rd.opt_string(mj, "label", f);
      rec.markers.push_back(std::move(mk));
    }
  }
  if (const json* es = rd.optional(j, "events", "")) {
    rd.array(*es, "events");
    for (std::size_t i = 0; i < es->size(); ++i) {
      const json& ej = (*es)[i];
      const std::string f = at_index("events", i);
      EventRecord e;
      e.t = rd.number(rd.require(ej, "t", f), f + ".t");
      e.kind = rd.string(rd.require(ej, "kind", f), f + ".kind");
      e.text = rd.opt_string(ej, "text", f);
      if (const json* v = rd.optional(ej, "robot", f)) e.robot = rd.int32(*v, f + ".robot");
      rec.events.push_back(std::move(e));
    }
  }
  if (const json* ps = rd.optional(j, "plots", "")) {
    rd.array(*ps, "plots");
    for (std::size_t i = 0; i < ps->size(); ++i) {
      const json& pj = (*ps)[i];
      const std::string f = at_index("plots", i);
      Plot p;
      p.title = rd.opt_string(pj, "title", f);
      p.x_label = rd.opt_string(pj, "x_label", f);
      p.y_label = rd.opt_string(pj, "y_label", f);
      const std::string kind = rd.opt_string(pj, "kind", f, "line");
      if (kind == "line") {
        p.kind = PlotKind::kLine;
      } else if (kind == "bar") {
        p.kind = PlotKind::kBar;
      } else {
        rd.fail_at(f + ".kind", "expected \"line\" or \"bar\", got \"" + kind + "\"");
      }
      p.time_axis = rd.opt_bool(pj, "time_axis", f, false);
      if (const json* cats = rd.optional(pj, "categories", f)) {
        rd.array(*cats, f + ".categories");
        for (std::size_t k = 0; k < cats->size(); ++k)
          p.categories.push_back(rd.string((*cats)[k], at_index(f + ".categories", k)));
      }
      const json& series = rd.array(rd.require(pj, "series", f), f + ".series");
      for (std::size_t k = 0; k < series.size(); ++k) {
        const std::string sf = at_index(f + ".series", k);
        Series s;
        s.name = rd.opt_string(series[k], "name", sf);
        s.color = rd.opt_string(series[k], "color", sf);
        if (const json* x = rd.optional(series[k], "x", sf)) s.x = rd.numbers(*x, sf + ".x");
        s.y = rd.numbers(rd.require(series[k], "y", sf), sf + ".y");
        p.series.push_back(std::move(s));
      }
      rec.plots.push_back(std::move(p));
    }
  }
  validate(rec, source);
  return rec;
}

void save_recording(const Recording& recording, const std::string& path) {
  const std::string text = to_json(recording);
  std::ofstream out(path, std::ios::binary);
  if (!out) throw Error(path, 0, "cannot open for writing");
  out << text << '\n';
  if (!out) throw Error(path, 0, "write failed");
}

Recording load_recording(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path, 0, "cannot open the recording");
  std::ostringstream ss;
  ss << in.rdbuf();
  return from_json(ss.str(), path);
}

}  // namespace voronav::report
