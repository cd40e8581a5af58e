#include "voronav/coordination/paper_networks.hpp"

#include <algorithm>
#include <random>
#include <string>

#include "voronav/core/error.hpp"

namespace voronav::coordination {

MdNetwork table4_network() {
  // Robots A1..A5 are indices 0..4. With the symmetric arc cost k0 = M + D the table fixes
  // k0(1,2)=13, k0(1,3)=7, k0(1,4)=11, k0(1,5)=9, k0(2,3)=8, k0(2,5)=4, k0(3,4)=7, k0(3,5)=8,
  // no box for (2,4), (4,5), and T^traveled = 34, 55, 26, 35, 38 s (A2's 80 s in round 1 then
  // follows). The split of k0 into M and D is not in the table; we take M = D = k0 / 2.
  MdNetwork net({34.0, 55.0, 26.0, 35.0, 38.0});
  const int pairs[8][2] = {{0, 1}, {0, 2}, {0, 3}, {0, 4}, {1, 2}, {1, 4}, {2, 3}, {2, 4}};
  const double k0[8] = {13, 7, 11, 9, 8, 4, 7, 8};
  for (int k = 0; k < 8; ++k)
    net.add_box(pairs[k][0], pairs[k][1], k0[k] / 2.0, k0[k] / 2.0);
  return net;
}

MdNetwork table4_network_delay_reading() {
  // Robots A1..A5 are indices 0..4. Travel times and arc costs c(i, j) = the delay i gets below j
  // (see docs/reproductions/coordination.md for the derivation from Table 4).
  MdNetwork net({45.0, 55.0, 43.0, 46.0, 46.0});
  // add_box(high, low, M, D): with `high` above `low`, D = c(low, high) and M = c(high, low).
  net.add_box(0, 1, 2.0, 13.0);  // c(2,1) = 13, c(1,2) = 2
  net.add_box(0, 2, 7.0, 2.0);   // c(3,1) = 2,  c(1,3) = 7
  net.add_box(0, 3, 11.0, 3.0);  // c(4,1) = 3,  c(1,4) = 11
  net.add_box(0, 4, 9.0, 2.0);   // c(5,1) = 2,  c(1,5) = 9
  net.add_box(1, 2, 8.0, 3.0);   // c(3,2) = 3,  c(2,3) = 8
  net.add_box(1, 4, 4.0, 3.0);   // c(5,2) = 3,  c(2,5) = 4
  net.add_box(2, 3, 7.0, 4.0);   // c(4,3) = 4,  c(3,4) = 7
  net.add_box(2, 4, 1.0, 8.0);   // c(5,3) = 8,  c(3,5) = 1
  return net;
}

MdNetwork random_network(int agents, int points, std::uint64_t seed,
                         const RandomNetworkOptions& o) {
  if (agents < 2) throw Error("agents", 0, "expected at least 2, got " + std::to_string(agents));
  if (points < 0) throw Error("points", 0, "expected >= 0, got " + std::to_string(points));
  if (!(o.travel_min > 0.0 && o.travel_max >= o.travel_min && o.shared_min > 0.0 &&
        o.shared_max >= o.shared_min && o.d_max >= o.d_min)) {
    throw Error("random_network", 0, "inconsistent ranges");
  }
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> travel(o.travel_min, o.travel_max);
  std::uniform_real_distribution<double> shared(o.shared_min, o.shared_max);
  std::uniform_real_distribution<double> dd(o.d_min, o.d_max);
  std::uniform_int_distribution<int> pick(0, agents - 1);
  std::vector<double> t(static_cast<std::size_t>(agents));
  for (auto& x : t)
    x = travel(rng);
  MdNetwork net(std::move(t));
  for (int p = 0; p < points; ++p) {
    int a = pick(rng), b = pick(rng);
    while (b == a)
      b = pick(rng);
    if (a > b) std::swap(a, b);
    const double k0 = shared(rng);
    const double d = std::min(dd(rng), k0 - 1e-3);  // keep M + D = k0 > 0
    net.add_box(a, b, k0 - d, d);
  }
  return net;
}

}  // namespace voronav::coordination
