#include "voronav/coordination/sipp_ga.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <numeric>
#include <random>
#include <string>

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
        n_(static_cast<int>(robots.size())) {
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

  int uniform(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }

  /// Chains fragments in a random order, avoiding the edges forbidden(a, b) when possible.
  template <class Forbidden>
  std::vector<int> reconnect(std::vector<std::vector<int>> frags, Forbidden forbidden) {
    std::vector<int> out;
    while (!frags.empty()) {
      std::vector<std::size_t> cand;
      for (std::size_t f = 0; f < frags.size(); ++f) {
        if (!forbidden(out.empty() ? -1 : out.back(), frags[f].front())) cand.push_back(f);
      }
      if (cand.empty()) {
        cand.resize(frags.size());
        std::iota(cand.begin(), cand.end(), std::size_t{0});
      }
      const std::size_t f =
          cand[static_cast<std::size_t>(uniform(0, static_cast<int>(cand.size()) - 1))];
      out.insert(out.end(), frags[f].begin(), frags[f].end());
      frags.erase(frags.begin() + static_cast<std::ptrdiff_t>(f));
    }
    return out;
  }

  std::vector<int> successors(const std::vector<int>& s) const {
    std::vector<int> succ(static_cast<std::size_t>(n_) + 1, -2);
    succ[static_cast<std::size_t>(n_)] = s.front();
    for (std::size_t k = 0; k + 1 < s.size(); ++k)
      succ[static_cast<std::size_t>(s[k])] = s[k + 1];
    return succ;
  }

  /// DPX: the edges common to both parents are kept; fragments are reconnected without any edge
  /// of either parent where possible.
  std::vector<int> dpx(const std::vector<int>& a, const std::vector<int>& b) {
    const auto sa = successors(a), sb = successors(b);
    std::vector<std::vector<int>> frags{{a.front()}};
    for (std::size_t k = 1; k < a.size(); ++k) {
      if (sb[static_cast<std::size_t>(a[k - 1])] == a[k]) {
        frags.back().push_back(a[k]);
      } else {
        frags.push_back({a[k]});
      }
    }
    return reconnect(std::move(frags), [&](int x, int y) {
      const auto i = static_cast<std::size_t>(x < 0 ? n_ : x);
      return sa[i] == y || sb[i] == y;
    });
  }

  std::vector<int> mutate(const std::vector<int>& s) {
    const int edges = n_ - 1;
    if (edges < 1) return s;
    const int k = std::min(edges, uniform(o_.mutation_min_edges, o_.mutation_max_edges));
    std::vector<int> pos(static_cast<std::size_t>(edges));
    std::iota(pos.begin(), pos.end(), 0);
    std::shuffle(pos.begin(), pos.end(), rng_);
    std::vector<char> cut(static_cast<std::size_t>(edges), 0);
    for (int i = 0; i < k; ++i)
      cut[static_cast<std::size_t>(pos[static_cast<std::size_t>(i)])] = 1;
    std::vector<std::vector<int>> frags{{s.front()}};
    std::vector<int> removed(static_cast<std::size_t>(n_) + 1, -2);
    for (std::size_t e = 0; e + 1 < s.size(); ++e) {
      if (cut[e]) {
        removed[static_cast<std::size_t>(s[e])] = s[e + 1];
        frags.push_back({s[e + 1]});
      } else {
        frags.back().push_back(s[e + 1]);
      }
    }
    return reconnect(std::move(frags), [&](int x, int y) {
      return removed[static_cast<std::size_t>(x < 0 ? n_ : x)] == y;
    });
  }

  /// 3-opt segment moves (no reversal: the only kind that keeps every edge's direction), first
  /// improvement.
  void three_opt(Individual& ind) {
    for (int it = 0; it < o_.three_opt && n_ >= 3 && !out_of_time(); ++it) {
      const int i = uniform(0, n_ - 1);
      const int j = uniform(i, std::min(n_ - 1, i + uniform(0, n_ - 1)));
      const int len = j - i + 1;
      if (len >= n_) continue;
      const int k = uniform(0, n_ - len);
      if (k == i) continue;
      std::vector<int> rest;
      for (int p = 0; p < n_; ++p)
        if (p < i || p > j) rest.push_back(ind.seq[static_cast<std::size_t>(p)]);
      std::vector<int> cand(rest.begin(), rest.begin() + k);
      cand.insert(cand.end(), ind.seq.begin() + i, ind.seq.begin() + j + 1);
      cand.insert(cand.end(), rest.begin() + k, rest.end());
      Individual c = make(std::move(cand));
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
        std::vector<int> child =
            dpx(pop[static_cast<std::size_t>(a)].seq, pop[static_cast<std::size_t>(b)].seq);
        if (unit(rng_) < o_.mutation_rate) child = mutate(child);
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
  std::mt19937_64 rng_;
  int n_;
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
