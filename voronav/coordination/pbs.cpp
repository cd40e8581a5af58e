#include "voronav/coordination/pbs.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "voronav/core/error.hpp"
#include "voronav/planning/grid_planner.hpp"
#include "voronav/planning/planner_factory.hpp"

namespace voronav::coordination {

namespace {

struct Box {
  double x0 = kInfinity, y0 = kInfinity, x1 = -kInfinity, y1 = -kInfinity;
};

Box bounds(const Trajectory& tr) {
  Box b;
  for (const Piece& p : tr.pieces) {
    for (const Vec2 q : {p.at(p.t0), p.at(p.t1)}) {
      b.x0 = std::min(b.x0, q.x);
      b.y0 = std::min(b.y0, q.y);
      b.x1 = std::max(b.x1, q.x);
      b.y1 = std::max(b.y1, q.y);
    }
  }
  return b;
}

struct Collision {
  int a = 0, b = 0;  // a < b
  double time = 0.0;
};

struct Node {
  std::vector<std::vector<int>> higher;  // higher[k]: robots put directly above k
  std::vector<std::vector<TimedWaypoint>> plans;
  std::vector<Trajectory> traj;
  std::vector<Box> box;
  std::vector<Collision> collisions;
  double cost = 0.0;
  std::size_t pairs = 0;
};

class Pbs {
 public:
  Pbs(const BinaryGrid& blocked, const std::vector<SippRobot>& robots, const PbsOptions& o)
      : robots_(robots), o_(o), g_(blocked.geometry()) {
    for (const auto& r : robots) {
      rmax_ = std::max(rmax_, r.radius);
      if (!inflated_.count(r.radius))
        inflated_.emplace(r.radius, planning::make_planning_grid(blocked, r.radius));
    }
    earliest_.assign(robots.size(), 0.0);
    if (o_.soft_obstacles && o_.sipp.at_goal == AtGoal::kStay) {
      auto planner =
          planning::make_planner(planning::PlannerKind::kAStar, planning::PlannerOptions{});
      for (std::size_t j = 0; j < robots.size(); ++j) {
        const auto res =
            planner->plan(inflated_.at(robots[j].radius), robots[j].start, robots[j].goal);
        if (res.ok()) earliest_[j] = res.length_cells * g_.resolution / robots[j].v_max;
      }
    }
  }

  PbsResult run() {
    const auto t0 = std::chrono::steady_clock::now();
    const std::size_t n = robots_.size();
    PbsResult out;
    auto root = std::make_unique<Node>();
    root->higher.assign(n, {});
    root->plans.assign(n, {});
    root->traj.assign(n, {});
    root->box.assign(n, {});
    for (std::size_t k = 0; k < n; ++k) {
      if (!replan(*root, static_cast<int>(k), out)) {
        out.message = "robot index " + std::to_string(k) + " has no plan even alone";
        return out;
      }
    }
    for (std::size_t a = 0; a < n; ++a) {
      for (std::size_t b = a + 1; b < n; ++b)
        test(*root, static_cast<int>(a), static_cast<int>(b));
    }
    finish(*root);
    std::vector<std::unique_ptr<Node>> stack;
    stack.push_back(std::move(root));
    while (!stack.empty()) {
      std::unique_ptr<Node> node = std::move(stack.back());
      stack.pop_back();
      if (node->collisions.empty()) return solution(*node, out);
      if (out.nodes_expanded >= o_.max_nodes) {
        out.message = "PBS node budget (" + std::to_string(o_.max_nodes) + ") exhausted";
        return out;
      }
      if (std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() >
          o_.time_limit_s) {
        out.message = "PBS time budget exhausted";
        return out;
      }
      ++out.nodes_expanded;
      const Collision c =
          *std::min_element(node->collisions.begin(), node->collisions.end(),
                            [](const Collision& x, const Collision& y) { return x.time < y.time; });
      std::vector<std::unique_ptr<Node>> children;
      for (const auto& [hi, lo] : {std::pair{c.a, c.b}, std::pair{c.b, c.a}}) {
        if (above(*node, lo, hi)) continue;  // lo is already above hi: the pair closes a cycle
        auto child = std::make_unique<Node>(*node);
        child->higher[static_cast<std::size_t>(lo)].push_back(hi);
        ++child->pairs;
        if (update(*child, lo, out)) {
          ++out.nodes_generated;
          children.push_back(std::move(child));
        }
      }
      std::sort(children.begin(), children.end(),
                [](const auto& x, const auto& y) { return x->cost > y->cost; });
      for (auto& ch : children)
        stack.push_back(std::move(ch));
    }
    out.message = "PBS search space exhausted: no priority pairs resolve every collision";
    return out;
  }

 private:
  /// True when `a` is transitively above `b` in the node's pairs.
  bool above(const Node& n, int a, int b) const {
    std::vector<char> seen(robots_.size(), 0);
    std::vector<int> todo{b};
    while (!todo.empty()) {
      const int k = todo.back();
      todo.pop_back();
      for (const int h : n.higher[static_cast<std::size_t>(k)]) {
        if (h == a) return true;
        if (!seen[static_cast<std::size_t>(h)]) {
          seen[static_cast<std::size_t>(h)] = 1;
          todo.push_back(h);
        }
      }
    }
    return false;
  }

  /// Every robot transitively above k.
  std::vector<int> all_above(const Node& n, int k) const {
    std::vector<char> seen(robots_.size(), 0);
    std::vector<int> todo{k}, out;
    while (!todo.empty()) {
      const int x = todo.back();
      todo.pop_back();
      for (const int h : n.higher[static_cast<std::size_t>(x)]) {
        if (!seen[static_cast<std::size_t>(h)]) {
          seen[static_cast<std::size_t>(h)] = 1;
          out.push_back(h);
          todo.push_back(h);
        }
      }
    }
    return out;
  }

  /// Exact collision test of robots a and b in the node; records it.
  bool test(Node& n, int a, int b) {
    const std::size_t i = static_cast<std::size_t>(std::min(a, b));
    const std::size_t j = static_cast<std::size_t>(std::max(a, b));
    const Trajectory &ta = n.traj[i], &tb = n.traj[j];
    const double lo = std::max(ta.present_from, tb.present_from);
    const double hi = std::min(ta.present_to, tb.present_to);
    if (lo > hi || (lo == hi && (ta.half_open || tb.half_open))) return false;
    const double rsum = robots_[i].radius + robots_[j].radius;
    const Box &p = n.box[i], &q = n.box[j];
    const double dx = std::max({0.0, p.x0 - q.x1, q.x0 - p.x1});
    const double dy = std::max({0.0, p.y0 - q.y1, q.y0 - p.y1});
    if (std::hypot(dx, dy) >= rsum - o_.tolerance) return false;
    const MinDistance d = first_below(ta, tb, lo, hi, rsum - o_.tolerance);
    if (!(d.distance < rsum - o_.tolerance)) return false;
    n.collisions.push_back({static_cast<int>(i), static_cast<int>(j), d.time});
    return true;
  }

  bool replan(Node& n, int k, PbsResult& out) {
    const std::size_t m = robots_.size();
    const SippRobot& r = robots_[static_cast<std::size_t>(k)];
    Reservations res(g_, rmax_);
    const std::vector<int> above_k = all_above(n, k);
    for (const int h : above_k)
      res.add(n.traj[static_cast<std::size_t>(h)], robots_[static_cast<std::size_t>(h)].radius);
    // Soft obstacles of the robots not above k (owner j: j's start while it gets away, under
    // wait; owner m + j: j's goal from its earliest arrival on, under stay): k keeps off them
    // when it can, so that ordering k above j later does not leave j without a plan.
    const bool soft = o_.soft_obstacles &&
                      (o_.sipp.at_start == AtStart::kWait || o_.sipp.at_goal == AtGoal::kStay);
    std::vector<char> tier0(2 * m, 0), tier1(2 * m, 1), none(2 * m, 1);
    if (soft) {
      tier0[static_cast<std::size_t>(k)] = tier0[m + static_cast<std::size_t>(k)] = 1;
      for (const int h : above_k)
        tier0[static_cast<std::size_t>(h)] = tier0[m + static_cast<std::size_t>(h)] = 1;
      for (std::size_t j = 0; j < m; ++j) {
        if (tier0[j]) continue;
        const SippRobot& q = robots_[j];
        if (o_.sipp.at_start == AtStart::kWait) {
          res.add_soft(g_.cell_center(q.start), q.radius, 0.0, 2.0 * g_.resolution / q.v_max,
                       static_cast<int>(j));
          tier1[j] = 0;
        }
        if (o_.sipp.at_goal == AtGoal::kStay)
          res.add_soft(g_.cell_center(q.goal), q.radius, earliest_[j], kInfinity,
                       static_cast<int>(m + j));
      }
    }
    SippStats st;
    SippOptions so = o_.sipp;
    std::optional<std::vector<TimedWaypoint>> plan;
    for (const std::vector<char>* inactive : {&tier0, &tier1, &none}) {
      if (!soft && inactive != &none) continue;
      so.inactive_owners = inactive;
      plan = sipp_plan(inflated_.at(r.radius), r.start, r.goal, r.radius, r.v_max, res, so, &st);
      ++out.replans;
      if (plan) break;
    }
    out.expansions += st.expansions;
    if (!plan) return false;
    const std::size_t kk = static_cast<std::size_t>(k);
    n.traj[kk] = trajectory_of(*plan, o_.sipp.at_start, o_.sipp.at_goal);
    n.box[kk] = bounds(n.traj[kk]);
    n.plans[kk] = std::move(*plan);
    return true;
  }

  /// Ma et al.'s UpdatePlan: replans `lo` and, in a topological order, every robot below it that
  /// collides with a robot above it. False when some robot has no plan.
  bool update(Node& n, int lo, PbsResult& out) {
    const std::size_t m = robots_.size();
    // Robots below lo (transitively), lo included.
    std::vector<std::vector<int>> lower(m);
    for (std::size_t k = 0; k < m; ++k) {
      for (const int h : n.higher[k])
        lower[static_cast<std::size_t>(h)].push_back(static_cast<int>(k));
    }
    std::vector<char> in(m, 0);
    std::vector<int> todo{lo}, set;
    in[static_cast<std::size_t>(lo)] = 1;
    while (!todo.empty()) {
      const int x = todo.back();
      todo.pop_back();
      set.push_back(x);
      for (const int l : lower[static_cast<std::size_t>(x)]) {
        if (!in[static_cast<std::size_t>(l)]) {
          in[static_cast<std::size_t>(l)] = 1;
          todo.push_back(l);
        }
      }
    }
    // Kahn's topological order of the set (higher first).
    std::vector<int> indeg(m, 0);
    for (const int x : set) {
      for (const int h : n.higher[static_cast<std::size_t>(x)])
        if (in[static_cast<std::size_t>(h)]) ++indeg[static_cast<std::size_t>(x)];
    }
    std::vector<int> ready;
    for (const int x : set)
      if (indeg[static_cast<std::size_t>(x)] == 0) ready.push_back(x);
    std::vector<char> replanned(m, 0);
    while (!ready.empty()) {
      std::sort(ready.begin(), ready.end(), std::greater<>());
      const int x = ready.back();
      ready.pop_back();
      bool need = x == lo;
      if (!need) {
        for (const int h : all_above(n, x)) {
          if (colliding(n, x, h)) {
            need = true;
            break;
          }
        }
      }
      if (need) {
        if (!replan(n, x, out)) return false;
        replanned[static_cast<std::size_t>(x)] = 1;
        // Its old collisions are void; test it again against everyone.
        std::erase_if(n.collisions, [&](const Collision& c) { return c.a == x || c.b == x; });
        for (std::size_t k = 0; k < m; ++k)
          if (static_cast<int>(k) != x) test(n, x, static_cast<int>(k));
      }
      for (const int l : lower[static_cast<std::size_t>(x)]) {
        if (in[static_cast<std::size_t>(l)] && --indeg[static_cast<std::size_t>(l)] == 0)
          ready.push_back(l);
      }
    }
    finish(n);
    return true;
  }

  bool colliding(const Node& n, int a, int b) const {
    const int i = std::min(a, b), j = std::max(a, b);
    return std::any_of(n.collisions.begin(), n.collisions.end(),
                       [&](const Collision& c) { return c.a == i && c.b == j; });
  }

  void finish(Node& n) const {
    double sum = 0.0, mk = 0.0;
    for (const auto& p : n.plans) {
      sum += p.back().t;
      mk = std::max(mk, p.back().t);
    }
    n.cost = o_.objective == Objective::kMakespan ? mk + 1e-6 * sum : sum;
  }

  PbsResult& solution(const Node& n, PbsResult& out) const {
    const std::size_t m = robots_.size();
    out.ok = true;
    out.plans = n.plans;
    out.priority_pairs = n.pairs;
    for (const auto& p : n.plans) {
      out.arrivals.push_back(p.back().t);
      out.makespan = std::max(out.makespan, p.back().t);
      out.sum_of_arrivals += p.back().t;
    }
    // A total order consistent with the pairs (Kahn, smallest index first).
    std::vector<int> indeg(m, 0);
    std::vector<std::vector<int>> lower(m);
    for (std::size_t k = 0; k < m; ++k) {
      indeg[k] = static_cast<int>(n.higher[k].size());
      for (const int h : n.higher[k])
        lower[static_cast<std::size_t>(h)].push_back(static_cast<int>(k));
    }
    std::vector<int> ready;
    for (std::size_t k = 0; k < m; ++k)
      if (indeg[k] == 0) ready.push_back(static_cast<int>(k));
    while (!ready.empty()) {
      std::sort(ready.begin(), ready.end(), std::greater<>());
      const int x = ready.back();
      ready.pop_back();
      out.order.push_back(x);
      for (const int l : lower[static_cast<std::size_t>(x)])
        if (--indeg[static_cast<std::size_t>(l)] == 0) ready.push_back(l);
    }
    out.message = "ok";
    return out;
  }

  const std::vector<SippRobot>& robots_;
  const PbsOptions& o_;
  const GridGeometry& g_;
  double rmax_ = 0.0;
  std::map<double, BinaryGrid> inflated_;
  std::vector<double> earliest_;  // shortest travel time per robot [s]
};

}  // namespace

PbsResult plan_pbs(const BinaryGrid& blocked, const std::vector<SippRobot>& robots,
                   const PbsOptions& options) {
  if (robots.empty()) return PbsResult{true, {}, {}, 0.0, 0.0, {}, 0, 0, 0, 0, 0, "ok"};
  if (!(options.time_limit_s > 0.0)) throw Error("pbs time limit", 0, "expected > 0 s");
  Pbs pbs(blocked, robots, options);
  return pbs.run();
}

}  // namespace voronav::coordination
