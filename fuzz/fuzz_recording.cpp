// libFuzzer target: replay recordings (report::from_json), with a JSON round trip of what loads.
#include "fuzz_util.hpp"
#include "voronav/report/example_recording.hpp"
#include "voronav/report/recording.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  voronav::fuzz::write_seeds(std::vector<std::string>{
      voronav::report::to_json(voronav::report::make_example_recording())});
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace voronav;
  fuzz::expect_clean("fuzz.json", [&] {
    const auto rec = report::from_json(fuzz::as_text(data, size), "fuzz.json");
    (void)report::from_json(report::to_json(rec), "fuzz.json");
  });
  return 0;
}
