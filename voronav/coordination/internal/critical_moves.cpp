#include "voronav/coordination/internal/critical_moves.hpp"

#include <algorithm>
#include <cmath>

namespace voronav::coordination::internal {

void apply_segment_move(const std::vector<int>& seq, const SegmentMove& m, std::vector<int>& cand,
                        int& from, int& to) {
  const int n = static_cast<int>(seq.size());
  const int len = m.j - m.i + 1;
  cand.clear();
  // rest[0, k), then the segment, then rest[k, end), where rest = seq without [i, j].
  auto rest_at = [&](int r) { return seq[static_cast<std::size_t>(r < m.i ? r : r + len)]; };
  for (int r = 0; r < m.k; ++r)
    cand.push_back(rest_at(r));
  cand.insert(cand.end(), seq.begin() + m.i, seq.begin() + m.j + 1);
  for (int r = m.k; r < n - len; ++r)
    cand.push_back(rest_at(r));
  from = std::min(m.i, m.k);
  to = std::max(m.j + 1, m.k + len);
}

bool random_segment_move(int n, std::mt19937_64& rng, SegmentMove& m) {
  if (n < 2) return false;
  auto uniform = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  m.i = uniform(0, n - 1);
  m.j = uniform(m.i, std::min(n - 1, m.i + uniform(0, n - 1)));
  const int len = m.j - m.i + 1;
  if (len >= n) return false;
  m.k = uniform(0, n - len);
  return m.k != m.i;
}

SwappedBlocks swapped_blocks(const SegmentMove& m) {
  const int len = m.j - m.i + 1;
  if (m.k < m.i) return {m.k, m.i, m.j + 1};
  return {m.i, m.j + 1, m.k + len};
}

int critical_robot(const Resolution& res, const std::vector<int>& rank) {
  if (res.status != ResolveStatus::kOk) return res.blocked;
  int c = -1;
  double worst = -1.0;
  for (std::size_t i = 0; i < res.completion.size(); ++i) {
    const double t = res.completion[i];
    if (c < 0 || t > worst + kTimeEpsilon ||
        (t >= worst - kTimeEpsilon && rank[i] > rank[static_cast<std::size_t>(c)])) {
      worst = std::max(worst, t);
      c = static_cast<int>(i);
    }
  }
  return c;
}

std::vector<Blocker> blockers(const MdNetwork& net, const std::vector<int>& rank,
                              const Resolution& res, int x) {
  struct Act {
    double m, d, hd;
    int j;
  };
  std::vector<Act> act;
  const auto& boxes = net.boxes();
  const int rx = rank[static_cast<std::size_t>(x)];
  for (const int k : net.incident(x)) {
    const MdBox& b = boxes[static_cast<std::size_t>(k)];
    const int j = b.a == x ? b.b : b.a;
    if (rank[static_cast<std::size_t>(j)] > rx) continue;
    act.push_back(
        {j == b.b ? b.d : b.m, j == b.b ? b.m : b.d, res.delays[static_cast<std::size_t>(j)], j});
  }
  std::vector<Blocker> out;
  auto add = [&](int j, double s) {
    for (auto& o : out) {
      if (o.robot == j) {
        o.shift += s;
        return;
      }
    }
    out.push_back({j, s});
  };
  // resolve()'s passes (md_network.cpp, resolve_robot_sparse), recording who shifts x.
  double delay = 0.0;
  bool changed = true;
  while (changed) {
    changed = false;
    for (const Act& e : act) {
      const double m = e.m + delay - e.hd;
      const double d = e.d - delay + e.hd;
      if (!(d > kTimeEpsilon) || !(m > kTimeEpsilon)) continue;
      add(e.j, d);
      if (std::isinf(d)) {
        changed = false;
        break;
      }
      delay += d;
      changed = true;
    }
  }
  std::stable_sort(out.begin(), out.end(), [&](const Blocker& a, const Blocker& b) {
    if (a.shift != b.shift) return a.shift > b.shift;
    return rank[static_cast<std::size_t>(a.robot)] < rank[static_cast<std::size_t>(b.robot)];
  });
  return out;
}

std::vector<SegmentMove> critical_moves(const MdNetwork& net, int n, const std::vector<int>& rank,
                                        const Resolution& res, int depth) {
  std::vector<SegmentMove> moves;
  if (n < 2 || res.completion.empty()) return moves;
  const int c = critical_robot(res, rank);
  if (c < 0) return moves;
  auto emit = [&](const SegmentMove& m) {
    if (std::find(moves.begin(), moves.end(), m) == moves.end()) moves.push_back(m);
  };
  std::vector<int> level{c}, next, seen{c};
  for (int d = 0; d <= depth && !level.empty(); ++d) {
    next.clear();
    for (const int x : level) {
      std::vector<Blocker> bl;
      if (res.status != ResolveStatus::kOk && x == res.blocked) {
        bl.push_back({res.blocked_by, kInfinity});
      } else {
        bl = blockers(net, rank, res, x);
      }
      const int px = rank[static_cast<std::size_t>(x)];
      for (const Blocker& b : bl) {
        const int pb = rank[static_cast<std::size_t>(b.robot)];
        if (px < n && pb < px) {
          emit({px, px, pb});  // x just above b
          emit({pb, pb, px});  // b just below x
        }
        if (std::find(seen.begin(), seen.end(), b.robot) == seen.end()) {
          seen.push_back(b.robot);
          next.push_back(b.robot);
        }
      }
    }
    level.swap(next);
  }
  return moves;
}

std::vector<DelayedPair> delayed_pairs(const MdNetwork& net, int n, const std::vector<int>& rank,
                                       const Resolution& res) {
  std::vector<DelayedPair> pairs;
  if (n < 2 || res.status != ResolveStatus::kOk || res.completion.empty()) return pairs;
  std::vector<int> delayed;
  for (int x = 0; x < net.size(); ++x) {
    if (rank[static_cast<std::size_t>(x)] < n &&
        res.delays[static_cast<std::size_t>(x)] > kTimeEpsilon)
      delayed.push_back(x);
  }
  std::stable_sort(delayed.begin(), delayed.end(), [&](int a, int b) {
    return res.completion[static_cast<std::size_t>(a)] >
           res.completion[static_cast<std::size_t>(b)];
  });
  for (const int x : delayed) {
    for (const Blocker& b : blockers(net, rank, res, x))
      pairs.push_back({x, b.robot});
  }
  return pairs;
}

void support_of(const MdNetwork& net, const std::vector<int>& rank, int c,
                std::vector<char>& in_support) {
  in_support.assign(static_cast<std::size_t>(net.size()), 0);
  std::vector<int> stack{c};
  in_support[static_cast<std::size_t>(c)] = 1;
  const auto& boxes = net.boxes();
  while (!stack.empty()) {
    const int y = stack.back();
    stack.pop_back();
    for (const int k : net.incident(y)) {
      const MdBox& b = boxes[static_cast<std::size_t>(k)];
      const int j = b.a == y ? b.b : b.a;
      if (rank[static_cast<std::size_t>(j)] > rank[static_cast<std::size_t>(y)]) continue;
      if (in_support[static_cast<std::size_t>(j)]) continue;
      in_support[static_cast<std::size_t>(j)] = 1;
      stack.push_back(j);
    }
  }
}

bool can_lower_makespan(const MdNetwork& net, const std::vector<int>& order,
                        const std::vector<char>& in_support, int a_begin, int a_end, int b_end,
                        std::vector<char>& scratch) {
  scratch.assign(static_cast<std::size_t>(net.size()), 0);
  for (int p = a_end; p < b_end; ++p)
    scratch[static_cast<std::size_t>(order[static_cast<std::size_t>(p)])] = 1;
  const auto& boxes = net.boxes();
  for (int p = a_begin; p < a_end; ++p) {
    const int a = order[static_cast<std::size_t>(p)];
    if (!in_support[static_cast<std::size_t>(a)]) continue;
    for (const int k : net.incident(a)) {
      const MdBox& b = boxes[static_cast<std::size_t>(k)];
      const int j = b.a == a ? b.b : b.a;
      if (scratch[static_cast<std::size_t>(j)]) return true;
    }
  }
  return false;
}

}  // namespace voronav::coordination::internal
