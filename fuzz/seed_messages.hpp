// Sample robot messages (one of each type, some with content) for the fuzz seeds of
// fuzz_messages and fuzz_dds_sample.
#pragma once

#include <vector>

#include "voronav/network/messages.hpp"

namespace voronav::fuzz {

inline std::vector<std::vector<std::uint8_t>> sample_messages() {
  using namespace network;
  Header h{RobotId{1}, RobotId{2}, RobotId{1}, 7, 1};
  SearchMessage search{RobotId{1},
                       2,
                       {3.5, -1.0},
                       {RobotId{1}, RobotId{4}},
                       {{{1.0, 2.0}, 0.5F, 1.5F}, {{2.0, 2.5}, 0.25F, 3.0F}},
                       {{0.0, 1.0}}};
  std::vector<Envelope> ms{{h, search},           {h, PathMessage{}}, {h, RepairMessage{}},
                           {h, RequestMessage{}}, {h, AckMessage{}},  {h, NotifyMessage{}},
                           {h, LinkAckMessage{}}};
  std::vector<std::vector<std::uint8_t>> out;
  for (const auto& m : ms)
    out.push_back(encode(m));
  return out;
}

}  // namespace voronav::fuzz
