#include "voronav/coordination/priority_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <random>
#include <string>

#include "voronav/coordination/internal/critical_moves.hpp"
#include "voronav/coordination/internal/ga_operators.hpp"
#include "voronav/coordination/internal/strided_threads.hpp"
#include "voronav/core/error.hpp"

namespace voronav::coordination {

namespace {
constexpr double kEps = 1e-9;

std::vector<int> concat(const std::vector<int>& a, const std::vector<int>& b) {
  std::vector<int> out(a);
  out.insert(out.end(), b.begin(), b.end());
  return out;
}

void check_split(const MdNetwork& net, const std::vector<int>& searched,
                 const std::vector<int>& suffix) {
  check_order(concat(searched, suffix), net.size());
}

/// c(i, j) of the EDF scheduler, summed over the boxes of i and j.
double edf_cost(const MdNetwork& net, int i, int j, EdfCost kind) {
  double c = 0.0;
  for (const int k : net.incident(i)) {
    const MdBox& b = net.boxes()[static_cast<std::size_t>(k)];
    if (b.a != j && b.b != j) continue;
    const auto [m, d] = net.oriented(k, j);
    if (kind == EdfCost::kSharedTime) {
      c += m + d;
    } else if (m > kTimeEpsilon && d > kTimeEpsilon) {
      c += d;
    }
  }
  return c;
}
}  // namespace

bool better(const Resolution& a, const Resolution& b) {
  if (a.makespan < b.makespan - kEps) return true;
  if (a.makespan > b.makespan + kEps) return false;
  return a.sum_of_arrivals < b.sum_of_arrivals - kEps;
}

EdfResult bottom_level_edf(const MdNetwork& net, const EdfOptions& options) {
  const int n = net.size();
  EdfResult r;
  for (const double t : net.travel_times())
    r.deadline = std::max(r.deadline, t);
  std::vector<int> ug(static_cast<std::size_t>(n));
  std::iota(ug.begin(), ug.end(), 0);
  std::vector<double> cost(static_cast<std::size_t>(n) * static_cast<std::size_t>(n), 0.0);
  for (int i = 0; i < n; ++i) {
    for (const int k : net.incident(i)) {
      const MdBox& b = net.boxes()[static_cast<std::size_t>(k)];
      const int j = b.a == i ? b.b : b.a;
      cost[static_cast<std::size_t>(i * n + j)] = edf_cost(net, i, j, options.cost);
    }
  }
  while (!ug.empty()) {
    EdfRound round;
    round.urgent_group = ug;
    round.completion.assign(static_cast<std::size_t>(n), std::numeric_limits<double>::quiet_NaN());
    int best = -1;
    double best_slack = -kInfinity;
    for (const int i : ug) {
      double t = net.travel_times()[static_cast<std::size_t>(i)];
      for (const int j : ug) {
        if (j != i) t += cost[static_cast<std::size_t>(i * n + j)];
      }
      round.completion[static_cast<std::size_t>(i)] = t;
      const double slack = r.deadline - t;
      if (slack >= -kEps && slack > best_slack + kEps) {
        best_slack = slack;
        best = i;
      }
    }
    round.removed = best;
    r.rounds.push_back(round);
    if (best < 0) break;
    r.removal_order.push_back(best);
    ug.erase(std::find(ug.begin(), ug.end(), best));
  }
  r.urgent_group = ug;
  // Most urgent (smallest slack = largest completion) first.
  std::vector<int> sorted = ug;
  if (!r.rounds.empty()) {
    const auto& last = r.rounds.back().completion;
    std::stable_sort(sorted.begin(), sorted.end(), [&](int a, int b) {
      return last[static_cast<std::size_t>(a)] > last[static_cast<std::size_t>(b)];
    });
  }
  r.order = sorted;
  for (auto it = r.removal_order.rbegin(); it != r.removal_order.rend(); ++it)
    r.order.push_back(*it);
  return r;
}

std::string_view to_string(SearchKind k) {
  switch (k) {
    case SearchKind::kNone:
      return "none";
    case SearchKind::kExhaustive:
      return "exhaustive";
    case SearchKind::kEdf:
      return "edf";
    case SearchKind::kGa:
      return "ga";
  }
  return "?";
}

std::string_view to_string(ThreeOptOrder o) {
  switch (o) {
    case ThreeOptOrder::kPaper:
      return "paper";
    case ThreeOptOrder::kCriticalFirst:
      return "critical-first";
    case ThreeOptOrder::kCriticalDelayed:
      return "critical-delayed";
  }
  return "?";
}

ThreeOptOrder parse_three_opt_order(std::string_view s) {
  if (s == "paper") return ThreeOptOrder::kPaper;
  if (s == "critical-first") return ThreeOptOrder::kCriticalFirst;
  if (s == "critical-delayed") return ThreeOptOrder::kCriticalDelayed;
  throw Error("--ga-three-opt-order", 0,
              "expected paper|critical-first|critical-delayed, got '" + std::string(s) + "'");
}

GaOptions ga_preset(std::string_view name) {
  GaOptions o;
  if (name == "paper") return o;
  if (name == "fast") {
    o.three_opt_order = ThreeOptOrder::kCriticalDelayed;
    o.delayed_gate = 10;
    o.stall_generations = 2;
    o.ils_patience = 15;
    o.ils_kick = 2;
    o.ils_evaluations = 250000;
    o.threads = 2;
    return o;
  }
  throw Error("--ga-preset", 0, "expected paper|fast, got '" + std::string(name) + "'");
}

SearchKind parse_search_kind(std::string_view s) {
  if (s == "none") return SearchKind::kNone;
  if (s == "exhaustive") return SearchKind::kExhaustive;
  if (s == "edf") return SearchKind::kEdf;
  if (s == "ga") return SearchKind::kGa;
  throw Error("--search", 0, "expected none|exhaustive|edf|ga, got '" + std::string(s) + "'");
}

// ---------------------------------------------------------------------------------------------
// Exhaustive search: depth-first over the orders of `searched`, with the delays of the placed
// prefix kept incrementally, pruned by a lower bound on (makespan, sum of arrivals).

namespace {

struct Exhaustive {
  const MdNetwork& net;
  std::vector<int> searched;
  std::vector<int> suffix;
  std::vector<int> prefix;
  std::vector<char> placed;
  std::vector<double> delays;
  Resolution best;
  std::vector<int> best_order;
  std::size_t evaluations = 0;
  double suffix_travel_max = 0.0;
  double suffix_travel_sum = 0.0;

  /// The smallest delay of robot i against the placed robots; infinity if none exists.
  double delay_of(int i) const {
    double delay = 0.0;
    bool changed = true;
    while (changed) {
      changed = false;
      for (const int k : net.incident(i)) {
        const MdBox& b = net.boxes()[static_cast<std::size_t>(k)];
        const int j = b.a == i ? b.b : b.a;
        if (!placed[static_cast<std::size_t>(j)]) continue;
        const auto [m, d] = net.oriented(k, j, delays[static_cast<std::size_t>(j)], delay);
        if (m > kTimeEpsilon && d > kTimeEpsilon) {
          if (std::isinf(d)) return kInfinity;
          delay += d;
          changed = true;
        }
      }
    }
    return delay;
  }

  void dfs(double mk, double sum) {
    if (prefix.size() == searched.size()) {
      ++evaluations;
      Resolution r = resolve(net, concat(prefix, suffix));
      if (best_order.empty() || better(r, best)) {
        best = std::move(r);
        best_order = concat(prefix, suffix);
      }
      return;
    }
    double rest_max = suffix_travel_max, rest_sum = suffix_travel_sum;
    for (const int i : searched) {
      if (placed[static_cast<std::size_t>(i)]) continue;
      rest_max = std::max(rest_max, net.travel_times()[static_cast<std::size_t>(i)]);
      rest_sum += net.travel_times()[static_cast<std::size_t>(i)];
    }
    const double lb_mk = std::max(mk, rest_max);
    if (!best_order.empty()) {
      if (lb_mk > best.makespan + kEps) return;
      if (lb_mk >= best.makespan - kEps && sum + rest_sum >= best.sum_of_arrivals - kEps) return;
    }
    for (const int i : searched) {
      if (placed[static_cast<std::size_t>(i)]) continue;
      const double d = delay_of(i);
      if (std::isinf(d)) continue;
      const double c = net.travel_times()[static_cast<std::size_t>(i)] + d;
      placed[static_cast<std::size_t>(i)] = 1;
      delays[static_cast<std::size_t>(i)] = d;
      prefix.push_back(i);
      dfs(std::max(mk, c), sum + c);
      prefix.pop_back();
      placed[static_cast<std::size_t>(i)] = 0;
      delays[static_cast<std::size_t>(i)] = 0.0;
    }
  }
};

}  // namespace

SearchResult exhaustive_search(const MdNetwork& net, const std::vector<int>& searched,
                               const std::vector<int>& suffix) {
  check_split(net, searched, suffix);
  Exhaustive ex{net, searched, suffix, {}, {}, {}, {}, {}, 0, 0.0, 0.0};
  ex.placed.assign(static_cast<std::size_t>(net.size()), 0);
  ex.delays.assign(static_cast<std::size_t>(net.size()), 0.0);
  for (const int i : suffix) {
    ex.suffix_travel_max =
        std::max(ex.suffix_travel_max, net.travel_times()[static_cast<std::size_t>(i)]);
    ex.suffix_travel_sum += net.travel_times()[static_cast<std::size_t>(i)];
  }
  ex.dfs(0.0, 0.0);
  SearchResult r;
  if (ex.best_order.empty()) {  // every order is blocked: report the plain order's status
    r.order = concat(searched, suffix);
    r.resolution = resolve(net, r.order);
  } else {
    r.order = ex.best_order;
    r.resolution = ex.best;
  }
  r.urgent_group = searched;
  r.evaluations = std::max<std::size_t>(ex.evaluations, 1);
  return r;
}

// ---------------------------------------------------------------------------------------------
// Genetic algorithm (sections 4.2.2 and 5.1). Orders are sequences of local indices 0..n-1 into
// `searched`; the suffix is appended for evaluation.

namespace {

class Ga {
 public:
  Ga(const MdNetwork& net, const std::vector<int>& searched, const std::vector<int>& suffix,
     const GaOptions& o)
      : net_(net),
        searched_(searched),
        suffix_(suffix),
        o_(o),
        rng_(o.seed),
        n_(static_cast<int>(searched.size())),
        ops_(n_, reconnection_weights(net, searched)),
        evaluator_(net) {}

  /// The greedy reconnection weight of edge a -> b (local indices): k0 = M + D summed over the
  /// boxes of a and b (a box no delay resolves counts 1e9).
  static std::vector<double> reconnection_weights(const MdNetwork& net,
                                                  const std::vector<int>& searched) {
    const int n = static_cast<int>(searched.size());
    std::vector<double> weight(static_cast<std::size_t>(n * n), 0.0);
    std::vector<int> local(static_cast<std::size_t>(net.size()), -1);
    for (int a = 0; a < n; ++a)
      local[static_cast<std::size_t>(searched[static_cast<std::size_t>(a)])] = a;
    for (const MdBox& b : net.boxes()) {
      const int la = local[static_cast<std::size_t>(b.a)];
      const int lb = local[static_cast<std::size_t>(b.b)];
      if (la < 0 || lb < 0) continue;
      const double k0 = std::isfinite(b.m + b.d) ? b.m + b.d : 1e9;
      weight[static_cast<std::size_t>(la * n + lb)] += k0;
      weight[static_cast<std::size_t>(lb * n + la)] += k0;
    }
    return weight;
  }

  struct Individual {
    std::vector<int> seq;
    Resolution res;
  };

  Individual make(std::vector<int> seq) {
    Individual ind{std::move(seq), {}};
    ind.res = evaluate(ind.seq);
    return ind;
  }

  Resolution evaluate(const std::vector<int>& seq) {
    ++evaluations_;
    std::vector<int> order;
    order.reserve(seq.size() + suffix_.size());
    for (const int l : seq)
      order.push_back(searched_[static_cast<std::size_t>(l)]);
    order.insert(order.end(), suffix_.begin(), suffix_.end());
    return resolve(net_, order);
  }

  /// The full order (searched robots, then the suffix) of a local sequence.
  void full_order(const std::vector<int>& seq, std::vector<int>& order) const {
    order.clear();
    for (const int l : seq)
      order.push_back(searched_[static_cast<std::size_t>(l)]);
    order.insert(order.end(), suffix_.begin(), suffix_.end());
  }

  int uniform(int lo, int hi) { return internal::uniform(rng_, lo, hi); }
  double unit() { return std::uniform_real_distribution<double>(0.0, 1.0)(rng_); }

  int three_opt_budget() const {
    return o_.three_opt_iterations > 0 ? o_.three_opt_iterations : n_ * (n_ - 1);
  }

  /// Evaluates the move seq -> cand (positions [from, to) differ) and takes it when better.
  bool try_move(Individual& ind, std::vector<int>& cand, std::vector<int>& base_order,
                std::vector<int>& cand_order, int from, int to) {
    // Only positions [from, to) change robots: the evaluator resolves again only the robots
    // whose higher neighbours changed (MoveEvaluator), and stops as soon as the candidate's
    // makespan exceeds the current one (it cannot be better then).
    full_order(cand, cand_order);
    ++evaluations_;
    Resolution r =
        evaluator_.resolve_move(base_order, ind.res, cand_order, from, to, ind.res.makespan + kEps);
    if (r.cut || !better(r, ind.res)) return false;
    ind.seq.swap(cand);
    ind.res = std::move(r);
    base_order.swap(cand_order);
    ++improvements_;
    return true;
  }

  /// 3-opt for the asymmetric case: move a segment to another place without reversing it
  /// (the only 3-opt move that keeps every edge's direction). First improvement, random moves.
  /// With `until_feasible`, stops as soon as the order has a delay schedule.
  int three_opt_random(Individual& ind, int budget, bool until_feasible) {
    std::vector<int> cand;
    std::vector<int> base_order, cand_order;
    full_order(ind.seq, base_order);
    int from = 0, to = 0, it = 0;
    for (; it < budget; ++it) {
      if (until_feasible && ind.res.status == ResolveStatus::kOk) break;
      if (!internal::GaOperators::segment_move(ind.seq, rng_, cand, from, to)) continue;
      try_move(ind, cand, base_order, cand_order, from, to);
    }
    return it;
  }

  /// Critical-first 3-opt (ThreeOptOrder::kCriticalFirst): the moves of critical_moves() in
  /// order, first improvement, until none improves (a local optimum) or the budget is spent.
  void three_opt_critical(Individual& ind) {
    int budget = three_opt_budget();
    std::vector<int> cand, base_order, cand_order;
    std::vector<int> rank(static_cast<std::size_t>(net_.size()), 0);
    int from = 0, to = 0;
    while (budget > 0) {
      full_order(ind.seq, base_order);
      for (int p = 0; p < net_.size(); ++p)
        rank[static_cast<std::size_t>(base_order[static_cast<std::size_t>(p)])] = p;
      const auto moves = internal::critical_moves(net_, n_, rank, ind.res, o_.three_opt_depth);
      bool improved = false;
      for (const auto& mv : moves) {
        if (budget <= 0) break;
        --budget;
        internal::apply_segment_move(ind.seq, mv, cand, from, to);
        if (try_move(ind, cand, base_order, cand_order, from, to)) {
          improved = true;
          break;
        }
      }
      if (improved) continue;
      if (o_.three_opt_order == ThreeOptOrder::kCriticalDelayed && !no_delayed_ &&
          ind.res.status == ResolveStatus::kOk && delayed_sweep(ind, rank, base_order, budget)) {
        continue;
      }
      if (ind.res.status != ResolveStatus::kOk) {
        // No listed move gives a delay schedule: random moves until one does.
        budget -= three_opt_random(ind, budget, true);
        if (ind.res.status == ResolveStatus::kOk) continue;
      }
      if (budget > 0 && o_.three_opt_patience > 0 && ind.res.status == ResolveStatus::kOk &&
          random_phase(ind, rank, base_order, budget)) {
        continue;
      }
      if (budget > 0) ++local_optima_;
      break;
    }
  }

  /// One sweep over internal::delayed_pairs() of the current order (ThreeOptOrder::
  /// kCriticalDelayed): for each pair (x, b) with b still above x, "x just above b", then "b just
  /// below x", each taken when it improves (makespan, sum of arrivals); the sweep goes on from
  /// the next pair with the new order. True when any move was taken.
  bool delayed_sweep(Individual& ind, std::vector<int>& rank, std::vector<int>& base_order,
                     int& budget) {
    std::vector<int> cand, cand_order;
    int from = 0, to = 0;
    bool any = false;
    for (const auto& pr : internal::delayed_pairs(net_, n_, rank, ind.res)) {
      for (int kind = 0; kind < 2 && budget > 0; ++kind) {
        const int px = rank[static_cast<std::size_t>(pr.x)];
        const int pb = rank[static_cast<std::size_t>(pr.b)];
        if (pb >= px || px >= n_) break;
        --budget;
        const internal::SegmentMove mv =
            kind == 0 ? internal::SegmentMove{px, px, pb} : internal::SegmentMove{pb, pb, px};
        internal::apply_segment_move(ind.seq, mv, cand, from, to);
        if (try_move(ind, cand, base_order, cand_order, from, to)) {
          ++delayed_improvements_;
          for (int p = from; p < to; ++p)
            rank[static_cast<std::size_t>(base_order[static_cast<std::size_t>(p)])] = p;
          any = true;
          break;
        }
      }
      if (budget <= 0) break;
    }
    return any;
  }

  /// Random segment moves that the exact cut cannot exclude, until one improves (true) or
  /// three_opt_patience evaluated moves in a row did not, or the budget is spent.
  bool random_phase(Individual& ind, const std::vector<int>& rank, std::vector<int>& base_order,
                    int& budget) {
    const int c = internal::critical_robot(ind.res, rank);
    if (c < 0) return false;
    internal::support_of(net_, rank, c, in_support_);
    std::vector<int> cand, cand_order;
    int fails = 0, from = 0, to = 0;
    internal::SegmentMove mv;
    while (budget > 0 && fails < o_.three_opt_patience) {
      --budget;
      if (!internal::random_segment_move(n_, rng_, mv)) continue;
      const auto bl = internal::swapped_blocks(mv);
      if (!internal::can_lower_makespan(net_, base_order, in_support_, bl.a_begin, bl.a_end,
                                        bl.b_end, scratch_)) {
        ++cut_moves_;
        continue;
      }
      internal::apply_segment_move(ind.seq, mv, cand, from, to);
      if (try_move(ind, cand, base_order, cand_order, from, to)) return true;
      ++fails;
    }
    return false;
  }

  /// GaOptions::polish_sweeps: sweeps over every single-robot segment move (robot at position p
  /// to position k != p of the rest; the paper's N (N - 1) moves, in a fixed order, no RNG), first
  /// improvement, the sweep going on from the next move with the new order; stops after a sweep
  /// that took no move or after polish_sweeps sweeps.
  void polish(Individual& ind, SearchResult& out) {
    std::vector<int> cand, base_order, cand_order;
    full_order(ind.seq, base_order);
    int from = 0, to = 0;
    for (int sweep = 0; sweep < o_.polish_sweeps; ++sweep) {
      ++out.polish_sweeps;
      bool any = false;
      for (int p = 0; p < n_; ++p) {
        for (int k = 0; k < n_; ++k) {
          if (k == p) continue;
          internal::apply_segment_move(ind.seq, internal::SegmentMove{p, p, k}, cand, from, to);
          if (try_move(ind, cand, base_order, cand_order, from, to)) {
            ++out.polish_improvements;
            any = true;
          }
        }
      }
      if (!any) break;
    }
  }

  /// One kick of the iterated local search (GaOptions::ils_patience): ils_kick random segment
  /// moves of `seq` (the paper's 3-opt draw, taken whatever they cost), then the child's 3-opt
  /// with `best` as the delayed gate (kCriticalDelayed: the sweeps only when critical-first brings
  /// the kick back to no worse than `best`); every draw from the stream `seed`.
  Individual make_kick(const std::vector<int>& seq, std::uint64_t seed, const Resolution& best) {
    rng_.seed(seed);
    std::vector<int> child(seq), cand;
    int from = 0, to = 0;
    for (int k = 0; k < o_.ils_kick; ++k) {
      while (!internal::GaOperators::segment_move(child, rng_, cand, from, to)) {
      }
      child.swap(cand);
    }
    Individual ind = make(std::move(child));
    three_opt(ind, &best);
    return ind;
  }

  /// GaOptions::ils_patience: steps of crossovers_per_generation kicks of `best` on the helpers
  /// (kick c on helper c mod T, its stream seed drawn here in kick order, so the result depends
  /// on neither T nor the threads' timing); the best kick of a step replaces `best` when better.
  /// Stops after ils_patience steps in a row without a better order, after max_rounds steps, or
  /// once the whole search has made ils_evaluations evaluations (0 = no such cap).
  void iterated_local_search(Individual& best, SearchResult& out,
                             std::vector<std::unique_ptr<Ga>>& helpers) {
    const int count = o_.crossovers_per_generation;
    std::vector<std::uint64_t> seeds(static_cast<std::size_t>(count));
    std::vector<Individual> kicks;
    auto evaluations = [&] {
      std::size_t e = evaluations_;
      for (const auto& h : helpers)
        e += h->evaluations_;
      return e;
    };
    int idle = 0;
    while (idle < o_.ils_patience && out.ils_steps < o_.max_rounds &&
           (o_.ils_evaluations == 0 || evaluations() < o_.ils_evaluations)) {
      for (auto& sd : seeds)
        sd = rng_();
      kicks.assign(static_cast<std::size_t>(count), Individual{});
      internal::run_strided(count, static_cast<int>(helpers.size()), [&](int t, int c) {
        kicks[static_cast<std::size_t>(c)] = helpers[static_cast<std::size_t>(t)]->make_kick(
            best.seq, seeds[static_cast<std::size_t>(c)], best.res);
      });
      ++out.ils_steps;
      std::size_t top = 0;
      for (std::size_t c = 1; c < kicks.size(); ++c)
        if (better(kicks[c].res, kicks[top].res)) top = c;
      if (better(kicks[top].res, best.res)) {
        best = std::move(kicks[top]);
        ++out.ils_improvements;
        idle = 0;
      } else {
        ++idle;
      }
    }
  }

  /// The resolution a child must match for the delayed sweeps (GaOptions::delayed_gate): the
  /// gate-th best of the population the parents come from; nullptr = no gate.
  const Resolution* gate_of(const std::vector<Individual>& pop, int pop_size) const {
    if (o_.delayed_gate <= 0 || o_.three_opt_order != ThreeOptOrder::kCriticalDelayed)
      return nullptr;
    return &pop[static_cast<std::size_t>(std::min(o_.delayed_gate, pop_size) - 1)].res;
  }

  /// The child's local search; with a gate (kCriticalDelayed), critical-first first and the
  /// delayed sweeps only when the child is then no worse than the gate.
  void three_opt(Individual& ind, const Resolution* gate = nullptr) {
    if (n_ < 3 || o_.three_opt_iterations < 0) return;
    if (gate != nullptr && o_.three_opt_order == ThreeOptOrder::kCriticalDelayed) {
      no_delayed_ = true;
      const std::size_t optima = local_optima_;
      three_opt_critical(ind);
      local_optima_ = optima;  // counted once, by the pass that ends the search
      no_delayed_ = false;
      if (!better(*gate, ind.res)) three_opt_critical(ind);
    } else if (o_.three_opt_order != ThreeOptOrder::kPaper) {
      three_opt_critical(ind);
    } else {
      three_opt_random(ind, three_opt_budget(), false);
    }
  }

  /// The order of one child from the main stream: two different parents drawn uniformly from the
  /// first pop_size individuals, DPX, then mutation with the mutation rate (the paper's GA, in the
  /// draw order both sequential paths share).
  std::vector<int> draw_child(const std::vector<Individual>& pop, int pop_size) {
    const int a = uniform(0, pop_size - 1);
    int b = uniform(0, pop_size - 2);
    if (b >= a) ++b;
    std::vector<int> child =
        ops_.dpx(pop[static_cast<std::size_t>(a)].seq, pop[static_cast<std::size_t>(b)].seq, rng_);
    if (unit() < o_.mutation_rate)
      child = ops_.mutate(child, o_.mutation_min_edges, o_.mutation_max_edges, rng_);
    return child;
  }

  /// One child of parents pa, pb: DPX, mutation with the mutation rate, 3-opt; every random
  /// draw from the stream `seed`.
  Individual make_child(const std::vector<int>& pa, const std::vector<int>& pb, std::uint64_t seed,
                        const Resolution* gate) {
    rng_.seed(seed);
    std::vector<int> child = ops_.dpx(pa, pb, rng_);
    if (unit() < o_.mutation_rate)
      child = ops_.mutate(child, o_.mutation_min_edges, o_.mutation_max_edges, rng_);
    Individual ind = make(std::move(child));
    three_opt(ind, gate);
    return ind;
  }

  /// The children of one generation with per-child RNG streams: the parents and a stream seed per
  /// child are drawn here (main stream, in child order); child c is made by helper c mod T. The
  /// result depends on neither T nor the threads' timing.
  void children_on_threads(const std::vector<Individual>& pop, int pop_size,
                           std::vector<Individual>& children,
                           std::vector<std::unique_ptr<Ga>>& helpers) {
    const int count = o_.crossovers_per_generation;
    std::vector<int> pa(static_cast<std::size_t>(count)), pb(static_cast<std::size_t>(count));
    std::vector<std::uint64_t> seeds(static_cast<std::size_t>(count));
    for (int c = 0; c < count; ++c) {
      const int a = uniform(0, pop_size - 1);
      int b = uniform(0, pop_size - 2);
      if (b >= a) ++b;
      pa[static_cast<std::size_t>(c)] = a;
      pb[static_cast<std::size_t>(c)] = b;
      seeds[static_cast<std::size_t>(c)] = rng_();
    }
    children.assign(static_cast<std::size_t>(count), Individual{});
    const Resolution* gate = gate_of(pop, pop_size);
    // An exception on a worker (bad_alloc, an Error) is rethrown here, on the caller's thread.
    internal::run_strided(count, static_cast<int>(helpers.size()), [&](int t, int c) {
      const auto uc = static_cast<std::size_t>(c);
      children[uc] = helpers[static_cast<std::size_t>(t)]->make_child(
          pop[static_cast<std::size_t>(pa[uc])].seq, pop[static_cast<std::size_t>(pb[uc])].seq,
          seeds[uc], gate);
    });
  }

  /// Advances the RNG past the draws of three_opt() in kPaper mode (three_opt_random() without
  /// until_feasible draws three_opt_budget() segment moves whatever the orders and the results).
  void skip_paper_three_opt_draws() {
    if (n_ < 3 || o_.three_opt_iterations < 0) return;
    internal::SegmentMove mv;
    const int budget = three_opt_budget();
    for (int it = 0; it < budget; ++it)
      (void)internal::random_segment_move(n_, rng_, mv);
  }

  /// GaOptions::workers: the children of one generation of the one-stream GA (threads == 0,
  /// kPaper) on worker threads, bit for bit the children of the sequential loop in run(). Each
  /// child's parents, crossover and mutation are drawn here in child order; its 3-opt then runs
  /// on helper c mod T from a copy of the stream taken just before its 3-opt draws, while the main
  /// stream skips those draws for the next child.
  void children_same_stream(const std::vector<Individual>& pop, int pop_size,
                            std::vector<Individual>& children,
                            std::vector<std::unique_ptr<Ga>>& helpers) {
    const int count = o_.crossovers_per_generation;
    std::vector<std::vector<int>> seqs(static_cast<std::size_t>(count));
    std::vector<internal::GaRng> streams(static_cast<std::size_t>(count));
    for (int c = 0; c < count; ++c) {
      seqs[static_cast<std::size_t>(c)] = draw_child(pop, pop_size);
      streams[static_cast<std::size_t>(c)] = rng_;
      skip_paper_three_opt_draws();
    }
    children.assign(static_cast<std::size_t>(count), Individual{});
    internal::run_strided(count, static_cast<int>(helpers.size()), [&](int t, int c) {
      const auto uc = static_cast<std::size_t>(c);
      Ga& h = *helpers[static_cast<std::size_t>(t)];
      h.rng_ = streams[uc];
      Individual ind = h.make(std::move(seqs[uc]));
      h.three_opt(ind, nullptr);
      children[uc] = std::move(ind);
    });
  }

  SearchResult run(const std::vector<int>& seed_order) {
    SearchResult out;
    out.urgent_group = searched_;
    std::vector<int> seed_local;
    if (!seed_order.empty()) {
      std::vector<int> local(static_cast<std::size_t>(net_.size()), -1);
      for (int a = 0; a < n_; ++a)
        local[static_cast<std::size_t>(searched_[static_cast<std::size_t>(a)])] = a;
      for (const int g : seed_order) {
        if (g < 0 || g >= net_.size() || local[static_cast<std::size_t>(g)] < 0) {
          throw Error("seed_order", 0, "robot " + std::to_string(g) + " is not searched");
        }
        seed_local.push_back(local[static_cast<std::size_t>(g)]);
      }
      if (static_cast<int>(seed_local.size()) != n_) {
        throw Error("seed_order", 0, "expected an order of all searched robots");
      }
    }
    const int pop_size = std::max(2, o_.population > 0 ? o_.population : n_);
    std::vector<Individual> pop;
    if (!seed_local.empty()) pop.push_back(make(seed_local));
    std::vector<int> base(static_cast<std::size_t>(n_));
    std::iota(base.begin(), base.end(), 0);
    while (static_cast<int>(pop.size()) < pop_size) {
      std::shuffle(base.begin(), base.end(), rng_);
      pop.push_back(make(base));
    }
    auto by_quality = [](const Individual& a, const Individual& b) { return better(a.res, b.res); };
    std::stable_sort(pop.begin(), pop.end(), by_quality);
    // Per-child RNG streams (threads >= 1): one Ga per thread makes children (its own RNG, reseeded
    // per child, and its own MoveEvaluator scratch).
    std::vector<std::unique_ptr<Ga>> helpers;
    const bool same_stream = o_.threads == 0 && o_.workers > 1;
    for (int t = 0; t < (same_stream ? o_.workers : o_.threads); ++t)
      helpers.push_back(std::make_unique<Ga>(net_, searched_, suffix_, o_));
    double prev = pop.front().res.makespan;
    const int elite = std::max(1, static_cast<int>(std::ceil(o_.elitism * pop_size)));
    int crossovers = 0;
    double stall_best = pop.front().res.makespan;
    int stall = 0;
    while (n_ >= 2 && out.rounds < o_.max_rounds) {
      std::vector<Individual> children;
      if (o_.threads > 0) {
        children_on_threads(pop, pop_size, children, helpers);
        crossovers += o_.crossovers_per_generation;
      } else if (same_stream) {
        children_same_stream(pop, pop_size, children, helpers);
        crossovers += o_.crossovers_per_generation;
      }
      for (int c = 0; c < o_.crossovers_per_generation && o_.threads == 0 && !same_stream; ++c) {
        Individual ind = make(draw_child(pop, pop_size));
        three_opt(ind, gate_of(pop, pop_size));
        children.push_back(std::move(ind));
        ++crossovers;
      }
      ++out.generations;
      std::vector<Individual> next;
      if (o_.truncation) {
        // Plain truncation (before issue #16): the best of the old population and the children.
        next.assign(pop.begin(), pop.begin() + elite);
        std::vector<Individual> pool(pop.begin() + elite, pop.end());
        for (auto& ch : children)
          pool.push_back(std::move(ch));
        std::stable_sort(pool.begin(), pool.end(), by_quality);
        for (auto& ind : pool) {
          if (static_cast<int>(next.size()) >= pop_size) break;
          const bool dup = std::any_of(next.begin(), next.end(),
                                       [&](const Individual& x) { return x.seq == ind.seq; });
          if (!dup) next.push_back(std::move(ind));
        }
      } else {
        // Elitism (section 4.2): the best `elite` survive unchanged; the children replace
        // non-elite members chosen at random, whatever their quality.
        next = std::move(pop);
        for (auto& ch : children) {
          if (elite >= pop_size) break;
          next[static_cast<std::size_t>(uniform(elite, pop_size - 1))] = std::move(ch);
        }
      }
      while (static_cast<int>(next.size()) < pop_size) {  // refill with random orders
        std::shuffle(base.begin(), base.end(), rng_);
        next.push_back(make(base));
      }
      std::stable_sort(next.begin(), next.end(), by_quality);
      pop = std::move(next);
      if (o_.stall_generations > 0) {
        const double cur = pop.front().res.makespan;
        const bool improved =
            std::isfinite(cur) && (!std::isfinite(stall_best) ||
                                   stall_best - cur > o_.convergence * std::max(stall_best, kEps));
        if (improved) {
          stall_best = cur;
          stall = 0;
        } else {
          ++stall;
        }
      }
      if (crossovers % std::max(1, o_.crossovers_per_round) < o_.crossovers_per_generation) {
        ++out.rounds;
        const double cur = pop.front().res.makespan;
        out.best_per_round.push_back(cur);
        const bool both_finite = std::isfinite(cur) && std::isfinite(prev);
        const double change =
            both_finite ? std::abs(prev - cur) / std::max(std::abs(prev), kEps) : 1.0;
        prev = cur;
        if (o_.stall_generations > 0) {
          if (stall >= o_.stall_generations) break;
        } else if (both_finite && change < o_.convergence) {
          break;
        }
      }
    }
    Individual& best = pop.front();
    out.makespan_before_ils = best.res.makespan;
    if (o_.ils_patience > 0 && n_ >= 3 && o_.three_opt_iterations >= 0) {
      if (helpers.empty()) helpers.push_back(std::make_unique<Ga>(net_, searched_, suffix_, o_));
      iterated_local_search(best, out, helpers);
    }
    out.makespan_before_polish = best.res.makespan;
    if (o_.polish_sweeps > 0 && n_ >= 2) {
      const std::size_t ga_improvements = improvements_;  // the polish counts its own moves
      polish(best, out);
      improvements_ = ga_improvements;
    }
    for (const int l : best.seq)
      out.order.push_back(searched_[static_cast<std::size_t>(l)]);
    out.order.insert(out.order.end(), suffix_.begin(), suffix_.end());
    out.resolution = best.res;
    for (const auto& h : helpers) {
      evaluations_ += h->evaluations_;
      improvements_ += h->improvements_;
      local_optima_ += h->local_optima_;
      cut_moves_ += h->cut_moves_;
      delayed_improvements_ += h->delayed_improvements_;
    }
    out.evaluations = evaluations_;
    out.three_opt_improvements = improvements_;
    out.three_opt_local_optima = local_optima_;
    out.three_opt_exact_cuts = cut_moves_;
    out.three_opt_delayed_improvements = delayed_improvements_;
    return out;
  }

 private:
  const MdNetwork& net_;
  const std::vector<int>& searched_;
  const std::vector<int>& suffix_;
  GaOptions o_;
  std::mt19937_64 rng_;
  int n_;
  internal::GaOperators ops_;
  MoveEvaluator evaluator_;
  std::size_t evaluations_ = 0;
  std::size_t improvements_ = 0;
  std::size_t local_optima_ = 0;
  std::size_t cut_moves_ = 0;
  std::size_t delayed_improvements_ = 0;
  bool no_delayed_ = false;
  std::vector<char> in_support_, scratch_;
};

void check_ga_options(const GaOptions& o) {
  auto bad = [](const char* what, const std::string& why) { throw Error(what, 0, why); };
  if (o.crossovers_per_generation < 1) bad("crossovers_per_generation", "expected >= 1");
  if (o.crossovers_per_round < 1) bad("crossovers_per_round", "expected >= 1");
  if (!(o.mutation_rate >= 0.0 && o.mutation_rate <= 1.0)) bad("mutation_rate", "expected [0, 1]");
  if (!(o.elitism >= 0.0 && o.elitism <= 1.0)) bad("elitism", "expected [0, 1]");
  if (o.mutation_min_edges < 1 || o.mutation_max_edges < o.mutation_min_edges) {
    bad("mutation_edges", "expected 1 <= min <= max");
  }
  if (!(o.convergence >= 0.0)) bad("convergence", "expected >= 0");
  if (o.max_rounds < 1) bad("max_rounds", "expected >= 1");
  if (o.stall_generations < 0) bad("stall_generations", "expected >= 0");
  if (o.delayed_gate < 0) bad("delayed_gate", "expected >= 0");
  if (o.polish_sweeps < 0) bad("polish_sweeps", "expected >= 0");
  if (o.ils_patience < 0) bad("ils_patience", "expected >= 0");
  if (o.ils_kick < 1) bad("ils_kick", "expected >= 1, got " + std::to_string(o.ils_kick));
  if (o.three_opt_depth < 0) bad("three_opt_depth", "expected >= 0");
  if (o.three_opt_patience < 0) bad("three_opt_patience", "expected >= 0");
  if (o.threads < 0 || o.threads > 64) bad("threads", "expected 0..64");
  if (o.workers < 1 || o.workers > 64) {
    bad("workers", "expected 1..64, got " + std::to_string(o.workers));
  }
  if (o.workers > 1 && (o.threads != 0 || o.three_opt_order != ThreeOptOrder::kPaper)) {
    bad("workers", "workers > 1 (got " + std::to_string(o.workers) +
                       ") needs threads = 0 and the paper's 3-opt order (the other orders draw "
                       "depending on the search, so their stream cannot be skipped ahead)");
  }
}

}  // namespace

SearchResult genetic_search(const MdNetwork& net, const std::vector<int>& searched,
                            const std::vector<int>& suffix, const std::vector<int>& seed_order,
                            const GaOptions& options) {
  check_split(net, searched, suffix);
  check_ga_options(options);
  if (searched.size() <= 1) {
    SearchResult r;
    r.order = concat(searched, suffix);
    r.resolution = resolve(net, r.order);
    r.urgent_group = searched;
    r.evaluations = 1;
    return r;
  }
  Ga ga(net, searched, suffix, options);
  return ga.run(seed_order);
}

SearchResult search_priority(const MdNetwork& net, const SearchOptions& options) {
  const int n = net.size();
  if (options.kind == SearchKind::kNone) {
    SearchResult r;
    r.order.resize(static_cast<std::size_t>(n));
    std::iota(r.order.begin(), r.order.end(), 0);
    r.resolution = resolve(net, r.order);
    r.evaluations = 1;
    return r;
  }
  std::vector<int> searched, suffix;
  EdfResult edf = bottom_level_edf(net, options.edf);
  if (options.edf_reduction) {
    searched.assign(edf.order.begin(),
                    edf.order.begin() + static_cast<std::ptrdiff_t>(edf.urgent_group.size()));
    suffix.assign(edf.order.begin() + static_cast<std::ptrdiff_t>(edf.urgent_group.size()),
                  edf.order.end());
  } else {
    searched = edf.order;
  }
  if (options.kind == SearchKind::kEdf) {
    SearchResult r;
    r.order = edf.order;
    r.resolution = resolve(net, r.order);
    r.urgent_group = edf.urgent_group;
    r.evaluations = 1;
    return r;
  }
  if (options.kind == SearchKind::kExhaustive) {
    if (static_cast<int>(searched.size()) > options.exhaustive_max) {
      throw Error("--search", 0,
                  "exhaustive search over " + std::to_string(searched.size()) +
                      " robots is too large (limit " + std::to_string(options.exhaustive_max) +
                      "); use ga");
    }
    return exhaustive_search(net, searched, suffix);
  }
  return genetic_search(net, searched, suffix, searched, options.ga);
}

}  // namespace voronav::coordination
