// RosBagWriter: a ROS 2 bag in one MCAP file (profile "ros2", schemas "ros2msg", messages "cdr"),
// as rosbag2's MCAP storage and Foxglove read it. One channel per topic, created at the first
// message; messages are buffered and written in time order on close(), so callers may produce
// topics in any order. Times are simulated seconds (log_time = publish_time).
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "voronav/bag/mcap_writer.hpp"
#include "voronav/bag/ros_msgs.hpp"

namespace voronav::bag {

class RosBagWriter {
 public:
  explicit RosBagWriter(std::filesystem::path file, McapOptions options = {});

  void write(const std::string& topic, double t_s, const ros::OccupancyGridMsg& m);
  void write(const std::string& topic, double t_s, const ros::PathMsg& m);
  void write(const std::string& topic, double t_s, const ros::TFMessage& m);
  void write(const std::string& topic, double t_s, const ros::PoseArrayMsg& m);
  void write(const std::string& topic, double t_s, const ros::MarkerArrayMsg& m);
  void write(const std::string& topic, double t_s, const ros::StringMsg& m);

  /// Messages so far per topic.
  [[nodiscard]] const std::map<std::string, std::size_t>& counts() const { return counts_; }
  /// Writes every message (sorted by time, stable) and the summary. Idempotent.
  void close();

 private:
  void add(const std::string& topic, std::string_view type, double t_s,
           std::vector<std::uint8_t> data);
  struct Pending {
    std::uint64_t t_ns;
    std::string topic;
    std::string type;
    std::vector<std::uint8_t> data;
  };
  std::filesystem::path file_;
  McapOptions options_;
  std::vector<Pending> pending_;
  std::map<std::string, std::size_t> counts_;
  std::map<std::string, std::string> topic_types_;
  bool closed_ = false;
};

}  // namespace voronav::bag
