#include "voronav/bag/ros_msgs.hpp"

#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "voronav/bag/cdr.hpp"
#include "voronav/core/error.hpp"

namespace voronav::bag::ros {
namespace {

// The .msg texts (ROS 2 Humble), keyed by "pkg/Type". Field types are fully qualified so that
// every reader resolves them without package context.
const std::map<std::string, std::string, std::less<>>& msg_texts() {
  static const std::map<std::string, std::string, std::less<>> texts = {
      {"builtin_interfaces/Time", "int32 sec\nuint32 nanosec\n"},
      {"builtin_interfaces/Duration", "int32 sec\nuint32 nanosec\n"},
      {"std_msgs/Header", "builtin_interfaces/Time stamp\nstring frame_id\n"},
      {"std_msgs/ColorRGBA", "float32 r\nfloat32 g\nfloat32 b\nfloat32 a\n"},
      {"std_msgs/String", "string data\n"},
      {"geometry_msgs/Point", "float64 x\nfloat64 y\nfloat64 z\n"},
      {"geometry_msgs/Vector3", "float64 x\nfloat64 y\nfloat64 z\n"},
      {"geometry_msgs/Quaternion", "float64 x 0\nfloat64 y 0\nfloat64 z 0\nfloat64 w 1\n"},
      {"geometry_msgs/Pose",
       "geometry_msgs/Point position\ngeometry_msgs/Quaternion orientation\n"},
      {"geometry_msgs/PoseStamped", "std_msgs/Header header\ngeometry_msgs/Pose pose\n"},
      {"geometry_msgs/PoseArray", "std_msgs/Header header\ngeometry_msgs/Pose[] poses\n"},
      {"geometry_msgs/Transform",
       "geometry_msgs/Vector3 translation\ngeometry_msgs/Quaternion rotation\n"},
      {"geometry_msgs/TransformStamped",
       "std_msgs/Header header\nstring child_frame_id\ngeometry_msgs/Transform transform\n"},
      {"tf2_msgs/TFMessage", "geometry_msgs/TransformStamped[] transforms\n"},
      {"nav_msgs/MapMetaData",
       "builtin_interfaces/Time map_load_time\nfloat32 resolution\nuint32 width\nuint32 height\n"
       "geometry_msgs/Pose origin\n"},
      {"nav_msgs/OccupancyGrid",
       "std_msgs/Header header\nnav_msgs/MapMetaData info\nint8[] data\n"},
      {"nav_msgs/Path", "std_msgs/Header header\ngeometry_msgs/PoseStamped[] poses\n"},
      {"visualization_msgs/Marker",
       "int32 ARROW=0\nint32 CUBE=1\nint32 SPHERE=2\nint32 CYLINDER=3\nint32 LINE_STRIP=4\n"
       "int32 LINE_LIST=5\nint32 CUBE_LIST=6\nint32 SPHERE_LIST=7\nint32 POINTS=8\n"
       "int32 TEXT_VIEW_FACING=9\nint32 MESH_RESOURCE=10\nint32 TRIANGLE_LIST=11\n"
       "int32 ADD=0\nint32 MODIFY=0\nint32 DELETE=2\nint32 DELETEALL=3\n"
       "std_msgs/Header header\nstring ns\nint32 id\nint32 type\nint32 action\n"
       "geometry_msgs/Pose pose\ngeometry_msgs/Vector3 scale\nstd_msgs/ColorRGBA color\n"
       "builtin_interfaces/Duration lifetime\nbool frame_locked\ngeometry_msgs/Point[] points\n"
       "std_msgs/ColorRGBA[] colors\nstring text\nstring mesh_resource\n"
       "bool mesh_use_embedded_materials\n"},
      {"visualization_msgs/MarkerArray", "visualization_msgs/Marker[] markers\n"},
  };
  return texts;
}

/// Complex field types of a .msg text, in order ("pkg/Type", without array brackets).
std::vector<std::string> field_types(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    const std::string type = line.substr(0, line.find(' '));
    if (type.find('/') == std::string::npos) continue;
    out.push_back(type.substr(0, type.find('[')));
  }
  return out;
}

void collect(const std::string& type, std::vector<std::string>& order,
             std::set<std::string>& seen) {
  for (const auto& dep : field_types(msg_texts().find(type)->second)) {
    if (!seen.insert(dep).second) continue;
    order.push_back(dep);
    collect(dep, order, seen);
  }
}

void put(CdrWriter& w, const Time& t) {
  w.i32(t.sec);
  w.u32(t.nanosec);
}
void put(CdrWriter& w, const Header& h) {
  put(w, h.stamp);
  w.string(h.frame_id);
}
void put(CdrWriter& w, const Point& p) {
  w.f64(p.x);
  w.f64(p.y);
  w.f64(p.z);
}
void put(CdrWriter& w, const Quaternion& q) {
  w.f64(q.x);
  w.f64(q.y);
  w.f64(q.z);
  w.f64(q.w);
}
void put(CdrWriter& w, const Pose& p) {
  put(w, p.position);
  put(w, p.orientation);
}
void put(CdrWriter& w, const ColorRGBA& c) {
  w.f32(c.r);
  w.f32(c.g);
  w.f32(c.b);
  w.f32(c.a);
}
void put(CdrWriter& w, const Marker& m) {
  put(w, m.header);
  w.string(m.ns);
  w.i32(m.id);
  w.i32(m.type);
  w.i32(m.action);
  put(w, m.pose);
  put(w, m.scale);
  put(w, m.color);
  put(w, m.lifetime);
  w.boolean(m.frame_locked);
  w.count(m.points.size());
  for (const auto& p : m.points)
    put(w, p);
  w.count(m.colors.size());
  for (const auto& c : m.colors)
    put(w, c);
  w.string(m.text);
  w.string(m.mesh_resource);
  w.boolean(m.mesh_use_embedded_materials);
}

}  // namespace

Time Time::from_seconds(double s) {
  if (!(s > 0.0)) return {};
  if (s >= 2147483647.0) return {2147483647, 999999999};  // the largest Time
  const auto ns = static_cast<std::int64_t>(std::llround(s * 1e9));
  return {static_cast<std::int32_t>(ns / 1000000000), static_cast<std::uint32_t>(ns % 1000000000)};
}

Quaternion Quaternion::from_yaw(double yaw) {
  return {0.0, 0.0, std::sin(yaw / 2.0), std::cos(yaw / 2.0)};
}

Pose Pose::from(const Pose2& p) {
  return {{p.position.x, p.position.y, 0.0}, Quaternion::from_yaw(p.yaw)};
}

OccupancyGridMsg OccupancyGridMsg::from(const OccupancyGrid& grid, Time t, std::string frame_id) {
  OccupancyGridMsg m;
  m.header = {t, std::move(frame_id)};
  m.map_load_time = t;
  m.resolution = static_cast<float>(grid.resolution());
  m.width = static_cast<std::uint32_t>(grid.width());
  m.height = static_cast<std::uint32_t>(grid.height());
  m.origin = Pose::from(grid.geometry().origin);
  m.data = grid.values();
  return m;
}

std::vector<std::uint8_t> encode(const OccupancyGridMsg& m) {
  CdrWriter w;
  put(w, m.header);
  put(w, m.map_load_time);
  w.f32(m.resolution);
  w.u32(m.width);
  w.u32(m.height);
  put(w, m.origin);
  w.count(m.data.size());
  w.bytes(m.data.data(), m.data.size());
  return w.take();
}

std::vector<std::uint8_t> encode(const PathMsg& m) {
  CdrWriter w;
  put(w, m.header);
  w.count(m.poses.size());
  for (const auto& p : m.poses) {
    put(w, p.header);
    put(w, p.pose);
  }
  return w.take();
}

std::vector<std::uint8_t> encode(const TFMessage& m) {
  CdrWriter w;
  w.count(m.transforms.size());
  for (const auto& t : m.transforms) {
    put(w, t.header);
    w.string(t.child_frame_id);
    put(w, t.translation);
    put(w, t.rotation);
  }
  return w.take();
}

std::vector<std::uint8_t> encode(const PoseArrayMsg& m) {
  CdrWriter w;
  put(w, m.header);
  w.count(m.poses.size());
  for (const auto& p : m.poses)
    put(w, p);
  return w.take();
}

std::vector<std::uint8_t> encode(const MarkerArrayMsg& m) {
  CdrWriter w;
  w.count(m.markers.size());
  for (const auto& mk : m.markers)
    put(w, mk);
  return w.take();
}

std::vector<std::uint8_t> encode(const StringMsg& m) {
  CdrWriter w;
  w.string(m.data);
  return w.take();
}

std::string definition(std::string_view type) {
  std::string key(type);
  if (const auto p = key.find("/msg/"); p != std::string::npos) key.erase(p, 4);
  if (msg_texts().find(key) == msg_texts().end())
    throw Error("ros2msg: no definition of message type '" + std::string(type) + "'");
  std::vector<std::string> deps;
  std::set<std::string> seen{key};
  collect(key, deps, seen);
  std::string out = msg_texts().find(key)->second;
  for (const auto& d : deps)
    out +=
        "================================================================================\nMSG: " +
        d + "\n" + msg_texts().find(d)->second;
  return out;
}

ColorRGBA color_from_css(std::string_view css, float a) {
  auto hex = [&](std::size_t i) -> int {
    int v = 0;
    for (std::size_t k = i; k < i + 2; ++k) {
      const char c = css[k];
      const int d = c >= '0' && c <= '9'   ? c - '0'
                    : c >= 'a' && c <= 'f' ? c - 'a' + 10
                    : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                           : -1;
      if (d < 0) return -1;
      v = v * 16 + d;
    }
    return v;
  };
  if (css.size() != 7 || css[0] != '#' || hex(1) < 0 || hex(3) < 0 || hex(5) < 0)
    return {0.5F, 0.5F, 0.5F, a};
  return {static_cast<float>(hex(1)) / 255.0F, static_cast<float>(hex(3)) / 255.0F,
          static_cast<float>(hex(5)) / 255.0F, a};
}

}  // namespace voronav::bag::ros
