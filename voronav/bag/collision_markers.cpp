#include "voronav/bag/collision_markers.hpp"

#include <cmath>
#include <cstdio>

#include "voronav/coordination/collision_map.hpp"

namespace voronav::bag {

std::vector<ros::Marker> collision_box_markers(const std::vector<coordination::Agent>& agents,
                                               const coordination::CoordinationResult& r,
                                               const coordination::CollisionMapOptions& mo) {
  namespace co = coordination;
  std::vector<ros::Marker> out;
  if (agents.empty()) return out;
  const double h = co::effective_node_spacing(agents, mo);
  int id = 0;
  for (std::size_t p = 0; p < r.order.size(); ++p) {
    for (std::size_t q = p + 1; q < r.order.size(); ++q) {
      const int hi = r.order[p], lo = r.order[q];
      const auto& A = agents[static_cast<std::size_t>(hi)];
      const auto& B = agents[static_cast<std::size_t>(lo)];
      for (const auto& b : co::collision_boxes(A, hi, B, lo, h, mo)) {
        ros::Marker m;
        m.ns = "robot_" + std::to_string(B.id) + " vs robot_" + std::to_string(A.id);
        m.id = id++;
        m.type = ros::Marker::kLineStrip;
        m.scale = {2.0 * B.radius, 0, 0};
        m.color = {0.84F, 0.15F, 0.16F, 0.35F};
        const double len = B.path.length();
        const int steps = 16;
        for (int k = 0; k <= steps; ++k) {
          const double s = len * (b.l_s + (b.l_e - b.l_s) * k / steps);
          const Vec2 pt = B.path.point_at_arc(s);
          m.points.push_back({pt.x, pt.y, 0.0});
        }
        ros::Marker text;
        text.ns = m.ns + " label";
        text.id = id++;
        text.type = ros::Marker::kTextViewFacing;
        const Vec2 mid = B.path.point_at_arc(len * 0.5 * (b.l_s + b.l_e));
        text.pose = ros::Pose::from({mid, 0.0});
        text.scale = {0, 0, 0.3};
        text.color = {0.0F, 0.0F, 0.0F, 1.0F};
        char buf[96];
        std::snprintf(buf, sizeof buf, "%d vs %d: M %.2f s, D %.2f s", B.id, A.id, b.m(),
                      b.t4 - b.t2);
        text.text = buf;
        out.push_back(std::move(m));
        out.push_back(std::move(text));
      }
    }
  }
  return out;
}

}  // namespace voronav::bag
