#include "voronav/render/color.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace voronav::render {

Color palette(int i) {
  static constexpr std::array<std::uint32_t, 20> kPalette = {
      0x1f77b4, 0xff7f0e, 0x2ca02c, 0xd62728, 0x9467bd, 0x8c564b, 0xe377c2,
      0x7f7f7f, 0xbcbd22, 0x17becf, 0xaec7e8, 0xffbb78, 0x98df8a, 0xff9896,
      0xc5b0d5, 0xc49c94, 0xf7b6d2, 0xc7c7c7, 0xdbdb8d, 0x9edae5};
  const auto n = static_cast<int>(kPalette.size());
  return Color::hex(kPalette[static_cast<std::size_t>(((i % n) + n) % n)]);
}

Color viridis(double t) {
  // Nine samples of matplotlib's viridis, linearly interpolated.
  static constexpr std::array<std::uint32_t, 9> kStops = {
      0x440154, 0x472d7b, 0x3b528b, 0x2c728e, 0x21918c, 0x28ae80, 0x5ec962, 0xaddc30, 0xfde725};
  if (!std::isfinite(t)) t = 0;
  t = std::clamp(t, 0.0, 1.0) * (kStops.size() - 1);
  const auto i = std::min<std::size_t>(static_cast<std::size_t>(t), kStops.size() - 2);
  const double f = t - static_cast<double>(i);
  const Color a = Color::hex(kStops[i]), b = Color::hex(kStops[i + 1]);
  return {a.r + (b.r - a.r) * f, a.g + (b.g - a.g) * f, a.b + (b.b - a.b) * f, 1.0};
}

}  // namespace voronav::render
