// libFuzzer target: coordination scenario YAML (coordination::load_scenario), then planning the
// robots' paths on the scenario's map (plan_agents: the avoid-disc loop, A*). The folder holds an
// 8x8 Moving AI map "m.map" that a mutated scenario may name.
#include "fuzz_util.hpp"
#include "voronav/coordination/scenario.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace voronav;
  static const bool once = [] {
    (void)fuzz::put("m.map",
                    "type octile\nheight 8\nwidth 8\nmap\n........\n........\n..@@....\n"
                    "........\n........\n....@...\n........\n........\n");
    return true;
  }();
  (void)once;
  const auto path = fuzz::put("input.yaml", fuzz::as_text(data, size));
  fuzz::expect_clean("", [&] {
    coordination::Scenario s;
    try {
      s = coordination::load_scenario(path);
    } catch (const Error& e) {
      if (e.source() != path.string())
        fuzz::finding(std::string("error not naming the file: ") + e.what());
      return;
    }
    if (s.robots.size() <= 16) (void)coordination::plan_agents(s);
  });
  return 0;
}
