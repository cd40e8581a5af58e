// Helpers shared by the translation units of sim::RobotAgent (robot_agent.cpp, the decentralized
// protocol files decentralized_*.cpp and centralized_protocol.cpp). Not a public header.
#pragma once

#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "voronav/network/messages.hpp"
#include "voronav/sim/robot_agent.hpp"

// Trace points of the protocol (compiled out; the library does no I/O).
#ifdef VORONAV_NS_TRACE
#include <cstdio>
#define NS_DEBUG(...) std::fprintf(stderr, __VA_ARGS__)
#else
#define NS_DEBUG(...) ((void)0)
#endif

namespace voronav::sim::agent_detail {

inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
inline constexpr std::uint32_t kRepairFlag = 0x80000000u;
/// PathMessage::exit_index of a Repair answer sent by a relay that sensed the break
/// (repair_sense_walk); Repair answers use no exit index otherwise (they join by position).
inline constexpr std::uint32_t kSensedAnswer = 0xFFFFFFFFu;
/// PathMessage::exit_index of the short notices of a relay's sensing walk (repair_sense_walk, no
/// points; `num` is the Repair's with kRepairFlag): it walks to sense the break, or it gave up
/// without a way.
inline constexpr std::uint32_t kSenseWalking = 0xFFFFFFFEu;
inline constexpr std::uint32_t kSenseGaveUp = 0xFFFFFFFDu;

inline std::uint64_t key_of(network::RobotId origin, std::uint32_t id) {
  return (static_cast<std::uint64_t>(origin.value) << 32) | id;
}

inline double path_len(Vec2 from, const std::vector<Vec2>& w) {
  double l = 0.0;
  for (Vec2 p : w) {
    l += distance(from, p);
    from = p;
  }
  return l;
}

}  // namespace voronav::sim::agent_detail

namespace voronav::sim {

/// Runs f() and adds its CPU time to the robot's computation (eq. 8/9).
template <typename F>
auto RobotAgent::timed(F&& f) {
  const auto t0 = std::chrono::steady_clock::now();
  auto out = f();
  report_.metrics.cpu_s +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace voronav::sim
