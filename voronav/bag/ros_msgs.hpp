// The ROS 2 messages voronav records (Humble layouts), their CDR encoders and their full
// `ros2msg` definitions. Each definition is the message's own .msg text followed by every type it
// depends on, each after a line of 80 '=' and "MSG: pkg/Type", the layout rosbag2's MCAP storage
// writes and Foxglove parses. Units: metres, radians, seconds (REP-103); frames by name.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "voronav/core/occupancy.hpp"
#include "voronav/core/pose2.hpp"

namespace voronav::bag::ros {

/// builtin_interfaces/Time and /Duration.
struct Time {
  std::int32_t sec = 0;
  std::uint32_t nanosec = 0;
  /// Seconds to Time (negative times clamp to 0, rounding to the nanosecond).
  [[nodiscard]] static Time from_seconds(double s);
};
struct Header {
  Time stamp;
  std::string frame_id = "map";
};
/// geometry_msgs/Point and /Vector3.
struct Point {
  double x = 0, y = 0, z = 0;
};
struct Quaternion {
  double x = 0, y = 0, z = 0, w = 1;
  /// A rotation by `yaw` [rad] about +z.
  [[nodiscard]] static Quaternion from_yaw(double yaw);
};
struct Pose {
  Point position;
  Quaternion orientation;
  [[nodiscard]] static Pose from(const Pose2& p);
};
struct ColorRGBA {
  float r = 0, g = 0, b = 0, a = 1;
};

/// nav_msgs/msg/OccupancyGrid (info = nav_msgs/MapMetaData).
struct OccupancyGridMsg {
  static constexpr std::string_view kType = "nav_msgs/msg/OccupancyGrid";
  Header header;
  Time map_load_time;
  float resolution = 0;
  std::uint32_t width = 0, height = 0;
  Pose origin;
  std::vector<std::int8_t> data;  ///< row-major, row 0 at the origin (bottom)
  /// The grid with its geometry; stamp and map_load_time = t.
  [[nodiscard]] static OccupancyGridMsg from(const OccupancyGrid& grid, Time t,
                                             std::string frame_id = "map");
};
struct PoseStamped {
  Header header;
  Pose pose;
};
/// nav_msgs/msg/Path.
struct PathMsg {
  static constexpr std::string_view kType = "nav_msgs/msg/Path";
  Header header;
  std::vector<PoseStamped> poses;
};
struct TransformStamped {
  Header header;
  std::string child_frame_id;
  Point translation;
  Quaternion rotation;
};
/// tf2_msgs/msg/TFMessage.
struct TFMessage {
  static constexpr std::string_view kType = "tf2_msgs/msg/TFMessage";
  std::vector<TransformStamped> transforms;
};
/// geometry_msgs/msg/PoseArray.
struct PoseArrayMsg {
  static constexpr std::string_view kType = "geometry_msgs/msg/PoseArray";
  Header header;
  std::vector<Pose> poses;
};
/// visualization_msgs/msg/Marker (Humble fields).
struct Marker {
  enum Type : std::int32_t {
    kArrow = 0,
    kCube = 1,
    kSphere = 2,
    kCylinder = 3,
    kLineStrip = 4,
    kLineList = 5,
    kCubeList = 6,
    kSphereList = 7,
    kPoints = 8,
    kTextViewFacing = 9
  };
  enum Action : std::int32_t { kAdd = 0, kDelete = 2, kDeleteAll = 3 };
  Header header;
  std::string ns;
  std::int32_t id = 0;
  std::int32_t type = kArrow;
  std::int32_t action = kAdd;
  Pose pose;
  Point scale{1, 1, 1};
  ColorRGBA color;
  Time lifetime;  ///< 0 = forever
  bool frame_locked = false;
  std::vector<Point> points;
  std::vector<ColorRGBA> colors;
  std::string text;
  std::string mesh_resource;
  bool mesh_use_embedded_materials = false;
};
/// visualization_msgs/msg/MarkerArray.
struct MarkerArrayMsg {
  static constexpr std::string_view kType = "visualization_msgs/msg/MarkerArray";
  std::vector<Marker> markers;
};
/// std_msgs/msg/String.
struct StringMsg {
  static constexpr std::string_view kType = "std_msgs/msg/String";
  std::string data;
};

/// CDR (XCDR1 little endian, with the encapsulation header) of each message.
[[nodiscard]] std::vector<std::uint8_t> encode(const OccupancyGridMsg& m);
[[nodiscard]] std::vector<std::uint8_t> encode(const PathMsg& m);
[[nodiscard]] std::vector<std::uint8_t> encode(const TFMessage& m);
[[nodiscard]] std::vector<std::uint8_t> encode(const PoseArrayMsg& m);
[[nodiscard]] std::vector<std::uint8_t> encode(const MarkerArrayMsg& m);
[[nodiscard]] std::vector<std::uint8_t> encode(const StringMsg& m);

/// The full ros2msg definition of `type` ("nav_msgs/msg/OccupancyGrid" or "nav_msgs/OccupancyGrid")
/// with its dependencies; throws voronav::Error for a type voronav does not know.
[[nodiscard]] std::string definition(std::string_view type);

/// A CSS colour "#rrggbb" as ColorRGBA with alpha `a` (grey for anything else).
[[nodiscard]] ColorRGBA color_from_css(std::string_view css, float a = 1.0F);

}  // namespace voronav::bag::ros
