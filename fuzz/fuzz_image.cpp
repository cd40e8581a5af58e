// libFuzzer target: image maps (PGM P2/P5, PNG) through io::read_image and io::load_floorplan.
#include "fuzz_util.hpp"
#include "voronav/io/floorplan.hpp"
#include "voronav/io/image.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace voronav;
  const auto path = fuzz::put("input.img", fuzz::as_text(data, size));
  fuzz::expect_clean(path.string(), [&] { (void)io::load_floorplan(path, {}); });
  return 0;
}
