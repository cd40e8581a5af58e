// libFuzzer target: Moving AI .scen files (io::load_movingai_scen, then check_scen_fits against a
// 8x8 map).
#include "fuzz_util.hpp"
#include "voronav/io/movingai.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace voronav;
  const auto path = fuzz::put("input.scen", fuzz::as_text(data, size));
  fuzz::expect_clean(path.string(), [&] {
    const auto q = io::load_movingai_scen(path);
    const OccupancyGrid grid(8, 8, kFree);
    io::check_scen_fits(q, grid, path);
  });
  return 0;
}
