// libFuzzer target: netsim scenario files (sim::load_netsim_scenario). The folder holds a 10x8
// world "w.map" that a mutated scenario may name.
#include "fuzz_util.hpp"
#include "voronav/sim/scenario_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace voronav;
  static const bool once = [] {
    (void)fuzz::put("w.map",
                    "type octile\nheight 8\nwidth 10\nmap\n..........\n..........\n....@@....\n"
                    "....@@....\n..........\n..........\n..........\n..........\n");
    return true;
  }();
  (void)once;
  const auto path = fuzz::put("input.yaml", fuzz::as_text(data, size));
  fuzz::expect_clean(path.string(), [&] { (void)sim::load_netsim_scenario(path.string()); });
  return 0;
}
