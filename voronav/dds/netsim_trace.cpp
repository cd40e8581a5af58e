// Trace files of the multi-process netsim run (internal/netsim_trace.hpp).
#include "voronav/dds/internal/netsim_trace.hpp"

#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>

namespace voronav::dds::internal {

using nlohmann::json;

TraceFile::TraceFile(const std::string& path) {
  if (path.empty()) return;
  f_.open(path, std::ios::app);
  on_ = static_cast<bool>(f_);
}

void TraceFile::line(const std::string& s) {
  if (!on_) return;
  f_ << s << '\n';
  f_.flush();
}

void TraceFile::robot_step(std::uint32_t k, double t, Vec2 p,
                           const std::vector<sim::RecordedMessage>& sent,
                           const std::vector<sim::RecordedRepair>& repairs) {
  json m = json::array();
  for (const auto& s : sent)
    m.push_back({s.t_s, s.to, static_cast<int>(s.type), s.bytes});
  json j{{"k", k}, {"t", t}, {"p", {p.x, p.y}}, {"m", m}};
  if (!repairs.empty()) {
    json r = json::array();
    for (const auto& e : repairs)
      r.push_back({e.t_s, e.robot, e.executed, e.what});
    j["r"] = r;
  }
  line(j.dump());
}

void TraceFile::robot_route(const std::vector<Vec2>& route) {
  json r = json::array();
  for (const auto& p : route)
    r.push_back({p.x, p.y});
  line(json{{"route", r}}.dump());
}

void TraceFile::event(const DdsEvent& e) {
  line(
      json{{"t", e.t_s}, {"k", e.step}, {"event", e.kind}, {"robot", e.robot}, {"detail", e.detail}}
          .dump());
}

void read_netsim_traces(const std::vector<std::string>& robot_files, const std::string& world_file,
                        const sim::NetSimScenario& sc, sim::Recording& rec,
                        std::vector<DdsEvent>& events) {
  const std::size_t n = sc.robots.size();
  rec = {};
  rec.world = sc.world.geometry();
  // step -> (t, robot -> pose)
  std::map<std::uint32_t, std::pair<double, std::map<std::size_t, Vec2>>> steps;
  for (std::size_t r = 0; r < robot_files.size() && r < n; ++r) {
    std::ifstream f(robot_files[r]);
    std::string s;
    while (std::getline(f, s)) {
      try {
        const json j = json::parse(s);
        if (j.contains("route")) {
          if (r == sc.source) {
            rec.route.clear();
            for (const auto& p : j["route"])
              rec.route.push_back({p.at(0).get<double>(), p.at(1).get<double>()});
          }
          continue;
        }
        const auto k = j.at("k").get<std::uint32_t>();
        auto& st = steps[k];
        st.first = j.at("t").get<double>();
        st.second[r] = {j.at("p").at(0).get<double>(), j.at("p").at(1).get<double>()};
        for (const auto& m : j.at("m")) {
          const int type = m.at(2).get<int>();
          if (type < 0 || type >= network::kMessageTypeCount) continue;
          rec.messages.push_back(
              {m.at(0).get<double>(), static_cast<std::uint32_t>(r), m.at(1).get<std::uint32_t>(),
               static_cast<network::MessageType>(type), m.at(3).get<std::size_t>()});
        }
        if (j.contains("r"))
          for (const auto& e : j.at("r"))
            rec.repairs.push_back({e.at(0).get<double>(), e.at(1).get<std::uint32_t>(),
                                   e.at(2).get<bool>(), e.at(3).get<std::string>()});
      } catch (const json::exception&) {
        // a line cut short by a killed process
      }
    }
  }
  std::vector<Vec2> last(sc.robots.begin(), sc.robots.end());
  for (const auto& [k, st] : steps) {
    for (const auto& [r, p] : st.second)
      last[r] = p;
    rec.steps.push_back({st.first, last});
  }
  std::stable_sort(rec.messages.begin(), rec.messages.end(),
                   [](const auto& a, const auto& b) { return a.t_s < b.t_s; });
  std::stable_sort(rec.repairs.begin(), rec.repairs.end(),
                   [](const auto& a, const auto& b) { return a.t_s < b.t_s; });
  std::ifstream w(world_file);
  std::string s;
  while (std::getline(w, s)) {
    try {
      const json j = json::parse(s);
      events.push_back({j.at("t").get<double>(), j.at("k").get<std::uint32_t>(),
                        j.at("event").get<std::string>(), j.at("robot").get<std::int64_t>(),
                        j.at("detail").get<std::string>()});
    } catch (const json::exception&) {
    }
  }
}

}  // namespace voronav::dds::internal
