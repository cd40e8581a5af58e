#include "voronav/coordination/scenario.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "voronav/coordination/schedule_io.hpp"
#include "voronav/core/error.hpp"
#include "voronav/core/read_file.hpp"
#include "voronav/io/movingai.hpp"
#include "voronav/planning/planner_factory.hpp"

namespace voronav::coordination {

namespace fs = std::filesystem;

namespace {

int line_of(const YAML::Node& n) {
  if (!n.IsDefined()) return 0;  // a missing key has no position (Mark() would throw)
  return n.Mark().line >= 0 ? n.Mark().line + 1 : 0;
}

std::string text(const YAML::Node& n, const std::string& src, const std::string& what) {
  if (!n.IsScalar()) throw Error(src, line_of(n), what + ": expected a string");
  return n.Scalar();
}

double number(const YAML::Node& n, const std::string& src, const std::string& what) {
  if (!n || !n.IsScalar()) throw Error(src, line_of(n), what + ": expected a number");
  try {
    const double v = n.as<double>();
    if (std::isnan(v)) throw Error(src, line_of(n), what + ": expected a number, got NaN");
    return v;
  } catch (const YAML::Exception&) {
    throw Error(src, line_of(n), what + ": expected a number, got '" + n.Scalar() + "'");
  }
}

Vec2 point(const YAML::Node& n, const std::string& src, const std::string& what) {
  if (!n || !n.IsSequence() || n.size() != 2)
    throw Error(src, line_of(n), what + ": expected [x, y]");
  const Vec2 p{number(n[0], src, what), number(n[1], src, what)};
  if (!p.is_finite()) throw Error(src, line_of(n), what + ": expected finite coordinates");
  return p;
}

}  // namespace

Scenario load_scenario(const fs::path& path) {
  const std::string src = path.string();
  YAML::Node root;
  try {
    root = YAML::Load(read_file_bounded(path, kMaxTextFileBytes, "scenario file"));
  } catch (const YAML::Exception& e) {
    throw Error(src, e.mark.line + 1, "not valid YAML: " + e.msg);
  }
  if (!root.IsMap()) throw Error(src, 1, "expected a mapping with 'robots'");
  Scenario s;
  s.source = path;
  if (root["map"]) {
    const fs::path map_path = path.parent_path() / text(root["map"], src, "map");
    try {
      s.map = io::load_map(map_path);
    } catch (const Error& e) {
      throw Error(src, line_of(root["map"]), std::string("map: ") + e.what());
    }
    s.cell_coordinates = s.map->format == io::MapFormat::kMovingAi;
  }
  if (root["coordinates"]) {
    const auto c = text(root["coordinates"], src, "coordinates");
    if (c != "cells" && c != "world") {
      throw Error(src, line_of(root["coordinates"]),
                  "coordinates: expected cells|world, got '" + c + "'");
    }
    s.cell_coordinates = c == "cells";
  }
  try {
    if (root["at_start"])
      s.map_options.at_start = parse_at_start(text(root["at_start"], src, "at_start"));
    if (root["at_goal"])
      s.map_options.at_goal = parse_at_goal(text(root["at_goal"], src, "at_goal"));
  } catch (const Error& e) {
    throw Error(src, 0, e.source() + ": " + e.reason());
  }
  if (root["node_spacing"]) {
    s.map_options.node_spacing = number(root["node_spacing"], src, "node_spacing");
    if (!(s.map_options.node_spacing >= 0.0) || !std::isfinite(s.map_options.node_spacing))
      throw Error(src, line_of(root["node_spacing"]),
                  "node_spacing: expected a finite number >= 0 [m] (0: automatic), got '" +
                      root["node_spacing"].Scalar() + "'");
  }
  const YAML::Node robots = root["robots"];
  if (!robots || !robots.IsSequence() || robots.size() == 0) {
    throw Error(src, line_of(root), "missing 'robots' (a non-empty list)");
  }
  int next_id = 1;
  for (const auto& r : robots) {
    RobotSpec spec;
    spec.line = line_of(r);
    if (!r.IsMap()) throw Error(src, spec.line, "robot: expected a mapping");
    if (r["id"]) {
      const double id = number(r["id"], src, "id");
      if (!(id >= 0.0 && id <= 1e9) || id != std::floor(id))
        throw Error(src, line_of(r["id"]),
                    "id: expected an integer in 0..1000000000, got '" + r["id"].Scalar() + "'");
      spec.id = static_cast<int>(id);
    } else {
      spec.id = next_id;
    }
    next_id = spec.id + 1;
    const std::string who = "robot " + std::to_string(spec.id);
    if (r["radius"]) spec.radius = number(r["radius"], src, who + " radius");
    if (r["v_max"]) spec.limits.v_max = number(r["v_max"], src, who + " v_max");
    if (r["a_max"] && !r["a_max"].IsNull())
      spec.limits.a_max = number(r["a_max"], src, who + " a_max");
    if (!(spec.radius > 0.0) || !std::isfinite(spec.radius)) {
      throw Error(src, spec.line, who + ": radius must be a positive number");
    }
    if (!(spec.limits.v_max > 0.0) || !std::isfinite(spec.limits.v_max)) {
      throw Error(src, spec.line, who + ": v_max must be a positive number");
    }
    if (!(spec.limits.a_max > 0.0)) throw Error(src, spec.line, who + ": a_max must be > 0");
    if (r["path"]) {
      if (!r["path"].IsSequence() || r["path"].size() == 0) {
        throw Error(src, spec.line, who + ": path: expected a list of [x, y]");
      }
      for (const auto& p : r["path"])
        spec.path.push_back(point(p, src, who + " path"));
    } else {
      if (!r["start"] || !r["goal"])
        throw Error(src, spec.line, who + ": needs start and goal, or a path");
      if (!s.map) throw Error(src, spec.line, who + ": start/goal need a 'map' to plan on");
      spec.start = point(r["start"], src, who + " start");
      spec.goal = point(r["goal"], src, who + " goal");
    }
    s.robots.push_back(std::move(spec));
  }
  return s;
}

Scenario load_mapf(const fs::path& map_path, const fs::path& scen_path, int k, double radius) {
  if (k < 1) throw Error("--agents", 0, "expected at least 1 agent, got " + std::to_string(k));
  if (!(radius > 0.0) || !std::isfinite(radius))
    throw Error("--radius", 0, "expected a positive radius");
  Scenario s;
  s.source = scen_path;
  s.map = io::load_map(map_path);
  s.cell_coordinates = true;
  const auto queries = io::load_movingai_scen(scen_path);
  io::check_scen_fits(queries, s.map->grid, scen_path);
  if (static_cast<int>(queries.size()) < k) {
    throw Error(scen_path.string(), 0,
                "has " + std::to_string(queries.size()) + " rows, fewer than " + std::to_string(k) +
                    " agents");
  }
  for (int i = 0; i < k; ++i) {
    const auto& q = queries[static_cast<std::size_t>(i)];
    RobotSpec r;
    r.id = i + 1;
    r.line = q.line;
    r.start = Vec2{static_cast<double>(q.start_x), static_cast<double>(q.start_y)};
    r.goal = Vec2{static_cast<double>(q.goal_x), static_cast<double>(q.goal_y)};
    r.radius = radius;
    s.robots.push_back(r);
  }
  return s;
}

namespace {

Cell to_cell(const Scenario& s, Vec2 p, const std::string& what) {
  const auto& g = s.map->grid.geometry();
  std::optional<Cell> c;
  if (s.cell_coordinates) {
    if (p.x != std::floor(p.x) || p.y != std::floor(p.y) || std::abs(p.x) > 1e9 ||
        std::abs(p.y) > 1e9) {
      throw Error(s.source.string(), 0, what + ": expected integer cell coordinates");
    }
    const int x = static_cast<int>(p.x), y = static_cast<int>(p.y);
    c = s.map->format == io::MapFormat::kMovingAi ? io::movingai_to_cell(x, y, g.height)
                                                  : Cell{x, y};
  } else {
    c = g.world_to_cell(p);
  }
  if (!c || !g.contains(*c)) throw Error(s.source.string(), 0, what + ": outside the map");
  return *c;
}

/// Keeps only the cells where the direction changes.
std::vector<Vec2> simplify(const std::vector<Cell>& cells, const GridGeometry& g) {
  std::vector<Vec2> out;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (i > 0 && i + 1 < cells.size()) {
      const int dx1 = cells[i].x - cells[i - 1].x, dy1 = cells[i].y - cells[i - 1].y;
      const int dx2 = cells[i + 1].x - cells[i].x, dy2 = cells[i + 1].y - cells[i].y;
      if (dx1 == dx2 && dy1 == dy2) continue;
    }
    out.push_back(g.cell_center(cells[i]));
  }
  return out;
}

}  // namespace

PlannedAgents plan_agents(const Scenario& s) {
  PlannedAgents out;
  const std::string src = s.source.string();
  std::optional<BinaryGrid> blocked;
  if (s.map) blocked = binarize(s.map->grid);
  // Radii of all robots decide the node spacing h; the boxes see parked robots up to r_i + r_j + h.
  std::vector<Agent> probe;
  for (const auto& r : s.robots)
    probe.push_back({r.id, TimedPath({{0, 0}}, {1.0, kInfinity}), r.radius});
  const double h = effective_node_spacing(probe, s.map_options);
  struct Ends {
    Cell start, goal;
  };
  std::vector<Ends> ends(s.robots.size());
  for (std::size_t i = 0; i < s.robots.size(); ++i) {
    const auto& r = s.robots[i];
    if (r.path.empty()) {
      const std::string who = "robot " + std::to_string(r.id);
      ends[i] = {to_cell(s, *r.start, who + " start"), to_cell(s, *r.goal, who + " goal")};
    }
  }
  for (std::size_t i = 0; i < s.robots.size(); ++i) {
    const auto& r = s.robots[i];
    const std::string who = "robot " + std::to_string(r.id);
    std::vector<Vec2> nodes = r.path;
    if (nodes.empty()) {
      const auto& g = blocked->geometry();
      planning::PlannerOptions popt;
      auto planner = planning::make_planner(planning::PlannerKind::kAStar, popt);
      const BinaryGrid base = planning::make_planning_grid(*blocked, r.radius);
      // The paper's assumption: the path avoids the other robots' starts and goals.
      BinaryGrid avoid = base;
      for (std::size_t j = 0; j < s.robots.size(); ++j) {
        if (j == i || !s.robots[j].path.empty()) continue;
        const double reach = r.radius + s.robots[j].radius + h;
        // The disc is clipped to the grid: a huge radius or spacing costs at most the map.
        const double span_d = std::ceil(reach / g.resolution) + 1.0;
        for (const Cell c : {ends[j].start, ends[j].goal}) {
          const Vec2 p = g.cell_center(c);
          const auto clip = [&](int v, double d, int n) {
            return static_cast<int>(std::clamp(v + d, -1.0, static_cast<double>(n)));
          };
          const int x0 = clip(c.x, -span_d, g.width), x1 = clip(c.x, span_d, g.width);
          const int y0 = clip(c.y, -span_d, g.height), y1 = clip(c.y, span_d, g.height);
          for (int dy = y0 - c.y; dy <= y1 - c.y; ++dy) {
            for (int dx = x0 - c.x; dx <= x1 - c.x; ++dx) {
              const Cell q{c.x + dx, c.y + dy};
              if (!g.contains(q) || q == ends[i].start || q == ends[i].goal) continue;
              if (distance(g.cell_center(q), p) < reach) avoid[q] = 1;
            }
          }
        }
      }
      auto res = planner->plan(avoid, ends[i].start, ends[i].goal);
      if (!res.ok()) {
        res = planner->plan(base, ends[i].start, ends[i].goal);
        if (res.ok()) ++out.fallback_paths;
      }
      if (!res.ok()) {
        throw Error(src, r.line,
                    who + ": no path from start to goal (" +
                        std::string(planning::to_string(res.status)) + ")");
      }
      nodes = simplify(res.path, g);
      if (!s.cell_coordinates) {
        nodes.front() = *r.start;
        nodes.back() = *r.goal;
      }
    }
    try {
      out.agents.push_back({r.id, TimedPath(std::move(nodes), r.limits), r.radius});
    } catch (const Error& e) {
      throw Error(src, r.line, who + ": " + e.source() + ": " + e.reason());
    }
  }
  return out;
}

}  // namespace voronav::coordination
