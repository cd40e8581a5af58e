// libFuzzer target: schedules in JSON or YAML (coordination::parse_schedule), then the
// continuous-time check (verify_schedule) with a small work limit.
#include <string>

#include "fuzz_util.hpp"
#include "voronav/coordination/schedule_io.hpp"
#include "voronav/coordination/verify.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace voronav;
  const std::string text(fuzz::as_text(data, size));
  fuzz::expect_clean("fuzz.yaml", [&] {
    const auto s = coordination::parse_schedule(text, "fuzz.yaml");
    if (s.agents.size() > 8) return;
    coordination::VerifyOptions vo;
    vo.at_start = s.at_start;
    vo.at_goal = s.at_goal;
    (void)coordination::verify_schedule(s.agents, s.delays, vo);
  });
  return 0;
}
