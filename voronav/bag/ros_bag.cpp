#include "voronav/bag/ros_bag.hpp"

#include <algorithm>
#include <cmath>

#include "voronav/core/error.hpp"

namespace voronav::bag {

RosBagWriter::RosBagWriter(std::filesystem::path file, McapOptions options)
    : file_(std::move(file)), options_(std::move(options)) {
  // Fail early (before a long run) when the file cannot be created.
  std::ofstream probe(file_, std::ios::binary | std::ios::trunc);
  if (!probe) throw Error(file_.string(), 0, "cannot open for writing");
}

void RosBagWriter::add(const std::string& topic, std::string_view type, double t_s,
                       std::vector<std::uint8_t> data) {
  if (closed_) throw Error(file_.string(), 0, "bag already closed");
  if (!std::isfinite(t_s)) throw Error("bag: topic " + topic + ": time is not finite");
  auto [it, fresh] = topic_types_.emplace(topic, std::string(type));
  if (!fresh && it->second != type)
    throw Error("bag: topic " + topic + " carries " + it->second + ", not " + std::string(type));
  if (t_s > 1.8e10)
    throw Error("bag: topic " + topic + ": time " + std::to_string(t_s) + " s is out of range");
  const auto ns = static_cast<std::uint64_t>(std::llround(std::max(0.0, t_s) * 1e9));
  pending_.push_back({ns, topic, std::string(type), std::move(data)});
  ++counts_[topic];
}

void RosBagWriter::write(const std::string& topic, double t, const ros::OccupancyGridMsg& m) {
  add(topic, m.kType, t, ros::encode(m));
}
void RosBagWriter::write(const std::string& topic, double t, const ros::PathMsg& m) {
  add(topic, m.kType, t, ros::encode(m));
}
void RosBagWriter::write(const std::string& topic, double t, const ros::TFMessage& m) {
  add(topic, m.kType, t, ros::encode(m));
}
void RosBagWriter::write(const std::string& topic, double t, const ros::PoseArrayMsg& m) {
  add(topic, m.kType, t, ros::encode(m));
}
void RosBagWriter::write(const std::string& topic, double t, const ros::MarkerArrayMsg& m) {
  add(topic, m.kType, t, ros::encode(m));
}
void RosBagWriter::write(const std::string& topic, double t, const ros::StringMsg& m) {
  add(topic, m.kType, t, ros::encode(m));
}

void RosBagWriter::close() {
  if (closed_) return;
  closed_ = true;
  std::stable_sort(pending_.begin(), pending_.end(),
                   [](const Pending& a, const Pending& b) { return a.t_ns < b.t_ns; });
  McapWriter w(file_, options_);
  std::map<std::string, std::uint16_t> schema_ids, channel_ids;
  for (const auto& p : pending_) {
    auto ch = channel_ids.find(p.topic);
    if (ch == channel_ids.end()) {
      auto sc = schema_ids.find(p.type);
      if (sc == schema_ids.end())
        sc = schema_ids.emplace(p.type, w.add_schema(p.type, "ros2msg", ros::definition(p.type)))
                 .first;
      // rosbag2 writes the QoS profiles of each topic; /map and the marker topics are latched
      // (transient local) so that late subscribers of `ros2 bag play` still get them.
      const bool latched = p.topic == "/map" || p.topic == "/voronoi" || p.topic == "/topology" ||
                           p.topic == "/collision_boxes";
      const std::string qos =
          std::string("- history: 3\n  depth: 0\n  reliability: 1\n  durability: ") +
          (latched ? "1" : "2") +
          "\n  deadline:\n    sec: 2147483647\n    nsec: 4294967295\n  lifespan:\n    sec: "
          "2147483647\n    nsec: 4294967295\n  liveliness: 1\n  liveliness_lease_duration:\n    "
          "sec: 2147483647\n    nsec: 4294967295\n  avoid_ros_namespace_conventions: false\n";
      ch = channel_ids
               .emplace(p.topic,
                        w.add_channel(sc->second, p.topic, "cdr", {{"offered_qos_profiles", qos}}))
               .first;
    }
    w.write(ch->second, p.t_ns, p.t_ns, p.data);
  }
  w.close();
  pending_.clear();
}

}  // namespace voronav::bag
