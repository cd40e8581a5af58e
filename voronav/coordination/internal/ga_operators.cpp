#include "voronav/coordination/internal/ga_operators.hpp"

#include <algorithm>
#include <numeric>

namespace voronav::coordination::internal {

namespace {
constexpr double kEps = 1e-9;
}  // namespace

template <class Forbidden>
std::vector<int> GaOperators::reconnect(std::vector<std::vector<int>> frags, Forbidden forbidden,
                                        GaRng& rng) const {
  std::vector<int> out;
  out.reserve(static_cast<std::size_t>(n_));
  auto take = [&](std::size_t f) {
    out.insert(out.end(), frags[f].begin(), frags[f].end());
    frags.erase(frags.begin() + static_cast<std::ptrdiff_t>(f));
  };
  {
    std::vector<std::size_t> cand;
    for (std::size_t f = 0; f < frags.size(); ++f) {
      if (!forbidden(-1, frags[f].front())) cand.push_back(f);
    }
    if (cand.empty()) {
      for (std::size_t f = 0; f < frags.size(); ++f)
        cand.push_back(f);
    }
    take(cand[static_cast<std::size_t>(uniform(rng, 0, static_cast<int>(cand.size()) - 1))]);
  }
  while (!frags.empty()) {
    const int tail = out.back();
    std::vector<std::size_t> cand;
    double best_w = -1.0;
    for (int pass = 0; pass < 2 && cand.empty(); ++pass) {
      for (std::size_t f = 0; f < frags.size(); ++f) {
        const int head = frags[f].front();
        if (pass == 0 && forbidden(tail, head)) continue;
        const double w =
            weight_.empty() ? 0.0 : weight_[static_cast<std::size_t>(tail * n_ + head)];
        if (w > best_w + kEps) {
          best_w = w;
          cand.assign(1, f);
        } else if (w >= best_w - kEps) {
          cand.push_back(f);
        }
      }
    }
    take(cand[static_cast<std::size_t>(uniform(rng, 0, static_cast<int>(cand.size()) - 1))]);
  }
  return out;
}

std::vector<int> GaOperators::successors(const std::vector<int>& seq) const {
  std::vector<int> succ(static_cast<std::size_t>(n_) + 1, -2);
  succ[static_cast<std::size_t>(n_)] = seq.front();  // virtual start node
  for (std::size_t k = 0; k + 1 < seq.size(); ++k)
    succ[static_cast<std::size_t>(seq[k])] = seq[k + 1];
  succ[static_cast<std::size_t>(seq.back())] = -1;
  return succ;
}

std::vector<int> GaOperators::dpx(const std::vector<int>& pa, const std::vector<int>& pb,
                                  GaRng& rng) const {
  const auto sa = successors(pa), sb = successors(pb);
  std::vector<std::vector<int>> frags{{pa.front()}};
  for (std::size_t k = 1; k < pa.size(); ++k) {
    if (sb[static_cast<std::size_t>(pa[k - 1])] == pa[k]) {
      frags.back().push_back(pa[k]);
    } else {
      frags.push_back({pa[k]});
    }
  }
  auto forbidden = [&](int a, int b) {
    const auto idx = static_cast<std::size_t>(a < 0 ? n_ : a);
    return sa[idx] == b || sb[idx] == b;
  };
  return reconnect(std::move(frags), forbidden, rng);
}

std::vector<int> GaOperators::mutate(const std::vector<int>& seq, int min_edges, int max_edges,
                                     GaRng& rng) const {
  const int edges = n_ - 1;
  if (edges < 1) return seq;
  const int k = std::min(edges, uniform(rng, min_edges, max_edges));
  std::vector<int> pos(static_cast<std::size_t>(edges));
  std::iota(pos.begin(), pos.end(), 0);
  std::shuffle(pos.begin(), pos.end(), rng);
  std::vector<char> cut(static_cast<std::size_t>(edges), 0);
  for (int i = 0; i < k; ++i)
    cut[static_cast<std::size_t>(pos[static_cast<std::size_t>(i)])] = 1;
  std::vector<std::vector<int>> frags{{seq.front()}};
  // The removed edges, including "the first node is first" (its edge from the virtual start).
  std::vector<int> removed_succ(static_cast<std::size_t>(n_) + 1, -2);
  removed_succ[static_cast<std::size_t>(n_)] = seq.front();
  for (std::size_t e = 0; e + 1 < seq.size(); ++e) {
    if (cut[e]) {
      removed_succ[static_cast<std::size_t>(seq[e])] = seq[e + 1];
      frags.push_back({seq[e + 1]});
    } else {
      frags.back().push_back(seq[e + 1]);
    }
  }
  auto forbidden = [&](int a, int b) {
    return removed_succ[static_cast<std::size_t>(a < 0 ? n_ : a)] == b;
  };
  return reconnect(std::move(frags), forbidden, rng);
}

bool GaOperators::segment_move(const std::vector<int>& seq, GaRng& rng, std::vector<int>& cand,
                               int& from, int& to) {
  const int n = static_cast<int>(seq.size());
  if (n < 2) return false;
  const int i = uniform(rng, 0, n - 1);
  const int j = uniform(rng, i, std::min(n - 1, i + uniform(rng, 0, n - 1)));
  const int len = j - i + 1;
  if (len >= n) return false;
  const int k = uniform(rng, 0, n - len);  // insertion position in the remaining sequence
  if (k == i) return false;
  cand.clear();
  // rest[0, k), then the segment, then rest[k, end), where rest = seq without [i, j].
  auto rest_at = [&](int r) { return seq[static_cast<std::size_t>(r < i ? r : r + len)]; };
  for (int r = 0; r < k; ++r)
    cand.push_back(rest_at(r));
  cand.insert(cand.end(), seq.begin() + i, seq.begin() + j + 1);
  for (int r = k; r < n - len; ++r)
    cand.push_back(rest_at(r));
  from = std::min(i, k);
  to = std::max(j + 1, k + len);
  return true;
}

}  // namespace voronav::coordination::internal
