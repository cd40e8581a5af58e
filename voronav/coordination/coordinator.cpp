#include "voronav/coordination/coordinator.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace voronav::coordination {

CoordinationResult coordinate(const std::vector<Agent>& agents, const CoordinateOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  CoordinationResult out;
  const MdNetwork net = build_network(agents, options.map);
  out.boxes = net.boxes().size();
  out.edf = bottom_level_edf(net);
  out.search = search_priority(net, options.search);
  out.order = out.search.order;
  Resolution res = out.search.resolution;
  const VerifyOptions vopt{options.map.at_start, options.map.at_goal, options.tolerance};
  std::vector<double> min_delays(agents.size(), 0.0);
  std::vector<int> rank(agents.size(), 0);
  for (std::size_t p = 0; p < out.order.size(); ++p)
    rank[static_cast<std::size_t>(out.order[p])] = static_cast<int>(p);
  while (res.status == ResolveStatus::kOk && options.verify) {
    const Verification v = verify_schedule(agents, res.delays, vopt);
    out.verified = true;
    if (v.valid) {
      out.valid = true;
      break;
    }
    if (v.conflicts.empty() || out.repairs >= options.max_repairs) {
      out.remaining = v.conflicts;
      break;
    }
    const Conflict& c = v.conflicts.front();
    out.missed.push_back(c);
    ++out.repairs;
    const int low =
        rank[static_cast<std::size_t>(c.a)] > rank[static_cast<std::size_t>(c.b)] ? c.a : c.b;
    const Agent& lo = agents[static_cast<std::size_t>(low)];
    const double step = std::max(0.05, (agents[static_cast<std::size_t>(c.a)].radius +
                                        agents[static_cast<std::size_t>(c.b)].radius) /
                                           lo.path.limits().v_max);
    min_delays[static_cast<std::size_t>(low)] = res.delays[static_cast<std::size_t>(low)] + step;
    res = resolve(net, out.order, min_delays);
  }
  out.status = res.status;
  out.delays = res.delays;
  out.arrivals = res.completion;
  out.makespan = res.makespan;
  out.sum_of_arrivals = res.sum_of_arrivals;
  if (res.status != ResolveStatus::kOk) {
    out.valid = false;
    out.message = "no delay-only schedule for this order: robot " +
                  std::to_string(agents[static_cast<std::size_t>(res.blocked)].id) +
                  " cannot wait out robot " +
                  std::to_string(agents[static_cast<std::size_t>(res.blocked_by)].id) +
                  " (a start or goal lies on the other's path)";
  } else if (!options.verify) {
    out.message = "not verified";
  } else if (out.valid) {
    out.message = out.repairs == 0 ? "ok"
                                   : "ok after repairing " + std::to_string(out.repairs) +
                                         " conflicts the collision boxes missed";
  } else {
    out.message = "the continuous-time check found overlaps that could not be repaired";
  }
  out.time_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace voronav::coordination
