// libFuzzer target: the ROS map_server YAML (io::read_ros_map); the folder holds a valid 4x3 PGM
// "map.pgm" and a PNG "map.png" that a mutated YAML may name.
#include "fuzz_util.hpp"
#include "voronav/io/ros_map.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace voronav;
  static const bool once = [] {
    (void)fuzz::put(
        "map.pgm",
        std::string_view("P5\n4 3\n255\n\xfe\xfe\x00\xfe\xfe\xcd\xfe\x00\xfe\xfe\xfe\xfe", 23));
    return true;
  }();
  (void)once;
  const auto path = fuzz::put("input.yaml", fuzz::as_text(data, size));
  fuzz::expect_clean(path.string(), [&] { (void)io::read_ros_map(path); });
  return 0;
}
