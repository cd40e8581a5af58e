// libFuzzer target: Moving AI .map files (io::load_movingai_map).
#include "fuzz_util.hpp"
#include "voronav/io/movingai.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace voronav;
  const auto path = fuzz::put("input.map", fuzz::as_text(data, size));
  fuzz::expect_clean(path.string(), [&] { (void)io::load_movingai_map(path); });
  return 0;
}
