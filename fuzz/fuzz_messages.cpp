// libFuzzer target: robot-to-robot messages (network::decode). What decodes must encode back to
// the same bytes and decode to the same message.
#include <span>

#include "fuzz_util.hpp"
#include "seed_messages.hpp"
#include "voronav/network/messages.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  voronav::fuzz::write_seeds(voronav::fuzz::sample_messages());
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace voronav;
  fuzz::expect_clean("message", [&] {
    const network::Envelope m = network::decode(std::span<const std::uint8_t>(data, size));
    const auto bytes = network::encode(m);
    if (!(network::decode(bytes) == m)) fuzz::finding("decode(encode(m)) != m");
  });
  return 0;
}
