#include "voronav/coordination/sipp_ga.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <numeric>
#include <random>
#include <string>

#include "voronav/coordination/internal/ga_operators.hpp"
#include "voronav/core/error.hpp"

namespace voronav::coordination {

namespace {

struct Individual {
  std::vector<int> seq;
  PrioritizedResult res;
  std::pair<double, double> key{kInfinity, kInfinity};
};

class SippGa {
 public:
  SippGa(const BinaryGrid& blocked, const std::vector<SippRobot>& robots, Objective objective,
         const PrioritizedOptions& planning, const SippGaOptions& o)
      : blocked_(blocked),
        robots_(robots),
        objective_(objective),
        planning_(planning),
        o_(o),
        rng_(o.seed),
        n_(static_cast<int>(robots.size())),
        ops_(n_, {}) {
    planning_.max_restarts = 0;
  }

  Individual make(std::vector<int> seq) {
    Individual ind;
    ind.seq = std::move(seq);
    ind.res = plan_prioritized(blocked_, robots_, ind.seq, planning_);
    ++evaluations_;
    if (ind.res.ok) {
      ind.key = objective_ == Objective::kMakespan
                    ? std::pair{ind.res.makespan, ind.res.sum_of_arrivals}
                    : std::pair{ind.res.sum_of_arrivals, ind.res.makespan};
    }
    return ind;
  }

  int uniform(int lo, int hi) { return internal::uniform(rng_, lo, hi); }

  /// 3-opt segment moves (internal::GaOperators::segment_move), first improvement.
  void three_opt(Individual& ind) {
    std::vector<int> cand;
    int from = 0, to = 0;
    for (int it = 0; it < o_.three_opt && n_ >= 3 && !out_of_time(); ++it) {
      if (!internal::GaOperators::segment_move(ind.seq, rng_, cand, from, to)) continue;
      Individual c = make(cand);
      if (c.key < ind.key) ind = std::move(c);
    }
  }

  /// The budget is process CPU time (not wall clock), so that the search does the same amount
  /// of work on a loaded machine as on an idle one.
  bool out_of_time() const {
    return static_cast<double>(std::clock() - t0_) / CLOCKS_PER_SEC > budget_s_;
  }

  SippGaResult run(const std::vector<std::vector<int>>& seeds) {
    SippGaResult out;
    const int pop_size = std::max(2, o_.population);
    std::vector<Individual> pop;
    // The first seed (the paper's EDF order) is always planned; the others while the budget
    // lasts (at K = 200 one prioritized planning run can take seconds).
    for (const auto& s : seeds) {
      if (static_cast<int>(pop.size()) >= pop_size || (!pop.empty() && out_of_time())) break;
      pop.push_back(make(s));
    }
    std::pair<double, double> best_seed{kInfinity, kInfinity};
    for (const auto& p : pop)
      best_seed = std::min(best_seed, p.key);
    std::vector<int> base(static_cast<std::size_t>(n_));
    std::iota(base.begin(), base.end(), 0);
    while (static_cast<int>(pop.size()) < pop_size && !out_of_time()) {
      std::shuffle(base.begin(), base.end(), rng_);
      pop.push_back(make(base));
    }
    auto by_key = [](const Individual& a, const Individual& b) { return a.key < b.key; };
    std::stable_sort(pop.begin(), pop.end(), by_key);
    const int size = static_cast<int>(pop.size());
    const int elite = std::max(1, static_cast<int>(std::ceil(o_.elitism * size)));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    while (n_ >= 2 && size >= 2 && out.generations < o_.max_generations && !out_of_time()) {
      for (int c = 0; c < o_.children && !out_of_time(); ++c) {
        const int a = uniform(0, size - 1);
        int b = uniform(0, size - 2);
        if (b >= a) ++b;
        std::vector<int> child = ops_.dpx(pop[static_cast<std::size_t>(a)].seq,
                                          pop[static_cast<std::size_t>(b)].seq, rng_);
        if (unit(rng_) < o_.mutation_rate)
          child = ops_.mutate(child, o_.mutation_min_edges, o_.mutation_max_edges, rng_);
        Individual ind = make(std::move(child));
        three_opt(ind);
        // Elitism (section 4.2): the child replaces a random non-elite member.
        if (elite < size) pop[static_cast<std::size_t>(uniform(elite, size - 1))] = std::move(ind);
      }
      std::stable_sort(pop.begin(), pop.end(), by_key);
      ++out.generations;
    }
    out.best = std::move(pop.front().res);
    out.order = pop.front().seq;
    out.evaluations = evaluations_;
    out.improved_over_seeds = pop.front().key < best_seed ? 1 : 0;
    return out;
  }

 private:
  const BinaryGrid& blocked_;
  const std::vector<SippRobot>& robots_;
  Objective objective_;
  PrioritizedOptions planning_;
  SippGaOptions o_;
  internal::GaRng rng_;
  int n_;
  internal::GaOperators ops_;  ///< no weights: the fragments are reconnected at random
  std::size_t evaluations_ = 0;
  double budget_s_ = sipp_ga_budget(o_, static_cast<std::size_t>(n_));
  std::clock_t t0_ = std::clock();
};

}  // namespace

double sipp_ga_budget(const SippGaOptions& options, std::size_t robots) {
  if (options.time_limit_s > 0.0) return options.time_limit_s;
  return std::clamp(options.auto_seconds_per_robot * static_cast<double>(robots),
                    options.auto_min_s, options.auto_max_s);
}

SippGaResult sipp_genetic_search(const BinaryGrid& blocked, const std::vector<SippRobot>& robots,
                                 const std::vector<std::vector<int>>& seeds, Objective objective,
                                 const PrioritizedOptions& planning, const SippGaOptions& options) {
  if (options.population < 2) throw Error("ga population", 0, "expected >= 2");
  if (options.children < 1) throw Error("ga children", 0, "expected >= 1");
  if (!(options.time_limit_s >= 0.0)) throw Error("ga time limit", 0, "expected >= 0 s");
  if (!(options.mutation_rate >= 0.0 && options.mutation_rate <= 1.0))
    throw Error("ga mutation rate", 0, "expected [0, 1]");
  if (options.mutation_min_edges < 1 || options.mutation_max_edges < options.mutation_min_edges)
    throw Error("ga mutation edges", 0, "expected 1 <= min <= max");
  for (const auto& s : seeds) {
    std::vector<int> sorted = s;
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t i = 0; i < sorted.size(); ++i)
      if (sorted.size() != robots.size() || sorted[i] != static_cast<int>(i))
        throw Error("ga seed", 0, "expected a permutation of the robots");
  }
  if (robots.empty()) return {};
  SippGa ga(blocked, robots, objective, planning, options);
  return ga.run(seeds);
}

}  // namespace voronav::coordination
