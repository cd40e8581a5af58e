#include "voronav/coordination/schedule_io.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "voronav/core/error.hpp"
#include "voronav/core/read_file.hpp"

namespace voronav::coordination {

AtStart parse_at_start(const std::string& s) {
  if (s == "wait") return AtStart::kWait;
  if (s == "appear") return AtStart::kAppear;
  throw Error("at_start", 0, "expected wait|appear, got '" + s + "'");
}
AtGoal parse_at_goal(const std::string& s) {
  if (s == "stay") return AtGoal::kStay;
  if (s == "leave") return AtGoal::kLeave;
  throw Error("at_goal", 0, "expected stay|leave, got '" + s + "'");
}
const char* to_string(AtStart s) {
  return s == AtStart::kWait ? "wait" : "appear";
}
const char* to_string(AtGoal g) {
  return g == AtGoal::kStay ? "stay" : "leave";
}

namespace {

nlohmann::json to_json(const Schedule& s) {
  if (s.delays.size() != s.agents.size())
    throw Error("schedule", 0, "one delay per agent expected");
  nlohmann::json agents = nlohmann::json::array();
  double makespan = 0.0, sum = 0.0;
  for (std::size_t i = 0; i < s.agents.size(); ++i) {
    const Agent& a = s.agents[i];
    nlohmann::json path = nlohmann::json::array();
    for (const Vec2 p : a.path.nodes())
      path.push_back({p.x, p.y});
    const bool timed = i < s.waypoints.size() && !s.waypoints[i].empty();
    const double arrival = timed ? s.waypoints[i].back().t : s.delays[i] + a.path.travel_time();
    makespan = std::max(makespan, arrival);
    sum += arrival;
    nlohmann::json j = {
        {"id", a.id},           {"radius", a.radius}, {"v_max", a.path.limits().v_max},
        {"delay", s.delays[i]}, {"arrival", arrival}, {"path", path}};
    j["a_max"] = std::isinf(a.path.limits().a_max) ? nlohmann::json(nullptr)
                                                   : nlohmann::json(a.path.limits().a_max);
    if (timed) {
      // SIPP: the motion itself, constant velocity between these [t, x, y].
      nlohmann::json w = nlohmann::json::array();
      for (const TimedWaypoint& p : s.waypoints[i])
        w.push_back({p.t, p.p.x, p.p.y});
      j["waypoints"] = w;
    } else {
      // Start delays (issue 19): [t, x, y] per path node, t [s] in the team's clock (the
      // robot's delay plus its travel time to the node), x, y [m] in frame "map"; between nodes
      // the robot follows its speed profile (v_max, a_max), so these are not read back.
      nlohmann::json w = nlohmann::json::array();
      for (std::size_t k = 0; k < a.path.nodes().size(); ++k) {
        const Vec2 p = a.path.nodes()[k];
        w.push_back({s.delays[i] + a.path.time_at_arc(a.path.cumulative()[k]), p.x, p.y});
      }
      j["timed_path"] = w;
    }
    agents.push_back(j);
  }
  nlohmann::json out = {{"format", "voronav-schedule"},
                        {"version", 1},
                        {"frame_id", "map"},
                        {"units", {{"time", "s"}, {"length", "m"}, {"speed", "m/s"}}},
                        {"at_start", to_string(s.at_start)},
                        {"at_goal", to_string(s.at_goal)},
                        {"makespan", makespan},
                        {"sum_of_arrivals", sum},
                        {"valid", s.valid},
                        {"agents", agents}};
  if (!s.map.empty()) out["map"] = s.map;
  return out;
}

void emit(YAML::Emitter& out, const nlohmann::json& j) {
  if (j.is_object()) {
    out << YAML::BeginMap;
    for (auto it = j.begin(); it != j.end(); ++it) {
      out << YAML::Key << it.key() << YAML::Value;
      emit(out, it.value());
    }
    out << YAML::EndMap;
  } else if (j.is_array()) {
    const bool flow = !j.empty() && !j.front().is_object() && !j.front().is_array();
    out << (flow ? YAML::Flow : YAML::Block) << YAML::BeginSeq;
    for (const auto& e : j)
      emit(out, e);
    out << YAML::EndSeq;
  } else if (j.is_null()) {
    out << YAML::Null;
  } else if (j.is_boolean()) {
    out << j.get<bool>();
  } else if (j.is_number_integer()) {
    out << j.get<long long>();
  } else if (j.is_number()) {
    out << YAML::Precision(17) << j.get<double>();
  } else {
    out << j.get<std::string>();
  }
}

}  // namespace

std::string schedule_to_json(const Schedule& s) {
  return to_json(s).dump(2) + "\n";
}

std::string schedule_to_yaml(const Schedule& s) {
  YAML::Emitter out;
  emit(out, to_json(s));
  return std::string(out.c_str()) + "\n";
}

Schedule parse_schedule(const std::string& text, const std::string& source) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw Error(source, e.mark.line + 1, "not valid JSON/YAML: " + e.msg);
  }
  // A missing key has no position (Mark() would throw): its error names the enclosing line.
  int context_line = 1;
  auto line_of = [&](const YAML::Node& n) {
    if (!n.IsDefined()) return context_line;
    return n.Mark().line >= 0 ? n.Mark().line + 1 : 0;
  };
  auto number = [&](const YAML::Node& n, const std::string& what) {
    if (!n.IsDefined()) throw Error(source, context_line, what + ": missing key");
    if (!n.IsScalar()) throw Error(source, line_of(n), what + ": expected a number");
    try {
      return n.as<double>();
    } catch (const YAML::Exception&) {
      throw Error(source, line_of(n), what + ": expected a number, got '" + n.Scalar() + "'");
    }
  };
  if (!root.IsMap()) throw Error(source, 1, "expected a mapping with an 'agents' list");
  Schedule s;
  try {
    auto scalar = [&](const YAML::Node& n, const std::string& what) {
      if (!n.IsScalar()) throw Error(source, line_of(n), what + ": expected a string");
      return n.Scalar();
    };
    if (root["at_start"]) s.at_start = parse_at_start(scalar(root["at_start"], "at_start"));
    if (root["at_goal"]) s.at_goal = parse_at_goal(scalar(root["at_goal"], "at_goal"));
  } catch (const Error& e) {
    if (e.source() == source) throw;
    throw Error(source, 0, e.source() + ": " + e.reason());
  }
  if (root["valid"] && root["valid"].IsScalar()) s.valid = root["valid"].as<bool>(false);
  if (root["map"]) {
    if (!root["map"].IsScalar())
      throw Error(source, line_of(root["map"]), "map: expected a file name");
    s.map = root["map"].Scalar();
  }
  bool any_timed = false;
  const YAML::Node agents = root["agents"];
  if (!agents || !agents.IsSequence()) throw Error(source, line_of(root), "missing 'agents' list");
  for (const auto& a : agents) {
    const int line = line_of(a);
    context_line = line;
    if (!a.IsMap()) throw Error(source, line, "agent: expected a mapping");
    const double id_value = number(a["id"], "id");
    if (!(id_value >= 0.0 && id_value <= 1e9) || id_value != std::floor(id_value))
      throw Error(source, line_of(a["id"]), "id: expected an integer in 0..1000000000");
    const int id = static_cast<int>(id_value);
    const std::string who = "agent " + std::to_string(id);
    const YAML::Node path = a["path"];
    std::vector<TimedWaypoint> timed;
    if (const YAML::Node w = a["waypoints"]; w) {
      if (!w.IsSequence() || w.size() == 0)
        throw Error(source, line_of(w), who + ": waypoints: expected a list of [t, x, y]");
      for (const auto& p : w) {
        if (!p.IsSequence() || p.size() != 3)
          throw Error(source, line_of(p), who + ": waypoint: expected [t, x, y]");
        timed.push_back({number(p[0], who + " waypoint t"),
                         {number(p[1], who + " waypoint x"), number(p[2], who + " waypoint y")}});
        if (timed.size() > 1 && !(timed.back().t > timed[timed.size() - 2].t))
          throw Error(source, line_of(p), who + ": waypoint times must increase strictly");
      }
      if (!(timed.front().t >= 0.0) || !std::isfinite(timed.back().t))
        throw Error(source, line_of(w), who + ": waypoint times must be finite and >= 0");
      any_timed = true;
    }
    if (!path || !path.IsSequence() || path.size() == 0) {
      throw Error(source, line, who + ": missing 'path' (a list of [x, y])");
    }
    std::vector<Vec2> nodes;
    for (const auto& p : path) {
      if (!p.IsSequence() || p.size() != 2)
        throw Error(source, line_of(p), who + ": path point: expected [x, y]");
      nodes.push_back({number(p[0], who + " path x"), number(p[1], who + " path y")});
    }
    MotionLimits lim;
    lim.v_max = number(a["v_max"], who + " v_max");
    if (a["a_max"] && !a["a_max"].IsNull()) lim.a_max = number(a["a_max"], who + " a_max");
    const double radius = number(a["radius"], who + " radius");
    const double delay = number(a["delay"], who + " delay");
    if (!(radius > 0.0) || !std::isfinite(radius))
      throw Error(source, line, who + ": radius must be > 0");
    if (!(delay >= 0.0) || !std::isfinite(delay))
      throw Error(source, line, who + ": delay must be >= 0");
    try {
      s.agents.push_back({id, TimedPath(std::move(nodes), lim), radius});
    } catch (const Error& e) {
      throw Error(source, line, who + ": " + e.source() + ": " + e.reason());
    }
    s.delays.push_back(delay);
    s.waypoints.push_back(std::move(timed));
  }
  if (!any_timed) s.waypoints.clear();
  return s;
}

void write_schedule(const std::filesystem::path& path, const Schedule& s) {
  const auto ext = path.extension().string();
  std::string text;
  if (ext == ".json") {
    text = schedule_to_json(s);
  } else if (ext == ".yaml" || ext == ".yml") {
    text = schedule_to_yaml(s);
  } else {
    throw Error(path.string(), 0, "expected a .json, .yaml or .yml file name");
  }
  std::ofstream f(path);
  f << text;
  if (!f) throw Error(path.string(), 0, "cannot write the file");
}

std::vector<Trajectory> trajectories(const Schedule& s) {
  std::vector<Trajectory> out;
  for (std::size_t i = 0; i < s.agents.size(); ++i) {
    if (i < s.waypoints.size() && !s.waypoints[i].empty()) {
      out.push_back(trajectory_of(s.waypoints[i], s.at_start, s.at_goal));
    } else {
      out.push_back(trajectory_of(s.agents[i].path, s.delays[i], s.at_start, s.at_goal));
    }
  }
  return out;
}

Schedule read_schedule(const std::filesystem::path& path) {
  return parse_schedule(read_file_bounded(path, kMaxTextFileBytes, "schedule file"), path.string());
}

}  // namespace voronav::coordination
