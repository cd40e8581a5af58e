#include "voronav/sim/scenario_file.hpp"

#include <yaml-cpp/yaml.h>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <set>
#include <sstream>
#include <string_view>
#include <system_error>

#include "voronav/core/error.hpp"
#include "voronav/core/read_file.hpp"
#include "voronav/io/map_loader.hpp"
#include "voronav/io/ros_map.hpp"
#include "voronav/sim/scenarios.hpp"

namespace voronav::sim {
namespace {

namespace fs = std::filesystem;

constexpr std::uint64_t kMaxU64 = std::numeric_limits<std::uint64_t>::max();

int line_of(const YAML::Node& n) {
  if (!n.IsDefined()) return 0;  // a missing key has no position (Mark() would throw)
  return n.Mark().line >= 0 ? n.Mark().line + 1 : 0;
}

std::string fmt(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);  // shortest exact representation
  return std::string(buf, r.ptr);
}

std::string fmt(Vec2 p) {
  std::string s = "[";
  s.append(fmt(p.x)).append(", ").append(fmt(p.y)).push_back(']');
  return s;
}

/// Reads the nodes of one scenario file; every error names the file and the node's line.
class Reader {
 public:
  explicit Reader(std::string source) : src_(std::move(source)) {}

  [[noreturn]] void fail(const YAML::Node& n, const std::string& reason) const {
    throw Error(src_, line_of(n), reason);
  }

  /// Every key of the mapping `map` must be one of `allowed`, once.
  void keys(const YAML::Node& map, const std::string& where,
            std::initializer_list<std::string_view> allowed) const {
    if (!map.IsMap()) fail(map, where + ": expected a mapping");
    std::set<std::string> seen;
    for (const auto& kv : map) {
      const std::string k = kv.first.IsScalar() ? kv.first.Scalar() : "";
      bool ok = false;
      for (auto a : allowed)
        ok |= a == k;
      if (!ok) {
        std::string list;
        for (auto a : allowed) {
          if (!list.empty()) list.append(", ");
          list.append(a);
        }
        fail(kv.first, where + ": unknown key '" + k + "' (expected one of: " + list + ")");
      }
      if (!seen.insert(k).second) fail(kv.first, where + ": duplicate key '" + k + "'");
    }
  }

  [[nodiscard]] double number(const YAML::Node& n, const std::string& what) const {
    if (!n.IsScalar()) fail(n, what + ": expected a number");
    double v = 0.0;
    try {
      v = n.as<double>();
    } catch (const YAML::Exception&) {
      fail(n, what + ": expected a number, got '" + n.Scalar() + "'");
    }
    if (!std::isfinite(v)) fail(n, what + ": expected a finite number, got '" + n.Scalar() + "'");
    return v;
  }
  [[nodiscard]] double positive(const YAML::Node& n, const std::string& what) const {
    const double v = number(n, what);
    if (!(v > 0.0)) fail(n, what + ": expected a number > 0, got " + n.Scalar());
    return v;
  }
  [[nodiscard]] double nonneg(const YAML::Node& n, const std::string& what) const {
    const double v = number(n, what);
    if (!(v >= 0.0)) fail(n, what + ": expected a number >= 0, got " + n.Scalar());
    return v;
  }
  [[nodiscard]] bool boolean(const YAML::Node& n, const std::string& what) const {
    if (n.IsScalar()) {
      const std::string v = n.Scalar();
      if (v == "true") return true;
      if (v == "false") return false;
    }
    fail(n, what + ": expected true or false, got '" + (n.IsScalar() ? n.Scalar() : "") + "'");
  }
  [[nodiscard]] double probability(const YAML::Node& n, const std::string& what) const {
    const double v = number(n, what);
    if (!(v >= 0.0 && v <= 1.0))
      fail(n, what + ": expected a probability in [0, 1], got " + n.Scalar());
    return v;
  }
  template <class Int>
  [[nodiscard]] Int integer(const YAML::Node& n, const std::string& what, Int lo, Int hi) const {
    const std::string s = n.IsScalar() ? n.Scalar() : "";
    Int v{};
    const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
    if (s.empty() || r.ec != std::errc() || r.ptr != s.data() + s.size() || v < lo || v > hi)
      fail(n, what + ": expected an integer in " + std::to_string(lo) + ".." + std::to_string(hi) +
                  ", got '" + s + "'");
    return v;
  }
  [[nodiscard]] Vec2 point(const YAML::Node& n, const std::string& what) const {
    if (!n.IsSequence() || n.size() != 2) fail(n, what + ": expected [x, y]");
    return {number(n[0], what + " x"), number(n[1], what + " y")};
  }
  /// A point of the world that a robot can stand on.
  [[nodiscard]] Vec2 free_point(const YAML::Node& n, const std::string& what,
                                const OccupancyGrid& world) const {
    const Vec2 p = point(n, what);
    const auto& g = world.geometry();
    const auto c = g.world_to_cell(p);
    if (!c || !g.contains(*c)) {
      const Vec2 lo = g.cell_center({0, 0}), hi = g.cell_center({g.width - 1, g.height - 1});
      fail(n, what + ": " + fmt(p) + " is outside the map (cell centres " + fmt(lo) + " to " +
                  fmt(hi) + " m)");
    }
    if (world[*c] != kFree) fail(n, what + ": " + fmt(p) + " is inside an obstacle");
    return p;
  }
  [[nodiscard]] const std::string& source() const { return src_; }

 private:
  std::string src_;
};

OccupancyGrid load_world(const Reader& rd, const YAML::Node& n, const fs::path& file,
                         std::string& resolved) {
  if (!n.IsScalar() || n.Scalar().empty()) rd.fail(n, "world: expected a map file name");
  fs::path p = n.Scalar();
  if (p.is_relative()) p = file.parent_path() / p;
  p = p.lexically_normal();
  resolved = p.string();
  std::error_code exists_ec;  // no throw for names the file system refuses (too long, ...)
  if (!fs::exists(p, exists_ec))
    rd.fail(n, "world: map file '" + n.Scalar() + "' not found (looked for " + resolved +
                   (exists_ec ? ": " + exists_ec.message() : std::string()) + ")");
  io::LoadedMap m;
  try {
    m = io::load_map(p);
  } catch (const Error& e) {
    rd.fail(n, std::string("world: ") + e.what());
  }
  if (m.grid.empty()) rd.fail(n, "world: the map is empty");
  // Ground truth: free or occupied; unknown (and occupancy >= 50) counts as an obstacle.
  const BinaryGrid blocked = binarize(m.grid);
  OccupancyGrid world(m.grid.geometry(), kFree);
  for (std::size_t i = 0; i < world.size(); ++i)
    world.data()[i] = blocked.data()[i] ? kOccupied : kFree;
  return world;
}

void read_options(const Reader& rd, const YAML::Node& n, NetSimScenarioFile& f) {
  rd.keys(n, "options",
          {"method",
           "sensing_range_m",
           "speed_mps",
           "robot_radius_m",
           "dt_s",
           "time_limit_s",
           "radio",
           "points",
           "path_wait_s",
           "bridge_wait_s",
           "search_timeout_s",
           "max_search_attempts",
           "link_timeout_s",
           "link_retries",
           "hop_limit",
           "repair_hops",
           "repair_expand_hops",
           "collect_s",
           "repair_timeout_s",
           "repair_resend_s",
           "repair_check_answer",
           "repair_rejoin_m",
           "repair_share_blocks",
           "repair_share_changed",
           "repair_share_met_blocks",
           "repair_fix_answer",
           "repair_fix_seen_only",
           "repair_walk_keep_ratio",
           "repair_resend_new_only",
           "repair_check_seen",
           "repair_sense_walk",
           "repair_sense_wait_s",
           "path_fallback_after_retries",
           "search_timeout_per_m",
           "search_activity_s",
           "keep_bridge_on_new_search",
           "source_straight_start",
           "frontier_by_points",
           "walk_replan_whole_map",
           "sense_when_boxed_in",
           "seed"});
  NetSimOptions& o = f.options;
  if (const auto m = n["method"]) {
    try {
      o.method = parse_method(m.IsScalar() ? m.Scalar() : "");
    } catch (const Error& e) {
      rd.fail(m, "options.method: " + e.reason());
    }
    f.has_method = true;
  }
  auto pos = [&](const char* key, double& v) {
    if (const auto m = n[key]) v = rd.positive(m, std::string("options.") + key);
  };
  auto nonneg = [&](const char* key, double& v) {
    if (const auto m = n[key]) v = rd.nonneg(m, std::string("options.") + key);
  };
  auto integer = [&](const char* key, int& v, int lo, int hi) {
    if (const auto m = n[key]) v = rd.integer<int>(m, std::string("options.") + key, lo, hi);
  };
  pos("sensing_range_m", o.sensing_range_m);
  pos("speed_mps", o.speed_mps);
  nonneg("robot_radius_m", o.robot_radius_m);
  pos("dt_s", o.dt_s);
  pos("time_limit_s", o.time_limit_s);
  nonneg("path_wait_s", o.path_wait_s);
  nonneg("bridge_wait_s", o.bridge_wait_s);
  pos("search_timeout_s", o.search_timeout_s);
  integer("max_search_attempts", o.max_search_attempts, 1, 1000000);
  pos("link_timeout_s", o.link_timeout_s);
  integer("link_retries", o.link_retries, 0, 1000000);
  integer("hop_limit", o.hop_limit, 1, 255);
  integer("repair_hops", o.repair_hops, 1, 255);
  integer("repair_expand_hops", o.repair_expand_hops, 0, 255);
  pos("collect_s", o.collect_s);
  pos("repair_timeout_s", o.repair_timeout_s);
  nonneg("repair_resend_s", o.repair_resend_s);
  nonneg("repair_rejoin_m", o.repair_rejoin_m);
  nonneg("repair_walk_keep_ratio", o.repair_walk_keep_ratio);
  nonneg("repair_sense_wait_s", o.repair_sense_wait_s);
  nonneg("search_timeout_per_m", o.search_timeout_per_m);
  nonneg("search_activity_s", o.search_activity_s);
  auto flag = [&](const char* key, bool& v) {
    if (const auto m = n[key]) v = rd.boolean(m, std::string("options.") + key);
  };
  flag("keep_bridge_on_new_search", o.keep_bridge_on_new_search);
  flag("source_straight_start", o.source_straight_start);
  flag("repair_check_answer", o.repair_check_answer);
  flag("repair_share_blocks", o.repair_share_blocks);
  flag("repair_share_changed", o.repair_share_changed);
  flag("repair_share_met_blocks", o.repair_share_met_blocks);
  flag("repair_fix_answer", o.repair_fix_answer);
  flag("repair_fix_seen_only", o.repair_fix_seen_only);
  flag("repair_resend_new_only", o.repair_resend_new_only);
  flag("repair_check_seen", o.repair_check_seen);
  flag("repair_sense_walk", o.repair_sense_walk);
  flag("path_fallback_after_retries", o.path_fallback_after_retries);
  flag("frontier_by_points", o.frontier_by_points);
  flag("walk_replan_whole_map", o.walk_replan_whole_map);
  flag("sense_when_boxed_in", o.sense_when_boxed_in);
  if (const auto m = n["seed"]) o.seed = rd.integer<std::uint64_t>(m, "options.seed", 0, kMaxU64);
  if (const auto r = n["radio"]) {
    rd.keys(r, "options.radio",
            {"range_m", "latency_s", "jitter_s", "loss", "duplicate", "reorder", "reorder_delay_s",
             "seed"});
    auto& ro = o.radio;
    const auto get = [&](const char* key, double& v, bool prob) {
      if (const auto m = r[key]) {
        const std::string what = std::string("options.radio.") + key;
        v = prob ? rd.probability(m, what) : rd.nonneg(m, what);
      }
    };
    get("range_m", ro.range_m, false);
    get("latency_s", ro.latency_s, false);
    get("jitter_s", ro.jitter_s, false);
    get("loss", ro.loss, true);
    get("duplicate", ro.duplicate, true);
    get("reorder", ro.reorder, true);
    get("reorder_delay_s", ro.reorder_delay_s, false);
    if (const auto m = r["seed"])
      ro.seed = rd.integer<std::uint64_t>(m, "options.radio.seed", 0, kMaxU64);
  }
  if (const auto p = n["points"]) {
    rd.keys(p, "options.points", {"min_site_separation_cells", "close_point_spacing_m"});
    if (const auto m = p["min_site_separation_cells"])
      o.points.min_site_separation_cells =
          rd.positive(m, "options.points.min_site_separation_cells");
    if (const auto m = p["close_point_spacing_m"])
      o.points.close_point_spacing_m = rd.positive(m, "options.points.close_point_spacing_m");
  }
  try {
    o.validate();
  } catch (const Error& e) {
    rd.fail(n, "options: " + std::string(e.what()));
  }
}

ObstacleChange read_change(const Reader& rd, const YAML::Node& n, const std::string& what,
                           const OccupancyGrid& world) {
  rd.keys(n, what, {"after_route_s", "at_s", "centralized_at_s", "value", "cells", "rect"});
  ObstacleChange ch;
  // When: at a simulated time (at_s, the same for both methods) or after the first route.
  const auto t = n["after_route_s"];
  const auto at = n["at_s"];
  if (!t && !at) rd.fail(n, what + ": missing key 'at_s' or 'after_route_s'");
  if (t && at) rd.fail(n, what + ": give either 'at_s' or 'after_route_s', not both");
  if (t) ch.after_route_s = rd.nonneg(t, what + ".after_route_s");
  if (at) ch.at_s = rd.nonneg(at, what + ".at_s");
  // The centralized method's own time (the paper runs, scenarios.hpp); only with at_s.
  if (const auto ct = n["centralized_at_s"]) {
    if (!at) rd.fail(ct, what + ": 'centralized_at_s' needs 'at_s'");
    ch.centralized_at_s = rd.nonneg(ct, what + ".centralized_at_s");
  }
  if (const auto v = n["value"]) {
    const std::string s = v.IsScalar() ? v.Scalar() : "";
    if (s == "occupied")
      ch.value = kOccupied;
    else if (s == "free")
      ch.value = kFree;
    else
      rd.fail(v, what + ".value: expected occupied or free, got '" + s + "'");
  }
  const auto& g = world.geometry();
  if (const auto cells = n["cells"]) {
    if (!cells.IsSequence()) rd.fail(cells, what + ".cells: expected a list of [x, y] cells");
    for (std::size_t i = 0; i < cells.size(); ++i) {
      const auto c = cells[i];
      const std::string cw = what + ".cells[" + std::to_string(i) + "]";
      if (!c.IsSequence() || c.size() != 2) rd.fail(c, cw + ": expected [x, y] (grid cell)");
      const Cell cell{rd.integer<int>(c[0], cw + " x", 0, g.width - 1),
                      rd.integer<int>(c[1], cw + " y", 0, g.height - 1)};
      ch.cells.push_back(cell);
    }
  }
  if (const auto r = n["rect"]) {
    if (!r.IsSequence() || r.size() != 4) rd.fail(r, what + ".rect: expected [x0, y0, x1, y1] [m]");
    const double x0 = rd.number(r[0], what + ".rect x0"), y0 = rd.number(r[1], what + ".rect y0");
    const double x1 = rd.number(r[2], what + ".rect x1"), y1 = rd.number(r[3], what + ".rect y1");
    if (x1 < x0 || y1 < y0) rd.fail(r, what + ".rect: expected x0 <= x1 and y0 <= y1");
    std::size_t covered = 0;
    for (int y = 0; y < g.height; ++y)
      for (int x = 0; x < g.width; ++x) {
        const Vec2 c = g.cell_center({x, y});
        if (c.x >= x0 && c.x <= x1 && c.y >= y0 && c.y <= y1) {
          ch.cells.push_back({x, y});
          ++covered;
        }
      }
    if (covered == 0) rd.fail(r, what + ".rect: covers no cell centre of the map");
  }
  if (ch.cells.empty()) rd.fail(n, what + ": expected 'cells' or 'rect' (at least one cell)");
  return ch;
}

}  // namespace

NetSimScenarioFile load_netsim_scenario(const std::string& path) {
  const Reader rd(path);
  YAML::Node root;
  try {
    root = YAML::Load(read_file_bounded(path, kMaxTextFileBytes, "scenario file"));
  } catch (const YAML::Exception& e) {
    throw Error(path, e.mark.line + 1, "malformed YAML: " + e.msg);
  }
  if (root.IsNull()) throw Error(path, 1, "the scenario file is empty (expected 'world', ...)");
  if (!root.IsMap()) rd.fail(root, "expected a mapping with 'world', 'robots', 'destination'");
  rd.keys(root, "scenario",
          {"world", "robots", "placement", "source", "destination", "changes", "options"});
  NetSimScenarioFile f;
  const auto world = root["world"];
  if (!world) rd.fail(root, "missing key 'world' (the map file, relative to this file)");
  NetSimScenario& sc = f.scenario;
  sc.world = load_world(rd, world, fs::path(path), f.world_path);
  if (const auto o = root["options"]) read_options(rd, o, f);

  const auto robots = root["robots"];
  const auto placement = root["placement"];
  const auto dest = root["destination"];
  std::optional<Vec2> destination;
  if (dest) destination = rd.free_point(dest, "destination", sc.world);
  if (robots && placement) rd.fail(placement, "give either 'robots' or 'placement', not both");
  if (robots) {
    if (!robots.IsSequence() || robots.size() == 0)
      rd.fail(robots, "robots: expected a non-empty list of [x, y] positions [m]");
    for (std::size_t i = 0; i < robots.size(); ++i)
      sc.robots.push_back(rd.free_point(robots[i], "robots[" + std::to_string(i) + "]", sc.world));
    if (!destination) rd.fail(root, "missing key 'destination' ([x, y] in metres)");
    sc.destination = *destination;
  } else if (placement) {
    rd.keys(placement, "placement", {"robots", "seed"});
    PlacementOptions po;
    po.robot_radius_m = f.options.robot_radius_m;
    const auto n = placement["robots"];
    if (!n) rd.fail(placement, "placement: missing key 'robots' (how many)");
    po.robots = rd.integer<int>(n, "placement.robots", 1, 100000);
    if (const auto s = placement["seed"])
      po.seed = rd.integer<std::uint64_t>(s, "placement.seed", 0, kMaxU64);
    try {
      sc = place_robots(sc.world, po, destination);
    } catch (const Error& e) {
      rd.fail(placement, "placement: " + e.reason());
    }
  } else {
    rd.fail(root, "missing key 'robots' (a list of [x, y]) or 'placement' ({robots: N, seed: S})");
  }
  if (const auto s = root["source"])
    sc.source = rd.integer<std::size_t>(s, "source", 0, sc.robots.size() - 1);
  if (const auto changes = root["changes"]) {
    if (!changes.IsSequence()) rd.fail(changes, "changes: expected a list");
    for (std::size_t i = 0; i < changes.size(); ++i)
      sc.changes.push_back(
          read_change(rd, changes[i], "changes[" + std::to_string(i) + "]", sc.world));
  }
  try {
    sc.validate();
  } catch (const Error& e) {
    rd.fail(root, e.what());
  }
  return f;
}

void save_netsim_scenario(const std::string& path, const NetSimScenario& sc,
                          const NetSimOptions& o) {
  sc.validate();
  o.validate();
  for (const auto v : sc.world.data())
    if (v != kFree && v != kOccupied)
      throw Error(path, 0, "the world must hold only free (0) and occupied (100) cells");
  for (const auto& ch : sc.changes)
    if (ch.value != kFree && ch.value != kOccupied)
      throw Error(path, 0, "a change value must be free (0) or occupied (100)");
  const fs::path file(path);
  const std::string world_name = file.stem().string() + "_world.yaml";
  io::save_ros_map(sc.world, file.parent_path() / world_name);

  std::ostringstream out;
  std::string quoted = "\"";
  for (char c : world_name) {
    if (c == '"' || c == '\\') quoted.push_back('\\');
    quoted.push_back(c);
  }
  quoted.push_back('"');
  out << "# voronav netsim scenario (docs/formats.md)\n"
      << "world: " << quoted << "\n"
      << "source: " << sc.source << "\n"
      << "destination: " << fmt(sc.destination) << "\n"
      << "robots:\n";
  for (const Vec2 p : sc.robots)
    out << "  - " << fmt(p) << "\n";
  out << "changes:" << (sc.changes.empty() ? " []" : "") << "\n";
  for (const auto& ch : sc.changes) {
    if (ch.at_s >= 0.0) {
      out << "  - at_s: " << fmt(ch.at_s) << "\n";
      if (ch.centralized_at_s >= 0.0)
        out << "    centralized_at_s: " << fmt(ch.centralized_at_s) << "\n";
    } else {
      out << "  - after_route_s: " << fmt(ch.after_route_s) << "\n";
    }
    out << "    value: " << (ch.value == kFree ? "free" : "occupied") << "\n"
        << "    cells: [";
    for (std::size_t i = 0; i < ch.cells.size(); ++i)
      out << (i ? ", " : "") << "[" << ch.cells[i].x << ", " << ch.cells[i].y << "]";
    out << "]\n";
  }
  const auto& r = o.radio;
  out << "options:\n"
      << "  method: " << to_string(o.method) << "\n"
      << "  sensing_range_m: " << fmt(o.sensing_range_m) << "\n"
      << "  speed_mps: " << fmt(o.speed_mps) << "\n"
      << "  robot_radius_m: " << fmt(o.robot_radius_m) << "\n"
      << "  dt_s: " << fmt(o.dt_s) << "\n"
      << "  time_limit_s: " << fmt(o.time_limit_s) << "\n"
      << "  radio:\n"
      << "    range_m: " << fmt(r.range_m) << "\n"
      << "    latency_s: " << fmt(r.latency_s) << "\n"
      << "    jitter_s: " << fmt(r.jitter_s) << "\n"
      << "    loss: " << fmt(r.loss) << "\n"
      << "    duplicate: " << fmt(r.duplicate) << "\n"
      << "    reorder: " << fmt(r.reorder) << "\n"
      << "    reorder_delay_s: " << fmt(r.reorder_delay_s) << "\n"
      << "    seed: " << r.seed << "\n"
      << "  points:\n"
      << "    min_site_separation_cells: " << fmt(o.points.min_site_separation_cells) << "\n"
      << "    close_point_spacing_m: " << fmt(o.points.close_point_spacing_m) << "\n"
      << "  path_wait_s: " << fmt(o.path_wait_s) << "\n"
      << "  bridge_wait_s: " << fmt(o.bridge_wait_s) << "\n"
      << "  search_timeout_s: " << fmt(o.search_timeout_s) << "\n"
      << "  max_search_attempts: " << o.max_search_attempts << "\n"
      << "  link_timeout_s: " << fmt(o.link_timeout_s) << "\n"
      << "  link_retries: " << o.link_retries << "\n"
      << "  hop_limit: " << o.hop_limit << "\n"
      << "  repair_hops: " << o.repair_hops << "\n"
      << "  repair_expand_hops: " << o.repair_expand_hops << "\n"
      << "  collect_s: " << fmt(o.collect_s) << "\n"
      << "  repair_timeout_s: " << fmt(o.repair_timeout_s) << "\n"
      << "  repair_resend_s: " << fmt(o.repair_resend_s) << "\n"
      << "  repair_check_answer: " << (o.repair_check_answer ? "true" : "false") << "\n"
      << "  repair_rejoin_m: " << fmt(o.repair_rejoin_m) << "\n"
      << "  repair_share_blocks: " << (o.repair_share_blocks ? "true" : "false") << "\n"
      << "  repair_share_changed: " << (o.repair_share_changed ? "true" : "false") << "\n"
      << "  repair_share_met_blocks: " << (o.repair_share_met_blocks ? "true" : "false") << "\n"
      << "  repair_fix_answer: " << (o.repair_fix_answer ? "true" : "false") << "\n"
      << "  repair_fix_seen_only: " << (o.repair_fix_seen_only ? "true" : "false") << "\n"
      << "  repair_walk_keep_ratio: " << fmt(o.repair_walk_keep_ratio) << "\n"
      << "  repair_resend_new_only: " << (o.repair_resend_new_only ? "true" : "false") << "\n"
      << "  repair_check_seen: " << (o.repair_check_seen ? "true" : "false") << "\n"
      << "  repair_sense_walk: " << (o.repair_sense_walk ? "true" : "false") << "\n"
      << "  repair_sense_wait_s: " << fmt(o.repair_sense_wait_s) << "\n"
      << "  path_fallback_after_retries: " << (o.path_fallback_after_retries ? "true" : "false")
      << "\n"
      << "  search_timeout_per_m: " << fmt(o.search_timeout_per_m) << "\n"
      << "  search_activity_s: " << fmt(o.search_activity_s) << "\n"
      << "  keep_bridge_on_new_search: " << (o.keep_bridge_on_new_search ? "true" : "false") << "\n"
      << "  source_straight_start: " << (o.source_straight_start ? "true" : "false") << "\n"
      << "  frontier_by_points: " << (o.frontier_by_points ? "true" : "false") << "\n"
      << "  walk_replan_whole_map: " << (o.walk_replan_whole_map ? "true" : "false") << "\n"
      << "  sense_when_boxed_in: " << (o.sense_when_boxed_in ? "true" : "false") << "\n"
      << "  seed: " << o.seed << "\n";
  std::ofstream f(file);
  if (!f) throw Error(path, 0, "cannot write the scenario file");
  f << out.str();
  if (!f) throw Error(path, 0, "write failed");
}

}  // namespace voronav::sim
